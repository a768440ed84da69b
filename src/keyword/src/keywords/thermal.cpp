// The heat transfer keywords (docs/thermal.md): *CONTROL_SOLUTION, *CONTROL_THERMAL_SOLVER,
// *CONTROL_THERMAL_TIMESTEP, *MAT_THERMAL_ISOTROPIC/_ORTHOTROPIC and
// *BOUNDARY_CONVECTION_SET, *BOUNDARY_FLUX_SET, *BOUNDARY_RADIATION_SET. Values that ask for
// what plyform does not implement (nonlinear thermal iterations, other linear solvers, curves
// against temperature, latent heat, enclosure radiation, erosion, the faces of thick thermal
// shells) are errors naming the field: ignoring them would give other temperatures than
// LS-DYNA's without a word.
#include <array>
#include <cmath>
#include <span>

#include "../keyword_registry.hpp"
#include "material_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kZeroOnly{0};
constexpr std::array kOneOnly{1};
constexpr std::array kZeroOne{0, 1};
constexpr std::array kZeroOneTwo{0, 1, 2};

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

/// Fails when a value that LS-DYNA reads as -ID of a curve is negative: plyform does not
/// evaluate that curve yet. `what` says what the curve would give.
void reject_negative_curve(KeywordInput& in, int line, std::string_view field, double value,
                           std::string_view what) {
  if (value < 0.0) {
    in.fail(line, std::string(field),
            fmt::format("{} = {} ({}, curve {}) is not supported yet; give a value >= 0", field,
                        value, what, -value));
  }
}

// --- *CONTROL_SOLUTION
constexpr std::array kSolutionFields{
    FieldSpec{.name = "SOLN",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "analysis: 0 structural only (temperatures as prescribed), 1 thermal "
                             "only (no mechanics), 2 coupled structural and thermal",
              .allowed = kZeroOneTwo,
              .allowed_note = "SOLN takes 0, 1 or 2"},
    FieldSpec{.name = "NLQ",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "LS-DYNA's vector length; kept as written (no meaning in plyform)"},
    FieldSpec{.name = "ISNAN",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "check of the force arrays for NaN: 0 or 1, both accepted (plyform "
                             "always checks for non-finite values)",
              .allowed = kZeroOne,
              .allowed_note = "ISNAN takes 0 or 1"},
    FieldSpec{.name = "LCINT",
              .type = FieldType::kInteger,
              .default_value = 100,
              .min_value = 0,
              .unit = "-",
              .description = "points of LS-DYNA's curve rediscretization; kept as written "
                             "(plyform evaluates curves exactly)"},
    FieldSpec{.name = "LCACC",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "truncation of curve values to significant figures: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "truncating curve values is not supported (curves are used as "
                              "written)"},
    FieldSpec{.name = "NCDCF",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "cycles between evaluations of *DEFINE_CURVE_FUNCTION: blank, 0 or 1",
              .allowed = kZeroOne,
              .allowed_note = "evaluating *DEFINE_CURVE_FUNCTION less often is not supported "
                              "(plyform has no *DEFINE_CURVE_FUNCTION)"},
    FieldSpec{.name = "NOCOPY",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "LS-DYNA's copying of history variables to buffers: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "NOCOPY = 1 is an LS-DYNA memory option plyform does not have"},
    FieldSpec{.name = "CRVP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "LS-DYNA's curve processing speed option: 0, 1 or 2, accepted "
                             "(without effect on the results)",
              .allowed = kZeroOneTwo,
              .allowed_note = "CRVP takes 0, 1 or 2"},
};
constexpr std::array kSolutionCards{
    CardSpec{.title = "Card 1", .fields = kSolutionFields, .presence = "required"},
};

void read_control_solution(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (SOLN NLQ ISNAN LCINT LCACC NCDCF ...)");
  }
  const CardValues v = in.read(kSolutionCards[0], *line);
  store_once(in, in.model().control_solution,
             model::ControlSolutionDesc{.soln = v.integer("SOLN"),
                                        .nlq = v.integer("NLQ"),
                                        .isnan = v.integer("ISNAN"),
                                        .lcint = v.integer("LCINT"),
                                        .where = in.where(line->line)});
}

// --- *CONTROL_THERMAL_SOLVER
// A written 0 is LS-DYNA's default, as a blank field (11, 8).
constexpr std::array kThermalSolvers{0, 11, 12};
constexpr std::array kGaussPointCounts{0, 8, 1};

constexpr std::array kSolverCard1{
    FieldSpec{.name = "ATYPE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0 steady state, 1 transient",
              .allowed = kZeroOne,
              .allowed_note = "ATYPE takes 0 or 1"},
    FieldSpec{.name = "PTYPE",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 2,
              .unit = "-",
              .description = "problem type: 0 linear (the only one supported)",
              .allowed = kZeroOnly,
              .allowed_note = "the nonlinear problem (PTYPE 1, 2: iterations with "
                              "temperature-dependent properties) is not supported yet"},
    FieldSpec{.name = "SOLVER",
              .type = FieldType::kInteger,
              .default_value = 11,
              .unit = "-",
              .description = "linear solver: 11 direct (LDL^T factorization), 12 conjugate "
                             "gradients with diagonal scaling",
              .allowed = kThermalSolvers,
              .allowed_note = "1-5 (LS-DYNA's former solvers), 13-16 (conjugate gradients with "
                              "other preconditioners), 17 (GMRES), 18 (ILDLT(T)), 19 (MUMPS) and "
                              "30 (nonsymmetric direct) are not supported"},
    FieldSpec{.name = "CGTOL",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "obsolete, replaced by RELTOL (card 2); read and ignored"},
    FieldSpec{.name = "GPT",
              .type = FieldType::kInteger,
              .default_value = 8,
              .unit = "-",
              .description = "Gauss points of the solids: 8 (2 x 2 x 2) or 1 (one point, which "
                             "has zero-energy temperature modes)",
              .allowed = kGaussPointCounts,
              .allowed_note = "GPT takes 8 or 1"},
    FieldSpec{.name = "EQHEAT",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "mechanical equivalent of heat (0: 1)"},
    FieldSpec{.name = "FWORK",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .min_value = 0.0,
              .max_value = 1.0,
              .unit = "-",
              .description = "fraction of the mechanical work turned into heat"},
    FieldSpec{.name = "SBC",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "Stefan-Boltzmann constant (enclosure radiation only); kept as "
                             "written"},
};
constexpr std::array kSolverCard2{
    FieldSpec{.name = "MSGLVL",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "LS-DYNA's message level; kept as written",
              .allowed = kZeroOneTwo,
              .allowed_note = "MSGLVL takes 0, 1 or 2"},
    FieldSpec{.name = "MAXITR",
              .type = FieldType::kInteger,
              .default_value = 500,
              .min_value = 0,
              .unit = "-",
              .description = "most conjugate-gradient iterations (SOLVER 12; blank or 0: 500)"},
    FieldSpec{.name = "ABSTOL",
              .type = FieldType::kReal,
              .default_value = 1e-10,
              .min_value = 0.0,
              .unit = "-",
              .description = "absolute tolerance (SOLVER 12; blank or 0: 1e-10)"},
    FieldSpec{.name = "RELTOL",
              .type = FieldType::kReal,
              .default_value = 1e-6,
              .min_value = 0.0,
              .unit = "-",
              .description = "relative tolerance (SOLVER 12; blank or 0: 1e-6)"},
    FieldSpec{.name = "OMEGA",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "relaxation of solvers 14 and 16: must be 0"},
    unused_field(),
    unused_field(),
    FieldSpec{.name = "TSF",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "-",
              .description = "thermal speed-up factor (blank or 0: 1; < 0: -TSF is a curve of "
                             "the factor against time)"},
};
constexpr std::array kSolverCard3{
    FieldSpec{.name = "MXDMP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "dumps of the matrix every MXDMP steps: must be 0"},
    FieldSpec{.name = "DTVF",
              .type = FieldType::kReal,
              .unit = "time",
              .description = "interval of view factor updates (enclosure radiation only); kept "
                             "as written"},
    FieldSpec{.name = "VARDEN",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 2,
              .unit = "-",
              .description = "variable thermal density: must be 0 (the thermal density stays TRO)",
              .allowed = kZeroOnly,
              .allowed_note = "a thermal density that follows the volume (VARDEN 1, 2) is not "
                              "supported: the thermal density stays TRO"},
    unused_field(),
    FieldSpec{.name = "NCYCL",
              .type = FieldType::kInteger,
              .default_value = 1,
              .min_value = 0,
              .unit = "-",
              .description = "thermal steps between assemblies of the conductance (blank or 0: 1)"},
};
constexpr std::array kSolverCards{
    CardSpec{.title = "Card 1", .fields = kSolverCard1, .presence = "required"},
    CardSpec{
        .title = "Card 2", .fields = kSolverCard2, .presence = "optional: defaults when left out"},
    CardSpec{
        .title = "Card 3", .fields = kSolverCard3, .presence = "optional: defaults when left out"},
};

void read_control_thermal_solver(KeywordInput& in) {
  const auto line1 = in.next_line();
  if (!line1) {
    in.fail(in.keyword().line, "", "missing card 1 (ATYPE PTYPE SOLVER CGTOL GPT EQHEAT ...)");
  }
  const CardValues c1 = in.read(kSolverCards[0], *line1);
  model::ControlThermalSolverDesc d;
  d.atype = c1.integer("ATYPE");
  d.ptype = c1.integer("PTYPE");
  d.solver = c1.integer("SOLVER") == 0 ? 11 : c1.integer("SOLVER");
  d.gpt = c1.integer("GPT") == 0 ? 8 : c1.integer("GPT");
  d.eqheat = zero_means(c1.real("EQHEAT"), 1.0);
  d.fwork = c1.real("FWORK");
  d.sbc = c1.real("SBC");
  d.where = in.where(line1->line);
  require_positive(in, line1->line, "EQHEAT", d.eqheat);
  if (has_more_cards(in)) {
    const auto line2 = in.next_line();
    const CardValues c2 = in.read(kSolverCards[1], *line2);
    d.msglvl = c2.integer("MSGLVL");
    d.maxitr = c2.integer("MAXITR") == 0 ? 500 : c2.integer("MAXITR");
    d.abstol = zero_means(c2.real("ABSTOL"), 1e-10);
    d.reltol = zero_means(c2.real("RELTOL"), 1e-6);
    d.omega = c2.real("OMEGA");
    d.tsf = zero_means(c2.real("TSF"), 1.0);  // < 0 stays: -TSF is a curve id
    require_zero(in, line2->line, "OMEGA", d.omega, "the relaxation of solvers 14 and 16");
    require_unused_blank(in, kSolverCards[1], c2, line2->line);
  }
  if (has_more_cards(in)) {
    const auto line3 = in.next_line();
    const CardValues c3 = in.read(kSolverCards[2], *line3);
    d.mxdmp = c3.integer("MXDMP");
    d.dtvf = c3.real("DTVF");
    d.varden = c3.integer("VARDEN");
    d.ncycl = c3.integer("NCYCL") == 0 ? 1 : c3.integer("NCYCL");
    require_zero(in, line3->line, "MXDMP", d.mxdmp, "dumps of the thermal matrix");
    require_unused_blank(in, kSolverCards[2], c3, line3->line);
  }
  store_once(in, in.model().thermal_solver, d);
}

// --- *CONTROL_THERMAL_TIMESTEP
constexpr std::array kTimestepFields{
    FieldSpec{.name = "TS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0 fixed step (ITS), 1 variable step (from ITS, between TMIN and "
                             "TMAX, aiming at DTEMP)",
              .allowed = kZeroOne,
              .allowed_note = "TS takes 0 or 1"},
    FieldSpec{.name = "TIP",
              .type = FieldType::kReal,
              .default_value = 0.5,
              .min_value = 0.0,
              .max_value = 1.0,
              .unit = "-",
              .description = "theta of the implicit step, 0.5 (Crank-Nicolson) to 1 (backward "
                             "Euler); blank or 0: 0.5"},
    FieldSpec{.name = "ITS",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "time",
              .description = "initial (with TS 0: every) thermal step"},
    FieldSpec{.name = "TMIN",
              .type = FieldType::kReal,
              .unit = "time",
              .description = "smallest step (0: the mechanical step); < 0, a curve, is not "
                             "supported"},
    FieldSpec{.name = "TMAX",
              .type = FieldType::kReal,
              .unit = "time",
              .description = "largest step (0: 100 mechanical steps); < 0, a curve, is not "
                             "supported"},
    FieldSpec{.name = "DTEMP",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "temperature",
              .description = "temperature change per step the variable step aims at (blank or "
                             "0: 1); < 0, a curve, is not supported"},
    FieldSpec{.name = "TSCP",
              .type = FieldType::kReal,
              .default_value = 0.5,
              .min_value = 0.0,
              .max_value = 1.0,
              .unit = "-",
              .description = "factor by which a variable step is cut, 0 < TSCP < 1 (blank or 0: "
                             "0.5)",
              .max_exclusive = true},
    FieldSpec{.name = "LCTS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of the thermal step against time: must be 0"},
};
constexpr std::array kTimestepCards{
    CardSpec{.title = "Card 1", .fields = kTimestepFields, .presence = "required"},
};

void read_control_thermal_timestep(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (TS TIP ITS TMIN TMAX DTEMP TSCP LCTS)");
  }
  const CardValues v = in.read(kTimestepCards[0], *line);
  const model::ControlThermalTimestepDesc d{.ts = v.integer("TS"),
                                            .tip = zero_means(v.real("TIP"), 0.5),
                                            .its = v.real("ITS"),
                                            .tmin = v.real("TMIN"),
                                            .tmax = v.real("TMAX"),
                                            .dtemp = zero_means(v.real("DTEMP"), 1.0),
                                            .tscp = zero_means(v.real("TSCP"), 0.5),
                                            .lcts = v.integer("LCTS"),
                                            .where = in.where(line->line)};
  if (d.tip < 0.5) {
    // Below 0.5 the theta method is only conditionally stable: a step set by accuracy (far
    // above the explicit bound) would blow up.
    in.fail(line->line, "TIP",
            fmt::format("TIP = {} is below 0.5: the implicit step is not unconditionally stable "
                        "there; give 0.5 (Crank-Nicolson) to 1 (backward Euler)",
                        d.tip));
  }
  reject_negative_curve(in, line->line, "TMIN", d.tmin, "the smallest step against time");
  reject_negative_curve(in, line->line, "TMAX", d.tmax, "the largest step against time");
  reject_negative_curve(in, line->line, "DTEMP", d.dtemp,
                        "the temperature change per step against time");
  require_zero(in, line->line, "LCTS", d.lcts, "a curve of the thermal step");
  store_once(in, in.model().thermal_timestep, d);
}

// --- *MAT_THERMAL_ISOTROPIC, *MAT_THERMAL_ORTHOTROPIC
constexpr std::array kOrthotropicAopts{0, 2};

constexpr FieldSpec kTmidField{.name = "TMID",
                               .type = FieldType::kInteger,
                               .min_value = 1,
                               .unit = "-",
                               .description = "thermal material id (*PART TMID)",
                               .required = true};
constexpr FieldSpec kTroField{.name = "TRO",
                              .type = FieldType::kReal,
                              .min_value = 0.0,
                              .unit = "mass/length^3",
                              .description =
                                  "thermal density (0: the structural density of "
                                  "the part)"};
constexpr FieldSpec kTgrlcField{.name = "TGRLC",
                                .type = FieldType::kInteger,
                                .unit = "-",
                                .description =
                                    "curve of the heat generation rate against time "
                                    "(0: constant TGMULT); < 0, against temperature, "
                                    "is not supported"};
constexpr FieldSpec kTgmultField{.name = "TGMULT",
                                 .type = FieldType::kReal,
                                 .unit = "power/length^3",
                                 .description =
                                     "heat generation rate per volume, or the "
                                     "multiplier of curve TGRLC"};
constexpr FieldSpec kTlatField{.name = "TLAT",
                               .type = FieldType::kReal,
                               .unit = "temperature",
                               .description = "phase change temperature; kept as written"};
constexpr FieldSpec kHlatField{.name = "HLAT",
                               .type = FieldType::kReal,
                               .unit = "energy/mass",
                               .description = "latent heat: must be 0 (not supported yet)"};
constexpr FieldSpec kHcField{.name = "HC",
                             .type = FieldType::kReal,
                             .min_value = 0.0,
                             .unit = "energy/(mass temperature)",
                             .description = "specific heat, > 0",
                             .required = true};
constexpr FieldSpec conductivity_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kReal,
                   .min_value = 0.0,
                   .unit = "power/(length temperature)",
                   .description = description};
}
constexpr FieldSpec vector_field(std::string_view name, std::string_view unit,
                                 std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kReal, .unit = unit, .description = description};
}

constexpr std::array kIsotropicCard1{kTmidField,   kTroField,  kTgrlcField,
                                     kTgmultField, kTlatField, kHlatField};
constexpr std::array kIsotropicCard2{
    kHcField,
    conductivity_field("TC", "thermal conductivity"),
};
constexpr std::array kIsotropicCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kIsotropicCard1, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kIsotropicCard2, .presence = "required"},
};

constexpr std::array kOrthotropicCard1{
    kTmidField,
    kTroField,
    kTgrlcField,
    kTgmultField,
    FieldSpec{.name = "AOPT",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "material axes: 0 from the element's nodes (a along N1-N2, d along "
                             "N1-N4), 2 global from the vectors A and D",
              .allowed = kOrthotropicAopts,
              .allowed_note = "AOPT 1 (axes from a point P), 3, 4 and coordinate systems (< 0) "
                              "are not supported yet"},
    kTlatField,
    kHlatField,
};
constexpr std::array kOrthotropicCard2{
    kHcField,
    conductivity_field("K1", "thermal conductivity along a"),
    conductivity_field("K2", "thermal conductivity along b"),
    conductivity_field("K3", "thermal conductivity along c"),
};
constexpr std::array kOrthotropicCard3{
    vector_field("XP", "length", "point P (AOPT 1 and 4); kept as written"),
    vector_field("YP", "length", "point P; kept as written"),
    vector_field("ZP", "length", "point P; kept as written"),
    vector_field("A1", "-", "vector A (AOPT 2)"),
    vector_field("A2", "-", "vector A (AOPT 2)"),
    vector_field("A3", "-", "vector A (AOPT 2)"),
};
constexpr std::array kOrthotropicCard4{
    vector_field("D1", "-", "vector D (AOPT 2): with A, the plane of a and b"),
    vector_field("D2", "-", "vector D (AOPT 2)"),
    vector_field("D3", "-", "vector D (AOPT 2)"),
};
constexpr std::array kOrthotropicCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kOrthotropicCard1, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kOrthotropicCard2, .presence = "required"},
    CardSpec{.title = "Card 3",
             .fields = kOrthotropicCard3,
             .presence = "optional: a missing card is read as blank"},
    CardSpec{.title = "Card 4",
             .fields = kOrthotropicCard4,
             .presence = "optional: a missing card is read as blank"},
};

double norm(const std::array<double, 3>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/// Card 1 fields both keywords share; the line is the card's.
void read_thermal_card1(KeywordInput& in, const CardValues& v, int line,
                        model::MatThermalDesc& mat) {
  mat.id = v.integer("TMID");
  mat.density = v.real("TRO");
  mat.tgrlc = v.integer("TGRLC");
  mat.tgmult = v.real("TGMULT");
  mat.tlat = v.real("TLAT");
  mat.hlat = v.real("HLAT");
  mat.where = in.where(line);
  reject_negative_curve(in, line, "TGRLC", mat.tgrlc,
                        "the heat generation rate against temperature");
  require_zero(in, line, "HLAT", mat.hlat, "latent heat of a phase change");
}

void read_mat_thermal_isotropic(KeywordInput& in) {
  const std::span<const CardSpec> cards = kIsotropicCards;
  if (in.option() == "TITLE") {
    // The title names the material in the deck only: nothing downstream shows it.
    in.next_card(cards[0], "title card");
  }
  model::MatThermalDesc mat;
  const auto line1 = in.next_line();
  if (!line1) {
    in.fail(in.keyword().line, "", "missing card 1 (TMID TRO TGRLC TGMULT TLAT HLAT)");
  }
  read_thermal_card1(in, in.read(cards[1], *line1), line1->line, mat);
  const auto line2 = in.next_line();
  if (!line2) {
    in.fail(line1->line, "", "missing card 2 (HC TC)");
  }
  const CardValues c2 = in.read(cards[2], *line2);
  mat.heat_capacity = c2.real("HC");
  const double tc = c2.real("TC");
  mat.conductivity = {tc, tc, tc};
  require_positive(in, line2->line, "HC", mat.heat_capacity);
  in.model().thermal_materials.push_back(mat);
}

void read_mat_thermal_orthotropic(KeywordInput& in) {
  const std::span<const CardSpec> cards = kOrthotropicCards;
  if (in.option() == "TITLE") {
    in.next_card(cards[0], "title card");  // as for the isotropic material: not kept
  }
  model::MatThermalDesc mat;
  mat.orthotropic = true;
  const auto line1 = in.next_line();
  if (!line1) {
    in.fail(in.keyword().line, "", "missing card 1 (TMID TRO TGRLC TGMULT AOPT TLAT HLAT)");
  }
  const CardValues c1 = in.read(cards[1], *line1);
  read_thermal_card1(in, c1, line1->line, mat);
  mat.aopt = static_cast<int>(c1.real("AOPT"));  // a real field in LS-DYNA; 0 or 2 here
  const auto line2 = in.next_line();
  if (!line2) {
    in.fail(line1->line, "", "missing card 2 (HC K1 K2 K3)");
  }
  const CardValues c2 = in.read(cards[2], *line2);
  mat.heat_capacity = c2.real("HC");
  mat.conductivity = {c2.real("K1"), c2.real("K2"), c2.real("K3")};
  require_positive(in, line2->line, "HC", mat.heat_capacity);

  // An error about a vector points at its card, or at the last card read when it is missing.
  int a_line = line2->line;
  if (const auto line3 = in.next_line()) {
    const CardValues c3 = in.read(cards[3], *line3);
    mat.p = {c3.real("XP"), c3.real("YP"), c3.real("ZP")};
    mat.a = {c3.real("A1"), c3.real("A2"), c3.real("A3")};
    a_line = line3->line;
  }
  int d_line = a_line;
  if (const auto line4 = in.next_line()) {
    const CardValues c4 = in.read(cards[4], *line4);
    mat.d = {c4.real("D1"), c4.real("D2"), c4.real("D3")};
    d_line = line4->line;
  }
  if (mat.aopt == 2) {
    const std::array<double, 3> cross{mat.a[1] * mat.d[2] - mat.a[2] * mat.d[1],
                                      mat.a[2] * mat.d[0] - mat.a[0] * mat.d[2],
                                      mat.a[0] * mat.d[1] - mat.a[1] * mat.d[0]};
    if (!(norm(mat.a) > 0.0)) {
      in.fail(a_line, "A1", "AOPT = 2 needs a non-zero vector A (A1 A2 A3, card 3)");
    }
    if (!(norm(cross) > 1.0e-12 * norm(mat.a) * norm(mat.d))) {
      in.fail(d_line, "D1",
              "AOPT = 2 needs a vector D (D1 D2 D3, card 4) that is non-zero and not parallel "
              "to A");
    }
  }
  in.model().thermal_materials.push_back(mat);
}

// --- *BOUNDARY_CONVECTION_SET, *BOUNDARY_FLUX_SET, *BOUNDARY_RADIATION_SET
constexpr FieldSpec kSsidField{.name = "SSID",
                               .type = FieldType::kInteger,
                               .min_value = 1,
                               .unit = "-",
                               .description = "segment set id (*SET_SEGMENT)",
                               .required = true};
constexpr FieldSpec kPserodField{.name = "PSEROD",
                                 .type = FieldType::kInteger,
                                 .unit = "-",
                                 .description =
                                     "part set whose eroded solids expose new "
                                     "segments: must be 0",
                                 .allowed = kZeroOnly,
                                 .allowed_note =
                                     "updating the boundary as solids erode is not "
                                     "supported (plyform has no erosion)"};
constexpr std::array kFaceLocs{-1, 0, 1};
constexpr FieldSpec kLocField{.name = "LOC",
                              .type = FieldType::kInteger,
                              .unit = "-",
                              .description =
                                  "face of thick thermal shells (*CONTROL_SHELL "
                                  "THSHEL 1): -1 bottom, 0 middle, 1 top",
                              .allowed = kFaceLocs};
constexpr FieldSpec curve_field(std::string_view name, std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kInteger, .unit = "-", .description = description};
}
constexpr FieldSpec time_curve_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .unit = "-",
                   .description = description};
}
constexpr FieldSpec mult_field(std::string_view name, std::string_view unit,
                               std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kReal,
                   .default_value = 1.0,
                   .unit = unit,
                   .description = description};
}

constexpr std::array kSetCard1{kSsidField, kPserodField};

constexpr std::array kConvectionCard2{
    curve_field("HLCID",
                "curve of the film coefficient h against time (0: constant HMULT); < 0, "
                "against temperature, is not supported"),
    mult_field("HMULT", "power/(length^2 temperature)",
               "h, or the multiplier of curve HLCID (blank: 1)"),
    time_curve_field("TLCID", "curve of the ambient temperature against time (0: constant TMULT)"),
    mult_field("TMULT", "temperature",
               "the ambient temperature, or the multiplier of curve TLCID (blank: 1)"),
    kLocField,
};
constexpr std::array kConvectionCards{
    CardSpec{.title = "Card 1",
             .fields = kSetCard1,
             .presence = "required; cards 1 and 2 repeat for more sets until the next keyword"},
    CardSpec{.title = "Card 2", .fields = kConvectionCard2, .presence = "required"},
};

constexpr FieldSpec node_mult_field(std::string_view name, std::string_view description) {
  return mult_field(name, "power/length^2", description);
}
constexpr std::array kFluxCard2{
    curve_field("LCID",
                "curve of the flux against time (0: the constants MLC1..MLC4); < 0, "
                "against temperature, is not supported"),
    node_mult_field("MLC1",
                    "flux (positive into the body) or curve multiplier at node N1 of "
                    "each segment (blank: 1)"),
    node_mult_field("MLC2", "the same at node N2 (blank: 1)"),
    node_mult_field("MLC3", "the same at node N3 (blank: 1)"),
    node_mult_field("MLC4", "the same at node N4 (blank: 1)"),
    kLocField,
    FieldSpec{.name = "NHISV",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "history variables of a user flux subroutine: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "NHISV > 0 calls a user flux subroutine, which plyform does not "
                              "have (so there is no card 3 of history values)"},
    unused_field(),
};
constexpr std::array kFluxCards{
    CardSpec{.title = "Card 1",
             .fields = kSetCard1,
             .presence = "required; cards 1 and 2 repeat for more sets until the next keyword"},
    CardSpec{.title = "Card 2", .fields = kFluxCard2, .presence = "required"},
};

constexpr std::array kRadiationCard1{
    kSsidField,
    FieldSpec{.name = "TYPE",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "1: radiation to the environment",
              .allowed = kOneOnly,
              .allowed_note = "radiation in an enclosure (TYPE 2, with view factors) is not "
                              "supported yet"},
    unused_field(),
    unused_field(),
    unused_field(),
    unused_field(),
    kPserodField,
};
constexpr std::array kRadiationCard2{
    curve_field("RFLCID",
                "curve of the radiation factor f against time (0: constant RFMULT); < 0, "
                "against temperature, is not supported"),
    mult_field("RFMULT", "power/(length^2 temperature^4)",
               "f (emissivity x Stefan-Boltzmann constant), or the multiplier of curve RFLCID "
               "(blank: 1)"),
    time_curve_field("TILCID",
                     "curve of the ambient temperature against time (0: constant TIMULT)"),
    mult_field("TIMULT", "temperature",
               "the ambient temperature (absolute), or the multiplier of curve TILCID (blank: "
               "1)"),
    kLocField,
};
constexpr std::array kRadiationCards{
    CardSpec{.title = "Card 1",
             .fields = kRadiationCard1,
             .presence = "required; cards 1 and 2 repeat for more sets until the next keyword"},
    CardSpec{.title = "Card 2", .fields = kRadiationCard2, .presence = "required"},
};

/// Reads the pairs of cards 1 and 2 up to the next keyword; fill_card2 reads card 2's fields
/// into the boundary.
template <typename FillCard2>
void read_heat_boundaries(KeywordInput& in, model::HeatBoundaryKind kind,
                          std::span<const CardSpec> cards, std::string_view card2_fields,
                          FillCard2 fill_card2) {
  bool any = false;
  while (const auto line1 = in.next_nonblank_line()) {
    const CardValues c1 = in.read(cards[0], *line1);
    require_unused_blank(in, cards[0], c1, line1->line);
    model::HeatBoundaryDesc b;
    b.kind = kind;
    b.segment_set_id = c1.integer("SSID");
    b.pserod = c1.integer("PSEROD");
    if (kind == model::HeatBoundaryKind::kRadiation) {
      b.type = c1.integer("TYPE");
    }
    const auto line2 = in.next_line();
    if (!line2) {
      in.fail(line1->line, "", fmt::format("missing card 2 ({}) after card 1", card2_fields));
    }
    const CardValues c2 = in.read(cards[1], *line2);
    require_unused_blank(in, cards[1], c2, line2->line);
    b.loc = c2.integer("LOC");
    b.where = in.where(line2->line);
    fill_card2(c2, line2->line, b);
    in.model().heat_boundaries.push_back(b);
    any = true;
  }
  if (!any) {
    in.fail(in.keyword().line, "", "missing card 1 (SSID ...)");
  }
}

void read_boundary_convection_set(KeywordInput& in) {
  read_heat_boundaries(
      in, model::HeatBoundaryKind::kConvection, kConvectionCards, "HLCID HMULT TLCID TMULT LOC",
      [&](const CardValues& v, int line, model::HeatBoundaryDesc& b) {
        b.curve_id = v.integer("HLCID");
        b.mult = v.real("HMULT");
        b.ambient_curve_id = v.integer("TLCID");
        b.ambient_mult = v.real("TMULT");
        reject_negative_curve(in, line, "HLCID", b.curve_id, "h against temperature");
      });
}

void read_boundary_flux_set(KeywordInput& in) {
  read_heat_boundaries(
      in, model::HeatBoundaryKind::kFlux, kFluxCards, "LCID MLC1 MLC2 MLC3 MLC4 LOC NHISV",
      [&](const CardValues& v, int line, model::HeatBoundaryDesc& b) {
        b.curve_id = v.integer("LCID");
        b.node_mult = {v.real("MLC1"), v.real("MLC2"), v.real("MLC3"), v.real("MLC4")};
        b.nhisv = v.integer("NHISV");
        reject_negative_curve(in, line, "LCID", b.curve_id, "the flux against temperature");
      });
}

void read_boundary_radiation_set(KeywordInput& in) {
  read_heat_boundaries(
      in, model::HeatBoundaryKind::kRadiation, kRadiationCards, "RFLCID RFMULT TILCID TIMULT LOC",
      [&](const CardValues& v, int line, model::HeatBoundaryDesc& b) {
        b.curve_id = v.integer("RFLCID");
        b.mult = v.real("RFMULT");
        b.ambient_curve_id = v.integer("TILCID");
        b.ambient_mult = v.real("TIMULT");
        reject_negative_curve(in, line, "RFLCID", b.curve_id, "f against temperature");
      });
}

}  // namespace

KeywordSpec control_solution_keyword() {
  return {.name = "CONTROL_SOLUTION",
          .options = kNoOptions,
          .handler = read_control_solution,
          .cards = kSolutionCards,
          .summary =
              "The analysis: SOLN 1 or 2 computes the temperatures of the parts with a thermal "
              "material (*PART TMID; docs/thermal.md), SOLN 0 (or no *CONTROL_SOLUTION) leaves "
              "them as prescribed. Given twice, the last one is used (with a warning)."};
}

KeywordSpec control_thermal_solver_keyword() {
  return {.name = "CONTROL_THERMAL_SOLVER",
          .options = kNoOptions,
          .handler = read_control_thermal_solver,
          .cards = kSolverCards,
          .summary =
              "The thermal analysis: steady or transient (ATYPE), linear only (PTYPE 0), the "
              "direct (11) or conjugate-gradient (12) solver with its tolerances, and the "
              "thermal speed-up factor TSF. Cards 2 and 3 may be left out. Without this "
              "keyword a SOLN 1 or 2 analysis is transient with the defaults. Given twice, "
              "the last one is used (with a warning)."};
}

KeywordSpec control_thermal_timestep_keyword() {
  return {.name = "CONTROL_THERMAL_TIMESTEP",
          .options = kNoOptions,
          .handler = read_control_thermal_timestep,
          .cards = kTimestepCards,
          .summary =
              "The implicit thermal step: theta (TIP), its length ITS, and with TS 1 a "
              "variable step between TMIN and TMAX. Curves of the step (LCTS, negative TMIN, "
              "TMAX, DTEMP) are not supported. Given twice, the last one is used (with a "
              "warning)."};
}

KeywordSpec mat_thermal_isotropic_keyword() {
  return {.name = "MAT_THERMAL_ISOTROPIC",
          .options = kNoneOrTitle,
          .handler = read_mat_thermal_isotropic,
          .cards = kIsotropicCards,
          .summary =
              "An isotropic thermal material (thermal material type 1) for *PART TMID: "
              "density, specific heat, conductivity and a heat generation rate. Latent heat "
              "(HLAT) and a generation rate against temperature (TGRLC < 0) are not "
              "supported."};
}

KeywordSpec mat_thermal_orthotropic_keyword() {
  return {.name = "MAT_THERMAL_ORTHOTROPIC",
          .options = kNoneOrTitle,
          .handler = read_mat_thermal_orthotropic,
          .cards = kOrthotropicCards,
          .summary =
              "An orthotropic thermal material (thermal material type 2): conductivities K1, "
              "K2, K3 along material axes a, b, c from the element (AOPT 0) or from the "
              "global vectors A and D (AOPT 2). Other axis options, latent heat and a "
              "generation rate against temperature are not supported."};
}

KeywordSpec boundary_convection_set_keyword() {
  return {.name = "BOUNDARY_CONVECTION_SET",
          .options = kNoOptions,
          .handler = read_boundary_convection_set,
          .cards = kConvectionCards,
          .summary =
              "Convection on the segments of a segment set: q = h (T_inf - T), h = HMULT x "
              "curve HLCID(t), T_inf = TMULT x curve TLCID(t) (a curve id 0: the multiplier "
              "alone). A film coefficient against temperature (HLCID < 0) is not supported."};
}

KeywordSpec boundary_flux_set_keyword() {
  return {.name = "BOUNDARY_FLUX_SET",
          .options = kNoOptions,
          .handler = read_boundary_flux_set,
          .cards = kFluxCards,
          .summary =
              "A heat flux into the segments of a segment set, MLCi x curve LCID(t) at node i "
              "of each segment (LCID 0: MLCi alone), positive into the body. Fluxes against "
              "temperature (LCID < 0) and user flux subroutines (NHISV) are not supported."};
}

KeywordSpec boundary_radiation_set_keyword() {
  return {.name = "BOUNDARY_RADIATION_SET",
          .options = kNoOptions,
          .handler = read_boundary_radiation_set,
          .cards = kRadiationCards,
          .summary =
              "Radiation of the segments of a segment set to the environment (TYPE 1): q = f "
              "(T_inf^4 - T^4), f = RFMULT x curve RFLCID(t), T_inf = TIMULT x curve "
              "TILCID(t), in absolute temperatures. Enclosure radiation (TYPE 2) and f against "
              "temperature (RFLCID < 0) are not supported."};
}

}  // namespace plyform::keyword
