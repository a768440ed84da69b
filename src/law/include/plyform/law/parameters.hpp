#pragma once
// Parameters of the interlayer contact law (docs/contact-law.md). Consistent units, as in
// LS-DYNA: e.g. mm, tonne, s, N, MPa, K.

#include <limits>
#include <vector>

#include "plyform/law/curve.hpp"

namespace plyform::law {

/// A parameter that depends on temperature: `lo` at and below T_lo, `hi` at and above T_hi,
/// with the C1 cubic transition s^2 (3 - 2 s) between; or, when `curve >= 0`, the curve of that
/// index in `Parameters::curves` (value against temperature).
struct TemperatureDependent {
  double lo = 0.0;
  double hi = 0.0;
  int curve = -1;  ///< index into Parameters::curves, -1 for the two-region form
};

enum class FrictionModel : int {
  coulomb = 0,       ///< |tau| <= mu(T) P, elastic predictor / return mapping
  hydrodynamic = 1,  ///< Newtonian film: tau = eta_f(T) v / h_f
};

enum class FrictionCoupling : int {
  additive = 0,  ///< the paper: friction acts on top of the cohesive normal law
  rccm = 1,      ///< original RCCM: mu (1 - beta), no friction while fully bonded
};

/// Everything the law needs, validated by `validate()` (or built from the deck constants by
/// `from_user_constants`). Plain data: copy it freely.
struct Parameters {
  double cn = 0.0;                 ///< C_N, cohesive normal stiffness [stress/length]
  TemperatureDependent sigma_max;  ///< peak cohesive tension [stress]
  double t_lo = 0.0;               ///< lower transition temperature [temperature]
  double t_hi = 0.0;               ///< upper transition temperature [temperature]
  double eta = 0.0;                ///< viscosity of the adhesion evolution [stress*length*time]
  TemperatureDependent zeta;       ///< re-healing rate [1/(stress*time)]
  double beta0 = 1.0;              ///< beta of initially bonded nodes and at first contact [-]
  double bond_tol = 0.0;           ///< gap within which a node is bonded at t = 0 [length]
  FrictionModel friction = FrictionModel::coulomb;
  TemperatureDependent mu;              ///< Coulomb coefficient (static when decay is on) [-]
  TemperatureDependent film_viscosity;  ///< eta_f of the molten film [stress*time]
  double film_thickness = 0.0;          ///< h_f [length]
  double vdc = 0.0;                     ///< normal damping, percent of critical [-]
  double beta_min = 1.0e-3;             ///< below it a node is fully debonded [-]
  double ct = 0.0;  ///< C_T, tangential adhesion stiffness (mixed mode) [stress/length]
  FrictionCoupling coupling = FrictionCoupling::additive;
  double decay_dc = 0.0;       ///< DC: mu = mu_s (r + (1 - r) exp(-DC |v|)) [time/length]
  double dynamic_ratio = 1.0;  ///< r = FD / FS of that decay [-]
  /// Upper bound of the Coulomb traction (LS-DYNA's VC, a viscous friction limit) [stress];
  /// 0: none. Set by the contact host, not a user constant.
  double friction_limit = 0.0;
  /// Gap beyond which a bonded node is released (the host's capture distance) [length].
  double release_gap = std::numeric_limits<double>::infinity();
  std::vector<Curve> curves;  ///< tables referenced by TemperatureDependent::curve
};

/// omega = sigma_max^2 / C_N: the adhesion energy per area (paper eq. 6).
[[nodiscard]] inline double adhesion_energy(double sigma_max, double cn) {
  return sigma_max * sigma_max / cn;
}

/// The C1 cubic blend of the two-region form, s in [0, 1] -> [0, 1].
[[nodiscard]] inline double cubic_transition(double s) {
  return s * s * (3.0 - 2.0 * s);
}

/// Evaluates a temperature-dependent parameter.
[[nodiscard]] inline double evaluate(const TemperatureDependent& p, const Parameters& params,
                                     double temperature) {
  if (p.curve >= 0)
    return params.curves[static_cast<std::size_t>(p.curve)](temperature);
  if (temperature <= params.t_lo)
    return p.lo;
  if (temperature >= params.t_hi)
    return p.hi;
  const double s = (temperature - params.t_lo) / (params.t_hi - params.t_lo);
  return p.lo + (p.hi - p.lo) * cubic_transition(s);
}

}  // namespace plyform::law
