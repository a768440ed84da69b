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
constexpr std::array kZeroToTwo{0, 1, 2};
constexpr std::array kIrquad{0, 2, 3};

constexpr std::array kCard1{
    FieldSpec{.name = "WRPANG",
              .default_value = 20.0,
              .unit = "degree",
              .description = "warping angle for warnings (read; plyform does not warn yet)"},
    FieldSpec{.name = "ESORT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "automatic sorting of triangular shells into a C0 triangle "
                             "formulation (0 none, 1, 2 with a report): read; plyform has no "
                             "triangle formulation, so a model with triangular shells (N3 = N4) "
                             "and ESORT 1 or 2 is an error naming how many, and one without "
                             "any runs as it would in LS-DYNA",
              .allowed = kZeroToTwo,
              .allowed_note = "ESORT takes 0, 1 or 2"},
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
// Card 3 (LS-PrePost writes it): what concerns formulations plyform does not have is read;
// what would change its shells must keep LS-DYNA's default.
constexpr std::array kCard3{
    FieldSpec{.name = "PSSTUPD",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "part set of the thickness update: must be 0 (every part)",
              .allowed = kZeroOnly,
              .allowed_note = "plyform updates every shell's thickness"},
    FieldSpec{.name = "SIDT4TU",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "part set of the type-4 thickness update: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "the type-4 thickness update is not supported"},
    FieldSpec{.name = "CNTCO",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "reference-surface offsets in contact: must be 0 (plyform's shells "
                             "have their reference surface at mid-thickness)",
              .allowed = kZeroOnly,
              .allowed_note = "shell offsets (NLOC) are not supported, so there is none to count"},
    FieldSpec{.name = "ITSFLG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "initial transverse shear stress: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "initial transverse shear stresses are not supported"},
    FieldSpec{.name = "IRQUAD",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "in-plane rule of 8-node quadratic shells (2 or 3): read; plyform "
                             "has no quadratic shells",
              .allowed = kIrquad,
              .allowed_note = "IRQUAD takes 0, 2 or 3"},
    FieldSpec{.name = "W-MODE",
              .min_value = 0.0,
              .max_value = 0.0,
              .unit = "degree",
              .description = "failure of shells by the W-mode angle: must be 0 (plyform deletes "
                             "no elements)"},
    FieldSpec{.name = "STRETCH",
              .min_value = 0.0,
              .max_value = 0.0,
              .unit = "-",
              .description = "failure of shells by stretch: must be 0 (plyform deletes no "
                             "elements)"},
    FieldSpec{.name = "ICRQ",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "continuous thickness and plastic strain across elements: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "ICRQ 1 is not supported"},
};
// Card 4: the checks of badly shaped shells. NFAIL 1 (stop with an error) is what plyform does
// with any inverted or degenerate element; deleting elements (2, 3) is not.
constexpr std::array kCard4{
    FieldSpec{.name = "NFAIL1",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "badly shaped 4-node shells: 0 none, 1 stop with an error (plyform "
                             "always stops on an inverted or collapsed element, naming it)",
              .allowed = kZeroOne,
              .allowed_note = "deleting badly shaped shells (2, 3) is not supported"},
    FieldSpec{.name = "NFAIL4",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "badly shaped triangles: as NFAIL1",
              .allowed = kZeroOne,
              .allowed_note = "deleting badly shaped shells (2, 3) is not supported"},
    FieldSpec{.name = "PSNFAIL",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "part set the NFAIL checks apply to: read (plyform checks every "
                             "shell)"},
    FieldSpec{.name = "KEEPCS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "keep the contact segments of failed shells: must be 0 (no shell "
                             "fails)",
              .allowed = kZeroOnly,
              .allowed_note = "plyform deletes no shells"},
    FieldSpec{.name = "DELFR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "deletion of shells left alone by failure: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "plyform deletes no shells"},
    FieldSpec{.name = "DRCPSID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "part set of the drilling rotation constraint: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "the drilling rotation constraint is not supported"},
    FieldSpec{.name = "DRCPRM",
              .min_value = 0.0,
              .max_value = 1.0,
              .unit = "-",
              .description = "drilling constraint scale: 0 or 1 (its default, unused without "
                             "DRCPSID)"},
    FieldSpec{.name = "INTPERR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "error on a missing integration point of *INTEGRATION_SHELL: read "
                             "(plyform has no user integration rules)",
              .allowed = kZeroOne,
              .allowed_note = "INTPERR takes 0 or 1"},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1", .fields = kCard1, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kCard2, .presence = "optional"},
    CardSpec{.title = "Card 3", .fields = kCard3, .presence = "optional"},
    CardSpec{.title = "Card 4",
             .fields = kCard4,
             .presence = "optional; cards 5 and after are "
                         "not read (an error)"},
};

void read_control_shell(KeywordInput& in) {
  model::ControlShellDesc desc;
  desc.where = in.keyword_where();
  const auto line1 = in.next_line();
  if (!line1)
    in.fail(in.keyword().line, "", "missing card 1 (WRPANG ESORT IRNXX ISTUPD ...)");
  const CardValues c1 = in.read(kCards[0], *line1);
  desc.istupd = c1.integer("ISTUPD");
  desc.esort = static_cast<int>(c1.integer("ESORT"));
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
  if (const auto line3 = in.next_line())
    (void)in.read(kCards[2], *line3);
  if (const auto line4 = in.next_line())
    (void)in.read(kCards[3], *line4);
  if (has_more_cards(in)) {
    const auto extra = in.next_nonblank_line();
    in.fail(extra->line, "",
            "cards 5 and after of *CONTROL_SHELL (DRCMTH LISPSID NLOCDT) are not read; end the "
            "keyword after card 4");
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
              "thickness; cards 3 and 4 as LS-PrePost writes them; fields plyform does not "
              "implement must keep their defaults."};
}

}  // namespace plyform::keyword
