// *PART: heading, then PID SECID MID EOSID HGID GRAV ADPOPT TMID.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kHeadingFields{
    FieldSpec{.name = "HEADING",
              .type = FieldType::kText,
              .width = 70,
              .description = "name of the part (may be blank)",
              .rest_of_line = true},
};
constexpr std::array kCard1Fields{
    FieldSpec{.name = "PID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "part id",
              .required = true},
    FieldSpec{.name = "SECID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "section id (must be defined: checked by setup::validate_mesh)"},
    FieldSpec{.name = "MID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "material id (must be defined: checked by setup::validate_mesh)"},
    FieldSpec{.name = "EOSID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "equation of state id: must be 0 (not supported yet)"},
    FieldSpec{.name = "HGID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "*HOURGLASS id (0: *CONTROL_HOURGLASS defaults)"},
    FieldSpec{.name = "GRAV",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "gravity initialisation flag (solids ignore it); kept as written"},
    FieldSpec{.name = "ADPOPT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "adaptive remeshing of the part: read and warned about (plyform "
                             "keeps the initial mesh)"},
    FieldSpec{.name = "TMID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "thermal material id (*MAT_THERMAL_...; 0: the part takes no part "
                             "in heat conduction)"},
};
constexpr std::array kCards{
    CardSpec{.title = "Heading card", .fields = kHeadingFields, .presence = "required"},
    CardSpec{.title = "Card 1",
             .fields = kCard1Fields,
             .presence = "required; heading and card 1 may repeat for more parts"},
};

void read_part(KeywordInput& in) {
  do {
    const auto heading_line = in.next_line();
    if (!heading_line) {
      in.fail(in.keyword().line, "", "missing heading card");
    }
    model::PartDesc part;
    part.title = in.read(kCards[0], *heading_line).text("HEADING");
    const auto line = in.next_line();
    if (!line) {
      in.fail(heading_line->line, "",
              "missing card 1 (PID SECID MID EOSID HGID GRAV ADPOPT TMID) after the heading");
    }
    const CardValues v = in.read(kCards[1], *line);
    part.id = v.integer("PID");
    part.section_id = v.integer("SECID");
    part.material_id = v.integer("MID");
    part.eos_id = v.integer("EOSID");
    part.hourglass_id = v.integer("HGID");
    part.grav = v.integer("GRAV");
    part.adpopt = v.integer("ADPOPT");
    part.thermal_material_id = v.integer("TMID");
    part.where = in.where(line->line);
    require_zero(in, line->line, "EOSID", part.eos_id, "an equation of state");
    if (part.adpopt != 0) {
      in.warn(line->line, "ADPOPT",
              "part " + std::to_string(part.id) + ": ADPOPT " + std::to_string(part.adpopt) +
                  " asks for adaptive remeshing, which plyform does not do yet: the part keeps "
                  "its initial mesh");
    }
    in.model().parts.push_back(std::move(part));
  } while (has_more_cards(in));
}

}  // namespace

KeywordSpec part_keyword() {
  return {.name = "PART",
          .options = kNoOptions,
          .handler = read_part,
          .cards = kCards,
          .summary =
              "A part: its section, material, hourglass control and thermal material "
              "(TMID, used when *CONTROL_SOLUTION computes temperatures). The heading card "
              "always comes first (LS-DYNA has no _TITLE option here). Options such as "
              "_INERTIA or _CONTACT are not supported."};
}

}  // namespace plyform::keyword
