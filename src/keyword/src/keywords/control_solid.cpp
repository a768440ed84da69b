// *CONTROL_SOLID as LS-PrePost writes it. Its fields choose formulations for tetrahedra,
// pentahedra and 10-node tetrahedra, which plyform does not have; what would change plyform's
// hexahedra must keep LS-DYNA's default.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kZeroOnly{0};
constexpr std::array kZeroOne{0, 1};
constexpr std::array kEsort{0, 1, 2};
constexpr std::array kSwlocl{0, 1, 2};

constexpr std::array kCard1{
    FieldSpec{.name = "ESORT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "sorting of degenerate solids into tetrahedron and pentahedron "
                             "formulations (0-2): read; plyform accepts only the degenerate "
                             "hexahedra it integrates as hexahedra, so nothing is sorted",
              .allowed = kEsort,
              .allowed_note = "ESORT takes 0, 1 or 2"},
    FieldSpec{.name = "FMATRX",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "deformation gradient of fully integrated solids (0 default)",
              .allowed = kZeroOnly,
              .allowed_note = "only LS-DYNA's default is used"},
    FieldSpec{.name = "NIPTETS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "points of the 4-node tetrahedron (read; plyform has none)"},
    FieldSpec{.name = "SWLOCL",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "output of the solids' local system (read)",
              .allowed = kSwlocl,
              .allowed_note = "SWLOCL takes 0, 1 or 2"},
    FieldSpec{.name = "PSFAIL",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "part set whose solids fail when inverted: must be 0 (plyform "
                             "stops on an inverted element)",
              .allowed = kZeroOnly,
              .allowed_note = "plyform deletes no elements"},
    FieldSpec{.name = "T10JTOL",
              .min_value = 0.0,
              .unit = "-",
              .description = "Jacobian tolerance of 10-node tetrahedra (read; plyform has none)"},
    FieldSpec{.name = "ICOHED",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "cohesive element deletion: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "plyform has no cohesive elements (its interfaces are contacts)"},
    FieldSpec{.name = "TET13K",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "13-node tetrahedron option (read; plyform has none)",
              .allowed = kZeroOne,
              .allowed_note = "TET13K takes 0 or 1"},
};
constexpr std::array kCard2{
    FieldSpec{.name = "PM1",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM2",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM3",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM4",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM5",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM6",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM7",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM8",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM9",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
    FieldSpec{.name = "PM10",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "node permutation of 10-node tetrahedra: must be 0"},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1", .fields = kCard1, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kCard2,
             .presence = "optional; cards 3 and after are not read (an error)"},
};

void read_control_solid(KeywordInput& in) {
  const auto line1 = in.next_line();
  if (!line1)
    in.fail(in.keyword().line, "", "missing card 1 (ESORT FMATRX NIPTETS SWLOCL ...)");
  (void)in.read(kCards[0], *line1);
  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kCards[1], *line2);
    for (const FieldSpec& f : kCard2)
      require_zero(in, line2->line, f.name, c2.integer(f.name), f.description);
  }
  if (has_more_cards(in)) {
    const auto extra = in.next_nonblank_line();
    in.fail(extra->line, "", "cards 3 and after of *CONTROL_SOLID are not read");
  }
}

}  // namespace

KeywordSpec control_solid_keyword() {
  return {.name = "CONTROL_SOLID",
          .options = kNoOptions,
          .handler = read_control_solid,
          .cards = kCards,
          .summary =
              "Solid controls as LS-PrePost writes them: the tetrahedron, pentahedron "
              "and 10-node options are read (plyform has hexahedra only); fields that "
              "would change hexahedra or delete elements must keep their defaults."};
}

}  // namespace plyform::keyword
