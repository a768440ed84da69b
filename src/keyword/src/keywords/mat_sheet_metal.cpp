// The metal plasticity keywords of real decks: *MAT_PLASTIC_KINEMATIC (*MAT_003) and
// *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (*MAT_037), both with _TITLE. Every field is
// read with LS-DYNA's meaning; what plyform does not implement (element erosion, the
// viscoplastic rate formulation, E from curves, strain averaging) is an error naming the
// field. Curves named are resolved when the model is built.
#include <array>
#include <cmath>
#include <string>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

// --- *MAT_PLASTIC_KINEMATIC

/// LS-DYNA's default failure strain: no erosion.
constexpr double kNoFailure = 1.0e20;

constexpr std::array kPkCard1Fields{
    kMaterialIdField,
    kDensityField,
    kYoungsModulusField,
    kPoissonRatioField,
    FieldSpec{.name = "SIGY",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "yield stress, > 0",
              .required = true},
    FieldSpec{.name = "ETAN",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "tangent modulus of the bilinear curve, 0 <= ETAN < E"},
    FieldSpec{.name = "BETA",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .max_value = 1.0,
              .unit = "-",
              .description = "hardening: 0 kinematic, 1 isotropic, between: mixed"},
};
constexpr std::array kPkCard2Fields{
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
    FieldSpec{.name = "FS",
              .type = FieldType::kReal,
              .default_value = kNoFailure,
              .min_value = 0.0,
              .unit = "-",
              .description = "plastic strain at element erosion: blank, 0 or >= 1e20 (none) "
                             "only, plyform deletes no elements"},
    FieldSpec{.name = "VP",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "rate formulation: 0 scales the yield stress by the factor of the "
                             "total strain rate (1, viscoplastic, and -1, deviatoric rate, are "
                             "not supported)"},
};
constexpr std::array kPkCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kPkCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kPkCard2Fields,
             .presence = "optional: a missing card is read as blank"},
};

void read_mat_plastic_kinematic(KeywordInput& in) {
  model::MatPlasticKinematicDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kPkCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO E PR SIGY ETAN BETA)");
  }
  const CardValues v = in.read(kPkCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.young = v.real("E");
  mat.poisson = v.real("PR");
  mat.sigy = v.real("SIGY");
  mat.etan = v.real("ETAN");
  mat.beta = v.real("BETA");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "E", mat.young);
  require_positive(in, line->line, "SIGY", mat.sigy);
  if (!(mat.etan < mat.young)) {
    in.fail(line->line, "ETAN",
            fmt::format("ETAN = {} must be below E = {} (the plastic modulus E ETAN / (E - ETAN) "
                        "must be finite)",
                        mat.etan, mat.young));
  }
  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kPkCards[2], *line2);
    mat.src = c2.real("SRC");
    mat.srp = c2.real("SRP");
    mat.fs = c2.real("FS");
    mat.vp = c2.real("VP");
    require_rate_pair(in, line2->line, "SRC", mat.src, "SRP", mat.srp);
    if (mat.fs == 0.0) {
      mat.fs = kNoFailure;  // LS-DYNA reads a 0 as its default
    }
    if (mat.fs < kNoFailure) {
      in.fail(line2->line, "FS",
              fmt::format("FS = {} (element erosion at that effective plastic strain) is not "
                          "supported: plyform deletes no elements; leave FS blank or 0",
                          mat.fs));
    }
    require_rate_scaling(in, line2->line, mat.vp);
  }
  in.model().plastic_kinematic_materials.push_back(std::move(mat));
}

// --- *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC

constexpr std::array kTaCard1Fields{
    kMaterialIdField,
    kDensityField,
    kYoungsModulusField,
    kPoissonRatioField,
    FieldSpec{.name = "SIGY",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "yield stress, > 0 (ignored when HLCID is given)"},
    FieldSpec{.name = "ETAN",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "plastic hardening modulus (this law's ETAN is the slope of the "
                             "yield stress against plastic strain, not a tangent modulus), >= 0 "
                             "(ignored when HLCID is given; < 0, LS-DYNA's normal-stress option, "
                             "is not supported)"},
    FieldSpec{.name = "R",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "normal anisotropy: the width-to-thickness plastic strain ratio "
                             "in uniaxial tension; < 0: the ratio |R| with LS-DYNA's stabilised "
                             "return (plyform's return is exact for either sign)",
              .required = true},
    FieldSpec{.name = "HLCID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "*DEFINE_CURVE of yield stress against effective plastic strain "
                             "(0: SIGY and ETAN)"},
};
constexpr std::array kTaCard2Fields{
    FieldSpec{.name = "IDSCALE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve scaling E against effective strain: must be 0 (not "
                             "supported yet)"},
    FieldSpec{.name = "EA",
              .type = FieldType::kReal,
              .unit = "stress",
              .description = "E against effective strain (with COE): must be 0 (not supported "
                             "yet)"},
    FieldSpec{.name = "COE",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "E against effective strain (with EA): must be 0 (not supported "
                             "yet)"},
    FieldSpec{.name = "ICFLD",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "forming limit curve for the formability output: read, not "
                             "written (a warning)"},
    FieldSpec{.name = "UNUSED",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "not used by LS-DYNA: blank or 0"},
    FieldSpec{.name = "STRAINLT",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "strain at which strain averaging starts: must be 0 (not "
                             "supported yet)"},
};
constexpr std::array kTaCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kTaCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kTaCard2Fields,
             .presence = "optional: a missing card is read as blank"},
};

void read_mat_transversely_anisotropic(KeywordInput& in) {
  model::MatTransverselyAnisotropicDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kTaCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO E PR SIGY ETAN R HLCID)");
  }
  const CardValues v = in.read(kTaCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.young = v.real("E");
  mat.poisson = v.real("PR");
  mat.sigy = v.real("SIGY");
  mat.etan = v.real("ETAN");
  mat.r = v.real("R");
  mat.hlcid = v.integer("HLCID");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "E", mat.young);
  // LS-DYNA: R < 0 selects its stabilised return with the ratio |R|; plyform's return is the
  // exact one for either sign, so it reads the ratio |R|.
  if (mat.r == 0.0) {
    in.fail(line->line, "R", "R = 0: give the Lankford ratio (R < 0 is read as |R|)");
  }
  if (mat.hlcid == 0) {
    if (!(mat.sigy > 0.0)) {
      in.fail(line->line, "SIGY",
              fmt::format("SIGY must be > 0 when HLCID does not give the yield stress, got {}",
                          mat.sigy));
    }
  }
  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kTaCards[2], *line2);
    mat.idscale = c2.integer("IDSCALE");
    mat.ea = c2.real("EA");
    mat.coe = c2.real("COE");
    mat.icfld = c2.integer("ICFLD");
    mat.strainlt = c2.real("STRAINLT");
    if (c2.real("UNUSED") != 0.0) {
      in.fail(line2->line, "UNUSED",
              fmt::format("field 5 holds {}, but LS-DYNA does not use it: leave it blank (are "
                          "the card's fields shifted?)",
                          c2.real("UNUSED")));
    }
    const std::string_view young_note = "Young's modulus against effective strain";
    require_zero(in, line2->line, "IDSCALE", mat.idscale, young_note);
    require_zero(in, line2->line, "EA", mat.ea, young_note);
    require_zero(in, line2->line, "COE", mat.coe, young_note);
    require_zero(in, line2->line, "STRAINLT", mat.strainlt, "strain averaging");
    if (mat.icfld != 0) {
      in.warn(line2->line, "ICFLD",
              fmt::format("ICFLD = {}: the formability index against the forming limit curve "
                          "is not written (the material behaves the same)",
                          mat.icfld));
    }
  }
  in.model().transversely_anisotropic_materials.push_back(std::move(mat));
}

}  // namespace

KeywordSpec mat_plastic_kinematic_keyword() {
  return {.name = "MAT_PLASTIC_KINEMATIC",
          .options = kNoneOrTitle,
          .handler = read_mat_plastic_kinematic,
          .cards = kPkCards,
          .summary =
              "J2 plasticity with bilinear hardening (material type 3): the plastic "
              "modulus E ETAN / (E - ETAN) split by BETA between the back stress "
              "(kinematic, BETA 0) and the yield stress (isotropic, BETA 1); the yield "
              "stress scaled by the Cowper-Symonds factor 1 + (rate/SRC)^(1/SRP) "
              "(docs/materials.md: the rate measure). Element erosion (FS) and the "
              "viscoplastic formulation (VP 1) are errors. Also read as *MAT_003."};
}

KeywordSpec mat_003_keyword() {
  KeywordSpec spec = mat_plastic_kinematic_keyword();
  spec.name = "MAT_003";
  spec.summary = "The same keyword as *MAT_PLASTIC_KINEMATIC, by number.";
  return spec;
}

KeywordSpec mat_transversely_anisotropic_keyword() {
  return {.name = "MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC",
          .options = kNoneOrTitle,
          .handler = read_mat_transversely_anisotropic,
          .cards = kTaCards,
          .summary =
              "Shells: Hill's 1948 yield function with normal anisotropy R (material "
              "type 37), isotropic hardening from the curve HLCID or bilinear from SIGY "
              "and the plastic modulus ETAN; R < 0 is read as |R| (LS-DYNA's "
              "stabilised return of the same law). E against strain (IDSCALE, EA, COE) "
              "and strain averaging (STRAINLT) are errors; ICFLD is read with a warning "
              "(its output is not written). Also read as *MAT_037."};
}

KeywordSpec mat_037_keyword() {
  KeywordSpec spec = mat_transversely_anisotropic_keyword();
  spec.name = "MAT_037";
  spec.summary = "The same keyword as *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC, by number.";
  return spec;
}

}  // namespace plyform::keyword
