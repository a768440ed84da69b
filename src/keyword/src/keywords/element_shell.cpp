// *ELEMENT_SHELL and *ELEMENT_SHELL_THICKNESS: 3- and 4-node shell elements.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<std::string_view, 2> kOptions{"", "THICKNESS"};

constexpr FieldSpec node_field(std::string_view name) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .width = 8,
                   .min_value = 0,
                   .unit = "-",
                   .description = "node id"};
}
constexpr FieldSpec blank_node_field(std::string_view name) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .width = 8,
                   .max_value = 0,
                   .unit = "-",
                   .description = "must be blank or 0 (8-node shells are not supported)"};
}

constexpr std::array kElementFields{
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
    blank_node_field("N5"),
    blank_node_field("N6"),
    blank_node_field("N7"),
    blank_node_field("N8"),
};
constexpr FieldSpec thickness_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kReal,
                   .width = 16,
                   .min_value = 0.0,
                   .unit = "length",
                   .description = description};
}
constexpr std::array kThicknessFields{
    thickness_field("THIC1", "thickness at N1 (0: the section's)"),
    thickness_field("THIC2", "thickness at N2 (0: the section's)"),
    thickness_field("THIC3", "thickness at N3 (0: the section's)"),
    thickness_field("THIC4", "thickness at N4 (0: the section's)"),
    FieldSpec{.name = "BETA",
              .type = FieldType::kReal,
              .width = 16,
              .unit = "degree",
              .description = "material angle of the element (orthotropic materials)"},
};
constexpr std::array kCards{
    CardSpec{.title = "Element card",
             .fields = kElementFields,
             .presence = "one per element, until the next keyword; a triangle repeats N3 as N4"},
    CardSpec{.title = "Thickness card",
             .fields = kThicknessFields,
             .presence = "with _THICKNESS only: after each element card"},
};

constexpr std::array<std::string_view, 4> kNodeNames{"N1", "N2", "N3", "N4"};
constexpr std::array<std::string_view, 4> kThicknessNames{"THIC1", "THIC2", "THIC3", "THIC4"};

void read_element_shell(KeywordInput& in) {
  const bool with_thickness = in.option() == "THICKNESS";
  std::vector<model::ElementShellDesc>& shells = in.model().shells;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues card = in.read(kCards[0], *line);
    model::ElementShellDesc element{.id = card.integer("EID"),
                                    .part_id = card.integer("PID"),
                                    .nodes = {},
                                    .has_thickness_card = false,
                                    .thickness = {},
                                    .beta = 0.0,
                                    .where = in.where(line->line)};
    for (std::size_t i = 0; i < kNodeNames.size(); ++i) {
      const int id = card.integer(kNodeNames[i]);
      if (id == 0) {
        in.fail(line->line, std::string(kNodeNames[i]),
                i < 3 ? "a shell element needs node ids N1..N4; write a triangle with N4 = N3"
                      : "N4 is blank or 0: write a triangle with N4 = N3");
      }
      element.nodes[i] = id;
    }
    if (with_thickness) {
      const auto thickness_line = in.next_line();
      if (!thickness_line) {
        in.fail(line->line, "THIC1",
                "missing thickness card (THIC1 THIC2 THIC3 THIC4 BETA) after the element card "
                "(_THICKNESS)");
      }
      const CardValues t = in.read(kCards[1], *thickness_line);
      element.has_thickness_card = true;
      for (std::size_t i = 0; i < kThicknessNames.size(); ++i) {
        element.thickness[i] = t.real(kThicknessNames[i]);
      }
      element.beta = t.real("BETA");
    }
    shells.push_back(element);
  }
}

}  // namespace

KeywordSpec element_shell_keyword() {
  return {.name = "ELEMENT_SHELL",
          .options = kOptions,
          .handler = read_element_shell,
          .cards = kCards,
          .summary =
              "3- and 4-node shell elements, 8-character fields (EID PID N1..N4; N5..N8 of "
              "8-node shells must be blank). A triangle is written with N4 = N3; "
              "setup::validate_mesh checks the node lists. The _THICKNESS option adds a card "
              "of nodal thicknesses and a material angle (16-character fields) after each "
              "element. Other options (_BETA, _MCID, _OFFSET, _COMPOSITE, ...) are not "
              "supported."};
}

}  // namespace plyform::keyword
