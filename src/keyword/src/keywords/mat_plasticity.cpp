// *MAT_PIECEWISE_LINEAR_PLASTICITY (*MAT_024) and *MAT_POWER_LAW_PLASTICITY (*MAT_018), both
// with _TITLE.
#include <array>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kPwlCard1Fields{
    kMaterialIdField,
    kDensityField,
    kYoungsModulusField,
    kPoissonRatioField,
    FieldSpec{.name = "SIGY",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "yield stress (ignored when LCSS or the EPS/ES table is given)"},
    FieldSpec{.name = "ETAN",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "tangent modulus (ignored when LCSS or the EPS/ES table is given)"},
    FieldSpec{.name = "FAIL",
              .type = FieldType::kReal,
              .default_value = 1.0e21,
              .unit = "-",
              .description = "plastic strain at element deletion (0: none); < 0 (a user "
                             "failure routine) is not supported"},
    FieldSpec{.name = "TDEL",
              .type = FieldType::kReal,
              .unit = "time",
              .description = "minimum time step for element deletion; kept as written"},
};
constexpr std::array kPwlCard2Fields{
    FieldSpec{.name = "C",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "1/time",
              .description = "Cowper-Symonds C: the yield stress scales by 1 + (rate/C)^(1/P) "
                             "(0: no rate effect)"},
    FieldSpec{.name = "P",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "-",
              .description = "Cowper-Symonds P (0: no rate effect)"},
    FieldSpec{.name = "LCSS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "*DEFINE_CURVE of yield stress against effective plastic strain, "
                             "or a *DEFINE_TABLE of such curves by strain rate (values the "
                             "rates, or their natural logarithms when the first is negative; "
                             "then C and P must be 0) (0: none)"},
    FieldSpec{.name = "LCSR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "strain rate scaling curve: must be 0 (not supported yet)"},
    FieldSpec{.name = "VP",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "rate formulation: 0 scales the yield stress by the factor of the "
                             "total strain rate (1 and -1 are errors with rates; without them "
                             "kept as written)"},
    FieldSpec{.name = "LCF",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "failure strain curve or table: must be 0 (not supported yet)"},
};
constexpr FieldSpec point_field(std::string_view name, std::string_view unit,
                                std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kReal, .unit = unit, .description = description};
}
constexpr std::array kPwlStrainFields{
    point_field("EPS1", "-", "effective plastic strain, point 1 (0 for the initial yield)"),
    point_field("EPS2", "-", "effective plastic strain, point 2"),
    point_field("EPS3", "-", "effective plastic strain, point 3"),
    point_field("EPS4", "-", "effective plastic strain, point 4"),
    point_field("EPS5", "-", "effective plastic strain, point 5"),
    point_field("EPS6", "-", "effective plastic strain, point 6"),
    point_field("EPS7", "-", "effective plastic strain, point 7"),
    point_field("EPS8", "-", "effective plastic strain, point 8"),
};
constexpr std::array kPwlStressFields{
    point_field("ES1", "stress", "yield stress at EPS1"),
    point_field("ES2", "stress", "yield stress at EPS2"),
    point_field("ES3", "stress", "yield stress at EPS3"),
    point_field("ES4", "stress", "yield stress at EPS4"),
    point_field("ES5", "stress", "yield stress at EPS5"),
    point_field("ES6", "stress", "yield stress at EPS6"),
    point_field("ES7", "stress", "yield stress at EPS7"),
    point_field("ES8", "stress", "yield stress at EPS8"),
};
constexpr std::array kPwlCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kPwlCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kPwlCard2Fields,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 3",
             .fields = kPwlStrainFields,
             .presence = "optional: the strains of the 8-point table"},
    CardSpec{.title = "Card 4",
             .fields = kPwlStressFields,
             .presence = "optional: the yield stresses of the 8-point table (the table ends "
                         "at the last non-zero ES)"},
};

constexpr std::array kPowerCard1Fields{
    kMaterialIdField,
    kDensityField,
    kYoungsModulusField,
    kPoissonRatioField,
    FieldSpec{.name = "K",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "strength coefficient, > 0",
              .required = true},
    FieldSpec{.name = "N",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "-",
              .description = "hardening exponent"},
    FieldSpec{.name = "SRC",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "1/time",
              .description = "Cowper-Symonds C: the yield stress scales by 1 + (rate/C)^(1/P) "
                             "(0: no rate effect)"},
    FieldSpec{.name = "SRP",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "-",
              .description = "Cowper-Symonds P (0: no rate effect)"},
};
constexpr std::array kPowerCard2Fields{
    FieldSpec{.name = "SIGY",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "-",
              .description = "initial yield: < 0.02 the strain to yield, >= 0.02 a yield stress "
                             "(0: from the elastic limit)"},
    FieldSpec{.name = "VP",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "rate formulation: 0 scales the yield stress by the factor of the "
                             "total strain rate (1 and -1 are errors with rates; without them "
                             "kept as written)"},
    FieldSpec{.name = "EPSF",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "-",
              .description = "plastic failure strain (0: none); kept as written"},
};
constexpr std::array kPowerCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kPowerCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kPowerCard2Fields,
             .presence = "optional: a missing card is read as blank"},
};

void read_mat_piecewise_linear(KeywordInput& in) {
  model::MatPiecewiseLinearPlasticityDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kPwlCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO E PR SIGY ETAN FAIL TDEL)");
  }
  const CardValues v = in.read(kPwlCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.youngs_modulus = v.real("E");
  mat.poisson_ratio = v.real("PR");
  mat.yield_stress = v.real("SIGY");
  mat.tangent_modulus = v.real("ETAN");
  mat.fail = v.real("FAIL");
  mat.tdel = v.real("TDEL");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "E", mat.youngs_modulus);
  if (mat.fail < 0.0) {
    in.fail(line->line, "FAIL",
            fmt::format("FAIL = {} (a user failure routine) is not supported; give the plastic "
                        "strain at failure, or 0 for none",
                        mat.fail));
  }

  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kPwlCards[2], *line2);
    mat.c = c2.real("C");
    mat.p = c2.real("P");
    mat.lcss = c2.integer("LCSS");
    mat.lcsr = c2.integer("LCSR");
    mat.vp = c2.real("VP");
    mat.lcf = c2.integer("LCF");
    require_rate_pair(in, line2->line, "C", mat.c, "P", mat.p);
    if (mat.c > 0.0)
      require_rate_scaling(in, line2->line, mat.vp);
    if (mat.lcss < 0) {
      in.fail(line2->line, "LCSS",
              fmt::format("LCSS = {}: a negative curve or table id is not supported; give the "
                          "id of a *DEFINE_CURVE of yield stress against effective plastic "
                          "strain",
                          mat.lcss));
    }
    require_zero(in, line2->line, "LCSR", mat.lcsr, "a strain rate scaling curve");
    require_zero(in, line2->line, "LCF", mat.lcf, "a failure strain curve");
  }

  std::array<double, 8> eps{};
  std::array<double, 8> es{};
  int eps_line = line->line;
  if (const auto line3 = in.next_line()) {
    const CardValues c3 = in.read(kPwlCards[3], *line3);
    for (std::size_t i = 0; i < eps.size(); ++i) {
      eps[i] = c3.at(i).real;
    }
    eps_line = line3->line;
  }
  if (const auto line4 = in.next_line()) {
    const CardValues c4 = in.read(kPwlCards[4], *line4);
    std::size_t count = 0;
    for (std::size_t i = 0; i < es.size(); ++i) {
      es[i] = c4.at(i).real;
      if (es[i] != 0.0) {
        count = i + 1;
      }
    }
    mat.eps.assign(eps.begin(), eps.begin() + static_cast<std::ptrdiff_t>(count));
    mat.es.assign(es.begin(), es.begin() + static_cast<std::ptrdiff_t>(count));
    if (mat.lcss == 0 && count > 0) {
      if (count < 2) {
        in.fail(line4->line, "ES2", "the EPS/ES table needs at least 2 points (ES1 and ES2 given)");
      }
      for (std::size_t i = 0; i < count; ++i) {
        if (!(es[i] > 0.0)) {
          in.fail(line4->line, fmt::format("ES{}", i + 1),
                  fmt::format("ES{} must be > 0, got {}", i + 1, es[i]));
        }
        if (eps[i] < 0.0 || (i > 0 && !(eps[i] > eps[i - 1]))) {
          in.fail(eps_line, fmt::format("EPS{}", i + 1),
                  fmt::format("the plastic strains EPS1..EPS{} must be >= 0 and increase; "
                              "EPS{} = {}",
                              count, i + 1, eps[i]));
        }
      }
    }
  }
  if (mat.lcss == 0 && mat.es.empty() && !(mat.yield_stress > 0.0)) {
    in.fail(line->line, "SIGY",
            "SIGY must be > 0 when neither LCSS nor the EPS/ES table gives the yield stress");
  }
  in.model().piecewise_linear_materials.push_back(std::move(mat));
}

void read_mat_power_law(KeywordInput& in) {
  model::MatPowerLawPlasticityDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kPowerCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO E PR K N SRC SRP)");
  }
  const CardValues v = in.read(kPowerCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.youngs_modulus = v.real("E");
  mat.poisson_ratio = v.real("PR");
  mat.k = v.real("K");
  mat.n = v.real("N");
  mat.src = v.real("SRC");
  mat.srp = v.real("SRP");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "E", mat.youngs_modulus);
  require_positive(in, line->line, "K", mat.k);
  require_rate_pair(in, line->line, "SRC", mat.src, "SRP", mat.srp);
  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kPowerCards[2], *line2);
    mat.sigy = c2.real("SIGY");
    mat.vp = c2.real("VP");
    mat.epsf = c2.real("EPSF");
    if (mat.src > 0.0)
      require_rate_scaling(in, line2->line, mat.vp);
  }
  in.model().power_law_materials.push_back(std::move(mat));
}

}  // namespace

KeywordSpec mat_piecewise_linear_plasticity_keyword() {
  return {.name = "MAT_PIECEWISE_LINEAR_PLASTICITY",
          .options = kNoneOrTitle,
          .handler = read_mat_piecewise_linear,
          .cards = kPwlCards,
          .summary =
              "Isotropic elasto-plasticity with isotropic hardening (material type 24): the "
              "yield stress against effective plastic strain from the curve LCSS, else from "
              "the 8-point EPS/ES table, else bilinear from SIGY and ETAN; with C and P the yield "
              "stress scaled by the Cowper-Symonds factor 1 + (rate/C)^(1/P) (VP 0), or with LCSS "
              "naming a table the yield curve read between the curves around the point's rate "
              "(docs/materials.md: the rate measure). The rate curve LCSR, failure curves "
              "(LCF), tables of curves (negative LCSS) and user failure (FAIL < 0) are "
              "errors. Also read as *MAT_024."};
}

KeywordSpec mat_024_keyword() {
  KeywordSpec spec = mat_piecewise_linear_plasticity_keyword();
  spec.name = "MAT_024";
  spec.summary = "The same keyword as *MAT_PIECEWISE_LINEAR_PLASTICITY, by number.";
  return spec;
}

KeywordSpec mat_power_law_plasticity_keyword() {
  return {.name = "MAT_POWER_LAW_PLASTICITY",
          .options = kNoneOrTitle,
          .handler = read_mat_power_law,
          .cards = kPowerCards,
          .summary =
              "Isotropic plasticity with power-law hardening sigma_y = K (eps_yp + eps_p)^N "
              "(material type 18), with SRC and SRP the yield stress scaled by the Cowper-Symonds "
              "factor 1 + (rate/SRC)^(1/SRP) (VP 0). Also read as "
              "*MAT_018."};
}

KeywordSpec mat_018_keyword() {
  KeywordSpec spec = mat_power_law_plasticity_keyword();
  spec.name = "MAT_018";
  spec.summary = "The same keyword as *MAT_POWER_LAW_PLASTICITY, by number.";
  return spec;
}

}  // namespace plyform::keyword
