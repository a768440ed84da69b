// The orthotropic sheet-metal keywords: *MAT_3-PARAMETER_BARLAT (*MAT_036) and *MAT_HILL_3R
// (*MAT_122), both with _TITLE, shells. Every field is read with LS-DYNA's meaning; what
// plyform does not implement (the hardening rules 5 to 9, kinematic hardening, heat treatment,
// volume correction, user failure, AOPT 1 and 4 and coordinate systems) is an error naming the
// field. Curves named are resolved when the model is built.
#include <array>
#include <cmath>
#include <string>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 4> kBarlatRules{1, 2, 3, 4};
constexpr std::array<int, 3> kHillRules{1, 2, 3};
constexpr std::array<int, 3> kAopts{0, 2, 3};
constexpr std::array<int, 2> kIters{0, 1};

constexpr FieldSpec real_field(std::string_view name, std::string_view unit,
                               std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kReal, .unit = unit, .description = description};
}
constexpr FieldSpec int_field(std::string_view name, std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kInteger, .unit = "-", .description = description};
}

constexpr FieldSpec hr_field(std::span<const int> rules, std::string_view note) {
  return FieldSpec{.name = "HR",
                   .type = FieldType::kReal,
                   .default_value = 1.0,
                   .unit = "-",
                   .description =
                       "hardening rule: 1 linear (P1 ETAN, P2 SIGY), 2 Swift k (e0 + "
                       "eps_p)^n (P1 k, P2 n), 3 the curve LCID, 4 Voce a - b "
                       "exp(-c eps_p) (P1 a, P2 b, P3 c; *MAT_036 only)",
                   .allowed = rules,
                   .allowed_note = note};
}
constexpr FieldSpec kAoptField{.name = "AOPT",
                               .type = FieldType::kReal,
                               .unit = "-",
                               .description =
                                   "material axes: 0 the element's edge N1->N2 turned "
                                   "by BETA, 2 the global vector a, 3 v x the normal "
                                   "turned by BETA (all projected on the shell)",
                               .allowed = kAopts,
                               .allowed_note =
                                   "AOPT 1, 4 and coordinate systems (< 0) are not "
                                   "supported for shells yet"};

// --- *MAT_3-PARAMETER_BARLAT

constexpr std::array kBarlatCard1{
    kMaterialIdField,
    kDensityField,
    kYoungsModulusField,
    kPoissonRatioField,
    hr_field(kBarlatRules,
             "HR 5 (Gosh), 6 (Hocket-Sherby), 7 (curves in three directions), 8 "
             "and 9 (tables over temperature and rate) are not supported yet"),
    real_field("P1", "-", "HR 1: tangent modulus ETAN (stress); HR 2: k (stress); HR 4: a"),
    real_field("P2", "-", "HR 1: yield stress (stress); HR 2: n; HR 4: b (stress)"),
    FieldSpec{.name = "ITER",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "0 full iterations, 1 three (LS-DYNA's speed option); plyform "
                             "always iterates the return to round-off",
              .allowed = kIters},
};
constexpr std::array kBarlatCard2{
    FieldSpec{.name = "M",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "exponent of the yield function, >= 2 (6 for BCC, 8 for FCC "
                             "metals; M < 0, kinematic hardening, is not supported)",
              .required = true},
    real_field("R00", "-", "Lankford ratio at 0 degrees to the rolling direction (AB with PB > 0)"),
    real_field("R45", "-", "Lankford ratio at 45 degrees (CB with PB > 0)"),
    real_field("R90", "-", "Lankford ratio at 90 degrees (HB with PB > 0)"),
    int_field("LCID", "HR 3: curve of yield stress against effective plastic strain"),
    real_field("E0", "-", "HR 2: plastic strain at yield (0: from SPI)"),
    real_field("SPI", "-",
               "HR 2 with E0 = 0: 0 the intersection (E/k)^(1/(n - 1)), <= 0.02 the strain "
               "itself, > 0.02 the initial yield stress: (SPI/k)^(1/n)"),
    real_field("P3", "-", "HR 4: c"),
};
constexpr std::array kBarlatCard3{
    kAoptField,
    real_field("C", "1/time", "Cowper-Symonds C (0: no rate effect)"),
    real_field("P", "-", "Cowper-Symonds P (0: no rate effect)"),
    int_field("VLCID", "volume correction curve: must be 0 (not supported)"),
    real_field("UNUSED", "-", "not used: blank"),
    real_field("PB", "-", "Barlat's p given directly (> 0): then R00, R45, R90 hold a, c, h"),
    int_field("HTA", "heat treatment: must be 0 (not supported)"),
    real_field("HTB", "-", "heat treatment: must be 0 (not supported)"),
};
constexpr std::array kBarlatCard4{
    real_field("XP", "length", "point P (AOPT 1 and 4); kept as written"),
    real_field("YP", "length", "point P; kept as written"),
    real_field("ZP", "length", "point P; kept as written"),
    real_field("A1", "-", "vector a (AOPT 2)"),
    real_field("A2", "-", "vector a (AOPT 2)"),
    real_field("A3", "-", "vector a (AOPT 2)"),
    int_field("HTC", "heat treatment: must be 0 (not supported)"),
    int_field("HTD", "heat treatment: must be 0 (not supported)"),
};
constexpr std::array kBarlatCard5{
    real_field("V1", "-", "vector v (AOPT 3)"),
    real_field("V2", "-", "vector v (AOPT 3)"),
    real_field("V3", "-", "vector v (AOPT 3)"),
    real_field("D1", "-", "vector d (AOPT 2 solids); kept as written"),
    real_field("D2", "-", "vector d; kept as written"),
    real_field("D3", "-", "vector d; kept as written"),
    real_field("BETA", "degree",
               "material angle about the normal (AOPT 0 and 3), unless the element's BETA is set"),
    real_field("HTFLAG", "-", "heat treatment stage: must be 0 (not supported)"),
};
constexpr std::array kBarlatCard6{
    real_field("USRFAIL", "-", "user failure routine: must be 0 (not supported)"),
    real_field("LCBI", "-", "HR 7 only: ignored"),
    real_field("LCSH", "-", "HR 7 only: ignored"),
};
constexpr std::array kBarlatCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kBarlatCard1, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kBarlatCard2, .presence = "required"},
    CardSpec{.title = "Card 3",
             .fields = kBarlatCard3,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 4",
             .fields = kBarlatCard4,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 5",
             .fields = kBarlatCard5,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 6",
             .fields = kBarlatCard6,
             .presence = "optional: a missing card is read as blank"},
};

// --- *MAT_HILL_3R

constexpr std::array kHillCard1{
    kMaterialIdField,
    kDensityField,
    kYoungsModulusField,
    kPoissonRatioField,
    hr_field(kHillRules, "HR 4 is *MAT_036's, not *MAT_122's"),
    real_field("P1", "-", "HR 1: tangent modulus ETAN (stress); HR 2: k (stress)"),
    real_field("P2", "-", "HR 1: yield stress (stress); HR 2: n"),
};
constexpr std::array kHillCard2{
    real_field("R00", "-", "Lankford ratio at 0 degrees to the rolling direction, > 0"),
    real_field("R45", "-", "Lankford ratio at 45 degrees, > 0"),
    real_field("R90", "-", "Lankford ratio at 90 degrees, > 0"),
    int_field("LCID", "HR 3: curve of yield stress against effective plastic strain"),
    real_field("E0", "-", "HR 2: plastic strain at yield (0: (E/k)^(1/(n - 1)))"),
};
constexpr std::array kHillCard3{kAoptField};
constexpr std::array kHillCard4{
    real_field("UNUSED1", "-", "not used"),     real_field("UNUSED2", "-", "not used"),
    real_field("UNUSED3", "-", "not used"),     real_field("A1", "-", "vector a (AOPT 2)"),
    real_field("A2", "-", "vector a (AOPT 2)"), real_field("A3", "-", "vector a (AOPT 2)"),
};
constexpr std::array kHillCard5{
    real_field("V1", "-", "vector v (AOPT 3)"),
    real_field("V2", "-", "vector v (AOPT 3)"),
    real_field("V3", "-", "vector v (AOPT 3)"),
    real_field("D1", "-", "vector d; kept as written"),
    real_field("D2", "-", "vector d; kept as written"),
    real_field("D3", "-", "vector d; kept as written"),
    real_field("BETA", "degree",
               "material angle about the normal (AOPT 0 and 3), unless the element's BETA is set"),
};
constexpr std::array kHillCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kHillCard1, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kHillCard2, .presence = "required"},
    CardSpec{.title = "Card 3",
             .fields = kHillCard3,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 4",
             .fields = kHillCard4,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 5",
             .fields = kHillCard5,
             .presence = "optional: a missing card is read as blank"},
};

// The hardening fields: each rule's constants in range.
void check_hardening(KeywordInput& in, int line1, int line2, double young,
                     const model::SheetHardeningDesc& h) {
  switch (h.hr) {
    case 1:
      if (!(h.p2 > 0.0))
        in.fail(line1, "P2", fmt::format("HR 1: P2 is the yield stress, > 0; got {}", h.p2));
      if (!(h.p1 >= 0.0 && h.p1 < young))
        in.fail(
            line1, "P1",
            fmt::format("HR 1: P1 is the tangent modulus, 0 <= P1 < E = {}; got {}", young, h.p1));
      break;
    case 2:
      if (!(h.p1 > 0.0))
        in.fail(line1, "P1",
                fmt::format("HR 2: P1 is the strength coefficient k, > 0; got {}", h.p1));
      if (!(h.p2 > 0.0 && h.p2 < 1.0))
        in.fail(line1, "P2",
                fmt::format("HR 2: P2 is the hardening exponent n, 0 < n < 1; got {}", h.p2));
      if (h.e0 < 0.0)
        in.fail(line2, "E0", fmt::format("E0 must be >= 0, got {}", h.e0));
      if (h.spi < 0.0)
        in.fail(line2, "SPI", fmt::format("SPI must be >= 0, got {}", h.spi));
      break;
    case 3:
      if (h.lcid <= 0)
        in.fail(line2, "LCID", "HR 3 needs the hardening curve LCID (> 0)");
      break;
    case 4:
      if (!(h.p1 > 0.0 && h.p2 >= 0.0 && h.p2 < h.p1))
        in.fail(line1, "P2",
                fmt::format("HR 4: the initial yield stress a - b = P1 - P2 must be > 0 with "
                            "b >= 0; got P1 = {}, P2 = {}",
                            h.p1, h.p2));
      if (!(h.p3 >= 0.0))
        in.fail(line2, "P3", fmt::format("HR 4: P3 is the rate c, >= 0; got {}", h.p3));
      break;
    default:
      break;
  }
  if (h.hr != 3 && h.lcid != 0) {
    in.warn(
        line2, "LCID",
        fmt::format("LCID = {} is read with HR 3 only; HR = {} gives the hardening", h.lcid, h.hr));
  }
}

// The axes' vectors for AOPT 2 and 3.
void check_axes(KeywordInput& in, int line_a, int line_v, const model::ShellAxesDesc& a) {
  const auto norm = [](const double* v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  };
  if (a.aopt == 2 && !(norm(a.a) > 0.0))
    in.fail(line_a, "A1", "AOPT = 2 needs a non-zero vector a (A1 A2 A3)");
  if (a.aopt == 3 && !(norm(a.v) > 0.0))
    in.fail(line_v, "V1", "AOPT = 3 needs a non-zero vector v (V1 V2 V3)");
}

void read_mat_3_parameter_barlat(KeywordInput& in) {
  model::MatBarlat89Desc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kBarlatCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO E PR HR P1 P2 ITER)");
  }
  const CardValues v = in.read(kBarlatCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.young = v.real("E");
  mat.poisson = v.real("PR");
  mat.hardening.hr = static_cast<int>(v.real("HR"));
  mat.hardening.p1 = v.real("P1");
  mat.hardening.p2 = v.real("P2");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "E", mat.young);

  const auto line2 = in.next_line();
  if (!line2) {
    in.fail(line->line, "", "missing card 2 (M R00 R45 R90 LCID E0 SPI P3)");
  }
  const CardValues c2 = in.read(kBarlatCards[2], *line2);
  mat.m = c2.real("M");
  mat.r00 = c2.real("R00");
  mat.r45 = c2.real("R45");
  mat.r90 = c2.real("R90");
  mat.hardening.lcid = c2.integer("LCID");
  mat.hardening.e0 = c2.real("E0");
  mat.hardening.spi = c2.real("SPI");
  mat.hardening.p3 = c2.real("P3");
  if (mat.m < 0.0) {
    in.fail(line2->line, "M",
            fmt::format("M = {}: a negative M adds Chaboche-Rousselier kinematic hardening "
                        "(card 3), which plyform does not implement; give M >= 2",
                        mat.m));
  }
  if (!(mat.m >= 2.0)) {
    in.fail(line2->line, "M",
            fmt::format("M = {}: the exponent must be >= 2 (6 for BCC, 8 for FCC metals; 2 is "
                        "Hill 1948)",
                        mat.m));
  }
  check_hardening(in, line->line, line2->line, mat.young, mat.hardening);

  int line_a = line2->line, line_v = line2->line;
  if (const auto line3 = in.next_line()) {
    const CardValues c3 = in.read(kBarlatCards[3], *line3);
    mat.axes.aopt = static_cast<int>(c3.real("AOPT"));
    mat.c = c3.real("C");
    mat.p = c3.real("P");
    mat.pb = c3.real("PB");
    require_rate_pair(in, line3->line, "C", mat.c, "P", mat.p);
    require_zero(in, line3->line, "VLCID", c3.integer("VLCID"), "volume correction curve");
    require_zero(in, line3->line, "HTA", c3.integer("HTA"), "heat treatment");
    require_zero(in, line3->line, "HTB", c3.real("HTB"), "heat treatment");
    if (mat.pb < 0.0)
      in.fail(line3->line, "PB", fmt::format("PB must be >= 0, got {}", mat.pb));
    line_a = line_v = line3->line;
  }
  if (const auto line4 = in.next_line()) {
    const CardValues c4 = in.read(kBarlatCards[4], *line4);
    mat.axes.a[0] = c4.real("A1"), mat.axes.a[1] = c4.real("A2"), mat.axes.a[2] = c4.real("A3");
    require_zero(in, line4->line, "HTC", c4.integer("HTC"), "heat treatment");
    require_zero(in, line4->line, "HTD", c4.integer("HTD"), "heat treatment");
    line_a = line_v = line4->line;
  }
  if (const auto line5 = in.next_line()) {
    const CardValues c5 = in.read(kBarlatCards[5], *line5);
    mat.axes.v[0] = c5.real("V1"), mat.axes.v[1] = c5.real("V2"), mat.axes.v[2] = c5.real("V3");
    mat.axes.d[0] = c5.real("D1"), mat.axes.d[1] = c5.real("D2"), mat.axes.d[2] = c5.real("D3");
    mat.axes.beta = c5.real("BETA");
    require_zero(in, line5->line, "HTFLAG", c5.real("HTFLAG"), "heat treatment");
    line_v = line5->line;
  }
  if (const auto line6 = in.next_line()) {
    const CardValues c6 = in.read(kBarlatCards[6], *line6);
    require_zero(in, line6->line, "USRFAIL", c6.real("USRFAIL"), "user failure routine");
  }
  check_axes(in, line_a, line_v, mat.axes);
  // The Lankford ratios (or with PB the coefficients a, c, h themselves) must be positive.
  const bool direct = mat.pb > 0.0;
  const std::array<std::pair<const char*, double>, 3> ratios{
      {{"R00", mat.r00}, {"R45", mat.r45}, {"R90", mat.r90}}};
  for (const auto& [name, value] : ratios) {
    if (!(value > 0.0)) {
      in.fail(line2->line, name,
              fmt::format("{} = {}: {} must be > 0", name, value,
                          direct ? "with PB > 0 this field holds Barlat's a, c or h, which"
                                 : "a Lankford ratio"));
    }
  }
  in.model().barlat89_materials.push_back(std::move(mat));
}

void read_mat_hill_3r(KeywordInput& in) {
  model::MatHill3RDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kHillCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO E PR HR P1 P2)");
  }
  const CardValues v = in.read(kHillCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.young = v.real("E");
  mat.poisson = v.real("PR");
  mat.hardening.hr = static_cast<int>(v.real("HR"));
  mat.hardening.p1 = v.real("P1");
  mat.hardening.p2 = v.real("P2");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "E", mat.young);

  const auto line2 = in.next_line();
  if (!line2) {
    in.fail(line->line, "", "missing card 2 (R00 R45 R90 LCID E0)");
  }
  const CardValues c2 = in.read(kHillCards[2], *line2);
  mat.r00 = c2.real("R00");
  mat.r45 = c2.real("R45");
  mat.r90 = c2.real("R90");
  mat.hardening.lcid = c2.integer("LCID");
  mat.hardening.e0 = c2.real("E0");
  require_positive(in, line2->line, "R00", mat.r00);
  require_positive(in, line2->line, "R45", mat.r45);
  require_positive(in, line2->line, "R90", mat.r90);
  check_hardening(in, line->line, line2->line, mat.young, mat.hardening);

  int line_a = line2->line, line_v = line2->line;
  if (const auto line3 = in.next_line()) {
    const CardValues c3 = in.read(kHillCards[3], *line3);
    mat.axes.aopt = static_cast<int>(c3.real("AOPT"));
    line_a = line_v = line3->line;
  }
  if (const auto line4 = in.next_line()) {
    const CardValues c4 = in.read(kHillCards[4], *line4);
    mat.axes.a[0] = c4.real("A1"), mat.axes.a[1] = c4.real("A2"), mat.axes.a[2] = c4.real("A3");
    line_a = line_v = line4->line;
  }
  if (const auto line5 = in.next_line()) {
    const CardValues c5 = in.read(kHillCards[5], *line5);
    mat.axes.v[0] = c5.real("V1"), mat.axes.v[1] = c5.real("V2"), mat.axes.v[2] = c5.real("V3");
    mat.axes.d[0] = c5.real("D1"), mat.axes.d[1] = c5.real("D2"), mat.axes.d[2] = c5.real("D3");
    mat.axes.beta = c5.real("BETA");
    line_v = line5->line;
  }
  check_axes(in, line_a, line_v, mat.axes);
  in.model().hill_3r_materials.push_back(std::move(mat));
}

}  // namespace

KeywordSpec mat_3_parameter_barlat_keyword() {
  return {.name = "MAT_3-PARAMETER_BARLAT",
          .options = kNoneOrTitle,
          .handler = read_mat_3_parameter_barlat,
          .cards = kBarlatCards,
          .summary =
              "Shells: the Barlat-Lian 1989 yield function with exponent M (material type "
              "36) in the material axes AOPT 0, 2 or 3, its coefficients a, c, h, p from "
              "R00, R45, R90 (or given with PB), isotropic hardening HR 1 to 4, "
              "Cowper-Symonds C and P (docs/materials.md). Also read as *MAT_036."};
}

KeywordSpec mat_036_keyword() {
  KeywordSpec spec = mat_3_parameter_barlat_keyword();
  spec.name = "MAT_036";
  spec.summary = "The same keyword as *MAT_3-PARAMETER_BARLAT, by number.";
  return spec;
}

KeywordSpec mat_hill_3r_keyword() {
  return {.name = "MAT_HILL_3R",
          .options = kNoneOrTitle,
          .handler = read_mat_hill_3r,
          .cards = kHillCards,
          .summary =
              "Shells: Hill's 1948 yield function from the Lankford ratios R00, R45, R90 "
              "(material type 122) in the material axes AOPT 0, 2 or 3, isotropic hardening "
              "HR 1 to 3 (docs/materials.md). Also read as *MAT_122."};
}

KeywordSpec mat_122_keyword() {
  KeywordSpec spec = mat_hill_3r_keyword();
  spec.name = "MAT_122";
  spec.summary = "The same keyword as *MAT_HILL_3R, by number.";
  return spec;
}

}  // namespace plyform::keyword
