// *INITIAL_STRAIN_SHELL: a shell's strain tensors (global axes, tensor shears) at its points,
// as LS-DYNA's dynain writes them for the inner and outer surfaces. Read and checked (setup:
// the element exists and is a shell); plyform's strain outputs are computed from the reference
// and current geometry (docs/outputs.md), so these strains are not applied, and setup says so
// in a warning.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<std::string_view, 2> kOptions{"", "SET"};
constexpr std::array<int, 2> kPlanes{1, 4};
constexpr std::array<int, 2> kFlags{0, 1};
constexpr std::array<int, 1> kGlobal{0};

constexpr std::array kHeaderFields{
    FieldSpec{.name = "EID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "shell element id",
              .required = true},
    FieldSpec{.name = "NPLANE",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "in-plane points given (1 or 4)",
              .allowed = kPlanes},
    FieldSpec{.name = "NTHICK",
              .type = FieldType::kInteger,
              .default_value = 2,
              .min_value = 1,
              .unit = "-",
              .description = "through-thickness points given (dynain: 2, the inner and outer "
                             "surfaces)"},
    FieldSpec{.name = "LARGE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0: 10-character fields; 1: 16-character fields (20 where a card "
                             "runs past column 80), two cards per "
                             "point",
              .allowed = kFlags},
    FieldSpec{.name = "UNUSED", .type = FieldType::kText, .description = "not used"},
    FieldSpec{.name = "UNUSED", .type = FieldType::kText, .description = "not used"},
    FieldSpec{.name = "UNUSED", .type = FieldType::kText, .description = "not used"},
    FieldSpec{.name = "ILOCAL",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0: global axes (local axes are not supported)",
              .allowed = kGlobal},
};

constexpr FieldSpec strain(std::string_view name, int width) {
  return FieldSpec{.name = name,
                   .width = width,
                   .unit = "-",
                   .description = "strain component, global axes (tensor shear)"};
}
constexpr FieldSpec zeta(int width) {
  return FieldSpec{.name = "T",
                   .width = width,
                   .min_value = -1.0,
                   .max_value = 1.0,
                   .unit = "-",
                   .description = "through-thickness coordinate, -1 (inner) .. 1 (outer)"};
}
constexpr std::array kPointFields{strain("EPSXX", 10),
                                  strain("EPSYY", 10),
                                  strain("EPSZZ", 10),
                                  strain("EPSXY", 10),
                                  strain("EPSYZ", 10),
                                  strain("EPSZX", 10),
                                  zeta(10)};
// LARGE 1, in fields of W characters (16: LS-DYNA's; 20: pydyna's, common_cards.hpp).
template <int W>
constexpr std::array kLargeFields1{strain("EPSXX", W), strain("EPSYY", W), strain("EPSZZ", W),
                                   strain("EPSXY", W), strain("EPSYZ", W)};
template <int W>
constexpr std::array kLargeFields2{strain("EPSZX", W), zeta(W)};
template <int W>
constexpr std::array kLargeCards{
    CardSpec{.title = "Strain card 1 (LARGE 1)", .fields = kLargeFields1<W>},
    CardSpec{.title = "Strain card 2 (LARGE 1)", .fields = kLargeFields2<W>},
};
constexpr std::array kCards{
    CardSpec{.title = "Header card",
             .fields = kHeaderFields,
             .presence = "one per element, repeated until the next keyword"},
    CardSpec{.title = "Strain card (LARGE 0)",
             .fields = kPointFields,
             .presence = "NTHICK x NPLANE after the header"},
    CardSpec{.title = "Strain card 1 (LARGE 1)",
             .fields = kLargeFields1<16>,
             .presence = "with LARGE 1, in place of the strain card (fields of 20 characters "
                         "where the card runs past column 80)"},
    CardSpec{.title = "Strain card 2 (LARGE 1)",
             .fields = kLargeFields2<16>,
             .presence = "with LARGE 1, after strain card 1, in its field width"},
};

void read_initial_strain_shell(KeywordInput& in) {
  if (in.option() == "SET") {
    in.fail(in.keyword().line, "SID",
            "the _SET form is not supported: give each element its own header card (EID)");
  }
  while (const auto line = in.next_nonblank_line()) {
    const CardValues h = in.read(kCards[0], *line);
    model::InitialStrainShellDesc d;
    d.element_id = h.integer("EID");
    d.nplane = h.integer("NPLANE");
    d.nthick = h.integer("NTHICK");
    d.large = h.integer("LARGE") == 1;
    d.where = in.where(line->line);
    for (int k = 0; k < d.nthick * d.nplane; ++k) {
      model::InitialStrainPoint p;
      const auto first = in.next_line();
      if (!first) {
        in.fail(line->line, "EPSXX",
                "missing strain card (EPSXX EPSYY EPSZZ EPSXY EPSYZ EPSZX T): NTHICK x NPLANE "
                "cards follow the header");
      }
      const auto& wide =
          d.large && large_field_width(*first) == 20 ? kLargeCards<20> : kLargeCards<16>;
      const CardValues a = in.read(d.large ? wide[0] : kCards[1], *first);
      constexpr std::array<std::string_view, 6> kNames{"EPSXX", "EPSYY", "EPSZZ",
                                                       "EPSXY", "EPSYZ", "EPSZX"};
      for (std::size_t c = 0; c < (d.large ? 5u : 6u); ++c)
        p.eps[c] = a.real(kNames[c]);
      if (d.large) {
        const CardValues b = in.next_card(wide[1], "strain card 2 (EPSZX T) of LARGE 1");
        p.eps[5] = b.real("EPSZX");
        p.t = b.real("T");
      } else {
        p.t = a.real("T");
      }
      d.points.push_back(p);
    }
    in.model().initial_shell_strains.push_back(std::move(d));
  }
}

}  // namespace

KeywordSpec initial_strain_shell_keyword() {
  return {.name = "INITIAL_STRAIN_SHELL",
          .options = kOptions,
          .handler = read_initial_strain_shell,
          .cards = kCards,
          .summary =
              "A shell's strain tensors at its points (global axes, tensor shears), as "
              "LS-DYNA's dynain writes them for the inner and outer surfaces. Read and "
              "checked (the element must be a shell), not applied: plyform computes its "
              "strain outputs from the reference and current geometry, so a run started "
              "from a dynain measures strain from the dynain's shape (a warning says "
              "so). The _SET form and local axes (ILOCAL 1) are refused."};
}

}  // namespace plyform::keyword
