#include "plyform/material/woven_ply.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hardening.hpp"

namespace plyform::material {

namespace {

using Ply = core::ReinforcedThermoplastic;
using H = WovenPlyHistory;

// A curve at x, linear beyond its ends with the end segments' slopes (a fibre or shear curve
// keeps stiffening past its last point; a one-point curve is constant).
double extrapolated(const core::LoadCurve& c, double x) {
  const std::size_t n = std::min(c.x.size(), c.y.size());
  if (n == 0)
    return 0.0;
  return detail::TabulatedHardening{c.x.data(), c.y.data(), n}.value(x);
}

// Slope of the same function at x.
double extrapolated_slope(const core::LoadCurve& c, double x) {
  const std::size_t n = std::min(c.x.size(), c.y.size());
  if (n == 0)
    return 0.0;
  return detail::TabulatedHardening{c.x.data(), c.y.data(), n}.slope(x);
}

// The two curves of a table around temperature t and the weight of the second.
struct Bracket {
  std::size_t lo = 0, hi = 0;
  double w = 0.0;
};
Bracket bracket(const core::CurveTable& table, double t) {
  const std::size_t n = table.curve.size();
  if (n <= 1 || t <= table.value.front())
    return {};
  if (t >= table.value.back())
    return {n - 1, n - 1, 0.0};
  const auto i = static_cast<std::size_t>(
      std::upper_bound(table.value.begin(), table.value.end(), t) - table.value.begin());
  return {i - 1, i, (t - table.value[i - 1]) / (table.value[i] - table.value[i - 1])};
}

// A table (or a one-curve table: a plain curve) at (t, x), each curve extrapolated in x.
double table_at(const core::CurveTable& table, double t, double x) {
  const Bracket b = bracket(table, t);
  const double lo = extrapolated(table.curve[b.lo], x);
  return b.w == 0.0 ? lo : (1.0 - b.w) * lo + b.w * extrapolated(table.curve[b.hi], x);
}

// The matrix's yield curve at one temperature, for the plane-stress return.
struct TableHardening {
  const core::CurveTable* table;
  Bracket b;
  [[nodiscard]] double value(double e) const {
    const double lo = extrapolated(table->curve[b.lo], e);
    return b.w == 0.0 ? lo : (1.0 - b.w) * lo + b.w * extrapolated(table->curve[b.hi], e);
  }
  [[nodiscard]] double slope(double e) const {
    const double lo = extrapolated_slope(table->curve[b.lo], e);
    return b.w == 0.0 ? lo : (1.0 - b.w) * lo + b.w * extrapolated_slope(table->curve[b.hi], e);
  }
};

// The plane-stress elastic step and J2 return of one point's matrix stress (the arrays of
// shell.cpp's kernels, for one point).
void matrix_step(const Ply& m, double t, double young, double nu, double dxx, double dyy,
                 double dxy, double* sm, double* eps_p, double& dzz) {
  const double c11 = young / (1.0 - nu * nu), c12 = nu * c11, two_g = young / (1.0 + nu);
  const double dsx = c11 * dxx + c12 * dyy, dsy = c12 * dxx + c11 * dyy;
  sm[0] += dsx;
  sm[1] += dsy;
  sm[2] += two_g * dxy;
  dzz = -nu / (1.0 - nu) * (dxx + dyy);
  if (m.yield.curve.empty() || eps_p == nullptr)
    return;
  const TableHardening h{&m.yield, bracket(m.yield, t)};
  const double x = sm[0], y = sm[1], s = sm[2];
  const double psi2 = x * x + y * y - x * y + 3.0 * s * s;
  const double sy_n = h.value(*eps_p);
  if (!(psi2 > sy_n * sy_n))
    return;
  // Simo-Taylor's plane-stress return, as shell.cpp's plane_stress_return_kernel.
  const double a = 0.5 * young / (1.0 - nu), b = 1.5 * young / (1.0 + nu);
  const double p_tr = x + y, q_tr = x - y;
  const double big_a = 0.25 * p_tr * p_tr, big_b = 0.75 * q_tr * q_tr + 3.0 * s * s;
  const double g =
      detail::plane_stress_return(h, a, b, big_a, big_b, *eps_p, std::sqrt(psi2), sy_n);
  const double ua = 1.0 / (1.0 + a * g), ub = 1.0 / (1.0 + b * g);
  const double pp = p_tr * ua, qq = q_tr * ub;
  sm[0] = 0.5 * (pp + qq);
  sm[1] = 0.5 * (pp - qq);
  sm[2] = s * ub;
  *eps_p += g * std::sqrt(big_a * ua * ua + big_b * ub * ub);
  dzz += -(nu / young) * (pp - p_tr) - 0.5 * g * pp;
}

// The unsigned angle between two unit vectors in the plane, in (0, pi), with its sine and cosine.
struct Angle {
  double th, sin, cos;
};
Angle angle_between(const double* a, const double* b) {
  const double c = a[0] * b[0] + a[1] * b[1];
  const double s = std::abs(a[0] * b[1] - a[1] * b[0]);
  return {std::atan2(s, c), s, c};
}

// The initial angle between families i and j (their ALPH difference), unsigned, in [0, pi].
double initial_angle(const Ply& m, int i, int j) {
  const double d =
      m.fibre[static_cast<std::size_t>(j)].alpha - m.fibre[static_cast<std::size_t>(i)].alpha;
  return std::abs(std::atan2(std::sin(d), std::cos(d)));
}

double locking(const Ply::Shear& s, double g) {
  if (!(s.lock_angle > 0.0))
    return 0.0;
  const double over = std::abs(g) - s.lock_angle;
  return over > 0.0 ? std::copysign(s.lock_modulus * over, g) : 0.0;
}

}  // namespace

double fibre_stress(const Ply::Fibre& f, double strain, double t) {
  if (!(strain > 0.0))
    return 0.0;
  if (f.stress.curve.empty())
    return f.modulus * strain;
  return std::max(0.0, table_at(f.stress, t, strain));
}

double elastic_shear_stress(const Ply::Shear& s, double gamma, double t) {
  const double g = std::abs(gamma);
  if (!s.stress.curve.empty())  // METH 2: the curve carries the locking
    return std::copysign(table_at(s.stress, t, g), gamma);
  if (s.lock_angle > 0.0 && g > s.lock_angle)
    return std::copysign(s.modulus * s.lock_angle + s.lock_modulus * (g - s.lock_angle), gamma);
  return s.modulus * gamma;
}

WovenPlyState woven_ply_state(const Ply& m, const double* h) {
  WovenPlyState st;
  if (h == nullptr || !(h[H::jacobian] > 0.0))
    return st;
  st.initialised = true;
  for (int i = 0; i < m.families; ++i) {
    const double* f = h + H::fibre + 2 * i;
    const double len = std::hypot(f[0], f[1]);
    st.direction[i][0] = f[0] / len;
    st.direction[i][1] = f[1] / len;
  }
  for (int k = 0; k + 1 < m.families; ++k)
    st.shear_angle[k] =
        initial_angle(m, k, k + 1) - angle_between(st.direction[k], st.direction[k + 1]).th;
  return st;
}

void shell_update(const Ply& m, std::size_t n, const ShellPoints& pts) {
  const int nf = m.families;
  // The families' initial angles, the same at every point (a per-point atan2, sin and cos cost
  // some 5 % of the hot draw).
  double initial[2] = {0.0, 0.0};
  for (int k = 0; k + 1 < nf; ++k)
    initial[k] = initial_angle(m, k, k + 1);
  // The matrix's constants at the last temperature met: the points of an element share their
  // thickness points' temperatures (ELFORM 16's four columns), and two curve look-ups a point
  // cost about 2 % of the hot draw.
  double t_last = std::numeric_limits<double>::quiet_NaN(), young = m.young, nu = m.poisson;
  for (std::size_t p = 0; p < n; ++p) {
    double* h = pts.history + H::count * p;
    const double t = pts.temperature != nullptr ? pts.temperature[p] : 0.0;
    if (!(t == t_last)) {
      young = m.young_of_t.x.empty() ? m.young : m.young_of_t(t);
      nu = m.poisson_of_t.x.empty() ? m.poisson : m.poisson_of_t(t);
      t_last = t;
    }
    if (!(h[H::jacobian] > 0.0)) {
      // First step: each family at ALPHi from the material axis a (the element's, at t = 0).
      const double axis = std::atan2(pts.sin_t[p], pts.cos_t[p]);
      for (int i = 0; i < nf; ++i) {
        const double ang = axis + m.fibre[static_cast<std::size_t>(i)].alpha;
        h[H::fibre + 2 * i] = std::cos(ang);
        h[H::fibre + 2 * i + 1] = std::sin(ang);
      }
      h[H::jacobian] = 1.0;
    }
    const double dxx = pts.dxx[p], dyy = pts.dyy[p], dxy = pts.dxy[p];
    const double w = pts.material_spin != nullptr ? pts.material_spin[p] : 0.0;
    const double turn = pts.frame_turn != nullptr ? pts.frame_turn[p] : 0.0;
    // 0. The frame turned through theta (tan theta = turn) over the step: what the history holds
    //    in the frame at t_n is turned by -theta into the frame at t_{n+1}, exactly.
    const double tc = 1.0 / std::sqrt(1.0 + turn * turn), ts = turn * tc;
    // 1. dF = (I - A/2)^-1 (I + A/2), A = [[dxx, dxy - w], [dxy + w, dyy]]: the mid-step
    //    velocity gradient times dt, in the frame at t_{n+1}.
    {
      const double a00 = 0.5 * dxx, a01 = 0.5 * (dxy - w), a10 = 0.5 * (dxy + w), a11 = 0.5 * dyy;
      const double m00 = 1.0 - a00, m01 = -a01, m10 = -a10, m11 = 1.0 - a11;
      const double idet = 1.0 / (m00 * m11 - m01 * m10);
      for (int i = 0; i < nf; ++i) {
        double* f = h + H::fibre + 2 * i;
        const double fx = tc * f[0] + ts * f[1], fy = tc * f[1] - ts * f[0];
        const double nx = fx + a00 * fx + a01 * fy;
        const double ny = fy + a10 * fx + a11 * fy;
        f[0] = idet * (m11 * nx - m01 * ny);
        f[1] = idet * (m00 * ny - m10 * nx);
      }
    }
    // 2. The matrix: its components turned into the new frame (by -theta, exactly) and by the
    //    material's spin (Cayley: Jaumann over the step), then the plane-stress increment and
    //    return.
    double* sm = h + H::matrix;
    if (w != 0.0 || turn != 0.0) {
      const double half_sq = 0.25 * w * w, inv = 1.0 / (1.0 + half_sq);
      const double cw = (1.0 - half_sq) * inv, sw = w * inv;
      const double c = cw * tc + sw * ts, s = sw * tc - cw * ts;  // the two turns composed
      const double sx = sm[0], sy = sm[1], sxy = sm[2];
      sm[0] = c * c * sx + s * s * sy - 2.0 * c * s * sxy;
      sm[1] = s * s * sx + c * c * sy + 2.0 * c * s * sxy;
      sm[2] = c * s * (sx - sy) + (c * c - s * s) * sxy;
    }
    double dzz = 0.0;
    matrix_step(m, t, young, nu, dxx, dyy, dxy, sm, pts.eps_p != nullptr ? pts.eps_p + p : nullptr,
                dzz);
    pts.dzz[p] = dzz;
    const double jac = h[H::jacobian] *= std::exp(dxx + dyy + dzz);
    const double inv_j = 1.0 / jac;
    // 3. Fibres and shear.
    double sx = sm[0], sy = sm[1], sxy = sm[2];
    double dir[3][2];
    double dszx = 0.0, dsyz = 0.0;
    const double g_m = 0.5 * young / (1.0 + nu);
    const double ezx = pts.dzx[p], eyz = pts.dyz[p];
    for (int i = 0; i < nf; ++i) {
      const auto& fam = m.fibre[static_cast<std::size_t>(i)];
      const double* f = h + H::fibre + 2 * i;
      // The stretch: sqrt, not hypot (whose care for overflow a fibre of length near 1 does not
      // need costs 2 % of the hot deep drawing).
      const double lambda = std::sqrt(f[0] * f[0] + f[1] * f[1]);
      const double ax = f[0] / lambda, ay = f[1] / lambda;
      dir[i][0] = ax;
      dir[i][1] = ay;
      const double s_f = lambda * fibre_stress(fam, lambda - 1.0, t) * inv_j;
      sx += s_f * ax * ax;
      sy += s_f * ay * ay;
      sxy += s_f * ax * ay;
      // Transverse shear in the family's axes (along a: G31, across: G23), tensor strains.
      const double e_along = ax * ezx + ay * eyz, e_across = -ay * ezx + ax * eyz;
      const double t_along = 2.0 * fam.g31 * e_along, t_across = 2.0 * fam.g23 * e_across;
      dszx += ax * t_along - ay * t_across;
      dsyz += ay * t_along + ax * t_across;
    }
    for (int k = 0; k + 1 < nf; ++k) {
      const auto& sh = m.shear[static_cast<std::size_t>(k)];
      const double* a = dir[k];
      const double* b = dir[k + 1];
      const Angle th = angle_between(a, b);
      const double gamma = initial[k] - th.th;
      double tau = 0.0;
      if (sh.meth == 3 && !sh.stress.curve.empty()) {
        // Elasto-plastic: tau = sign min(|tau_tr|, c(kappa + |tau_tr| / G)), the loading curve c
        // reached exactly on monotonic loading (docs/materials.md).
        double& gp = h[H::shear_plastic + static_cast<std::size_t>(k)];
        double& kappa = h[H::shear_hardening + static_cast<std::size_t>(k)];
        const double tau_tr = sh.modulus * (gamma - gp);
        const double backbone = table_at(sh.stress, t, kappa + std::abs(tau_tr) / sh.modulus);
        if (std::abs(tau_tr) > backbone) {
          const double dk = (std::abs(tau_tr) - backbone) / sh.modulus;
          gp += std::copysign(dk, tau_tr);
          kappa += dk;
          tau = std::copysign(backbone, tau_tr);
        } else {
          tau = tau_tr;
        }
        tau += locking(sh, gamma);
      } else {
        tau = elastic_shear_stress(sh, gamma, t);
      }
      if (tau != 0.0) {
        const double c = tau * inv_j / std::max(th.sin, 1e-6);
        sx += c * (2.0 * a[0] * b[0] - th.cos * (a[0] * a[0] + b[0] * b[0]));
        sy += c * (2.0 * a[1] * b[1] - th.cos * (a[1] * a[1] + b[1] * b[1]));
        sxy += c * (a[0] * b[1] + a[1] * b[0] - th.cos * (a[0] * a[1] + b[0] * b[1]));
      }
    }
    pts.sxx[p] = sx;
    pts.syy[p] = sy;
    pts.sxy[p] = sxy;
    // 4. Transverse shear, elastic.
    pts.szx[p] += 2.0 * g_m * ezx + dszx;
    pts.syz[p] += 2.0 * g_m * eyz + dsyz;
  }
}

}  // namespace plyform::material
