#pragma once
// The backward-Euler (closest point) plane-stress return of an anisotropic yield function with
// isotropic hardening, for the sheet-metal laws (*MAT_036 Barlat 89, *MAT_122 Hill 3R). In the
// material axes, with s = (s11, s22, s12), strains (e11, e22, gamma12) and the plane-stress
// compliance Cinv, it solves for s and dlam
//   R_s = Cinv (s - s_tr) + dlam grad phi(s) = 0,   R_f = phi(s) - sigma_y(e_n + dlam) = 0
// by Newton's method on the four unknowns (the Jacobian [[Cinv + dlam Hess phi, grad phi],
// [grad phi^T, -sigma_y']] reduced to a 3 x 3 solve) with a backtracking line search on the
// residual's norm. The yield functions are convex and smooth, so from the trial state Newton
// converges quadratically on an explicit step's small increments; a point that does not
// converge in kMaxIterations (a step far beyond the surface) is returned again in substeps of
// its elastic increment, 8 then 64. Private to plyform_material; derivation: docs/materials.md.

#include <algorithm>
#include <cmath>

#include "anisotropic_yield.hpp"

namespace plyform::material::detail {

inline constexpr int kAnisotropicMaxIterations = 40;

/// A symmetric 3 x 3 matrix's inverse applied to two vectors: x = A^-1 u, y = A^-1 v.
inline void solve_symmetric3(const double* a, const double* u, const double* v, double* x,
                             double* y) {
  const double c00 = a[4] * a[8] - a[5] * a[7], c01 = a[5] * a[6] - a[3] * a[8],
               c02 = a[3] * a[7] - a[4] * a[6];
  const double c11 = a[0] * a[8] - a[2] * a[6], c12 = a[2] * a[3] - a[0] * a[5];
  const double c22 = a[0] * a[4] - a[1] * a[3];
  const double inv_det = 1.0 / (a[0] * c00 + a[1] * c01 + a[2] * c02);
  // A symmetric: the adjugate is symmetric, adj_ij = c_ij.
  const double adj[9] = {c00, c01, c02, c01, c11, c12, c02, c12, c22};
  for (int i = 0; i < 3; ++i) {
    x[i] = inv_det * (adj[3 * i] * u[0] + adj[3 * i + 1] * u[1] + adj[3 * i + 2] * u[2]);
    y[i] = inv_det * (adj[3 * i] * v[0] + adj[3 * i + 1] * v[1] + adj[3 * i + 2] * v[2]);
  }
}

/// The plane-stress compliance (e11, e22, gamma12 from s11, s22, s12), row-major.
struct PlaneStressCompliance {
  double c[9];
  PlaneStressCompliance(double young, double nu)
      : c{1.0 / young, -nu / young, 0.0,
          -nu / young, 1.0 / young, 0.0,
          0.0,         0.0,         2.0 * (1.0 + nu) / young} {}
};

/// One return from s_tr with the effective plastic strain e_n. Returns whether it converged;
/// s (out) the stress, dlam (out) the effective plastic strain increment.
template <class Y, class H>
bool anisotropic_return_once(const Y& yf, const H& hard, const PlaneStressCompliance& cc,
                             const double* s_tr, double e_n, double* s, double& dlam) {
  const double tol = 1e-12 * hard.value(e_n);
  // The residual's size in stress units: R_s scaled by 1 / Cinv_11 = E.
  const double young = 1.0 / cc.c[0];
  const auto residual = [&](const double* st, double dl, const YieldState& y, double* rs) {
    const double ds[3] = {st[0] - s_tr[0], st[1] - s_tr[1], st[2] - s_tr[2]};
    for (int i = 0; i < 3; ++i)
      rs[i] = cc.c[3 * i] * ds[0] + cc.c[3 * i + 1] * ds[1] + cc.c[3 * i + 2] * ds[2] + dl * y.g[i];
    const double rf = y.phi - hard.value(e_n + dl);
    return std::max(
        {std::abs(rf), young * std::abs(rs[0]), young * std::abs(rs[1]), young * std::abs(rs[2])});
  };
  s[0] = s_tr[0], s[1] = s_tr[1], s[2] = s_tr[2];
  dlam = 0.0;
  YieldState y;
  yf.evaluate(s, y);
  double rs[3];
  double r0 = residual(s, dlam, y, rs);
  for (int it = 0; it < kAnisotropicMaxIterations && r0 > tol; ++it) {
    const double rf = y.phi - hard.value(e_n + dlam);
    double a[9];
    for (int i = 0; i < 9; ++i)
      a[i] = cc.c[i] + dlam * y.hs[i];
    double ai_r[3], ai_g[3];
    solve_symmetric3(a, rs, y.g, ai_r, ai_g);
    const double g_ai_g = y.g[0] * ai_g[0] + y.g[1] * ai_g[1] + y.g[2] * ai_g[2];
    const double g_ai_r = y.g[0] * ai_r[0] + y.g[1] * ai_r[1] + y.g[2] * ai_r[2];
    const double ddl = (rf - g_ai_r) / (g_ai_g + hard.slope(e_n + dlam));
    const double ds[3] = {-ai_r[0] - ai_g[0] * ddl, -ai_r[1] - ai_g[1] * ddl,
                          -ai_r[2] - ai_g[2] * ddl};
    // The full step, evaluated with the Hessian (it is taken nearly always); else halve it
    // until the residual falls (at most 12 times), then evaluate the Hessian where it landed.
    double step = 1.0;
    for (int k = 0; k < 12; ++k) {
      const double st[3] = {s[0] + step * ds[0], s[1] + step * ds[1], s[2] + step * ds[2]};
      const double dl = std::max(dlam + step * ddl, 0.0);
      YieldState yt;
      yf.evaluate(st, yt, k == 0);
      double rst[3];
      const double r = residual(st, dl, yt, rst);
      if (r < (1.0 - 1e-4 * step) * r0 || k == 11) {
        s[0] = st[0], s[1] = st[1], s[2] = st[2];
        dlam = dl;
        if (k == 0)
          y = yt;
        else
          yf.evaluate(s, y);
        rs[0] = rst[0], rs[1] = rst[1], rs[2] = rst[2];
        r0 = r;
        break;
      }
      step *= 0.5;
    }
  }
  return r0 <= 1e3 * tol;
}

/// The return of a point whose trial stress s_tr lies outside the yield surface: from the
/// start-of-step stress s_n (inside) the elastic increment s_tr - s_n is taken whole, else in 8
/// and then 64 substeps. s (out) the stress; returns the effective plastic strain increment.
template <class Y, class H>
double anisotropic_return(const Y& yf, const H& hard, const PlaneStressCompliance& cc,
                          const double* s_n, const double* s_tr, double e_n, double* s) {
  double dlam = 0.0;
  if (anisotropic_return_once(yf, hard, cc, s_tr, e_n, s, dlam))
    return dlam;
  for (const int pieces : {8, 64}) {
    double cur[3] = {s_n[0], s_n[1], s_n[2]};
    double e = e_n;
    bool ok = true;
    for (int k = 0; k < pieces; ++k) {
      const double st[3] = {cur[0] + (s_tr[0] - s_n[0]) / pieces,
                            cur[1] + (s_tr[1] - s_n[1]) / pieces,
                            cur[2] + (s_tr[2] - s_n[2]) / pieces};
      if (!yf.exceeds(st, hard.value(e))) {
        cur[0] = st[0], cur[1] = st[1], cur[2] = st[2];
        continue;
      }
      double dl = 0.0;
      ok = anisotropic_return_once(yf, hard, cc, st, e, cur, dl) && ok;
      e += dl;
    }
    s[0] = cur[0], s[1] = cur[1], s[2] = cur[2];
    if (ok || pieces == 64)
      return e - e_n;
  }
  return 0.0;  // not reached
}

}  // namespace plyform::material::detail
