// *INITIAL_STRESS_SHELL: a shell's stress and effective plastic strain at t = 0 at each of its
// points, global axes (LS-DYNA's dynain writes it so: docs/outputs.md). The header card
// EID NPLANE NTHICK NHISV NTENSR LARGE NTHINT NTHHSV, then per point (NTHICK groups of NPLANE
// in-plane points) one stress card of 10-character fields, or with LARGE 1 two of 16 (20 where
// the card runs past column 80: common_cards.hpp), each followed by its NHISV history values (8
// per card, 5 with LARGE 1). setup::build applies the stresses (setup/build_initial_stress.cpp).
#include <array>

#include <fmt/format.h>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<std::string_view, 2> kOptions{"", "SET"};
constexpr std::array<int, 2> kPlanes{1, 4};
constexpr std::array<int, 2> kFlags{0, 1};

constexpr FieldSpec count(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .unit = "-",
                   .description = description};
}

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
              .description = "in-plane points given: 1 (one for the element) or 4 (2 x 2 Gauss "
                             "points, order (-,-) (+,-) (+,+) (-,+))",
              .allowed = kPlanes},
    FieldSpec{.name = "NTHICK",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "through-thickness points given (interpolated to the section's "
                             "NIP points by their T)",
              .required = true},
    count("NHISV", "history values per point (read, not applied: warned about)"),
    FieldSpec{.name = "NTENSR",
              .type = FieldType::kInteger,
              .max_value = 0,
              .unit = "-",
              .description = "tensor history components: must be 0 (not supported)"},
    FieldSpec{.name = "LARGE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0: 10-character fields; 1: 16-character fields (20 where a card "
                             "runs past column 80), two cards per point",
              .allowed = kFlags},
    FieldSpec{.name = "NTHINT",
              .type = FieldType::kInteger,
              .max_value = 0,
              .unit = "-",
              .description = "thermal integration points: must be 0 (not supported)"},
    FieldSpec{.name = "NTHHSV",
              .type = FieldType::kInteger,
              .max_value = 0,
              .unit = "-",
              .description = "thermal history values: must be 0 (not supported)"},
};

constexpr FieldSpec stress(std::string_view name, std::string_view description, int width) {
  return FieldSpec{.name = name, .width = width, .unit = "stress", .description = description};
}
constexpr FieldSpec zeta(int width) {
  return FieldSpec{.name = "T",
                   .width = width,
                   .min_value = -1.0,
                   .max_value = 1.0,
                   .unit = "-",
                   .description =
                       "through-thickness coordinate of the point, -1 (bottom) .. 1 "
                       "(top)",
                   .required = true};
}
constexpr FieldSpec plastic(int width) {
  return FieldSpec{.name = "EPS",
                   .width = width,
                   .min_value = 0.0,
                   .unit = "-",
                   .description = "effective plastic strain"};
}

constexpr std::array kPointFields{
    zeta(10),
    stress("SIGXX", "stress xx, global axes", 10),
    stress("SIGYY", "stress yy", 10),
    stress("SIGZZ", "stress zz", 10),
    stress("SIGXY", "stress xy", 10),
    stress("SIGYZ", "stress yz", 10),
    stress("SIGZX", "stress zx", 10),
    plastic(10),
};
// LARGE 1, in fields of W characters (16: LS-DYNA's; 20: pydyna's, common_cards.hpp).
template <int W>
constexpr std::array kLargeFields1{
    zeta(W),
    stress("SIGXX", "stress xx, global axes", W),
    stress("SIGYY", "stress yy", W),
    stress("SIGZZ", "stress zz", W),
    stress("SIGXY", "stress xy", W),
};
template <int W>
constexpr std::array kLargeFields2{
    stress("SIGYZ", "stress yz", W),
    stress("SIGZX", "stress zx", W),
    plastic(W),
};
constexpr std::array kHistoryFields{
    FieldSpec{.name = "HISV", .unit = "-", .description = "history value (not applied)"},
    FieldSpec{.name = "HISV", .unit = "-", .description = "..."},
    FieldSpec{.name = "HISV", .unit = "-", .description = "..."},
    FieldSpec{.name = "HISV", .unit = "-", .description = "..."},
    FieldSpec{.name = "HISV", .unit = "-", .description = "..."},
    FieldSpec{.name = "HISV", .unit = "-", .description = "..."},
    FieldSpec{.name = "HISV", .unit = "-", .description = "..."},
    FieldSpec{.name = "HISV", .unit = "-", .description = "..."},
};
constexpr std::array kCards{
    CardSpec{.title = "Header card",
             .fields = kHeaderFields,
             .presence = "one per element, repeated until the next keyword"},
    CardSpec{.title = "Point card (LARGE 0)",
             .fields = kPointFields,
             .presence = "NTHICK x NPLANE after the header: per thickness point, its NPLANE "
                         "in-plane points"},
    CardSpec{.title = "Point card 1 (LARGE 1)",
             .fields = kLargeFields1<16>,
             .presence = "with LARGE 1, in place of the point card (fields of 20 characters "
                         "where the card runs past column 80)"},
    CardSpec{.title = "Point card 2 (LARGE 1)",
             .fields = kLargeFields2<16>,
             .presence = "with LARGE 1, after point card 1, in its field width"},
    CardSpec{.title = "History cards",
             .fields = kHistoryFields,
             .presence = "after each point when NHISV > 0: NHISV values, 8 per card (LARGE 1: "
                         "5 per card, in the point's field width)"},
};
// The history values with LARGE 1: five fields of W characters.
template <int W>
constexpr std::array kLargeHistoryFields{
    FieldSpec{.name = "HISV", .width = W, .unit = "-", .description = "history value"},
    FieldSpec{.name = "HISV", .width = W, .unit = "-", .description = "history value"},
    FieldSpec{.name = "HISV", .width = W, .unit = "-", .description = "history value"},
    FieldSpec{.name = "HISV", .width = W, .unit = "-", .description = "history value"},
    FieldSpec{.name = "HISV", .width = W, .unit = "-", .description = "history value"},
};
// The LARGE 1 cards of one width: point card 1, point card 2, history card.
template <int W>
constexpr std::array kLargeCards{
    CardSpec{.title = "Point card 1 (LARGE 1)", .fields = kLargeFields1<W>},
    CardSpec{.title = "Point card 2 (LARGE 1)", .fields = kLargeFields2<W>},
    CardSpec{.title = "History card (LARGE 1)", .fields = kLargeHistoryFields<W>},
};

/// Reads one point: its stress card(s), then its history cards (read over: warned about once).
model::InitialStressPoint read_point(KeywordInput& in, int header_line, bool large, int nhisv) {
  model::InitialStressPoint p;
  const auto first = in.next_line();
  if (!first) {
    in.fail(header_line, "T",
            "missing point card (T SIGXX ... EPS): NTHICK x NPLANE cards follow the header");
  }
  p.where = in.where(first->line);
  const auto& wide = large && large_field_width(*first) == 20 ? kLargeCards<20> : kLargeCards<16>;
  const CardValues a = in.read(large ? wide[0] : kCards[1], *first);
  p.t = a.real("T");
  p.sigma[0] = a.real("SIGXX");
  p.sigma[1] = a.real("SIGYY");
  p.sigma[2] = a.real("SIGZZ");
  p.sigma[3] = a.real("SIGXY");
  if (large) {
    const CardValues b = in.next_card(wide[1], "point card 2 (SIGYZ SIGZX EPS) of LARGE 1");
    p.sigma[4] = b.real("SIGYZ");
    p.sigma[5] = b.real("SIGZX");
    p.eps = b.real("EPS");
  } else {
    p.sigma[4] = a.real("SIGYZ");
    p.sigma[5] = a.real("SIGZX");
    p.eps = a.real("EPS");
  }
  const int per_card = large ? 5 : 8;
  for (int read = 0; read < nhisv; read += per_card)
    (void)in.next_card(large ? wide[2] : kCards[4], "history card (NHISV values)");
  return p;
}

void read_initial_stress_shell(KeywordInput& in) {
  if (in.option() == "SET") {
    in.fail(in.keyword().line, "SID",
            "the _SET form is not supported: give each element its own header card (EID)");
  }
  bool warned_history = false;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues h = in.read(kCards[0], *line);
    model::InitialStressShellDesc d;
    d.element_id = h.integer("EID");
    d.nplane = h.integer("NPLANE");
    d.nthick = h.integer("NTHICK");
    d.nhisv = h.integer("NHISV");
    d.large = h.integer("LARGE") == 1;
    d.where = in.where(line->line);
    for (int k = 0; k < d.nthick * d.nplane; ++k)
      d.points.push_back(read_point(in, line->line, d.large, d.nhisv));
    if (d.nhisv > 0 && !warned_history) {
      warned_history = true;
      in.warn(line->line, "NHISV",
              fmt::format("NHISV = {}: the history values are read over and not applied (plyform "
                          "sets each point's stress and effective plastic strain only)",
                          d.nhisv));
    }
    in.model().initial_shell_stresses.push_back(std::move(d));
  }
}

}  // namespace

KeywordSpec initial_stress_shell_keyword() {
  return {.name = "INITIAL_STRESS_SHELL",
          .options = kOptions,
          .handler = read_initial_stress_shell,
          .cards = kCards,
          .summary =
              "A shell's stress (global axes) and effective plastic strain at t = 0 at "
              "each of its points, as LS-DYNA's dynain writes them. The stresses are "
              "turned into the element's co-rotational frame of t = 0 (plane stress: "
              "the normal component in that frame is dropped) and interpolated linearly "
              "in T to the section's NIP points (held constant beyond the points given); "
              "NPLANE 4 gives ELFORM 16 each Gauss point's value and ELFORM 2 their mean, "
              "NPLANE 1 every in-plane point the same. The thickness comes from "
              "*ELEMENT_SHELL_THICKNESS. History values (NHISV) are read over with a "
              "warning; the _SET form, NTENSR, NTHINT and NTHHSV are refused."};
}

}  // namespace plyform::keyword
