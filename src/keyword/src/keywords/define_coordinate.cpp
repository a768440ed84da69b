// *DEFINE_COORDINATE_SYSTEM(_TITLE) and *DEFINE_COORDINATE_VECTOR(_TITLE): local coordinate
// systems fixed in space, by id, for the keywords whose CID names one (*BOUNDARY_SPC).
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr FieldSpec kCidField{.name = "CID",
                              .type = FieldType::kInteger,
                              .min_value = 1,
                              .unit = "-",
                              .description = "coordinate system id (shared by both keywords)",
                              .required = true};
constexpr FieldSpec coordinate(std::string_view name, std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kReal, .unit = "length", .description = description};
}

constexpr std::array kSystemCard1Fields{
    kCidField,
    coordinate("XO", "x of the origin"),
    coordinate("YO", "y of the origin"),
    coordinate("ZO", "z of the origin"),
    coordinate("XL", "x of a point on the local x axis"),
    coordinate("YL", "y of a point on the local x axis"),
    coordinate("ZL", "z of a point on the local x axis"),
    FieldSpec{.name = "CIDL",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "system the points are given in: must be 0 (global)"},
};
constexpr std::array kSystemCard2Fields{
    coordinate("XP", "x of a point in the local x-y plane, off the x axis"),
    coordinate("YP", "y of that point"),
    coordinate("ZP", "z of that point"),
};
constexpr std::string_view kRepeat =
    "one system per title card (with _TITLE) and card pair, until the next keyword";
constexpr std::array kSystemCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kSystemCard1Fields, .presence = kRepeat},
    CardSpec{.title = "Card 2", .fields = kSystemCard2Fields, .presence = "after each card 1"},
};

constexpr std::array kVectorFields{
    kCidField,
    coordinate("XX", "x of the vector along local x (the origin is at 0)"),
    coordinate("YX", "y of the vector along local x"),
    coordinate("ZX", "z of the vector along local x"),
    coordinate("XV", "x of a vector in the local x-y plane, off the x axis"),
    coordinate("YV", "y of that vector"),
    coordinate("ZV", "z of that vector"),
    FieldSpec{.name = "NID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "node whose rotation turns the system: must be 0 (the system "
                             "stays fixed in space)"},
};
constexpr std::array kVectorCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1",
             .fields = kVectorFields,
             .presence = "one system per title card (with _TITLE) and card, until the next "
                         "keyword"},
};

/// Fails on card 1's line when the points do not span a plane through the origin.
void require_axes(KeywordInput& in, const model::CoordinateSystemDesc& system,
                  std::string_view what) {
  if (!model::coordinate_axes(system)) {
    in.fail(system.where.line, "",
            fmt::format("coordinate system {}: {} (the local x axis needs a length, and the "
                        "x-y point must lie off it)",
                        system.id, what));
  }
}

void read_coordinate_system(KeywordInput& in) {
  bool any = false;
  while (true) {
    model::CoordinateSystemDesc system;
    if (in.option() == "TITLE") {
      const auto title = in.next_nonblank_line();
      if (!title)
        break;
      system.title = in.read(kSystemCards[0], *title).text("TITLE");
    }
    const auto line = in.option() == "TITLE" ? in.next_line() : in.next_nonblank_line();
    if (!line) {
      if (in.option() == "TITLE" || !any) {
        in.fail(in.keyword().line, "",
                "missing card 1 (CID XO YO ZO XL YL ZL CIDL) and card 2 (XP YP ZP)");
      }
      break;
    }
    const CardValues c1 = in.read(kSystemCards[1], *line);
    system.id = c1.integer("CID");
    system.origin = {c1.real("XO"), c1.real("YO"), c1.real("ZO")};
    system.on_x = {c1.real("XL"), c1.real("YL"), c1.real("ZL")};
    system.where = in.where(line->line);
    require_zero(in, line->line, "CIDL", c1.integer("CIDL"),
                 "points given in another local system");
    const auto line2 = in.next_line();
    if (!line2) {
      in.fail(line->line, "XP", "missing card 2 (XP YP ZP): a point in the local x-y plane");
    }
    const CardValues c2 = in.read(kSystemCards[2], *line2);
    system.in_xy = {c2.real("XP"), c2.real("YP"), c2.real("ZP")};
    require_axes(in, system, "the origin, the x point and the x-y point do not span a plane");
    in.model().coordinate_systems.push_back(std::move(system));
    any = true;
  }
}

void read_coordinate_vector(KeywordInput& in) {
  bool any = false;
  while (true) {
    model::CoordinateSystemDesc system;
    system.from_vectors = true;
    if (in.option() == "TITLE") {
      const auto title = in.next_nonblank_line();
      if (!title)
        break;
      system.title = in.read(kVectorCards[0], *title).text("TITLE");
    }
    const auto line = in.option() == "TITLE" ? in.next_line() : in.next_nonblank_line();
    if (!line) {
      if (in.option() == "TITLE" || !any) {
        in.fail(in.keyword().line, "", "missing card 1 (CID XX YX ZX XV YV ZV NID)");
      }
      break;
    }
    const CardValues c = in.read(kVectorCards[1], *line);
    system.id = c.integer("CID");
    system.on_x = {c.real("XX"), c.real("YX"), c.real("ZX")};
    system.in_xy = {c.real("XV"), c.real("YV"), c.real("ZV")};
    system.where = in.where(line->line);
    require_zero(in, line->line, "NID", c.integer("NID"), "a system turning with a node");
    require_axes(in, system, "the two vectors do not span a plane");
    in.model().coordinate_systems.push_back(std::move(system));
    any = true;
  }
}

}  // namespace

KeywordSpec define_coordinate_system_keyword() {
  return {.name = "DEFINE_COORDINATE_SYSTEM",
          .options = kNoneOrTitle,
          .handler = read_coordinate_system,
          .cards = kSystemCards,
          .summary =
              "A local coordinate system fixed in space: local x from the origin towards "
              "(XL, YL, ZL), local z normal to the plane of the origin, that point and "
              "(XP, YP, ZP), y = z x x. Named by the CID of *BOUNDARY_SPC; a system nothing "
              "names is read and kept. CIDL must be 0."};
}

KeywordSpec define_coordinate_vector_keyword() {
  return {.name = "DEFINE_COORDINATE_VECTOR",
          .options = kNoneOrTitle,
          .handler = read_coordinate_vector,
          .cards = kVectorCards,
          .summary =
              "A local coordinate system fixed in space from two vectors: local x along "
              "(XX, YX, ZX), local z normal to it and (XV, YV, ZV), y = z x x; its ids are "
              "those of *DEFINE_COORDINATE_SYSTEM. NID must be 0."};
}

}  // namespace plyform::keyword
