#include "plyform/material/sheet_metal_plasticity.hpp"

#include <cmath>

#include "anisotropic_return.hpp"
#include "anisotropic_yield.hpp"
#include "hardening.hpp"
#include "plane_stress_trial.hpp"
#include "plyform/material/strain_rate.hpp"

namespace plyform::material {

namespace {

detail::Barlat89Yield barlat_yield(const Barlat89Coefficients& k, double m) {
  return {k.a, k.c, k.h, k.p, m};
}

// The Lankford ratio of a yield function's flow under uniaxial stress at angle t from a: the
// stress (cos^2 t, sin^2 t, cos t sin t) in the material axes, the flow g = grad phi (e_aa, e_bb,
// gamma_ab); the width strain (along t + 90 degrees) over the thickness strain -(e_aa + e_bb).
template <class Y>
double r_value(const Y& yf, double t) {
  const double c = std::cos(t), s = std::sin(t);
  const double st[3] = {c * c, s * s, c * s};
  detail::YieldState y;
  yf.evaluate(st, y);
  const double width = y.g[0] * s * s + y.g[1] * c * c - y.g[2] * c * s;
  return width / -(y.g[0] + y.g[1]);
}

// (x, y) components of a symmetric plane tensor <-> the axes at angle t (cos c, sin s).
inline void to_axes(double c, double s, double xx, double yy, double xy, double* out) {
  out[0] = c * c * xx + s * s * yy + 2.0 * c * s * xy;
  out[1] = s * s * xx + c * c * yy - 2.0 * c * s * xy;
  out[2] = c * s * (yy - xx) + (c * c - s * s) * xy;
}
inline void from_axes(double c, double s, const double* in, double& xx, double& yy, double& xy) {
  xx = c * c * in[0] + s * s * in[1] - 2.0 * c * s * in[2];
  yy = s * s * in[0] + c * c * in[1] + 2.0 * c * s * in[2];
  xy = c * s * (in[0] - in[1]) + (c * c - s * s) * in[2];
}

// The return of every point of the call whose trial stress lies outside its yield surface. The
// start-of-step stress (the substeps' start) is the trial less the elastic increment.
template <class Y, class H>
void orthotropic_return_kernel(const Y& yf, const H& hard, const CowperSymonds& rate, double young,
                               double nu, std::size_t n, const ShellPoints& pts) {
  const double c11 = young / (1.0 - nu * nu), c12 = nu * c11, two_g = young / (1.0 + nu);
  const detail::PlaneStressCompliance cc(young, nu);
  const double thickness_factor = (2.0 * nu - 1.0) / young;
  for (std::size_t p = 0; p < n; ++p) {
    const double c = pts.cos_t[p], s = pts.sin_t[p];
    double tr[3];
    to_axes(c, s, pts.sxx[p], pts.syy[p], pts.sxy[p], tr);
    const double k = rate.on() ? rate.factor(shell_strain_rate(pts, p, pts.dt)) : 1.0;
    const auto h = detail::scaled(hard, k);
    const double e_n = pts.eps_p[p];
    if (!yf.exceeds(tr, h.value(e_n)))
      continue;
    double de[3];
    to_axes(c, s, c11 * pts.dxx[p] + c12 * pts.dyy[p], c12 * pts.dxx[p] + c11 * pts.dyy[p],
            two_g * pts.dxy[p], de);
    const double sn[3] = {tr[0] - de[0], tr[1] - de[1], tr[2] - de[2]};
    double out[3];
    const double dlam = detail::anisotropic_return(yf, h, cc, sn, tr, e_n, out);
    from_axes(c, s, out, pts.sxx[p], pts.syy[p], pts.sxy[p]);
    pts.eps_p[p] = e_n + dlam;
    // Thickness: the elastic -(nu/E) d(s_aa + s_bb) and the plastic -(d e_aa^p + d e_bb^p),
    // d e^p = Cinv (s_tr - s): together (2 nu - 1)/E times the trace's fall.
    pts.dzz[p] += thickness_factor * ((tr[0] + tr[1]) - (out[0] + out[1]));
  }
}

}  // namespace

Barlat89Coefficients barlat89_coefficients(double r00, double r45, double r90, double m) {
  Barlat89Coefficients k;
  const double q0 = r00 / (1.0 + r00), q90 = r90 / (1.0 + r90);
  k.a = 2.0 - 2.0 * std::sqrt(q0 * q90);
  k.c = 2.0 - k.a;
  k.h = std::sqrt(q0 / q90);
  // r45(p) rises from -1/2 at p = 0 (no shear flow) without bound: bracket, then bisect.
  const auto r45_of = [&](double p) {
    Barlat89Coefficients t = k;
    t.p = p;
    return barlat89_r_value(t, m, 0.25 * M_PI);
  };
  double lo = 0.0, hi = 1.0;
  while (r45_of(hi) < r45 && hi < 1e6)
    hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (r45_of(mid) < r45 ? lo : hi) = mid;
  }
  k.p = 0.5 * (lo + hi);
  return k;
}

double barlat89_equivalent_stress(const Barlat89Coefficients& k, double m, double s_aa, double s_bb,
                                  double s_ab) {
  const double s[3] = {s_aa, s_bb, s_ab};
  return barlat_yield(k, m).value(s);
}

double barlat89_r_value(const Barlat89Coefficients& k, double m, double angle) {
  return r_value(barlat_yield(k, m), angle);
}

double yield_stress(const core::SheetHardening& h, double eps_p) {
  return detail::with_hardening(h, [&](const auto& law) { return law.value(eps_p); });
}

void shell_update(const core::Barlat89Plastic& m, std::size_t n, const ShellPoints& pts) {
  detail::plane_stress_trial(m.young, m.poisson, n, pts);
  const detail::Barlat89Yield yf{m.a, m.c, m.h, m.p, m.m};
  detail::with_hardening(m.hardening, [&](const auto& h) {
    orthotropic_return_kernel(yf, h, CowperSymonds{m.rate_c, m.rate_p}, m.young, m.poisson, n, pts);
  });
}

void shell_update(const core::Hill3RPlastic& m, std::size_t n, const ShellPoints& pts) {
  detail::plane_stress_trial(m.young, m.poisson, n, pts);
  const detail::Hill48Yield yf = detail::Hill48Yield::from_r(m.r00, m.r45, m.r90);
  detail::with_hardening(m.hardening, [&](const auto& h) {
    orthotropic_return_kernel(yf, h, CowperSymonds{}, m.young, m.poisson, n, pts);
  });
}

}  // namespace plyform::material
