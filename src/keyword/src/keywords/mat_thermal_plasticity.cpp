// Temperature-dependent mechanics: *MAT_ELASTIC_PLASTIC_THERMAL (*MAT_004, with _TITLE) and
// *MAT_ADD_THERMAL_EXPANSION. The reader checks the tables and rejects what plyform cannot
// honour (orthotropic expansion, the secant form with TREF, a material id for PID) by name;
// the parts and curves named are resolved when the model is built.
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

// --- *MAT_ELASTIC_PLASTIC_THERMAL
constexpr std::size_t kMaxPoints = 8;

/// A field LS-DYNA leaves unused; a value there most likely means the card's fields are
/// shifted, so it must stay blank (checked by require_unused_blank).
constexpr FieldSpec unused_field() {
  return FieldSpec{.name = "UNUSED",
                   .type = FieldType::kReal,
                   .unit = "-",
                   .description = "not used by LS-DYNA: blank or 0"};
}

void require_unused_blank(KeywordInput& in, const CardSpec& card, const CardValues& v, int line) {
  for (std::size_t i = 0; i < card.fields.size(); ++i) {
    if (card.fields[i].name == "UNUSED" && v.at(i).real != 0.0) {
      in.fail(line, "UNUSED",
              fmt::format("field {} holds {}, but LS-DYNA does not use it: leave it blank "
                          "(are the card's fields shifted?)",
                          i + 1, v.at(i).real));
    }
  }
}

/// One value of the temperature table (a real; the range, if any, is checked on reading).
constexpr FieldSpec point_field(std::string_view name, std::string_view unit,
                                std::string_view description,
                                std::optional<double> min_value = std::nullopt,
                                std::optional<double> max_value = std::nullopt,
                                bool max_exclusive = false) {
  return FieldSpec{.name = name,
                   .type = FieldType::kReal,
                   .min_value = min_value,
                   .max_value = max_value,
                   .unit = unit,
                   .description = description,
                   .max_exclusive = max_exclusive};
}

constexpr std::array kEptCard1Fields{
    kMaterialIdField, kDensityField,  unused_field(), unused_field(),
    unused_field(),   unused_field(), unused_field(), unused_field(),
};
constexpr std::array kEptTemperatureFields{
    point_field("T1", "temperature", "temperature of point 1"),
    point_field("T2", "temperature", "temperature of point 2, above T1"),
    point_field("T3", "temperature", "temperature of point 3, above T2 (blank: 2 points)"),
    point_field("T4", "temperature", "temperature of point 4, above T3 (blank: 3 points)"),
    point_field("T5", "temperature", "temperature of point 5, above T4 (blank: 4 points)"),
    point_field("T6", "temperature", "temperature of point 6, above T5 (blank: 5 points)"),
    point_field("T7", "temperature", "temperature of point 7, above T6 (blank: 6 points)"),
    point_field("T8", "temperature", "temperature of point 8, above T7 (blank: 7 points)"),
};
constexpr std::array kEptYoungFields{
    point_field("E1", "stress", "Young's modulus at T1, > 0", 0.0),
    point_field("E2", "stress", "Young's modulus at T2, > 0", 0.0),
    point_field("E3", "stress", "Young's modulus at T3, > 0", 0.0),
    point_field("E4", "stress", "Young's modulus at T4, > 0", 0.0),
    point_field("E5", "stress", "Young's modulus at T5, > 0", 0.0),
    point_field("E6", "stress", "Young's modulus at T6, > 0", 0.0),
    point_field("E7", "stress", "Young's modulus at T7, > 0", 0.0),
    point_field("E8", "stress", "Young's modulus at T8, > 0", 0.0),
};
constexpr std::array kEptPoissonFields{
    point_field("PR1", "-", "Poisson's ratio at T1, -1 < PR1 < 0.5", -1.0, 0.5, true),
    point_field("PR2", "-", "Poisson's ratio at T2, -1 < PR2 < 0.5", -1.0, 0.5, true),
    point_field("PR3", "-", "Poisson's ratio at T3, -1 < PR3 < 0.5", -1.0, 0.5, true),
    point_field("PR4", "-", "Poisson's ratio at T4, -1 < PR4 < 0.5", -1.0, 0.5, true),
    point_field("PR5", "-", "Poisson's ratio at T5, -1 < PR5 < 0.5", -1.0, 0.5, true),
    point_field("PR6", "-", "Poisson's ratio at T6, -1 < PR6 < 0.5", -1.0, 0.5, true),
    point_field("PR7", "-", "Poisson's ratio at T7, -1 < PR7 < 0.5", -1.0, 0.5, true),
    point_field("PR8", "-", "Poisson's ratio at T8, -1 < PR8 < 0.5", -1.0, 0.5, true),
};
constexpr std::array kEptAlphaFields{
    point_field("ALPHA1", "1/temperature",
                "coefficient of thermal expansion at T1 (the tangent coefficient: the thermal "
                "strain rate is ALPHA dT/dt)"),
    point_field("ALPHA2", "1/temperature", "coefficient of thermal expansion at T2"),
    point_field("ALPHA3", "1/temperature", "coefficient of thermal expansion at T3"),
    point_field("ALPHA4", "1/temperature", "coefficient of thermal expansion at T4"),
    point_field("ALPHA5", "1/temperature", "coefficient of thermal expansion at T5"),
    point_field("ALPHA6", "1/temperature", "coefficient of thermal expansion at T6"),
    point_field("ALPHA7", "1/temperature", "coefficient of thermal expansion at T7"),
    point_field("ALPHA8", "1/temperature", "coefficient of thermal expansion at T8"),
};
constexpr std::array kEptYieldFields{
    point_field("SIGY1", "stress", "yield stress at T1, > 0", 0.0),
    point_field("SIGY2", "stress", "yield stress at T2, > 0", 0.0),
    point_field("SIGY3", "stress", "yield stress at T3, > 0", 0.0),
    point_field("SIGY4", "stress", "yield stress at T4, > 0", 0.0),
    point_field("SIGY5", "stress", "yield stress at T5, > 0", 0.0),
    point_field("SIGY6", "stress", "yield stress at T6, > 0", 0.0),
    point_field("SIGY7", "stress", "yield stress at T7, > 0", 0.0),
    point_field("SIGY8", "stress", "yield stress at T8, > 0", 0.0),
};
constexpr std::array kEptTangentFields{
    point_field("ETAN1", "stress", "plastic hardening modulus at T1, 0 <= ETAN1 < E1", 0.0),
    point_field("ETAN2", "stress", "plastic hardening modulus at T2, 0 <= ETAN2 < E2", 0.0),
    point_field("ETAN3", "stress", "plastic hardening modulus at T3, 0 <= ETAN3 < E3", 0.0),
    point_field("ETAN4", "stress", "plastic hardening modulus at T4, 0 <= ETAN4 < E4", 0.0),
    point_field("ETAN5", "stress", "plastic hardening modulus at T5, 0 <= ETAN5 < E5", 0.0),
    point_field("ETAN6", "stress", "plastic hardening modulus at T6, 0 <= ETAN6 < E6", 0.0),
    point_field("ETAN7", "stress", "plastic hardening modulus at T7, 0 <= ETAN7 < E7", 0.0),
    point_field("ETAN8", "stress", "plastic hardening modulus at T8, 0 <= ETAN8 < E8", 0.0),
};
constexpr std::string_view kPointCardPresence =
    "required: a value for each point of card 2, blank after the last point";
constexpr std::array kEptCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kEptCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kEptTemperatureFields,
             .presence = "required: the table has one point for each T written, 2 to 8, "
                         "consecutive from T1 and increasing"},
    CardSpec{.title = "Card 3", .fields = kEptYoungFields, .presence = kPointCardPresence},
    CardSpec{.title = "Card 4", .fields = kEptPoissonFields, .presence = kPointCardPresence},
    CardSpec{.title = "Card 5", .fields = kEptAlphaFields, .presence = kPointCardPresence},
    CardSpec{.title = "Card 6", .fields = kEptYieldFields, .presence = kPointCardPresence},
    CardSpec{.title = "Card 7", .fields = kEptTangentFields, .presence = kPointCardPresence},
};

/// The values of one card of the table (cards 3-7) and the card's line.
struct PointCard {
  std::vector<double> values;
  int line = 0;
};

void read_mat_elastic_plastic_thermal(KeywordInput& in) {
  const std::span<const CardSpec> cards = kEptCards;
  model::MatElasticPlasticThermalDesc mat;
  if (in.option() == "TITLE") {
    mat.title = in.next_card(cards[0], "title card").text("TITLE");
  }
  const auto line1 = in.next_line();
  if (!line1) {
    in.fail(in.keyword().line, "", "missing card 1 (MID RO)");
  }
  const CardValues c1 = in.read(cards[1], *line1);
  mat.id = c1.integer("MID");
  mat.density = c1.real("RO");
  mat.where = in.where(line1->line);
  require_positive(in, line1->line, "RO", mat.density);
  require_unused_blank(in, cards[1], c1, line1->line);

  // A missing card is reported at the last card read.
  int last_line = line1->line;
  const auto next_table_line = [&](std::size_t card, std::string_view fields) {
    const auto line = in.next_line();
    if (!line) {
      in.fail(last_line, "", fmt::format("missing card {} ({})", card, fields));
    }
    last_line = line->line;
    return *line;
  };

  // Card 2: the points are the T fields written, consecutive from T1 (a temperature may be 0,
  // so a blank, not a zero, ends the table).
  const DataLine t_line = next_table_line(2, "T1..T8");
  const CardValues t = in.read(cards[2], t_line);
  std::size_t n = 0;
  while (n < kMaxPoints && !t.at(n).blank) {
    ++n;
  }
  for (std::size_t i = n + 1; i < kMaxPoints; ++i) {
    if (!t.at(i).blank) {
      in.fail(t_line.line, std::string(cards[2].fields[i].name),
              fmt::format("T{} is written after a blank T{}: the temperatures must be written "
                          "consecutively from T1",
                          i + 1, n + 1));
    }
  }
  if (n < 2) {
    in.fail(t_line.line, n == 0 ? "T1" : "T2",
            fmt::format("the table needs at least 2 temperatures (T1 and T2), got {}", n));
  }
  for (std::size_t i = 0; i < n; ++i) {
    mat.temperature.push_back(t.at(i).real);
    if (i > 0 && !(mat.temperature[i] > mat.temperature[i - 1])) {
      in.fail(t_line.line, std::string(cards[2].fields[i].name),
              fmt::format("the temperatures must increase: T{} = {} is not above T{} = {} "
                          "(leave the fields after the last point blank)",
                          i + 1, mat.temperature[i], i, mat.temperature[i - 1]));
    }
  }

  // Cards 3-7: one value per point; a value written after point n belongs to no temperature.
  const auto read_points = [&](std::size_t card, std::string_view fields) {
    const DataLine line = next_table_line(card, fields);
    const CardValues v = in.read(cards[card], line);
    PointCard out{.values = {}, .line = line.line};
    for (std::size_t i = 0; i < kMaxPoints; ++i) {
      const std::string_view name = cards[card].fields[i].name;
      if (i < n) {
        out.values.push_back(v.at(i).real);
      } else if (!v.at(i).blank) {
        in.fail(line.line, std::string(name),
                fmt::format("{} is written, but the table has {} points (T1..T{} on card 2): "
                            "leave it blank, or add its temperature",
                            name, n, n));
      }
    }
    return out;
  };
  const auto field_name = [&](std::size_t card, std::size_t i) {
    return std::string(cards[card].fields[i].name);
  };

  const PointCard e = read_points(3, "E1..E8");
  for (std::size_t i = 0; i < n; ++i) {
    require_positive(in, e.line, field_name(3, i), e.values[i]);
  }
  const PointCard pr = read_points(4, "PR1..PR8");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(pr.values[i] > -1.0 && pr.values[i] < 0.5)) {
      in.fail(pr.line, field_name(4, i),
              fmt::format("PR{} must be in (-1, 0.5), got {}", i + 1, pr.values[i]));
    }
  }
  const PointCard alpha = read_points(5, "ALPHA1..ALPHA8");
  const PointCard sigy = read_points(6, "SIGY1..SIGY8");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(sigy.values[i] > 0.0)) {
      in.fail(sigy.line, field_name(6, i),
              fmt::format("SIGY{} must be > 0, got {} (a thermo-elastic table without yield "
                          "stresses is not supported)",
                          i + 1, sigy.values[i]));
    }
  }
  const PointCard etan = read_points(7, "ETAN1..ETAN8");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(etan.values[i] >= 0.0 && etan.values[i] < e.values[i])) {
      in.fail(etan.line, field_name(7, i),
              fmt::format("ETAN{} must be >= 0 and below E{} = {}, got {}", i + 1, i + 1,
                          e.values[i], etan.values[i]));
    }
  }
  mat.young = e.values;
  mat.poisson = pr.values;
  mat.alpha = alpha.values;
  mat.sigy = sigy.values;
  mat.etan = etan.values;
  in.model().elastic_plastic_thermal_materials.push_back(std::move(mat));
}

// --- *MAT_ADD_THERMAL_EXPANSION
constexpr std::array kAddExpansionFields{
    FieldSpec{.name = "PID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "part (*PART) whose material expands, >= 1; < 0 (LS-DYNA's "
                             "material -PID) is not supported",
              .required = true},
    FieldSpec{.name = "LCID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "*DEFINE_CURVE of the thermal expansion coefficient (1/temperature, "
                             "the tangent coefficient) against temperature; 0: the constant MULT"},
    FieldSpec{.name = "MULT",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "-",
              .description = "scale on curve LCID, or with LCID 0 the coefficient itself "
                             "(1/temperature) (blank: 1)"},
    FieldSpec{.name = "LCIDY",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of the coefficient along local y: must be 0 (orthotropic "
                             "thermal expansion is not supported)"},
    FieldSpec{.name = "MULTY",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "scale or coefficient along local y: blank or 0 (the x "
                             "properties: isotropic)"},
    FieldSpec{.name = "LCIDZ",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of the coefficient along local z: must be 0 (orthotropic "
                             "thermal expansion is not supported)"},
    FieldSpec{.name = "MULTZ",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "scale or coefficient along local z: blank or 0 (the x "
                             "properties: isotropic)"},
    FieldSpec{.name = "TREF",
              .type = FieldType::kReal,
              .unit = "temperature",
              .description = "reference temperature of LS-DYNA's secant form: must be 0 "
                             "(plyform integrates the tangent form alpha(T) dT/dt)"},
};
constexpr std::array kAddExpansionCards{
    CardSpec{.title = "Card 1", .fields = kAddExpansionFields, .presence = "required"},
};

void reject_orthotropic(KeywordInput& in, int line, std::string_view field, double value) {
  if (value != 0.0) {
    in.fail(line, std::string(field),
            fmt::format("{} = {}: orthotropic thermal expansion is not supported; leave LCIDY, "
                        "MULTY, LCIDZ and MULTZ blank (the expansion is isotropic, from LCID "
                        "and MULT)",
                        field, value));
  }
}

void read_mat_add_thermal_expansion(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (PID LCID MULT LCIDY MULTY LCIDZ MULTZ TREF)");
  }
  const CardValues v = in.read(kAddExpansionCards[0], *line);
  const model::MatAddThermalExpansionDesc d{.pid = v.integer("PID"),
                                            .lcid = v.integer("LCID"),
                                            .mult = v.real("MULT"),
                                            .where = in.where(line->line)};
  if (d.pid < 0) {
    in.fail(line->line, "PID",
            fmt::format("PID = {} (all parts of material {}) is not supported; give the part id",
                        d.pid, -static_cast<long long>(d.pid)));
  }
  if (d.pid == 0) {
    in.fail(line->line, "PID", "PID must be >= 1 (the id of a *PART), got 0");
  }
  reject_orthotropic(in, line->line, "LCIDY", v.real("LCIDY"));
  reject_orthotropic(in, line->line, "MULTY", v.real("MULTY"));
  reject_orthotropic(in, line->line, "LCIDZ", v.real("LCIDZ"));
  reject_orthotropic(in, line->line, "MULTZ", v.real("MULTZ"));
  if (const double tref = v.real("TREF"); tref != 0.0) {
    in.fail(line->line, "TREF",
            fmt::format("TREF = {} (the secant form of the thermal strain) is not supported; "
                        "leave it blank or 0 (the tangent form alpha(T) dT/dt)",
                        tref));
  }
  in.model().thermal_expansions.push_back(d);
}

}  // namespace

KeywordSpec mat_elastic_plastic_thermal_keyword() {
  return {.name = "MAT_ELASTIC_PLASTIC_THERMAL",
          .options = kNoneOrTitle,
          .handler = read_mat_elastic_plastic_thermal,
          .cards = kEptCards,
          .summary =
              "Isotropic elasto-plasticity with bilinear isotropic hardening whose constants "
              "(E, PR, ALPHA, SIGY, ETAN) are tabulated at 2 to 8 temperatures (material type "
              "4): linear in temperature between the points, constant outside them. The table "
              "has one point for each temperature written on card 2 (a blank ends it, a 0 is a "
              "temperature); a value written after the last point, or a thermo-elastic table "
              "(SIGY blank), is an error. Also read as *MAT_004."};
}

KeywordSpec mat_004_keyword() {
  KeywordSpec spec = mat_elastic_plastic_thermal_keyword();
  spec.name = "MAT_004";
  spec.summary = "The same keyword as *MAT_ELASTIC_PLASTIC_THERMAL, by number.";
  return spec;
}

KeywordSpec mat_add_thermal_expansion_keyword() {
  return {.name = "MAT_ADD_THERMAL_EXPANSION",
          .options = kNoOptions,
          .handler = read_mat_add_thermal_expansion,
          .cards = kAddExpansionCards,
          .summary =
              "An isotropic thermal expansion added to the material of part PID, whatever its "
              "law: the thermal strain rate alpha(T) dT/dt with alpha = MULT x curve LCID(T) "
              "(LCID 0: alpha = MULT). Orthotropic expansion (LCIDY, MULTY, LCIDZ, MULTZ), the "
              "secant form (TREF) and a material id for PID (< 0) are errors."};
}

}  // namespace plyform::keyword
