#include "plyform/law/user_constants.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace plyform::law {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Index constants, so the conversion below reads by name.
enum Uc : int {
  kModel = 1,
  kCn,
  kSmaxLo,
  kSmaxHi,
  kTLo,
  kTHi,
  kEta,
  kZetaLo,
  kZetaHi,
  kBeta0,
  kBondTol,
  kFric,
  kMuLo,
  kMuHi,
  kViscLo,
  kViscHi,
  kFilmH,
  kVdc,
  kBetaMin,
  kCt,
  kCoupling,
  kDc,
  kFdRatio,
  kGRelease,
  kCount = kGRelease
};

// clang-format off
constexpr std::array<ConstantSpec, kCount> kTable{{
  {kModel,   "MODEL",    "-",                  "1 = RCCM cohesive law with re-healing",                 1.0,  false, 0,       1.0, 1.0,  false, true,  false},
  {kCn,      "CN",       "stress/length",      "cohesive normal stiffness C_N",                         0.0,  true,  0,       0.0, kInf, true,  false, false},
  {kSmaxLo,  "SMAX_LO",  "stress",             "peak cohesive tension sigma_max at and below T_LO",     0.0,  true,  0,       0.0, kInf, true,  false, true},
  {kSmaxHi,  "SMAX_HI",  "stress",             "sigma_max at and above T_HI (default SMAX_LO)",         0.0,  false, kSmaxLo, 0.0, kInf, true,  false, true},
  {kTLo,     "T_LO",     "temperature",        "lower temperature of the cubic transition",             0.0,  false, 0,      -kInf, kInf, false, false, false},
  {kTHi,     "T_HI",     "temperature",        "upper temperature of the transition (default T_LO)",    0.0,  false, kTLo,   -kInf, kInf, false, false, false},
  {kEta,     "ETA",      "stress*length*time", "viscosity eta of the adhesion evolution",               0.0,  true,  0,       0.0, kInf, true,  false, false},
  {kZetaLo,  "ZETA_LO",  "1/(stress*time)",    "re-healing rate zeta at and below T_LO (0: none)",      0.0,  false, 0,       0.0, kInf, false, false, true},
  {kZetaHi,  "ZETA_HI",  "1/(stress*time)",    "zeta at and above T_HI (default ZETA_LO)",              0.0,  false, kZetaLo, 0.0, kInf, false, false, true},
  {kBeta0,   "BETA0",    "-",                  "beta of initially bonded nodes and at first contact",   1.0,  false, 0,       0.0, 1.0,  false, false, false},
  {kBondTol, "BOND_TOL", "length",             "gap tolerance for initial bonding at t = 0 (0: none)",  0.0,  false, 0,       0.0, kInf, false, false, false},
  {kFric,    "FRIC",     "-",                  "tangential law: 0 = Coulomb, 1 = hydrodynamic film",    0.0,  false, 0,       0.0, 1.0,  false, true,  false},
  {kMuLo,    "MU_LO",    "-",                  "Coulomb coefficient at and below T_LO",                 0.0,  false, 0,       0.0, kInf, false, false, true},
  {kMuHi,    "MU_HI",    "-",                  "Coulomb coefficient at and above T_HI (default MU_LO)", 0.0,  false, kMuLo,   0.0, kInf, false, false, true},
  {kViscLo,  "VISC_LO",  "stress*time",        "film viscosity at and below T_LO (hydrodynamic)",       0.0,  false, 0,       0.0, kInf, false, false, true},
  {kViscHi,  "VISC_HI",  "stress*time",        "film viscosity at and above T_HI (default VISC_LO)",    0.0,  false, kViscLo, 0.0, kInf, false, false, true},
  {kFilmH,   "FILM_H",   "length",             "film thickness h_f (required when FRIC = 1)",           0.0,  false, 0,       0.0, kInf, false, false, false},
  {kVdc,     "VDC",      "percent",            "normal damping in percent of critical",                 0.0,  false, 0,       0.0, 100.0, false, false, false},
  {kBetaMin, "BETA_MIN", "-",                  "beta below which a node is fully debonded",             1e-3, false, 0,       0.0, 1.0,  true,  false, false},
  {kCt,      "CT",       "stress/length",      "tangential adhesion stiffness C_T, mixed mode (0: off)", 0.0, false, 0,       0.0, kInf, false, false, false},
  {kCoupling,"COUPLING", "-",                  "friction: 0 = on top of cohesion, 1 = RCCM mu (1 - beta)", 0.0, false, 0,     0.0, 1.0,  false, true,  false},
  {kDc,      "DC",       "time/length",        "static-dynamic decay: mu = mu_s (r + (1 - r) exp(-DC v))", 0.0, false, 0,     0.0, kInf, false, false, false},
  {kFdRatio, "FD_RATIO", "-",                  "r = dynamic / static coefficient of that decay",        1.0,  false, 0,       0.0, kInf, false, false, false},
  {kGRelease,"G_RELEASE","length",             "gap beyond which a bonded node is released (0: never)", 0.0,  false, 0,       0.0, kInf, false, false, false},
}};
// clang-format on

std::string number(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

std::string describe_range(const ConstantSpec& s) {
  std::ostringstream os;
  if (s.integer && s.min == s.max) {
    os << "the value " << s.min;
    return os.str();
  }
  if (s.integer) {
    os << "a whole number from " << s.min << " to " << s.max;
    return os.str();
  }
  const bool has_min = std::isfinite(s.min);
  const bool has_max = std::isfinite(s.max);
  if (has_min && has_max) {
    os << (s.min_open ? "greater than " : "from ") << s.min
       << (s.min_open ? " and at most " : " to ") << s.max;
  } else if (has_min) {
    os << (s.min_open ? "greater than " : "at least ") << s.min;
  } else if (has_max) {
    os << "at most " << s.max;
  } else {
    os << "any finite number";
  }
  return os.str();
}

ConstantError make_error(const ConstantSpec& s, double value, const std::string& what) {
  std::ostringstream os;
  os << "constant UC" << s.index << " " << s.name << " = " << number(value) << ": " << what;
  return ConstantError{s.index, s.name, value, os.str()};
}

bool in_range(const ConstantSpec& s, double v) {
  if (!std::isfinite(v))
    return false;
  if (s.min_open ? !(v > s.min) : !(v >= s.min))
    return false;
  if (v > s.max)
    return false;
  if (s.integer && v != std::floor(v))
    return false;
  return true;
}

}  // namespace

std::span<const ConstantSpec> user_constant_table() {
  return kTable;
}

FromConstantsResult from_user_constants(std::span<const std::optional<double>> uc,
                                        std::span<const Curve> curves) {
  FromConstantsResult result;
  Parameters& p = result.parameters;
  if (uc.size() > kTable.size()) {
    std::ostringstream os;
    os << "NOC = " << uc.size() << " constants given, the law has " << kTable.size()
       << " (UC1 to UC" << kTable.size() << ")";
    result.errors.push_back({0, "NOC", static_cast<double>(uc.size()), os.str()});
  }

  // Resolve values: given, default_from, or default; check ranges and curve references.
  std::array<double, kCount + 1> v{};
  std::array<bool, kCount + 1> given{};
  std::array<int, kCount + 1> curve_index{};
  curve_index.fill(-1);
  for (const ConstantSpec& s : kTable) {
    const auto i = static_cast<std::size_t>(s.index);
    const bool present = i - 1 < uc.size() && uc[i - 1].has_value();
    given[i] = present;
    if (!present) {
      if (s.required) {
        result.errors.push_back(ConstantError{
            s.index, s.name, 0.0,
            std::string("constant UC") + std::to_string(s.index) + " " + s.name + " is required (" +
                s.meaning + ", " + describe_range(s) + ") but was not given"});
        v[i] = s.default_value;
      } else if (s.default_from > 0) {
        v[i] = v[static_cast<std::size_t>(s.default_from)];
        curve_index[i] = curve_index[static_cast<std::size_t>(s.default_from)];
      } else {
        v[i] = s.default_value;
      }
      continue;
    }
    const double value = *uc[i - 1];
    v[i] = value;
    if (s.temperature_dependent && value < 0.0 && std::isfinite(value)) {
      const double id = -value;
      if (id != std::floor(id)) {
        result.errors.push_back(make_error(
            s, value, "a negative value selects a load curve and must be -N, N a curve id"));
        continue;
      }
      int found = -1;
      for (std::size_t c = 0; c < curves.size(); ++c) {
        if (curves[c].id() == static_cast<int>(id))
          found = static_cast<int>(c);
      }
      if (found < 0) {
        result.errors.push_back(make_error(s, value,
                                           "refers to load curve " +
                                               std::to_string(static_cast<long>(id)) +
                                               ", which is not defined"));
        continue;
      }
      if (const std::string why = curves[static_cast<std::size_t>(found)].validate();
          !why.empty()) {
        result.errors.push_back(make_error(
            s, value,
            "load curve " + std::to_string(static_cast<long>(id)) + " is unusable: " + why));
        continue;
      }
      curve_index[i] = found;
      continue;
    }
    if (!in_range(s, value)) {
      result.errors.push_back(make_error(s, value, "expected " + describe_range(s)));
    }
  }

  // The two slots of a temperature-dependent pair must agree on their form.
  const auto pair = [&](Uc lo, Uc hi, TemperatureDependent& out) {
    const auto l = static_cast<std::size_t>(lo);
    const auto h = static_cast<std::size_t>(hi);
    if (curve_index[l] >= 0 || curve_index[h] >= 0) {
      if (given[h] && curve_index[h] != curve_index[l] && !(v[h] == 0.0 && curve_index[l] >= 0)) {
        result.errors.push_back(
            make_error(kTable[h - 1], v[h],
                       std::string("must be blank, 0 or the same curve as ") + kTable[l - 1].name +
                           " when either of the pair is given by a load curve"));
      }
      out.curve = curve_index[l] >= 0 ? curve_index[l] : curve_index[h];
    }
    out.lo = v[l];
    out.hi = v[h];
  };

  std::vector<int> used_curves;  // indices into `curves`, copied into the parameters below
  TemperatureDependent smax, zeta, mu, visc;
  pair(kSmaxLo, kSmaxHi, smax);
  pair(kZetaLo, kZetaHi, zeta);
  pair(kMuLo, kMuHi, mu);
  pair(kViscLo, kViscHi, visc);
  for (TemperatureDependent* t : {&smax, &zeta, &mu, &visc}) {
    if (t->curve < 0)
      continue;
    int local = -1;
    for (std::size_t k = 0; k < used_curves.size(); ++k) {
      if (used_curves[k] == t->curve)
        local = static_cast<int>(k);
    }
    if (local < 0) {
      local = static_cast<int>(used_curves.size());
      used_curves.push_back(t->curve);
      p.curves.push_back(curves[static_cast<std::size_t>(t->curve)]);
    }
    t->curve = local;
  }

  p.cn = v[kCn];
  p.sigma_max = smax;
  p.t_lo = v[kTLo];
  p.t_hi = v[kTHi];
  p.eta = v[kEta];
  p.zeta = zeta;
  p.beta0 = v[kBeta0];
  p.bond_tol = v[kBondTol];
  p.friction = static_cast<FrictionModel>(static_cast<int>(v[kFric]));
  p.mu = mu;
  p.film_viscosity = visc;
  p.film_thickness = v[kFilmH];
  p.vdc = v[kVdc];
  p.beta_min = v[kBetaMin];
  p.ct = v[kCt];
  p.coupling = static_cast<FrictionCoupling>(static_cast<int>(v[kCoupling]));
  p.decay_dc = v[kDc];
  p.dynamic_ratio = v[kFdRatio];
  p.release_gap = v[kGRelease] > 0.0 ? v[kGRelease] : std::numeric_limits<double>::infinity();

  // Cross checks between constants.
  const auto two_region_differs = [](const TemperatureDependent& t) {
    return t.curve < 0 && t.lo != t.hi;
  };
  if (p.t_hi < p.t_lo) {
    result.errors.push_back(
        make_error(kTable[kTHi - 1], p.t_hi, "must not be below T_LO = " + number(p.t_lo)));
  } else if (p.t_hi == p.t_lo && (two_region_differs(smax) || two_region_differs(zeta) ||
                                  two_region_differs(mu) || two_region_differs(visc))) {
    result.errors.push_back(
        make_error(kTable[kTHi - 1], p.t_hi,
                   "must be greater than T_LO when a parameter has different _LO and _HI values"));
  }
  if (p.friction == FrictionModel::hydrodynamic && given[kFric] && !(p.film_thickness > 0.0)) {
    result.errors.push_back(make_error(kTable[kFilmH - 1], p.film_thickness,
                                       "must be greater than 0 when FRIC = 1 (hydrodynamic)"));
  }
  return result;
}

std::vector<std::optional<double>> to_user_constants(const Parameters& p) {
  const auto slot = [&](const TemperatureDependent& t, bool hi) -> double {
    if (t.curve >= 0 && static_cast<std::size_t>(t.curve) < p.curves.size()) {
      return -static_cast<double>(p.curves[static_cast<std::size_t>(t.curve)].id());
    }
    return hi ? t.hi : t.lo;
  };
  std::vector<std::optional<double>> uc(kCount);
  uc[kModel - 1] = 1.0;
  uc[kCn - 1] = p.cn;
  uc[kSmaxLo - 1] = slot(p.sigma_max, false);
  uc[kSmaxHi - 1] = slot(p.sigma_max, true);
  uc[kTLo - 1] = p.t_lo;
  uc[kTHi - 1] = p.t_hi;
  uc[kEta - 1] = p.eta;
  uc[kZetaLo - 1] = slot(p.zeta, false);
  uc[kZetaHi - 1] = slot(p.zeta, true);
  uc[kBeta0 - 1] = p.beta0;
  uc[kBondTol - 1] = p.bond_tol;
  uc[kFric - 1] = static_cast<double>(static_cast<int>(p.friction));
  uc[kMuLo - 1] = slot(p.mu, false);
  uc[kMuHi - 1] = slot(p.mu, true);
  uc[kViscLo - 1] = slot(p.film_viscosity, false);
  uc[kViscHi - 1] = slot(p.film_viscosity, true);
  uc[kFilmH - 1] = p.film_thickness;
  uc[kVdc - 1] = p.vdc;
  uc[kBetaMin - 1] = p.beta_min;
  uc[kCt - 1] = p.ct;
  uc[kCoupling - 1] = static_cast<double>(static_cast<int>(p.coupling));
  uc[kDc - 1] = p.decay_dc;
  uc[kFdRatio - 1] = p.dynamic_ratio;
  uc[kGRelease - 1] = std::isfinite(p.release_gap) ? p.release_gap : 0.0;
  return uc;
}

std::vector<ConstantError> validate(const Parameters& p) {
  return from_user_constants(to_user_constants(p), p.curves).errors;
}

}  // namespace plyform::law
