// *ELEMENT_SOLID: 8-node solid elements (degenerate shapes as repeated nodes).
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr FieldSpec node_field(std::string_view name) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .width = 8,
                   .min_value = 0,
                   .unit = "-",
                   .description = "node id"};
}

constexpr std::array kOneCardFields{
    FieldSpec{.name = "EID",
              .type = FieldType::kInteger,
              .width = 8,
              .min_value = 1,
              .unit = "-",
              .description = "element id",
              .required = true},
    FieldSpec{.name = "PID",
              .type = FieldType::kInteger,
              .width = 8,
              .min_value = 1,
              .unit = "-",
              .description = "part id",
              .required = true},
    node_field("N1"),
    node_field("N2"),
    node_field("N3"),
    node_field("N4"),
    node_field("N5"),
    node_field("N6"),
    node_field("N7"),
    node_field("N8"),
};
constexpr std::array kNodeCardFields{
    node_field("N1"),
    node_field("N2"),
    node_field("N3"),
    node_field("N4"),
    node_field("N5"),
    node_field("N6"),
    node_field("N7"),
    node_field("N8"),
    FieldSpec{.name = "N9",
              .type = FieldType::kInteger,
              .width = 8,
              .max_value = 0,
              .unit = "-",
              .description = "must be blank (10-node tetrahedra are not supported)"},
    FieldSpec{.name = "N10",
              .type = FieldType::kInteger,
              .width = 8,
              .max_value = 0,
              .unit = "-",
              .description = "must be blank"},
};
constexpr std::array kCards{
    CardSpec{.title = "Element card",
             .fields = kOneCardFields,
             .presence = "one per element, until the next keyword. When N1..N8 are all blank "
                         "the LS-DYNA 971+ two-card form is read: the next line is the node "
                         "card"},
    CardSpec{.title = "Node card (two-card form)",
             .fields = kNodeCardFields,
             .presence = "after an element card with EID and PID only"},
};

constexpr std::array<std::string_view, 8> kNodeNames{"N1", "N2", "N3", "N4",
                                                     "N5", "N6", "N7", "N8"};

void read_element_solid(KeywordInput& in) {
  std::vector<model::ElementSolidDesc>& solids = in.model().solids;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues card = in.read(kCards[0], *line);
    model::ElementSolidDesc element{.id = card.integer("EID"),
                                    .part_id = card.integer("PID"),
                                    .nodes = {},
                                    .where = in.where(line->line)};
    bool all_blank = true;
    for (std::string_view name : kNodeNames) {
      all_blank = all_blank && card.blank(name);
    }
    const CardValues node_card = [&] {
      if (!all_blank) {
        return card;
      }
      const auto nodes_line = in.next_line();
      if (!nodes_line) {
        in.fail(line->line, "N1",
                "missing node card: element card with EID and PID only must be followed by "
                "N1..N8 (two-card form)");
      }
      element.where = in.where(nodes_line->line);
      return in.read(kCards[1], *nodes_line);
    }();
    for (std::size_t i = 0; i < kNodeNames.size(); ++i) {
      const int id = node_card.integer(kNodeNames[i]);
      if (id == 0) {
        in.fail(element.where.line, std::string(kNodeNames[i]),
                "a solid element needs 8 node ids; write tetrahedra and pentahedra with "
                "repeated nodes (N1 N2 N3 N4 N4 N4 N4 N4, N1 N2 N3 N4 N5 N5 N6 N6)");
      }
      element.nodes[i] = id;
    }
    solids.push_back(std::move(element));
  }
}

}  // namespace

KeywordSpec element_solid_keyword() {
  return {.name = "ELEMENT_SOLID",
          .options = kNoOptions,
          .handler = read_element_solid,
          .cards = kCards,
          .summary =
              "8-node solid elements, 8-character fields (EID PID N1..N8 on one 80-column "
              "card), or LS-DYNA 971+'s two-card form (EID PID, then N1..N8). Degenerate "
              "shapes are written with repeated nodes; setup::validate_mesh checks the "
              "patterns. Element options (_ORTHO, _DOF, _TET4TOTET10, ...) are not supported."};
}

}  // namespace plyform::keyword
