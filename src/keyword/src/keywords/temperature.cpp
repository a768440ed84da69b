// *INITIAL_TEMPERATURE_NODE/_SET and *BOUNDARY_TEMPERATURE_NODE/_SET: nodal temperatures at
// t = 0 and prescribed temperature histories. With *CONTROL_SOLUTION SOLN 1 or 2 plyform
// computes the temperatures (docs/thermal.md): these are its initial and boundary conditions;
// with SOLN 0 the temperatures stay as given here.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kLocs{0};
constexpr std::array kFaceLocs{-1, 0, 1};

// A prescribed temperature may hold one face of a thick thermal shell.
constexpr FieldSpec face_loc_field() {
  return FieldSpec{.name = "LOC",
                   .type = FieldType::kInteger,
                   .unit = "-",
                   .description =
                       "face of thick thermal shells (*CONTROL_SHELL THSHEL 1): -1 "
                       "bottom, 0 middle, 1 top",
                   .allowed = kFaceLocs};
}

constexpr FieldSpec loc_field() {
  return FieldSpec{.name = "LOC",
                   .type = FieldType::kInteger,
                   .unit = "-",
                   .description = "shell surface of thermal shells: must be 0",
                   .allowed = kLocs,
                   .allowed_note =
                       "the top and bottom surfaces of thermal shells (LOC -1, 1) "
                       "are not supported"};
}

constexpr std::array kInitialNodeFields{
    FieldSpec{.name = "NID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "node id",
              .required = true},
    FieldSpec{.name = "TEMP", .unit = "temperature", .description = "temperature at t = 0"},
    loc_field(),
};
constexpr std::array kInitialSetFields{
    FieldSpec{.name = "NSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "node set id (0: every node of the model)"},
    FieldSpec{.name = "TEMP", .unit = "temperature", .description = "temperature at t = 0"},
    loc_field(),
};
constexpr std::array kInitialNodeCards{
    CardSpec{.title = "Card 1",
             .fields = kInitialNodeFields,
             .presence = "one node per card, until the next keyword"},
};
constexpr std::array kInitialSetCards{
    CardSpec{.title = "Card 1",
             .fields = kInitialSetFields,
             .presence = "one set per card, until the next keyword"},
};

template <std::size_t N>
constexpr std::array<FieldSpec, 6> boundary_fields(const char (&target)[N],
                                                   std::string_view description) {
  return {FieldSpec{.name = std::string_view(target, N - 1),
                    .type = FieldType::kInteger,
                    .min_value = 1,
                    .unit = "-",
                    .description = description,
                    .required = true},
          FieldSpec{.name = "LCID",
                    .type = FieldType::kInteger,
                    .min_value = 0,
                    .unit = "-",
                    .description = "curve of the temperature against time (0: constant CMULT)"},
          FieldSpec{.name = "CMULT",
                    .default_value = 1.0,
                    .unit = "-",
                    .description = "multiplier of the curve (blank: 1), or the temperature "
                                   "when LCID = 0"},
          face_loc_field(),
          FieldSpec{.name = "TDEATH",
                    .default_value = 1e20,
                    .min_value = 0.0,
                    .unit = "time",
                    .description = "time the prescription ends (0 is read as 1e20)"},
          FieldSpec{.name = "TBIRTH",
                    .min_value = 0.0,
                    .unit = "time",
                    .description = "time the prescription starts (before: the initial "
                                   "temperature)"}};
}
constexpr std::array kBoundaryNodeFields = boundary_fields("NID", "node id");
constexpr std::array kBoundarySetFields = boundary_fields("NSID", "node set id");
constexpr std::array kBoundaryNodeCards{
    CardSpec{.title = "Card 1",
             .fields = kBoundaryNodeFields,
             .presence = "one node per card, until the next keyword"},
};
constexpr std::array kBoundarySetCards{
    CardSpec{.title = "Card 1",
             .fields = kBoundarySetFields,
             .presence = "one set per card, until the next keyword"},
};

void read_initial(KeywordInput& in, model::NodeTarget target, const CardSpec& card) {
  const bool set = target == model::NodeTarget::kSet;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues v = in.read(card, *line);
    model::InitialTemperatureDesc t;
    t.target = target;
    t.target_id = v.integer(set ? "NSID" : "NID");
    t.temperature = v.real("TEMP");
    t.loc = v.integer("LOC");
    t.where = in.where(line->line);
    in.model().initial_temperatures.push_back(t);
  }
}

void read_boundary(KeywordInput& in, model::NodeTarget target, const CardSpec& card) {
  const bool set = target == model::NodeTarget::kSet;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues v = in.read(card, *line);
    model::BoundaryTemperatureDesc t;
    t.target = target;
    t.target_id = v.integer(set ? "NSID" : "NID");
    t.curve_id = v.integer("LCID");
    t.cmult = v.real("CMULT");
    t.loc = v.integer("LOC");
    t.death = v.real("TDEATH") == 0.0 ? 1e20 : v.real("TDEATH");
    t.birth = v.real("TBIRTH");
    t.where = in.where(line->line);
    if (t.death <= t.birth) {
      in.fail(line->line, "TDEATH",
              fmt::format("TDEATH = {} is not after TBIRTH = {}", t.death, t.birth));
    }
    in.model().temperature_histories.push_back(t);
  }
}

}  // namespace

KeywordSpec initial_temperature_node_keyword() {
  return {.name = "INITIAL_TEMPERATURE_NODE",
          .options = kNoOptions,
          .handler =
              [](KeywordInput& in) {
                read_initial(in, model::NodeTarget::kNode, kInitialNodeCards[0]);
              },
          .cards = kInitialNodeCards,
          .summary = "The temperature of single nodes at t = 0."};
}

KeywordSpec initial_temperature_set_keyword() {
  return {
      .name = "INITIAL_TEMPERATURE_SET",
      .options = kNoOptions,
      .handler =
          [](KeywordInput& in) { read_initial(in, model::NodeTarget::kSet, kInitialSetCards[0]); },
      .cards = kInitialSetCards,
      .summary =
          "The temperature of every node of a node set at t = 0; NSID = 0 sets every "
          "node of the model."};
}

KeywordSpec boundary_temperature_node_keyword() {
  return {.name = "BOUNDARY_TEMPERATURE_NODE",
          .options = kNoOptions,
          .handler =
              [](KeywordInput& in) {
                read_boundary(in, model::NodeTarget::kNode, kBoundaryNodeCards[0]);
              },
          .cards = kBoundaryNodeCards,
          .summary =
              "A prescribed temperature of single nodes, CMULT x curve LCID against time "
              "between TBIRTH and TDEATH. A node may take one *BOUNDARY_TEMPERATURE "
              "entry only."};
}

KeywordSpec boundary_temperature_set_keyword() {
  return {.name = "BOUNDARY_TEMPERATURE_SET",
          .options = kNoOptions,
          .handler =
              [](KeywordInput& in) {
                read_boundary(in, model::NodeTarget::kSet, kBoundarySetCards[0]);
              },
          .cards = kBoundarySetCards,
          .summary = "As *BOUNDARY_TEMPERATURE_NODE, for every node of a node set."};
}

}  // namespace plyform::keyword
