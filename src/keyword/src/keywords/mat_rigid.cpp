// *MAT_RIGID (*MAT_020), with _TITLE.
#include <array>
#include <cmath>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 5> kCmos{-2, -1, 0, 1, 2};

constexpr FieldSpec real_field(std::string_view name, std::string_view unit,
                               std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kReal, .unit = unit, .description = description};
}

constexpr std::array kCard1Fields{
    kMaterialIdField,
    kDensityField,
    FieldSpec{.name = "E",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "stress",
              .description = "Young's modulus, > 0 (contact stiffness only)",
              .required = true},
    kPoissonRatioField,
    real_field("N", "-", "MADYMO coupling: must be 0 (not supported)"),
    real_field("COUPLE", "-", "MADYMO/CAL3D coupling option: must be 0 (not supported)"),
    real_field("M", "-", "MADYMO/CAL3D system: must be 0 (not supported)"),
    FieldSpec{.name = "ALIAS",
              .type = FieldType::kText,
              .width = 10,
              .description = "VDA surface name; kept as written"},
};
constexpr std::array kCard2Fields{
    FieldSpec{.name = "CMO",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "constraints: 0 none, 1 global (CON1 CON2), -1 local, +-2 about a "
                             "point; kept as written",
              .allowed = kCmos},
    real_field("CON1", "-",
               "CMO > 0: translations fixed, 0 none, 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 all; "
               "CMO < 0: a coordinate system id"),
    real_field("CON2", "-",
               "CMO > 0: rotations fixed (codes as CON1); CMO < 0: SPC flags xyzXYZ as a "
               "number of six 0/1 digits"),
    FieldSpec{.name = "SPCNID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "node of the constraint point (|CMO| = 2); kept as written"},
    real_field("XSPC", "length", "constraint point x (|CMO| = 2); kept as written"),
    real_field("YSPC", "length", "constraint point y; kept as written"),
    real_field("ZSPC", "length", "constraint point z; kept as written"),
};
constexpr std::array kCard3Fields{
    real_field("LCO/A1", "-",
               "output coordinate system id (A2..V3 zero) or vector a x; kept as written"),
    real_field("A2", "-", "vector a y; kept as written"),
    real_field("A3", "-", "vector a z; kept as written"),
    real_field("V1", "-", "vector v x; kept as written"),
    real_field("V2", "-", "vector v y; kept as written"),
    real_field("V3", "-", "vector v z; kept as written"),
};
constexpr std::array kCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kCard2Fields,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 3",
             .fields = kCard3Fields,
             .presence = "optional: a missing card is read as blank"},
};

/// Reads a real field that LS-DYNA uses as an integer code; a fraction is an error.
int integer_code(KeywordInput& in, int line, const CardValues& v, std::string_view field) {
  const double value = v.real(field);
  if (value != std::trunc(value) || std::abs(value) > 1.0e9) {
    in.fail(line, std::string(field), fmt::format("{} = {} is not an integer code", field, value));
  }
  return static_cast<int>(value);
}

void read_mat_rigid(KeywordInput& in) {
  model::MatRigidDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(kCards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO E PR N COUPLE M ALIAS)");
  }
  const CardValues v = in.read(kCards[1], *line);
  mat.id = v.integer("MID");
  mat.density = v.real("RO");
  mat.youngs_modulus = v.real("E");
  mat.poisson_ratio = v.real("PR");
  mat.n = v.real("N");
  mat.couple = v.real("COUPLE");
  mat.m = v.real("M");
  mat.alias = v.text("ALIAS");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  require_positive(in, line->line, "E", mat.youngs_modulus);
  require_zero(in, line->line, "N", mat.n, "MADYMO coupling");
  require_zero(in, line->line, "COUPLE", mat.couple, "MADYMO/CAL3D coupling");
  require_zero(in, line->line, "M", mat.m, "MADYMO/CAL3D coupling");

  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kCards[2], *line2);
    mat.cmo = integer_code(in, line2->line, c2, "CMO");
    mat.con1 = integer_code(in, line2->line, c2, "CON1");
    mat.con2 = integer_code(in, line2->line, c2, "CON2");
    mat.spcnid = c2.integer("SPCNID");
    mat.spc = {c2.real("XSPC"), c2.real("YSPC"), c2.real("ZSPC")};
    const auto check_code = [&](std::string_view field, int value) {
      if (mat.cmo > 0 && (value < 0 || value > 7)) {
        in.fail(line2->line, std::string(field),
                fmt::format("{} = {} is out of range: with CMO > 0 it must be in [0, 7]", field,
                            value));
      }
    };
    check_code("CON1", mat.con1);
    check_code("CON2", mat.con2);
  }
  if (const auto line3 = in.next_line()) {
    const CardValues c3 = in.read(kCards[3], *line3);
    mat.a = {c3.real("LCO/A1"), c3.real("A2"), c3.real("A3")};
    mat.v = {c3.real("V1"), c3.real("V2"), c3.real("V3")};
  }
  in.model().rigid_materials.push_back(std::move(mat));
}

}  // namespace

KeywordSpec mat_rigid_keyword() {
  return {.name = "MAT_RIGID",
          .options = kNoneOrTitle,
          .handler = read_mat_rigid,
          .cards = kCards,
          .summary =
              "The elements of a part with this material form one rigid body (material type "
              "20); E and PR set the contact stiffness only. The constraints of card 2 and the "
              "output axes of card 3 are read as written. MADYMO/CAL3D coupling (N, COUPLE, "
              "M) is an error. Also read as *MAT_020."};
}

KeywordSpec mat_020_keyword() {
  KeywordSpec spec = mat_rigid_keyword();
  spec.name = "MAT_020";
  spec.summary = "The same keyword as *MAT_RIGID, by number.";
  return spec;
}

}  // namespace plyform::keyword
