// *MAT_REINFORCED_THERMOPLASTIC (*MAT_249, with _TITLE): fibre families in a thermoplastic
// matrix, for shells.
#include <array>
#include <cmath>
#include <numbers>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 3> kAopts{0, 2, 3};
constexpr std::array<int, 3> kNfibs{1, 2, 3};
constexpr std::array<int, 1> kThick{0};

constexpr FieldSpec real_field(std::string_view name, std::string_view unit,
                               std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kReal, .unit = unit, .description = description};
}
constexpr FieldSpec real_field(std::string_view name, std::string_view unit,
                               std::string_view description, double min) {
  return FieldSpec{.name = name,
                   .type = FieldType::kReal,
                   .min_value = min,
                   .unit = unit,
                   .description = description};
}
constexpr FieldSpec id_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .unit = "-",
                   .description = description};
}

constexpr std::array kCard1Fields{
    kMaterialIdField,
    kDensityField,
    real_field("EM", "stress", "the matrix's Young's modulus (> 0 unless LCEM)", 0.0),
    id_field("LCEM", "curve of EM against temperature (replaces EM)"),
    FieldSpec{.name = "PRM",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .max_value = 0.5,
              .unit = "-",
              .description = "the matrix's Poisson's ratio",
              .max_exclusive = true},
    id_field("LCPRM", "curve of PRM against temperature (replaces PRM)"),
    id_field("LCSIGY",
             "the matrix's yield stress against effective plastic strain: a curve, or a table "
             "of such curves over temperature (0: elastic matrix)"),
    real_field("BETA", "-",
               "mixed hardening (0 kinematic, 1 isotropic): with LCSIGY only BETA = 1 is "
               "implemented"),
};
constexpr std::array kCard2Fields{
    FieldSpec{.name = "NFIB",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "number of fibre families",
              .required = true,
              .allowed = kNfibs},
    FieldSpec{.name = "AOPT",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "material axes: 0 the element's edge N1->N2 turned by MANGL, 2 the "
                             "global vector a (with d), 3 v x the shell normal turned by MANGL",
              .allowed = kAopts,
              .allowed_note = "AOPT 1, 4 and coordinate systems (< 0) are not supported"},
    real_field("XP", "length", "point P (AOPT 1 and 4); kept as written"),
    real_field("YP", "length", "point P; kept as written"),
    real_field("ZP", "length", "point P; kept as written"),
    real_field("A1", "-", "vector a (AOPT 2)"),
    real_field("A2", "-", "vector a (AOPT 2)"),
    real_field("A3", "-", "vector a (AOPT 2)"),
};
constexpr std::array kCard3Fields{
    real_field("V1", "-", "vector v (AOPT 3)"),
    real_field("V2", "-", "vector v (AOPT 3)"),
    real_field("V3", "-", "vector v (AOPT 3)"),
    real_field("D1", "-", "vector d (AOPT 2)"),
    real_field("D2", "-", "vector d (AOPT 2)"),
    real_field("D3", "-", "vector d (AOPT 2)"),
    real_field("MANGL", "degree",
               "material angle about the normal (AOPT 0 and 3); an element card's non-zero "
               "BETA replaces it"),
    FieldSpec{.name = "THICK",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "fibre stresses scaled by the thickness change: 0 (no scaling)",
              .allowed = kThick,
              .allowed_note = "THICK 1 (scaling the fibre stresses) is not implemented"},
};
#define PLYFORM_FIBRE_FIELDS(N)                                                             \
  std::array {                                                                              \
    id_field("IDF" N, "the family's id for post-processing; kept as written"),              \
        real_field("ALPH" N, "degree", "the family's angle from the material axis a"),      \
        real_field("EF" N, "stress",                                                        \
                   "the family's stiffness in the ply (fibre modulus times its volume "     \
                   "fraction): nominal stress per unit fibre strain, tension only",         \
                   0.0),                                                                    \
        id_field("LCEF" N,                                                                  \
                 "curve (or table over temperature) of nominal fibre stress against fibre " \
                 "strain; replaces EF" N),                                                  \
        real_field("G23_" N, "stress", "transverse shear modulus across the fibres", 0.0),  \
        real_field("G31_" N, "stress", "transverse shear modulus along the fibres", 0.0),   \
  }
#define PLYFORM_SHEAR_FIELDS(P)                                                                  \
  std::array {                                                                                   \
    real_field("G" P, "stress",                                                                  \
               "linear shear modulus between the families (METH" P " 3: the unloading slope)",   \
               0.0),                                                                             \
        id_field("LCG" P,                                                                        \
                 "curve (or table over temperature) of the nominal shear stress against the "    \
                 "shear angle, radians"),                                                        \
        real_field("ALOC" P, "radian", "locking angle (0: none); < pi/2", 0.0),                  \
        real_field("GLOC" P, "stress", "shear modulus past the locking angle", 0.0),             \
        FieldSpec{.name = "METH" P,                                                              \
                  .type = FieldType::kInteger,                                                   \
                  .unit = "-",                                                                   \
                  .description = "with LCG" P                                                    \
                                 ": 2 elastic, 3 elasto-plastic (the curve is the loading "      \
                                 "curve); 0, 1 (curves of the fibres' scalar product) and 4, 5 " \
                                 "(stitched non-crimp fabrics) are not implemented"},            \
  }
constexpr auto kFibre1Fields = PLYFORM_FIBRE_FIELDS("1");
constexpr auto kFibre2Fields = PLYFORM_FIBRE_FIELDS("2");
constexpr auto kFibre3Fields = PLYFORM_FIBRE_FIELDS("3");
constexpr auto kShear12Fields = PLYFORM_SHEAR_FIELDS("12");
constexpr auto kShear23Fields = PLYFORM_SHEAR_FIELDS("23");
#undef PLYFORM_FIBRE_FIELDS
#undef PLYFORM_SHEAR_FIELDS
constexpr std::array kCard9Fields{
    id_field("POSTV",
             "extra post-processing variables: not written (plyform writes the fibre "
             "directions and the shear angle as VTU cell arrays); a warning when set"),
    real_field("IHIS", "-", "history initialisation by *INITIAL_STRESS_SHELL: must be 0"),
};
constexpr std::array kCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kCard2Fields, .presence = "required"},
    CardSpec{.title = "Card 3", .fields = kCard3Fields, .presence = "required"},
    CardSpec{.title = "Card 4 (fibre family 1)", .fields = kFibre1Fields, .presence = "required"},
    CardSpec{.title = "Card 5 (shear 1-2)", .fields = kShear12Fields, .presence = "NFIB >= 2"},
    CardSpec{.title = "Card 6 (fibre family 2)", .fields = kFibre2Fields, .presence = "NFIB >= 2"},
    CardSpec{
        .title = "Card 7 (shear 2-3)",
        .fields = kShear23Fields,
        .presence = "NFIB = 3; with NFIB 2 it may be written blank (LS-PrePost) before card 9"},
    CardSpec{.title = "Card 8 (fibre family 3)",
             .fields = kFibre3Fields,
             .presence = "NFIB = 3; with NFIB 2 it may be written blank"},
    CardSpec{.title = "Card 9",
             .fields = kCard9Fields,
             .presence = "optional: a missing card is read as blank"},
};

double norm(const std::array<double, 3>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

model::FibreFamilyDesc read_family(KeywordInput& in, const CardSpec& card, const DataLine& line,
                                   int k) {
  const CardValues c = in.read(card, line);
  const std::string n = std::to_string(k);
  model::FibreFamilyDesc f;
  f.idf = c.integer("IDF" + n);
  f.alpha = c.real("ALPH" + n);
  f.ef = c.real("EF" + n);
  f.lcef = c.integer("LCEF" + n);
  f.g23 = c.real("G23_" + n);
  f.g31 = c.real("G31_" + n);
  f.where = in.where(line.line);
  return f;
}

model::FibreShearDesc read_shear(KeywordInput& in, const CardSpec& card, const DataLine& line,
                                 const std::string& pair) {
  const CardValues c = in.read(card, line);
  model::FibreShearDesc s;
  s.g = c.real("G" + pair);
  s.lcg = c.integer("LCG" + pair);
  s.aloc = c.real("ALOC" + pair);
  s.gloc = c.real("GLOC" + pair);
  s.meth = c.integer("METH" + pair);
  s.where = in.where(line.line);
  return s;
}

// The checks of one family and one pair that need more than a field's range.
void check_family(KeywordInput& in, const model::FibreFamilyDesc& f, int k) {
  if (!(f.ef > 0.0) && f.lcef == 0)
    in.fail(f.where.line, "EF" + std::to_string(k),
            fmt::format("fibre family {} needs EF{} > 0 or a curve LCEF{}", k, k, k));
}

void check_shear(KeywordInput& in, const model::FibreShearDesc& s, const std::string& pair) {
  const int line = s.where.line;
  if (s.aloc >= 0.5 * std::numbers::pi)
    in.fail(line, "ALOC" + pair,
            fmt::format("ALOC{} = {} radians: a locking angle must be below pi/2 (it is given "
                        "in radians, not degrees)",
                        pair, s.aloc));
  if (s.gloc > 0.0 && !(s.aloc > 0.0) && (s.lcg == 0 || s.meth == 3))
    in.fail(line, "GLOC" + pair,
            fmt::format("GLOC{} is given but ALOC{} is 0: a locking modulus needs a locking "
                        "angle",
                        pair, pair));
  if (s.lcg != 0) {
    if (s.meth != 2 && s.meth != 3)
      in.fail(line, "METH" + pair,
              fmt::format("METH{} = {} is not implemented: with a curve LCG{} use 2 (elastic, "
                          "shear stress against the shear angle) or 3 (elasto-plastic); 0 and 1 "
                          "(curves of the fibres' scalar product) and 4, 5 (stitched non-crimp "
                          "fabrics) are not",
                          pair, s.meth, pair));
    if (s.meth == 3 && !(s.g > 0.0))
      in.fail(line, "G" + pair,
              fmt::format("METH{} = 3 (elasto-plastic) needs G{} > 0: the elastic slope of "
                          "unloading",
                          pair, pair));
    if (s.meth == 2 && (s.aloc != 0.0 || s.gloc != 0.0))
      in.warn(line, "ALOC" + pair,
              fmt::format("ALOC{} and GLOC{} are ignored with METH{} = 2, as in LS-DYNA: the "
                          "curve LCG{} carries the locking",
                          pair, pair, pair, pair));
  } else if (!(s.g > 0.0)) {
    in.warn(line, "G" + pair,
            fmt::format("G{} = 0 and no curve LCG{}: the families shear freely (only the "
                        "matrix resists)",
                        pair, pair));
  }
}

bool all_zero(const model::FibreFamilyDesc& f) {
  return f.idf == 0 && f.alpha == 0.0 && f.ef == 0.0 && f.lcef == 0 && f.g23 == 0.0 && f.g31 == 0.0;
}
bool all_zero(const model::FibreShearDesc& s) {
  return s.g == 0.0 && s.lcg == 0 && s.aloc == 0.0 && s.gloc == 0.0 && s.meth == 0;
}

void read_mat_249(KeywordInput& in) {
  model::MatReinforcedThermoplasticDesc mat;
  if (in.option() == "TITLE")
    mat.title = in.next_card(kCards[0], "title card").text("TITLE");
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", "missing card 1 (MID RO EM LCEM PRM LCPRM LCSIGY BETA)");
  const CardValues c1 = in.read(kCards[1], *line);
  mat.id = c1.integer("MID");
  mat.density = c1.real("RO");
  mat.em = c1.real("EM");
  mat.lcem = c1.integer("LCEM");
  mat.prm = c1.real("PRM");
  mat.lcprm = c1.integer("LCPRM");
  mat.lcsigy = c1.integer("LCSIGY");
  mat.beta = c1.real("BETA");
  mat.where = in.where(line->line);
  require_positive(in, line->line, "RO", mat.density);
  if (mat.lcem == 0)
    require_positive(in, line->line, "EM", mat.em);
  if (mat.lcsigy != 0 && mat.beta != 1.0)
    in.fail(line->line, "BETA",
            fmt::format("BETA = {}: kinematic and mixed hardening of the matrix are not "
                        "implemented; set BETA = 1 (isotropic hardening by LCSIGY)",
                        mat.beta));

  const auto l2 = in.next_line();
  if (!l2)
    in.fail(line->line, "", "missing card 2 (NFIB AOPT XP YP ZP A1 A2 A3)");
  const CardValues c2 = in.read(kCards[2], *l2);
  const int line2 = l2->line;
  mat.nfib = c2.integer("NFIB");
  mat.aopt = static_cast<int>(c2.real("AOPT"));
  mat.p = {c2.real("XP"), c2.real("YP"), c2.real("ZP")};
  mat.a = {c2.real("A1"), c2.real("A2"), c2.real("A3")};
  const auto line3 = in.next_line();
  if (!line3)
    in.fail(line2, "", "missing card 3 (V1 V2 V3 D1 D2 D3 MANGL THICK)");
  const CardValues c3 = in.read(kCards[3], *line3);
  mat.v = {c3.real("V1"), c3.real("V2"), c3.real("V3")};
  mat.d = {c3.real("D1"), c3.real("D2"), c3.real("D3")};
  mat.mangl = c3.real("MANGL");
  mat.thick = c3.real("THICK");
  if (mat.aopt == 2) {
    const std::array<double, 3> cross{mat.a[1] * mat.d[2] - mat.a[2] * mat.d[1],
                                      mat.a[2] * mat.d[0] - mat.a[0] * mat.d[2],
                                      mat.a[0] * mat.d[1] - mat.a[1] * mat.d[0]};
    if (!(norm(mat.a) > 0.0))
      in.fail(line2, "A1", "AOPT = 2 needs a non-zero vector a (A1 A2 A3, card 2)");
    if (!(norm(cross) > 1.0e-12 * norm(mat.a) * norm(mat.d)))
      in.fail(line3->line, "D1",
              "AOPT = 2 needs a vector d (D1 D2 D3, card 3) that is non-zero and not parallel "
              "to a");
  }
  if (mat.aopt == 3 && !(norm(mat.v) > 0.0))
    in.fail(line3->line, "V1", "AOPT = 3 needs a non-zero vector v (V1 V2 V3, card 3)");

  // Cards 4..8 by NFIB; LS-PrePost may write the cards of unused families blank. Card 9 is
  // optional: count what is left before the next keyword.
  const auto next = [&](const char* what) {
    const auto l = in.next_line();
    if (!l)
      in.fail(line3->line, "", fmt::format("missing {}", what));
    return *l;
  };
  mat.fibres.push_back(read_family(in, kCards[4], next("card 4 (fibre family 1)"), 1));
  if (mat.nfib >= 2) {
    mat.shears.push_back(read_shear(in, kCards[5], next("card 5 (shear 1-2)"), "12"));
    mat.fibres.push_back(read_family(in, kCards[6], next("card 6 (fibre family 2)"), 2));
  }
  const std::size_t left = in.remaining().size();
  if (mat.nfib == 3 || (mat.nfib == 2 && left >= 2)) {
    const DataLine l7 = next("card 7 (shear 2-3)");
    const model::FibreShearDesc s = read_shear(in, kCards[7], l7, "23");
    const DataLine l8 = next("card 8 (fibre family 3)");
    const model::FibreFamilyDesc f = read_family(in, kCards[8], l8, 3);
    if (mat.nfib == 3) {
      mat.shears.push_back(s);
      mat.fibres.push_back(f);
    } else if (!all_zero(s) || !all_zero(f)) {
      in.fail(all_zero(s) ? l8.line : l7.line, all_zero(s) ? "EF3" : "G23",
              "NFIB = 2 but the cards of a third family (cards 7 and 8) carry values: set "
              "NFIB = 3 or leave them blank");
    }
  } else if (mat.nfib == 1 && left >= 3) {
    for (int k = 5; k <= 6; ++k) {
      const DataLine l = next("card");
      const bool zero = k == 5 ? all_zero(read_shear(in, kCards[5], l, "12"))
                               : all_zero(read_family(in, kCards[6], l, 2));
      if (!zero)
        in.fail(l.line, k == 5 ? "G12" : "EF2",
                "NFIB = 1 but the cards of a second family carry values: set NFIB = 2 or leave "
                "them blank");
    }
    if (in.remaining().size() >= 3) {
      next("card 7");
      next("card 8");
    }
  }
  for (std::size_t i = 0; i < mat.fibres.size(); ++i)
    check_family(in, mat.fibres[i], static_cast<int>(i) + 1);
  for (std::size_t i = 0; i < mat.shears.size(); ++i)
    check_shear(in, mat.shears[i], i == 0 ? "12" : "23");
  if (const auto l9 = in.next_line()) {
    const CardValues c9 = in.read(kCards[9], *l9);
    mat.postv = c9.integer("POSTV");
    mat.ihis = c9.real("IHIS");
    require_zero(in, l9->line, "IHIS", mat.ihis, "history initialisation");
    if (mat.postv != 0)
      in.warn(l9->line, "POSTV",
              "POSTV: the extra post-processing variables are not written (plyform writes the "
              "fibre directions and the shear angle as VTU cell arrays)");
  }
  in.model().reinforced_thermoplastic_materials.push_back(std::move(mat));
}

}  // namespace

KeywordSpec mat_reinforced_thermoplastic_keyword() {
  return {.name = "MAT_REINFORCED_THERMOPLASTIC",
          .options = kNoneOrTitle,
          .handler = read_mat_249,
          .cards = kCards,
          .summary =
              "Fibre families in a thermoplastic matrix (material type 249), for shells: a woven "
              "ply (NFIB 2) or a unidirectional one (NFIB 1). The stress is the matrix's "
              "(isotropic, E and nu against temperature, J2 with LCSIGY) plus each family's "
              "tension along its current direction plus the shear between neighbouring families "
              "against their shear angle, with locking (docs/materials.md). The fibre "
              "directions are per-point history that follow the deformation. THICK 1, IHIS, "
              "kinematic hardening (BETA < 1 with LCSIGY), METH 0/1/4/5 and AOPT 1/4/< 0 are "
              "errors. Also read as *MAT_249."};
}

KeywordSpec mat_249_keyword() {
  KeywordSpec spec = mat_reinforced_thermoplastic_keyword();
  spec.name = "MAT_249";
  spec.summary = "The same keyword as *MAT_REINFORCED_THERMOPLASTIC, by number.";
  return spec;
}

}  // namespace plyform::keyword
