// *CONTROL_ADAPTIVE: h-adaptive remeshing. plyform does not refine meshes yet; a deck that asks
// for it is read and runs on its initial mesh, with a warning that says so (a forming deck
// written by LS-PrePost often carries the card whether or not the user counts on it).
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kFields{
    FieldSpec{.name = "ADPFREQ", .unit = "time", .description = "interval of refinements"},
    FieldSpec{.name = "ADPTOL", .unit = "-", .description = "error tolerance (or angle)"},
    FieldSpec{.name = "ADPTYP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "kind of refinement"},
    FieldSpec{.name = "MAXLVL",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "most levels of refinement"},
    FieldSpec{.name = "TBIRTH", .unit = "time", .description = "start of refinement"},
    FieldSpec{.name = "TDEATH", .unit = "time", .description = "end of refinement"},
    FieldSpec{.name = "LCADP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of the refinement interval"},
    FieldSpec{.name = "IOFLAG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "output of the adapted mesh"},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1",
             .fields = kFields,
             .presence = "required; the further cards (their layout differs between LS-DYNA "
                         "versions) are passed over"},
};

void read_control_adaptive(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", "missing card 1 (ADPFREQ ADPTOL ADPTYP MAXLVL ...)");
  (void)in.read(kCards[0], *line);
  in.skip_rest();
  in.warn(in.keyword().line, "",
          "adaptive remeshing is not done by plyform yet: the run goes on with the initial mesh "
          "(results may differ from LS-DYNA's where it would refine)");
}

constexpr std::array kAdapstepFields{
    FieldSpec{.name = "FACTIN",
              .default_value = 1.0,
              .unit = "-",
              .description = "initial relaxation factor of the contact forces in an adaptive "
                             "step"},
    FieldSpec{.name = "DFACTR",
              .default_value = 0.01,
              .unit = "-",
              .description = "its increment per step"},
};
constexpr std::array kAdapstepCards{
    CardSpec{.title = "Card 1", .fields = kAdapstepFields, .presence = "required"},
};

void read_control_adapstep(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", "missing card 1 (FACTIN DFACTR)");
  (void)in.read(kAdapstepCards[0], *line);
  in.warn(in.keyword().line, "",
          "the contact relaxation of adaptive steps has nothing to act on: plyform does not "
          "refine meshes yet");
}

}  // namespace

KeywordSpec control_adapstep_keyword() {
  return {.name = "CONTROL_ADAPSTEP",
          .options = kNoOptions,
          .handler = read_control_adapstep,
          .cards = kAdapstepCards,
          .summary =
              "Contact force relaxation during the steps of h-adaptive remeshing: read "
              "and warned about (plyform keeps the initial mesh)."};
}

KeywordSpec control_adaptive_keyword() {
  return {.name = "CONTROL_ADAPTIVE",
          .options = kNoOptions,
          .handler = read_control_adaptive,
          .cards = kCards,
          .summary =
              "h-adaptive remeshing: read (card 1 by its fields, the further cards passed over) "
              "and warned about; plyform runs on the initial mesh. A part's ADPOPT is warned "
              "about the same way."};
}

}  // namespace plyform::keyword
