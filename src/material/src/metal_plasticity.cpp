#include "plyform/material/metal_plasticity.hpp"

#include <algorithm>
#include <cmath>

#include "hardening.hpp"
#include "plane_stress_batch.hpp"
#include "plane_stress_trial.hpp"
#include "plyform/material/strain_rate.hpp"

namespace plyform::material {

double cowper_symonds_factor(const core::PlasticKinematic& m, double rate) {
  return CowperSymonds{m.src, m.srp}.factor(rate);
}

namespace {

double plastic_modulus(double young, double etan) {
  return young * etan / (young - etan);
}

// ---------------------------------------------------------------------------------------------
// *MAT_003, solids. The back stress alpha is a deviatoric tensor carried with the material: it
// turns with the same incremental rotation Q as the stress (Jaumann rate, Hughes-Winget), so a
// pure spin leaves the yield surface where the material took it. The return about alpha:
// with xi = s - alpha, the flow d eps^p = dlam 3/2 xi / q is along the trial xi (the elastic
// predictor moves s by -2 G d eps^p, the back stress by +(1 - BETA) 2/3 E_p d eps^p, both
// along xi_tr), so xi = xi_tr (1 - (3 G + (1 - BETA) E_p) dlam / q_tr) and the consistency
// condition q = k (SIGY + BETA E_p (eps_p + dlam)) is linear in dlam.
// ---------------------------------------------------------------------------------------------

// a <- Q a Q^T for a symmetric a (xx, yy, zz, xy, yz, zx), Q the Cayley rotation of
// elastic_jaumann with u, v, s = dt/2 (W_12, W_23, W_31).
void rotate(double u, double v, double s, double* a) {
  const double k = 2.0 / (1.0 + u * u + v * v + s * s);
  const double q11 = 1.0 - k * (u * u + s * s), q22 = 1.0 - k * (u * u + v * v),
               q33 = 1.0 - k * (s * s + v * v);
  const double q12 = k * (u + s * v), q21 = k * (-u + s * v), q23 = k * (v + u * s),
               q32 = k * (-v + u * s), q31 = k * (s + u * v), q13 = k * (-s + u * v);
  const double a11 = a[0], a22 = a[1], a33 = a[2], a12 = a[3], a23 = a[4], a31 = a[5];
  const double t11 = q11 * a11 + q12 * a12 + q13 * a31, t12 = q11 * a12 + q12 * a22 + q13 * a23,
               t13 = q11 * a31 + q12 * a23 + q13 * a33;
  const double t21 = q21 * a11 + q22 * a12 + q23 * a31, t22 = q21 * a12 + q22 * a22 + q23 * a23,
               t23 = q21 * a31 + q22 * a23 + q23 * a33;
  const double t31 = q31 * a11 + q32 * a12 + q33 * a31, t32 = q31 * a12 + q32 * a22 + q33 * a23,
               t33 = q31 * a31 + q32 * a23 + q33 * a33;
  a[0] = t11 * q11 + t12 * q12 + t13 * q13;
  a[1] = t21 * q21 + t22 * q22 + t23 * q23;
  a[2] = t31 * q31 + t32 * q32 + t33 * q33;
  a[3] = t11 * q21 + t12 * q22 + t13 * q23;
  a[4] = t21 * q31 + t22 * q32 + t23 * q33;
  a[5] = t31 * q11 + t32 * q12 + t33 * q13;
}

// The back stress (bx, by, bt) turned by the element's spin phi (Cayley form, as the element
// turned the stresses; a point without spin keeps it as it is), and the shifted trial
// eta = sigma - alpha with its squared equivalent stress, across SIMD lanes.
void turn_back_stress(std::size_t n, const double* __restrict phi, const double* __restrict sxx,
                      const double* __restrict syy, const double* __restrict sxy,
                      double* __restrict bx, double* __restrict by, double* __restrict bt,
                      double* __restrict ex, double* __restrict ey, double* __restrict et,
                      double* __restrict psi2) {
  for (std::size_t i = 0; i < n; ++i) {
    const double half_sq = 0.25 * phi[i] * phi[i], inv = 1.0 / (1.0 + half_sq);
    const double c = (1.0 - half_sq) * inv, sn = phi[i] * inv;
    const double x = bx[i], y = by[i], t = bt[i];
    const bool turn = phi[i] != 0.0;
    bx[i] = turn ? c * c * x + sn * sn * y - 2.0 * c * sn * t : x;
    by[i] = turn ? sn * sn * x + c * c * y + 2.0 * c * sn * t : y;
    bt[i] = turn ? c * sn * (x - y) + (c * c - sn * sn) * t : t;
    ex[i] = sxx[i] - bx[i];
    ey[i] = syy[i] - by[i];
    et[i] = sxy[i] - bt[i];
    psi2[i] = ex[i] * ex[i] + ey[i] * ey[i] - ex[i] * ey[i] + 3.0 * et[i] * et[i];
  }
}

}  // namespace

void solid_update(const core::PlasticKinematic& m, std::size_t n, ConstSymView d,
                  const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                  SymView sigma, double* eps_p, double* back) {
  // The stress's rotation and elastic trial in one vectorised pass.
  elastic_jaumann(core::ElasticMaterial{m.density, m.young, m.poisson}, n, d, w_xy, w_yz, w_zx, dt,
                  sigma);
  const double three_g = 1.5 * m.young / (1.0 + m.poisson);
  const double ep = plastic_modulus(m.young, m.etan);
  const double h_kin = (1.0 - m.beta) * ep, h_iso = m.beta * ep;
  const bool rate = m.src > 0.0 && m.srp > 0.0;
  const double half_dt = 0.5 * dt;
  for (std::size_t p = 0; p < n; ++p) {
    double* a = back + 6 * p;
    rotate(half_dt * w_xy[p], half_dt * w_yz[p], half_dt * w_zx[p], a);
    const double mean = (sigma.xx[p] + sigma.yy[p] + sigma.zz[p]) / 3.0;
    const double x[6] = {sigma.xx[p] - mean - a[0], sigma.yy[p] - mean - a[1],
                         sigma.zz[p] - mean - a[2], sigma.xy[p] - a[3],
                         sigma.yz[p] - a[4],        sigma.zx[p] - a[5]};
    const double q_tr = std::sqrt(1.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2] +
                                         2.0 * (x[3] * x[3] + x[4] * x[4] + x[5] * x[5])));
    const double k = rate ? cowper_symonds_factor(m, solid_strain_rate(d, p)) : 1.0;
    const double radius = k * (m.sigy + h_iso * eps_p[p]);
    if (!(q_tr > radius))
      continue;
    const double dlam = (q_tr - radius) / (three_g + h_kin + k * h_iso);
    const double fs = three_g * dlam / q_tr, fa = h_kin * dlam / q_tr;
    sigma.xx[p] -= fs * x[0];
    sigma.yy[p] -= fs * x[1];
    sigma.zz[p] -= fs * x[2];
    sigma.xy[p] -= fs * x[3];
    sigma.yz[p] -= fs * x[4];
    sigma.zx[p] -= fs * x[5];
    for (int i = 0; i < 6; ++i)
      a[i] += fa * x[i];
    eps_p[p] += dlam;
  }
}

// *MAT_003, shells. The deviatoric back stress alpha has alpha_zz = -(alpha_xx + alpha_yy) != 0
// while sigma_zz = 0, so xi = dev(sigma) - alpha = dev(sigma - alpha); shifting sigma - alpha
// by its zz component (a hydrostatic shift, which dev ignores) gives xi = dev(eta) with
// eta = (sxx - ab_xx, syy - ab_yy, sxy - ab_xy, eta_zz = 0), ab_xx = alpha_xx - alpha_zz,
// ab_yy = alpha_yy - alpha_zz, ab_xy = alpha_xy: the J2 of xi is the plane-stress von Mises
// form of eta. With d alpha = 2/3 H d eps^p, H = (1 - BETA) E_p, d ab_ij = 2/3 H (d eps^p_ij -
// d eps^p_zz delta_ij) in the plane, d eps^p_zz = -(d eps^p_xx + d eps^p_yy); with the J2 flow
// of the shell return (shell.cpp) that is, in p, q, t (p = xx + yy, q = xx - yy, t = xy),
// d ab = H gamma (P, Q, T),
// gamma = dlam / q_eta and (P, Q, T) those of eta. With the stress's backward-Euler change
// (-a gamma P, -b gamma Q, -b gamma T), a = E/(2(1 - nu)), b = 3 G (the J2 shell return):
//   P = P_tr / (1 + (a + H) gamma),  (Q, T) = (Q_tr, T_tr) / (1 + (b + H) gamma),
// the J2 plane-stress return of eta_tr = sigma_tr - ab with a + H, b + H in place of a, b and
// the isotropic part k (SIGY + BETA E_p eps_p) as the yield stress: exact (Simo-Taylor) to
// round-off by the same scalar Newton.
void shell_update(const core::PlasticKinematic& m, std::size_t n, const ShellPoints& pts,
                  double dt) {
  detail::plane_stress_trial(m.young, m.poisson, n, pts);
  const double nu = m.poisson;
  const double a = 0.5 * m.young / (1.0 - nu), b = 1.5 * m.young / (1.0 + nu);
  const double nu_e = nu / m.young;
  const double ep = plastic_modulus(m.young, m.etan);
  const double h_kin = (1.0 - m.beta) * ep, h_iso = m.beta * ep;
  const bool rate = m.src > 0.0 && m.srp > 0.0 && dt > 0.0;
  // The yielding points' returns are solved together (plane_stress_batch.hpp). Per block of
  // points: the back stress turned and the shifted trial's equivalent stress across SIMD lanes,
  // then the rate factors, then the yield test.
  detail::KinematicPlaneStressBatch batch(a, b, nu_e, h_kin, pts.sxx, pts.syy, pts.sxy, pts.eps_p,
                                          pts.dzz, pts.history);
  constexpr std::size_t kBlock = 64;
  double bx[kBlock], by[kBlock], bt[kBlock], phi[kBlock];
  double ex[kBlock], ey[kBlock], et[kBlock], psi2[kBlock], k[kBlock];
  for (std::size_t p0 = 0; p0 < n; p0 += kBlock) {
    const std::size_t m_block = std::min(kBlock, n - p0);
    for (std::size_t i = 0; i < m_block; ++i) {
      const double* ab = pts.history + 6 * (p0 + i);  // xx, yy, (zz), xy: the solid's slots
      bx[i] = ab[0];
      by[i] = ab[1];
      bt[i] = ab[3];
      phi[i] = pts.spin != nullptr ? pts.spin[p0 + i] : 0.0;
    }
    turn_back_stress(m_block, phi, pts.sxx + p0, pts.syy + p0, pts.sxy + p0, bx, by, bt, ex, ey, et,
                     psi2);
    for (std::size_t i = 0; i < m_block; ++i) {
      double* ab = pts.history + 6 * (p0 + i);
      ab[0] = bx[i];
      ab[1] = by[i];
      ab[3] = bt[i];
    }
    for (std::size_t i = 0; i < m_block; ++i)
      k[i] = rate ? cowper_symonds_factor(m, shell_strain_rate(pts, p0 + i, dt)) : 1.0;
    for (std::size_t i = 0; i < m_block; ++i) {
      const std::size_t p = p0 + i;
      const detail::LinearHardening h{k[i] * m.sigy, k[i] * h_iso};
      const double sy_n = h.value(pts.eps_p[p]);
      if (psi2[i] > sy_n * sy_n)
        batch.add(p, h.sigy, h.hp, ex[i] + ey[i], ex[i] - ey[i], et[i], std::sqrt(psi2[i]));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// *MAT_037: Hill 1948 with normal anisotropy r, plane stress. In p = sxx + syy, q = sxx - syy,
// t = sxy the yield function is diagonal (the eigenframe of the Hill matrix):
//   sigma_eq^2 = p^2 / (2 (1 + r)) + (1 + 2r)/(1 + r) (q^2 / 2 + 2 t^2),
// and the associated flow d eps^p = dlam d sigma_eq / d sigma gives, with gamma = dlam /
// sigma_eq, d eps^p_xx + d eps^p_yy = gamma p / (1 + r), d eps^p_xx - d eps^p_yy =
// gamma (1 + 2r)/(1 + r) q, d eps^p_xy = gamma (1 + 2r)/(1 + r) t. Plane-stress elasticity is
// diagonal in the same variables (p: E/(1 - nu) on the trace, q, t: 2 G), so backward Euler
// scales each: p = p_tr / (1 + a gamma), (q, t) = (q_tr, t_tr) / (1 + b gamma),
// a = E / ((1 - nu)(1 + r)), b = 2 G (1 + 2r)/(1 + r), and sigma_eq^2(gamma) = A / (1 + a
// gamma)^2 + B / (1 + b gamma)^2 with A, B the trial's two parts: the scalar problem of the J2
// return (r = 1 gives its a, b, A, B). sigma_eq being homogeneous of degree 1, the plastic
// work is sigma_eq dlam: the effective plastic strain grows by dlam = gamma sigma_eq.
// Thickness: d eps^p_zz = -gamma p / (1 + r) and the elastic -(nu/E)(p - p_tr).
// ---------------------------------------------------------------------------------------------
namespace {

template <class F>
decltype(auto) with_hardening(const core::TransverselyAnisotropicPlastic& m, F&& f) {
  const auto& c = m.curve;
  const std::size_t n = std::min(c.plastic_strain.size(), c.yield_stress.size());
  if (n > 0)
    return f(detail::TabulatedHardening{c.plastic_strain.data(), c.yield_stress.data(), n});
  return f(detail::LinearHardening{m.sigy, m.etan});  // ETAN: the plastic modulus
}

template <class H>
void hill_return_kernel(const H& h, double young, double nu, double r, std::size_t n,
                        double* __restrict sxx, double* __restrict syy, double* __restrict sxy,
                        double* __restrict eps_p, double* __restrict dzz) {
  const double cp = 1.0 / (1.0 + r), cq = (1.0 + 2.0 * r) / (1.0 + r);
  const double a = young / (1.0 - nu) * cp;
  const double b = young / (1.0 + nu) * cq;
  const double nu_e = nu / young;
  for (std::size_t p = 0; p < n; ++p) {
    const double p_tr = sxx[p] + syy[p], q_tr = sxx[p] - syy[p], t = sxy[p];
    const double big_a = 0.5 * cp * p_tr * p_tr;
    const double big_b = cq * (0.5 * q_tr * q_tr + 2.0 * t * t);
    const double psi2 = big_a + big_b;
    const double sy_n = h.value(eps_p[p]);
    if (!(psi2 > sy_n * sy_n))
      continue;
    const double g =
        detail::plane_stress_return(h, a, b, big_a, big_b, eps_p[p], std::sqrt(psi2), sy_n);
    const double ua = 1.0 / (1.0 + a * g), ub = 1.0 / (1.0 + b * g);
    const double pp = p_tr * ua, qq = q_tr * ub;
    sxx[p] = 0.5 * (pp + qq);
    syy[p] = 0.5 * (pp - qq);
    sxy[p] = t * ub;
    eps_p[p] += g * std::sqrt(big_a * ua * ua + big_b * ub * ub);
    dzz[p] += -nu_e * (pp - p_tr) - cp * g * pp;
  }
}

}  // namespace

double yield_stress(const core::TransverselyAnisotropicPlastic& m, double eps_p) {
  return with_hardening(m, [&](const auto& h) { return h.value(eps_p); });
}

void shell_update(const core::TransverselyAnisotropicPlastic& m, std::size_t n,
                  const ShellPoints& pts) {
  detail::plane_stress_trial(m.young, m.poisson, n, pts);
  with_hardening(m, [&](const auto& h) {
    hill_return_kernel(h, m.young, m.poisson, m.r, n, pts.sxx, pts.syy, pts.sxy, pts.eps_p,
                       pts.dzz);
  });
}

}  // namespace plyform::material
