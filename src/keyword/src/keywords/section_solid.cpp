// *SECTION_SOLID(_TITLE): SECID ELFORM AET.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 3> kElforms{0, 1, 2};

constexpr std::array kCard1Fields{
    FieldSpec{.name = "SECID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "section id",
              .required = true},
    FieldSpec{.name = "ELFORM",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "1: constant stress (one point, hourglass control), 2: fully "
                             "integrated selectively reduced; 0 is read as 1",
              .allowed = kElforms,
              .allowed_note = "plyform has ELFORM 1 and 2 solids only for now"},
    FieldSpec{.name = "AET",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "ambient element type: must be 0 (not supported)"},
};
constexpr std::array kCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1",
             .fields = kCard1Fields,
             .presence = "required; may repeat for more sections (with the title card before "
                         "each under _TITLE)"},
};

void read_section_solid(KeywordInput& in) {
  do {
    model::SectionSolidDesc section;
    if (in.option() == "TITLE") {
      section.title = in.next_card(kCards[0], "title card").text("TITLE");
    }
    const auto line = in.next_line();
    if (!line) {
      in.fail(in.keyword().line, "", "missing card 1 (SECID ELFORM AET)");
    }
    const CardValues v = in.read(kCards[1], *line);
    section.id = v.integer("SECID");
    section.elform = v.integer("ELFORM") == 0 ? 1 : v.integer("ELFORM");
    section.aet = v.integer("AET");
    section.where = in.where(line->line);
    require_zero(in, line->line, "AET", section.aet, "ambient element type");
    in.model().solid_sections.push_back(std::move(section));
  } while (has_more_cards(in));
}

}  // namespace

KeywordSpec section_solid_keyword() {
  return {.name = "SECTION_SOLID",
          .options = kNoneOrTitle,
          .handler = read_section_solid,
          .cards = kCards,
          .summary =
              "The formulation of solid elements. Fields after AET (LS-DYNA's COHOFF, "
              "GASKETT, and the cards of ELFORM 101-105) are not read."};
}

}  // namespace plyform::keyword
