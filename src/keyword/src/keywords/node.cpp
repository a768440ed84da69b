// *NODE: node ids and coordinates.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 8> kConstraintCodes{0, 1, 2, 3, 4, 5, 6, 7};

constexpr std::array kNodeFields{
    FieldSpec{.name = "NID",
              .type = FieldType::kInteger,
              .width = 8,
              .min_value = 1,
              .unit = "-",
              .description = "node id",
              .required = true},
    FieldSpec{.name = "X", .type = FieldType::kReal, .width = 16, .description = "x, length"},
    FieldSpec{.name = "Y", .type = FieldType::kReal, .width = 16, .description = "y, length"},
    FieldSpec{.name = "Z", .type = FieldType::kReal, .width = 16, .description = "z, length"},
    FieldSpec{.name = "TC",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "translational constraint: 0 none, 1 x, 2 y, 3 z, 4 x+y, 5 y+z, "
                             "6 z+x, 7 all",
              .allowed = kConstraintCodes},
    FieldSpec{.name = "RC",
              .type = FieldType::kInteger,
              .width = 8,
              .unit = "-",
              .description = "rotational constraint, codes as TC (kept; solids have none)",
              .allowed = kConstraintCodes},
};
constexpr std::array kCards{
    CardSpec{.title = "Node cards",
             .fields = kNodeFields,
             .presence = "one per node, until the next keyword (blank lines are skipped)"},
};

void read_node(KeywordInput& in) {
  std::vector<model::NodeDesc>& nodes = in.model().nodes;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues v = in.read(kCards[0], *line);
    nodes.push_back({.id = v.integer("NID"),
                     .x = v.real("X"),
                     .y = v.real("Y"),
                     .z = v.real("Z"),
                     .tc = v.integer("TC"),
                     .rc = v.integer("RC"),
                     .where = in.where(line->line)});
  }
}

}  // namespace

KeywordSpec node_keyword() {
  return {.name = "NODE",
          .options = kNoOptions,
          .handler = read_node,
          .cards = kCards,
          .summary =
              "Nodes. Fixed format has LS-DYNA's widths: NID 8, X Y Z 16 each, TC RC 8 "
              "each (80 columns)."};
}

}  // namespace plyform::keyword
