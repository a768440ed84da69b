// *SECTION_SHELL(_TITLE): formulation, integration and thickness of shells.
#include <array>
#include <cmath>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 3> kElforms{0, 2, 16};
constexpr std::array<int, 1> kQuadratures{0};
constexpr std::array<int, 2> kIcomps{0, 1};

constexpr std::array kCard1Fields{
    FieldSpec{.name = "SECID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "section id",
              .required = true},
    FieldSpec{.name = "ELFORM",
              .type = FieldType::kInteger,
              .default_value = 2,
              .unit = "-",
              .description = "2: Belytschko-Tsay, 16: fully integrated; 0 is read as 2",
              .allowed = kElforms,
              .allowed_note = "plyform reads ELFORM 2 and 16 shells only for now"},
    FieldSpec{.name = "SHRF",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "transverse shear factor (0 is read as 1; LS-DYNA recommends 5/6)"},
    FieldSpec{.name = "NIP",
              .type = FieldType::kReal,
              .default_value = 2,
              .min_value = 0,
              .max_value = 10,
              .unit = "-",
              .description = "integration points through the thickness, a whole number (0 is "
                             "read as 2); a real field in LS-DYNA"},
    FieldSpec{.name = "PROPT",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "-",
              .description = "printout option; kept as written"},
    FieldSpec{.name = "QR/IRID",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "quadrature through the thickness: 0 Gauss",
              .allowed = kQuadratures,
              .allowed_note = "trapezoidal (1) and user rules (< 0, *INTEGRATION_SHELL) are not "
                              "supported yet; LS-DYNA selects Lobatto with INTGRD of "
                              "*CONTROL_SHELL, not here"},
    FieldSpec{.name = "ICOMP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "1: a material angle per integration point (angle cards follow)",
              .allowed = kIcomps},
    FieldSpec{.name = "SETYP",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "2D solid type (ELFORM 13-15 only); kept as written"},
};
constexpr FieldSpec thickness_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kReal,
                   .min_value = 0.0,
                   .unit = "length",
                   .description = description};
}
constexpr std::array kCard2Fields{
    thickness_field("T1", "thickness at the element's N1"),
    thickness_field("T2", "thickness at N2 (0: T1)"),
    thickness_field("T3", "thickness at N3 (0: T1)"),
    thickness_field("T4", "thickness at N4 (0: T1)"),
    FieldSpec{.name = "NLOC",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "reference surface: must be 0 (mid-surface; offsets are not "
                             "supported yet)"},
    FieldSpec{.name = "MAREA",
              .type = FieldType::kReal,
              .unit = "mass/length^2",
              .description = "non-structural mass per area: must be 0 (not supported yet)"},
    FieldSpec{.name = "IDOF",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "thickness field option: must be 0 (not supported yet)"},
    FieldSpec{.name = "EDGSET",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "edge node set of shell seatbelts: must be 0"},
};
constexpr FieldSpec angle_field() {
  return FieldSpec{.name = "B",
                   .type = FieldType::kReal,
                   .unit = "degree",
                   .description = "material angle at an integration point"};
}
constexpr std::array kAngleFields{angle_field(), angle_field(), angle_field(), angle_field(),
                                  angle_field(), angle_field(), angle_field(), angle_field()};
constexpr std::array kCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kCard2Fields,
             .presence = "required; title card, cards 1, 2 (and angle cards) may repeat for "
                         "more sections"},
    CardSpec{.title = "Angle cards",
             .fields = kAngleFields,
             .presence = "with ICOMP = 1 only: NIP angles B1..B_NIP, eight per card",
             .numbering = FieldNumbering::kSequential},
};

void read_section_shell(KeywordInput& in) {
  do {
    model::SectionShellDesc section;
    if (in.option() == "TITLE") {
      section.title = in.next_card(kCards[0], "title card").text("TITLE");
    }
    const auto line = in.next_line();
    if (!line) {
      in.fail(in.keyword().line, "",
              "missing card 1 (SECID ELFORM SHRF NIP PROPT QR/IRID ICOMP SETYP)");
    }
    const CardValues v = in.read(kCards[1], *line);
    section.id = v.integer("SECID");
    section.elform = v.integer("ELFORM") == 0 ? 2 : v.integer("ELFORM");
    section.shear_factor = v.real("SHRF") == 0.0 ? 1.0 : v.real("SHRF");
    const double nip = v.real("NIP");
    if (nip != std::trunc(nip)) {
      in.fail(line->line, "NIP", fmt::format("NIP = {} is not a whole number of points", nip));
    }
    section.nip = nip == 0.0 ? 2 : static_cast<int>(nip);
    section.propt = v.real("PROPT");
    section.quadrature = static_cast<int>(v.real("QR/IRID"));
    section.icomp = v.integer("ICOMP");
    section.setyp = v.integer("SETYP");
    section.where = in.where(line->line);

    const auto line2 = in.next_line();
    if (!line2) {
      in.fail(line->line, "", "missing card 2 (T1 T2 T3 T4 NLOC MAREA IDOF EDGSET)");
    }
    const CardValues c2 = in.read(kCards[2], *line2);
    constexpr std::array<std::string_view, 4> kThickness{"T1", "T2", "T3", "T4"};
    for (std::size_t i = 0; i < kThickness.size(); ++i) {
      const double t = c2.real(kThickness[i]);
      section.thickness[i] = (i > 0 && t == 0.0) ? section.thickness[0] : t;
    }
    section.nloc = c2.real("NLOC");
    section.marea = c2.real("MAREA");
    section.idof = c2.real("IDOF");
    section.edgset = c2.integer("EDGSET");
    require_zero(in, line2->line, "NLOC", section.nloc, "a reference surface off the mid-plane");
    require_zero(in, line2->line, "MAREA", section.marea, "non-structural mass");
    require_zero(in, line2->line, "IDOF", section.idof, "a thickness field option");
    require_zero(in, line2->line, "EDGSET", section.edgset, "shell seatbelts");

    if (section.icomp == 1) {
      for (int card = 0; static_cast<int>(section.angles.size()) < section.nip; ++card) {
        const auto angles = in.next_line();
        if (!angles) {
          in.fail(line2->line, fmt::format("B{}", section.angles.size() + 1),
                  fmt::format("ICOMP = 1 needs {} material angles B1..B{} (eight per card) "
                              "after card 2; {} found",
                              section.nip, section.nip, section.angles.size()));
        }
        const CardValues b = in.read(kCards[3], *angles, card);
        for (std::size_t i = 0;
             i < b.size() && static_cast<int>(section.angles.size()) < section.nip; ++i) {
          section.angles.push_back(b.at(i).real);
        }
      }
    }
    in.model().shell_sections.push_back(std::move(section));
  } while (has_more_cards(in));
}

}  // namespace

KeywordSpec section_shell_keyword() {
  return {.name = "SECTION_SHELL",
          .options = kNoneOrTitle,
          .handler = read_section_shell,
          .cards = kCards,
          .summary =
              "The formulation, through-thickness integration and thickness of shell "
              "elements. ELFORM 2 (Belytschko-Tsay: one in-plane point, hourglass control) and "
              "16 (fully integrated: 2 x 2 in-plane points, MITC4 transverse shear, no "
              "hourglass modes, so a part's *HOURGLASS is ignored with a warning), Gauss "
              "integration with NIP 1..10 points, and "
              "per-point material angles (ICOMP = 1) are read; offsets (NLOC), non-structural "
              "mass (MAREA), IDOF and EDGSET must be 0. The cards of user-defined shells "
              "(ELFORM 101-105) are not read. An element's *ELEMENT_SHELL_THICKNESS card "
              "takes precedence over T1..T4."};
}

}  // namespace plyform::keyword
