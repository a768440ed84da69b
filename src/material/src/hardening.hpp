#pragma once
// Isotropic hardening laws as small value types (the kernels are templates on them, so the law is
// chosen once per block), and the scalar return-mapping solvers of J2 plasticity shared by the
// solid (3D) and shell (plane-stress) updates. Private to plyform_material.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "plyform/core/material.hpp"

namespace plyform::material::detail {

/// sigma_y = sigy + hp eps_p.
struct LinearHardening {
  double sigy;
  double hp;
  [[nodiscard]] double value(double e) const { return sigy + hp * e; }
  [[nodiscard]] double slope(double /*e*/) const { return hp; }
};

/// A hardening law scaled by a factor k (a point's Cowper-Symonds factor).
template <class H>
struct ScaledHardening {
  H h;
  double k;
  [[nodiscard]] double value(double e) const { return k * h.value(e); }
  [[nodiscard]] double slope(double e) const { return k * h.slope(e); }
};

/// Piecewise linear (x_i, y_i), i < n, extrapolated with the end slopes; n = 1 is constant.
struct TabulatedHardening {
  const double* x;
  const double* y;
  std::size_t n;
  // Segment i with x_i <= e < x_{i+1}, clamped to [0, n - 2].
  [[nodiscard]] std::size_t segment(double e) const {
    const std::size_t j = static_cast<std::size_t>(std::upper_bound(x, x + n, e) - x);
    const std::size_t i = j == 0 ? 0 : j - 1;
    return std::min(i, n - 2);
  }
  [[nodiscard]] double value(double e) const {
    if (n == 1)
      return y[0];
    const std::size_t i = segment(e);
    return y[i] + (y[i + 1] - y[i]) / (x[i + 1] - x[i]) * (e - x[i]);
  }
  [[nodiscard]] double slope(double e) const {
    if (n == 1)
      return 0.0;
    const std::size_t i = segment(e);
    return (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  }
};

/// A hardening law scaled by k, as its own type: a linear law stays linear (the shells' batched
/// return takes it), any other is wrapped.
inline LinearHardening scaled(const LinearHardening& h, double k) {
  return {k * h.sigy, k * h.hp};
}
template <class H>
ScaledHardening<H> scaled(const H& h, double k) {
  return {h, k};
}

/// Two yield curves of a table by strain rate (*MAT_024's LCSS naming a *DEFINE_TABLE) and the
/// weight w of the second at a point's rate: linear in the rate between them.
struct RateTableHardening {
  TabulatedHardening lo, hi;
  double w;
  [[nodiscard]] double value(double e) const {
    return w == 0.0 ? lo.value(e) : (1.0 - w) * lo.value(e) + w * hi.value(e);
  }
  [[nodiscard]] double slope(double e) const {
    return w == 0.0 ? lo.slope(e) : (1.0 - w) * lo.slope(e) + w * hi.slope(e);
  }
};

/// The yield curves of *MAT_024's rate table around an effective strain rate (1/time): the
/// table's values are rates, or their natural logarithms when the first is negative; below the
/// first value the first curve, above the last the last.
inline RateTableHardening rate_table_at(const core::PiecewiseLinearPlasticity& m, double rate) {
  const auto tabulated = [&](std::size_t i) {
    const core::HardeningCurve& c = m.rate_curves[i];
    return TabulatedHardening{c.plastic_strain.data(), c.yield_stress.data(),
                              std::min(c.plastic_strain.size(), c.yield_stress.size())};
  };
  const std::vector<double>& v = m.rate_values;
  const double x = m.log_rates ? (rate > 0.0 ? std::log(rate) : -1e300) : rate;
  if (v.size() == 1 || x <= v.front())
    return {tabulated(0), tabulated(0), 0.0};
  if (x >= v.back())
    return {tabulated(v.size() - 1), tabulated(v.size() - 1), 0.0};
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), x) - v.begin()) - 1;
  return {tabulated(i), tabulated(i + 1), (x - v[i]) / (v[i + 1] - v[i])};
}

/// sigma_y = k (e0 + eps_p)^n.
struct PowerHardening {
  double k;
  double n;
  double e0;
  [[nodiscard]] double value(double e) const { return k * std::pow(e0 + e, n); }
  [[nodiscard]] double slope(double e) const { return n * k * std::pow(e0 + e, n - 1.0); }
};

/// sigma_y = a - b exp(-c eps_p) (Voce).
struct VoceHardening {
  double a;
  double b;
  double c;
  [[nodiscard]] double value(double e) const { return a - b * std::exp(-c * e); }
  [[nodiscard]] double slope(double e) const { return b * c * std::exp(-c * e); }
};

/// Calls f with the hardening rule HR of the sheet-metal laws (*MAT_036, *MAT_122).
template <class F>
decltype(auto) with_hardening(const core::SheetHardening& m, F&& f) {
  using Rule = core::SheetHardening::Rule;
  switch (m.rule) {
    case Rule::kSwift:
      return f(PowerHardening{m.k, m.n, m.e0});
    case Rule::kCurve: {
      const auto& c = m.curve;
      return f(TabulatedHardening{c.plastic_strain.data(), c.yield_stress.data(),
                                  std::min(c.plastic_strain.size(), c.yield_stress.size())});
    }
    case Rule::kVoce:
      return f(VoceHardening{m.a, m.b, m.c});
    case Rule::kLinear:
      break;
  }
  return f(LinearHardening{m.sigy, m.hp});
}

/// Calls f with the hardening of *MAT_024: the curve when it has points, else bilinear with
/// E_p = E ETAN / (E - ETAN). The block's law is chosen here, once.
template <class F>
decltype(auto) with_hardening(const core::PiecewiseLinearPlasticity& m, F&& f) {
  const auto& c = m.curve;
  const std::size_t n = std::min(c.plastic_strain.size(), c.yield_stress.size());
  if (n > 0)
    return f(TabulatedHardening{c.plastic_strain.data(), c.yield_stress.data(), n});
  return f(LinearHardening{m.sigy, m.young * m.etan / (m.young - m.etan)});
}

/// Calls f with the hardening of *MAT_018.
template <class F>
decltype(auto) with_hardening(const core::PowerLawPlasticity& m, F&& f) {
  const double e0 =
      m.sigy > 0.0 ? std::pow(m.sigy / m.k, 1.0 / m.n) : std::pow(m.young / m.k, 1.0 / (m.n - 1.0));
  return f(PowerHardening{m.k, m.n, e0});
}

/// Root of a decreasing scalar function r on [lo, hi] with r(lo) > 0 >= r(hi): Newton from x0
/// (lo by default), falling back to bisection whenever a step leaves the bracket (kinks of
/// piecewise curves). f(x, r, dr) evaluates r(x) and r'(x). Stops when |r| <= tol, when the
/// bracket is at round-off, or after a step shorter than step_tol, returning the stepped-to point
/// unevaluated: a Newton step that short leaves an error of the order of its square, and a
/// bisection step one below its length.
template <class F>
double solve_decreasing(F&& f, double lo, double hi, double tol, double step_tol = 0.0,
                        double x0 = -1.0) {
  double x = x0 > lo && x0 < hi ? x0 : lo;
  for (int it = 0; it < 200; ++it) {
    double r = 0.0, dr = 0.0;
    f(x, r, dr);
    if (std::abs(r) <= tol)
      return x;
    if (r > 0.0)
      lo = x;
    else
      hi = x;
    double xn = x - r / dr;
    if (!(xn > lo && xn < hi))
      xn = 0.5 * (lo + hi);
    if (hi - lo <= 4e-16 * hi || std::abs(xn - x) <= std::max(step_tol, 1e-16 * x))
      return xn;  // bracket, or a step, at the accuracy asked for
    x = xn;
  }
  return x;
}

/// 3D radial return: dlam >= 0 with q_tr - 3 G dlam = sigma_y(e_n + dlam), given
/// q_tr > sigma_y(e_n). Bracket: for a nondecreasing curve dlam <= (q_tr - sigma_y(e_n)) / 3G.
template <class H>
double radial_return(const H& h, double three_g, double q_tr, double e_n, double sy_n) {
  const double hi = (q_tr - sy_n) / three_g;
  const double tol = 1e-14 * q_tr;
  return solve_decreasing(
      [&](double x, double& r, double& dr) {
        r = q_tr - three_g * x - h.value(e_n + x);
        dr = -three_g - h.slope(e_n + x);
      },
      0.0, hi, tol);
}

/// Plane-stress return (Simo-Taylor) in the variables p = sxx + syy, q = sxx - syy, t = sxy.
/// With gamma = dlam / sigma_eq (dlam the effective plastic strain increment), the backward-Euler
/// stress is p = p_tr / (1 + a gamma), (q, t) = (q_tr, t_tr) / (1 + b gamma),
/// a = E / (2 (1 - nu)), b = 3 G, and sigma_eq^2(gamma) = A / (1 + a gamma)^2 + B / (1 + b gamma)^2
/// with A = p_tr^2 / 4, B = 3 q_tr^2 / 4 + 3 t_tr^2. gamma solves
/// r = 1 - sigma_y(e_n + gamma sigma_eq) / sigma_eq = 0: in this form r is linear in gamma for
/// pure shear or pure p with perfect plasticity, so Newton needs about one step fewer than on
/// sigma_eq^2 - sigma_y^2, and far fewer on large increments. It starts with the Newton step from
/// gamma = 0, where everything is known from the trial state, and stops once a step moves the
/// stress by less than 1e-13 of itself (a gamma, b gamma below 1e-13). Returns gamma.
/// plane_stress_residual evaluates r and r'; the batched solver (plane_stress_batch.hpp) solves
/// the same equation for many points at once.
template <class H>
inline void plane_stress_residual(const H& h, double a, double b, double big_a, double big_b,
                                  double e_n, double g, double& r, double& dr) {
  const double ua = 1.0 / (1.0 + a * g);
  const double ub = 1.0 / (1.0 + b * g);
  const double psi = std::sqrt(big_a * ua * ua + big_b * ub * ub);
  const double inv_psi = 1.0 / psi;
  const double dpsi = -(big_a * a * ua * ua * ua + big_b * b * ub * ub * ub) * inv_psi;
  const double e = e_n + g * psi;
  const double sy = h.value(e);
  r = 1.0 - sy * inv_psi;
  dr = -(h.slope(e) * (psi + g * dpsi) - sy * dpsi * inv_psi) * inv_psi;
}

/// The first iterate of plane_stress_return: the Newton step from gamma = 0, where sigma_eq,
/// sigma_y and their slopes are the trial's. 0 when that step leaves (0, hi).
template <class H>
inline double plane_stress_first_step(const H& h, double a, double b, double big_a, double big_b,
                                      double e_n, double psi_tr, double sy_n, double hi) {
  const double dpsi0 = -(big_a * a + big_b * b) / psi_tr;
  const double dr0 = -(h.slope(e_n) * psi_tr - sy_n * dpsi0 / psi_tr) / psi_tr;
  const double g0 = -(1.0 - sy_n / psi_tr) / dr0;
  return g0 > 0.0 && g0 < hi ? g0 : 0.0;
}

/// The stopping measures of plane_stress_return: |r| (a relative yield-surface distance) and a
/// step that moves the stress by less than 1e-13 of itself (a gamma, b gamma).
inline constexpr double kPlaneStressResidualTol = 1e-15;
inline double plane_stress_step_tol(double a, double b) {
  return 1e-13 / std::max(a, b);
}

template <class H>
double plane_stress_return(const H& h, double a, double b, double big_a, double big_b, double e_n,
                           double psi_tr, double sy_n) {
  const double hi = (psi_tr / sy_n - 1.0) / std::min(a, b);
  return solve_decreasing(
      [&](double g, double& r, double& dr) {
        plane_stress_residual(h, a, b, big_a, big_b, e_n, g, r, dr);
      },
      0.0, hi, kPlaneStressResidualTol, plane_stress_step_tol(a, b),
      plane_stress_first_step(h, a, b, big_a, big_b, e_n, psi_tr, sy_n, hi));
}

}  // namespace plyform::material::detail
