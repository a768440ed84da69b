// *MAT_ELASTIC (*MAT_001) and *MAT_MOONEY-RIVLIN_RUBBER (*MAT_027), both with _TITLE.
#include <array>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr FieldSpec kMid{.name = "MID",
                         .type = FieldType::kInteger,
                         .min_value = 1,
                         .unit = "-",
                         .description = "material id",
                         .required = true};
constexpr FieldSpec kRo{.name = "RO",
                        .type = FieldType::kReal,
                        .min_value = 0.0,
                        .unit = "mass/length^3",
                        .description = "density, > 0",
                        .required = true};
constexpr FieldSpec kPr{.name = "PR",
                        .type = FieldType::kReal,
                        .min_value = -1.0,
                        .max_value = 0.5,
                        .unit = "-",
                        .description = "Poisson's ratio",
                        .max_exclusive = true};

constexpr std::array kElasticFields{
    kMid,
    kRo,
    FieldSpec{.name = "E",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "Young's modulus, > 0",
              .required = true},
    kPr,
    FieldSpec{.name = "DA",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "axial damping factor (beams only); kept as written"},
    FieldSpec{.name = "DB",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "bending damping factor (beams only); kept as written"},
    FieldSpec{.name = "K",
              .type = FieldType::kReal,
              .unit = "stress",
              .description = "bulk modulus (the _FLUID option only): must be 0"},
};
constexpr std::array kElasticCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kElasticFields, .presence = "required"},
};

constexpr std::array kRubberCard1Fields{
    kMid,
    kRo,
    FieldSpec{.name = "PR",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .max_value = 0.5,
              .unit = "-",
              .description = "Poisson's ratio (0.49 or more for rubber)",
              .max_exclusive = true},
    FieldSpec{.name = "A", .type = FieldType::kReal, .unit = "stress", .description = "constant A"},
    FieldSpec{.name = "B", .type = FieldType::kReal, .unit = "stress", .description = "constant B"},
    FieldSpec{.name = "REF",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "reference geometry flag: must be 0 (not supported)"},
};
constexpr std::array kRubberCard2Fields{
    FieldSpec{.name = "SGL",
              .type = FieldType::kReal,
              .unit = "length",
              .description = "specimen gauge length (curve fit only); kept as written"},
    FieldSpec{.name = "SW",
              .type = FieldType::kReal,
              .unit = "length",
              .description = "specimen width (curve fit only); kept as written"},
    FieldSpec{.name = "ST",
              .type = FieldType::kReal,
              .unit = "length",
              .description = "specimen thickness (curve fit only); kept as written"},
    FieldSpec{.name = "LCID1",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "force-deflection curve of a fit: must be 0 (not supported)"},
    FieldSpec{.name = "TBHYS",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "hysteresis table: must be 0 (not supported)"},
};
constexpr std::array kRubberCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kRubberCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kRubberCard2Fields,
             .presence = "optional: a missing card 2 is read as blank"},
};

void read_mat_elastic(KeywordInput& in) {
  model::MatElasticDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kElasticCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO E PR DA DB K)");
  }
  const CardValues v = in.read(kElasticCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.youngs_modulus = v.real("E");
  mat.poisson_ratio = v.real("PR");
  mat.da = v.real("DA");
  mat.db = v.real("DB");
  mat.k = v.real("K");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "E", mat.youngs_modulus);
  require_zero(in, line->line, "K", mat.k, "the bulk modulus of *MAT_ELASTIC_FLUID");
  in.model().elastic_materials.push_back(std::move(mat));
}

void read_mat_mooney_rivlin(KeywordInput& in) {
  model::MatMooneyRivlinDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kRubberCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO PR A B REF)");
  }
  const CardValues v = in.read(kRubberCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.poisson_ratio = v.real("PR");
  mat.a = v.real("A");
  mat.b = v.real("B");
  mat.ref = v.real("REF");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_zero(in, line->line, "REF", mat.ref, "a reference geometry");
  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kRubberCards[2], *line2);
    mat.sgl = c2.real("SGL");
    mat.sw = c2.real("SW");
    mat.st = c2.real("ST");
    mat.lcid1 = c2.integer("LCID1");
    mat.tbhys = c2.real("TBHYS");
    require_zero(in, line2->line, "LCID1", mat.lcid1,
                 "fitting A and B to a force-deflection curve");
    require_zero(in, line2->line, "TBHYS", mat.tbhys, "a hysteresis table");
  }
  if (mat.a == 0.0 && mat.b == 0.0) {
    in.fail(line->line, "A",
            "A = B = 0 asks LS-DYNA to fit them to a test curve, which is not supported; give "
            "A and B");
  }
  in.model().mooney_rivlin_materials.push_back(std::move(mat));
}

}  // namespace

KeywordSpec mat_elastic_keyword() {
  return {.name = "MAT_ELASTIC",
          .options = kNoneOrTitle,
          .handler = read_mat_elastic,
          .cards = kElasticCards,
          .summary =
              "Isotropic linear elasticity (material type 1); also read as *MAT_001. "
              "*MAT_ELASTIC_FLUID is not supported."};
}

KeywordSpec mat_001_keyword() {
  KeywordSpec spec = mat_elastic_keyword();
  spec.name = "MAT_001";
  spec.summary = "The same keyword as *MAT_ELASTIC, by number.";
  return spec;
}

KeywordSpec mat_mooney_rivlin_keyword() {
  return {.name = "MAT_MOONEY-RIVLIN_RUBBER",
          .options = kNoneOrTitle,
          .handler = read_mat_mooney_rivlin,
          .cards = kRubberCards,
          .summary =
              "Mooney-Rivlin rubber (material type 27) with the constants A and B given. "
              "Fitting A and B to a test curve (A = B = 0, LCID1), REF and TBHYS are not "
              "supported and are errors when set. Also read as *MAT_027."};
}

KeywordSpec mat_027_keyword() {
  KeywordSpec spec = mat_mooney_rivlin_keyword();
  spec.name = "MAT_027";
  spec.summary = "The same keyword as *MAT_MOONEY-RIVLIN_RUBBER, by number.";
  return spec;
}

}  // namespace plyform::keyword
