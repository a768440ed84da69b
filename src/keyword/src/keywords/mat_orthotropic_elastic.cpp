// *MAT_ORTHOTROPIC_ELASTIC (*MAT_002), with _TITLE.
#include <array>
#include <cmath>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 2> kAopts{0, 2};
constexpr std::array<int, 2> kMacfs{0, 1};

constexpr FieldSpec modulus_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kReal,
                   .min_value = 0.0,
                   .unit = "stress",
                   .description = description,
                   .required = true};
}
constexpr FieldSpec ratio_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name, .type = FieldType::kReal, .unit = "-", .description = description};
}
constexpr FieldSpec real_field(std::string_view name, std::string_view unit,
                               std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kReal, .unit = unit, .description = description};
}

constexpr std::array kCard1Fields{
    kMaterialIdField,
    kDensityField,
    modulus_field("EA", "Young's modulus along a, > 0"),
    modulus_field("EB", "Young's modulus along b, > 0"),
    modulus_field("EC", "Young's modulus along c, > 0"),
    ratio_field("PRBA", "Poisson's ratio nu_ba"),
    ratio_field("PRCA", "Poisson's ratio nu_ca"),
    ratio_field("PRCB", "Poisson's ratio nu_cb"),
};
constexpr std::array kCard2Fields{
    modulus_field("GAB", "shear modulus ab, > 0"),
    modulus_field("GBC", "shear modulus bc, > 0"),
    modulus_field("GCA", "shear modulus ca, > 0"),
    FieldSpec{.name = "AOPT",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "material axes: 0 from the element's nodes (N1->N2 is a; shells: "
                             "rotated by BETA), 2 global from vectors a and d",
              .allowed = kAopts,
              .allowed_note = "AOPT 1, 3, 4 and coordinate systems (< 0) are not supported "
                              "yet"},
    real_field("G", "stress", "frequency-independent damping modulus: must be 0 (not supported)"),
    real_field("SIGF", "stress", "limit stress of that damping: must be 0 (not supported)"),
};
constexpr std::array kCard3Fields{
    real_field("XP", "length", "point P (AOPT 1 and 4); kept as written"),
    real_field("YP", "length", "point P; kept as written"),
    real_field("ZP", "length", "point P; kept as written"),
    real_field("A1", "-", "vector a (AOPT 2)"),
    real_field("A2", "-", "vector a (AOPT 2)"),
    real_field("A3", "-", "vector a (AOPT 2)"),
    FieldSpec{.name = "MACF",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "axes change of bricks: 1 (or 0) no change",
              .allowed = kMacfs,
              .allowed_note = "switching material axes is not supported yet"},
    FieldSpec{.name = "IHIS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "stiffness initialisation from history data: must be 0"},
};
constexpr std::array kCard4Fields{
    real_field("V1", "-", "vector v (AOPT 3 and 4); kept as written"),
    real_field("V2", "-", "vector v; kept as written"),
    real_field("V3", "-", "vector v; kept as written"),
    real_field("D1", "-", "vector d (AOPT 2)"),
    real_field("D2", "-", "vector d (AOPT 2)"),
    real_field("D3", "-", "vector d (AOPT 2)"),
    real_field("BETA", "degree", "material angle (AOPT 0 shells); kept as written"),
    real_field("REF", "-", "reference geometry flag: must be 0 (not supported)"),
};
constexpr std::array kCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kCard2Fields, .presence = "required"},
    CardSpec{.title = "Card 3",
             .fields = kCard3Fields,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 4",
             .fields = kCard4Fields,
             .presence = "optional: a missing card is read as blank"},
};

double norm(const std::array<double, 3>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

void read_mat_orthotropic_elastic(KeywordInput& in) {
  model::MatOrthotropicElasticDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO EA EB EC PRBA PRCA PRCB)");
  }
  const CardValues v = in.read(kCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.ea = v.real("EA");
  mat.eb = v.real("EB");
  mat.ec = v.real("EC");
  mat.prba = v.real("PRBA");
  mat.prca = v.real("PRCA");
  mat.prcb = v.real("PRCB");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "EA", mat.ea);
  require_positive(in, line->line, "EB", mat.eb);
  require_positive(in, line->line, "EC", mat.ec);

  const auto line2 = in.next_line();
  if (!line2) {
    in.fail(line->line, "", "missing card 2 (GAB GBC GCA AOPT G SIGF)");
  }
  const CardValues c2 = in.read(kCards[2], *line2);
  mat.gab = c2.real("GAB");
  mat.gbc = c2.real("GBC");
  mat.gca = c2.real("GCA");
  mat.aopt = static_cast<int>(c2.real("AOPT"));
  mat.g = c2.real("G");
  mat.sigf = c2.real("SIGF");
  require_positive(in, line2->line, "GAB", mat.gab);
  require_positive(in, line2->line, "GBC", mat.gbc);
  require_positive(in, line2->line, "GCA", mat.gca);
  require_zero(in, line2->line, "G", mat.g, "frequency-independent damping");
  require_zero(in, line2->line, "SIGF", mat.sigf, "frequency-independent damping");

  int vectors_line = line2->line;
  if (const auto line3 = in.next_line()) {
    const CardValues c3 = in.read(kCards[3], *line3);
    mat.p = {c3.real("XP"), c3.real("YP"), c3.real("ZP")};
    mat.a = {c3.real("A1"), c3.real("A2"), c3.real("A3")};
    mat.macf = c3.integer("MACF") == 0 ? 1 : c3.integer("MACF");
    require_zero(in, line3->line, "IHIS", c3.integer("IHIS"), "history data initialisation");
    vectors_line = line3->line;
  }
  if (const auto line4 = in.next_line()) {
    const CardValues c4 = in.read(kCards[4], *line4);
    mat.v = {c4.real("V1"), c4.real("V2"), c4.real("V3")};
    mat.d = {c4.real("D1"), c4.real("D2"), c4.real("D3")};
    mat.beta = c4.real("BETA");
    mat.ref = c4.real("REF");
    require_zero(in, line4->line, "REF", mat.ref, "a reference geometry");
    vectors_line = line4->line;
  }
  if (mat.aopt == 2) {
    const std::array<double, 3> cross{mat.a[1] * mat.d[2] - mat.a[2] * mat.d[1],
                                      mat.a[2] * mat.d[0] - mat.a[0] * mat.d[2],
                                      mat.a[0] * mat.d[1] - mat.a[1] * mat.d[0]};
    if (!(norm(mat.a) > 0.0)) {
      in.fail(vectors_line, "A1", "AOPT = 2 needs a non-zero vector a (A1 A2 A3, card 3)");
    }
    if (!(norm(cross) > 1.0e-12 * norm(mat.a) * norm(mat.d))) {
      in.fail(vectors_line, "D1",
              "AOPT = 2 needs a vector d (D1 D2 D3, card 4) that is non-zero and not parallel "
              "to a");
    }
  }
  in.model().orthotropic_elastic_materials.push_back(std::move(mat));
}

}  // namespace

KeywordSpec mat_orthotropic_elastic_keyword() {
  return {.name = "MAT_ORTHOTROPIC_ELASTIC",
          .options = kNoneOrTitle,
          .handler = read_mat_orthotropic_elastic,
          .cards = kCards,
          .summary =
              "Linear orthotropic elasticity in material axes a, b, c (material type 2), the "
              "axes from the element (AOPT 0) or global vectors a and d (AOPT 2). Other axis "
              "options, damping (G, SIGF), MACF, IHIS and REF are errors when set. Also read "
              "as *MAT_002."};
}

KeywordSpec mat_002_keyword() {
  KeywordSpec spec = mat_orthotropic_elastic_keyword();
  spec.name = "MAT_002";
  spec.summary = "The same keyword as *MAT_ORTHOTROPIC_ELASTIC, by number.";
  return spec;
}

}  // namespace plyform::keyword
