// *LOAD_SEGMENT, *LOAD_SEGMENT_SET, *LOAD_SHELL_ELEMENT and *LOAD_SHELL_SET (each with _ID):
// pressure on segments or shell elements, following their current area and normal.
#include <array>
#include <span>
#include <string>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr FieldSpec kCurveField{.name = "LCID",
                                .type = FieldType::kInteger,
                                .min_value = 1,
                                .unit = "-",
                                .description = "curve of the pressure against time",
                                .required = true};
constexpr FieldSpec kScaleField{.name = "SF",
                                .type = FieldType::kReal,
                                .default_value = 1.0,
                                .unit = "-",
                                .description = "scale factor of the curve's ordinate"};
constexpr FieldSpec kArrivalField{
    .name = "AT",
    .type = FieldType::kReal,
    .min_value = 0.0,
    .unit = "time",
    .description =
        "arrival (birth) time: no pressure before it; the curve is read at the "
        "run's time, not shifted"};

constexpr std::array kSegmentFields{
    kCurveField,
    kScaleField,
    kArrivalField,
    segment_node("N1", true),
    segment_node("N2", true),
    segment_node("N3", true),
    segment_node("N4", false),
    FieldSpec{.name = "N5",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "mid-side node of a quadratic segment: must be blank (four-node "
                             "segments only)"},
};

template <std::size_t N>
constexpr std::array<FieldSpec, 4> target_fields(const char (&name)[N],
                                                 std::string_view description) {
  return {FieldSpec{.name = std::string_view(name, N - 1),
                    .type = FieldType::kInteger,
                    .min_value = 1,
                    .unit = "-",
                    .description = description,
                    .required = true},
          kCurveField, kScaleField, kArrivalField};
}
constexpr std::array kSegmentSetFields = target_fields("SSID", "segment set id (*SET_SEGMENT)");
constexpr std::array kShellFields = target_fields("EID", "shell element id");
constexpr std::array kShellSetFields = target_fields("ESID", "shell set id (*SET_SHELL)");

constexpr std::string_view kRepeat =
    "one per load, until the next keyword; under _ID each is preceded by its ID card";
constexpr std::array kSegmentCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kSegmentFields, .presence = kRepeat},
};
constexpr std::array kSegmentSetCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kSegmentSetFields, .presence = kRepeat},
};
constexpr std::array kShellCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kShellFields, .presence = kRepeat},
};
constexpr std::array kShellSetCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kShellSetFields, .presence = kRepeat},
};

void read_pressure(KeywordInput& in, model::PressureTarget target,
                   std::span<const CardSpec> cards) {
  for (IdAndLine item = next_item(in, cards); item.line; item = next_item(in, cards)) {
    const CardValues v = in.read(cards[1], *item.line);
    model::LoadPressureDesc load;
    load.target = target;
    load.id = item.id;
    load.heading = std::move(item.heading);
    load.curve_id = v.integer("LCID");
    load.scale = v.real("SF");
    load.arrival = v.real("AT");
    load.keyword = in.keyword().display();
    load.where = in.where(item.line->line);
    switch (target) {
      case model::PressureTarget::kSegment: {
        require_zero(in, item.line->line, "N5", v.integer("N5"), "a quadratic segment");
        const int n3 = v.integer("N3");
        const int n4 = v.integer("N4");
        load.nodes = {v.integer("N1"), v.integer("N2"), n3, n4 == 0 ? n3 : n4};
        break;
      }
      case model::PressureTarget::kSegmentSet:
        load.target_id = v.integer("SSID");
        break;
      case model::PressureTarget::kShell:
        load.target_id = v.integer("EID");
        break;
      case model::PressureTarget::kShellSet:
        load.target_id = v.integer("ESID");
        break;
    }
    in.model().pressure_loads.push_back(std::move(load));
  }
}

}  // namespace

KeywordSpec load_segment_keyword() {
  return {.name = "LOAD_SEGMENT",
          .options = kNoneOrId,
          .handler =
              [](KeywordInput& in) {
                read_pressure(in, model::PressureTarget::kSegment, kSegmentCards);
              },
          .cards = kSegmentCards,
          .summary =
              "A pressure of a curve against time on one segment (a quadrilateral, or a "
              "triangle with N4 blank, 0 or N3) given by its nodes. The pressure "
              "follows the segment's current area and normal; positive pressure pushes "
              "against the normal of N1 -> N2 -> N3 (the right-hand rule). Its work is "
              "booked as external work (docs/boundary-conditions.md)."};
}

KeywordSpec load_segment_set_keyword() {
  return {.name = "LOAD_SEGMENT_SET",
          .options = kNoneOrId,
          .handler =
              [](KeywordInput& in) {
                read_pressure(in, model::PressureTarget::kSegmentSet, kSegmentSetCards);
              },
          .cards = kSegmentSetCards,
          .summary =
              "A pressure of a curve against time on every segment of a *SET_SEGMENT, "
              "as *LOAD_SEGMENT."};
}

KeywordSpec load_shell_element_keyword() {
  return {
      .name = "LOAD_SHELL_ELEMENT",
      .options = kNoneOrId,
      .handler =
          [](KeywordInput& in) { read_pressure(in, model::PressureTarget::kShell, kShellCards); },
      .cards = kShellCards,
      .summary =
          "A pressure of a curve against time on one shell element, on its "
          "mid-surface as *LOAD_SEGMENT on the element's nodes N1..N4 (positive "
          "pressure pushes against the shell's normal)."};
}

KeywordSpec load_shell_set_keyword() {
  return {.name = "LOAD_SHELL_SET",
          .options = kNoneOrId,
          .handler =
              [](KeywordInput& in) {
                read_pressure(in, model::PressureTarget::kShellSet, kShellSetCards);
              },
          .cards = kShellSetCards,
          .summary =
              "A pressure of a curve against time on every shell element of a "
              "*SET_SHELL, as *LOAD_SHELL_ELEMENT."};
}

}  // namespace plyform::keyword
