// *CONTROL_SHELL: the through-thickness rule (INTGRD), the thickness update (ISTUPD) and the
// default theory. Every other field must keep LS-DYNA's default: plyform does not implement
// what it would change, and says so rather than ignoring it.

#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kZeroOnly{0};
constexpr std::array kZeroOne{0, 1};
constexpr std::array kTheories{0, 2};
constexpr std::array kMiters{0, 1, 2};
constexpr std::array kBwcs{0, 2};
constexpr std::array kIrnxx{0, -1};
constexpr std::array kCstyp6{0, 1};

constexpr std::array kCard1{
    FieldSpec{.name = "WRPANG",
              .default_value = 20.0,
              .unit = "degree",
              .description = "warping angle for warnings (read; plyform does not warn yet)"},
    FieldSpec{
        .name = "ESORT",
        .type = FieldType::kInteger,
        .unit = "-",
        .description = "automatic sorting of triangular shells (0 only)",
        .allowed = kZeroOnly,
        .allowed_note = "sorting triangles to a C0 triangle formulation is not supported yet"},
    FieldSpec{.name = "IRNXX",
              .type = FieldType::kInteger,
              .default_value = -1,
              .unit = "-",
              .description = "shell normal update option (-1 or 0)",
              .allowed = kIrnxx,
              .allowed_note = "only LS-DYNA's default normal update is used"},
    FieldSpec{.name = "ISTUPD",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "thickness update; plyform always updates the thickness",
              .allowed = kZeroOne},
    FieldSpec{.name = "THEORY",
              .type = FieldType::kInteger,
              .default_value = 2,
              .unit = "-",
              .description = "default shell theory (2, Belytschko-Tsay)",
              .allowed = kTheories,
              .allowed_note = "plyform has the Belytschko-Tsay shell (2)"},
    FieldSpec{.name = "BWC",
              .type = FieldType::kInteger,
              .default_value = 2,
              .unit = "-",
              .description = "warping stiffness (2: none, Belytschko-Tsay)",
              .allowed = kBwcs,
              .allowed_note = "the Belytschko-Wong-Chiang warping stiffness is not supported yet"},
    FieldSpec{.name = "MITER",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "plane-stress plasticity (exact return in plyform)",
              .allowed = kMiters,
              .allowed_note = "plyform's plane-stress return is exact (1 and 2 are accepted)"},
    FieldSpec{.name = "PROJ",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "warping projection (0 only)",
              .allowed = kZeroOnly,
              .allowed_note = "the projection method for warped elements is not supported yet"},
};
constexpr std::array kCard2{
    FieldSpec{.name = "ROTASCL",
              .default_value = 1.0,
              .min_value = 1.0,
              .max_value = 1.0,
              .unit = "-",
              .description = "rotary inertia scale (1 only)"},
    FieldSpec{.name = "INTGRD",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "through-thickness rule: 0 Gauss, 1 Lobatto",
              .allowed = kZeroOne},
    FieldSpec{.name = "LAMSHT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "laminated shell theory (0 only)",
              .allowed = kZeroOnly,
              .allowed_note = "laminated shell theory is not supported yet"},
    FieldSpec{.name = "CSTYP6",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "ELFORM 6 coordinate system (read)",
              .allowed = kCstyp6},
    FieldSpec{.name = "THSHEL",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "thermal shells: 0 one temperature through the thickness, 1 a "
                             "temperature gradient through it (bottom, middle, top)",
              .allowed = kZeroOne},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1", .fields = kCard1, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kCard2, .presence = "optional"},
};

void read_control_shell(KeywordInput& in) {
  model::ControlShellDesc desc;
  desc.where = in.keyword_where();
  const auto line1 = in.next_line();
  if (!line1)
    in.fail(in.keyword().line, "", "missing card 1 (WRPANG ESORT IRNXX ISTUPD ...)");
  const CardValues c1 = in.read(kCards[0], *line1);
  desc.istupd = c1.integer("ISTUPD");
  desc.theory = c1.integer("THEORY") == 0 ? 2 : c1.integer("THEORY");
  desc.where = in.where(line1->line);
  if (desc.istupd == 0) {
    in.warn(line1->line, "ISTUPD",
            "plyform updates the shell thickness from the through-thickness strain (as with "
            "ISTUPD = 1)");
  }
  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kCards[1], *line2);
    desc.intgrd = c2.integer("INTGRD");
    desc.thshel = c2.integer("THSHEL");
  }
  if (in.model().control_shell) {
    in.warn(in.keyword().line, "",
            "*CONTROL_SHELL given again: this one replaces the one at line " +
                std::to_string(in.model().control_shell->where.line));
  }
  in.model().control_shell = desc;
}

}  // namespace

KeywordSpec control_shell_keyword() {
  return {.name = "CONTROL_SHELL",
          .options = kNoOptions,
          .handler = read_control_shell,
          .cards = kCards,
          .summary =
              "Shell controls: INTGRD selects Gauss (0) or Lobatto (1) points through the "
              "thickness; fields plyform does not implement must keep their defaults."};
}

}  // namespace plyform::keyword
