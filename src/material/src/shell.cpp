#include "plyform/material/shell.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "hardening.hpp"
#include "plane_stress_batch.hpp"
#include "plane_stress_trial.hpp"
#include "plyform/material/strain_rate.hpp"
#include "plyform/material/thermal_plasticity.hpp"

namespace plyform::material {

// ---------------------------------------------------------------------------------------------
// Isotropic plane stress. The elastic step (one vectorised pass, plane_stress_trial.hpp) is shared
// by the elastic law and the trial of the plastic laws:
//   d sxx = E/(1 - nu^2) (dxx + nu dyy), d syy = E/(1 - nu^2) (dyy + nu dxx), d sxy = 2 G dxy,
//   d syz = 2 G dyz, d szx = 2 G dzx, dzz = -nu/(1 - nu) (dxx + dyy) = -(nu/E)(d sxx + d syy).
// ---------------------------------------------------------------------------------------------
namespace {

// Plane-stress J2 return (Simo-Taylor), per point after the elastic trial. In p = sxx + syy,
// q = sxx - syy, t = sxy the plane-stress elasticity and the flow d eps^p = dlam 3/2 s / sigma_eq
// (s the deviator of (sxx, syy, sxy, szz = 0)) decouple:
//   d eps^p_xx + d eps^p_yy = gamma p / 2,  d eps^p_xx - d eps^p_yy = 3/2 gamma q,
//   d eps^p_xy = 3/2 gamma t,  gamma = dlam / sigma_eq,
// and with p = E/(1 - nu) (eps_xx + eps_yy)^e, q = 2 G (eps_xx - eps_yy)^e, t = 2 G eps_xy^e the
// backward-Euler stress is p = p_tr / (1 + a gamma), (q, t) = (q_tr, t_tr) / (1 + b gamma),
// a = E / (2 (1 - nu)), b = 3 G; sigma_eq^2 = p^2 / 4 + 3 q^2 / 4 + 3 t^2. The scalar gamma
// solves sigma_eq(gamma)^2 = sigma_y(eps_p + gamma sigma_eq(gamma))^2 (detail::
// plane_stress_return). The return changes p by p - p_tr, so the elastic thickness strain of
// the trial is corrected by -(nu/E)(p - p_tr), and the plastic part is
// d eps^p_zz = -(d eps^p_xx + d eps^p_yy) = -gamma p / 2.
// `hardening(p)`: point p's yield curve (the law's, scaled by the point's Cowper-Symonds
// factor, or read from a rate table at the point's rate).
template <class Make>
void plane_stress_return_kernel(const Make& hardening, double young, double nu, std::size_t n,
                                double* __restrict sxx, double* __restrict syy,
                                double* __restrict sxy, double* __restrict eps_p,
                                double* __restrict dzz) {
  using H = decltype(hardening(std::size_t{0}));
  if constexpr (std::is_same_v<H, detail::LinearHardening>) {
    // The common bilinear case: the yielding points' returns are solved together.
    detail::LinearPlaneStressBatch batch(sxx, syy, sxy, eps_p, dzz);
    for (std::size_t p = 0; p < n; ++p) {
      const double x = sxx[p], y = syy[p], t = sxy[p];
      const double psi2 = x * x + y * y - x * y + 3.0 * t * t;
      const detail::LinearHardening h = hardening(p);
      const double sy_n = h.value(eps_p[p]);
      if (psi2 > sy_n * sy_n)
        batch.add(p, young, nu, h.sigy, h.hp, x + y, x - y, t, std::sqrt(psi2));
    }
    return;
  }
  const double a = 0.5 * young / (1.0 - nu);
  const double b = 1.5 * young / (1.0 + nu);
  const double nu_e = nu / young;
  for (std::size_t p = 0; p < n; ++p) {
    const double x = sxx[p], y = syy[p], t = sxy[p];
    const double psi2 = x * x + y * y - x * y + 3.0 * t * t;
    const H h = hardening(p);
    const double sy_n = h.value(eps_p[p]);
    if (!(psi2 > sy_n * sy_n))
      continue;
    const double p_tr = x + y, q_tr = x - y;
    const double big_a = 0.25 * p_tr * p_tr;
    const double big_b = 0.75 * q_tr * q_tr + 3.0 * t * t;
    const double g =
        detail::plane_stress_return(h, a, b, big_a, big_b, eps_p[p], std::sqrt(psi2), sy_n);
    const double ua = 1.0 / (1.0 + a * g), ub = 1.0 / (1.0 + b * g);
    const double pp = p_tr * ua, qq = q_tr * ub;
    sxx[p] = 0.5 * (pp + qq);
    syy[p] = 0.5 * (pp - qq);
    sxy[p] = t * ub;
    eps_p[p] += g * std::sqrt(big_a * ua * ua + big_b * ub * ub);
    dzz[p] += -nu_e * (pp - p_tr) - 0.5 * g * pp;
  }
}

template <class Law>
void shell_j2(const Law& m, std::size_t n, const ShellPoints& s) {
  // The rates read the increments, which the trial leaves as they are (it overwrites dzz,
  // which the rate does not read).
  detail::plane_stress_trial(m.young, m.poisson, n, s);
  const auto kernel = [&](const auto& hardening) {
    plane_stress_return_kernel(hardening, m.young, m.poisson, n, s.sxx, s.syy, s.sxy, s.eps_p,
                               s.dzz);
  };
  if constexpr (std::is_same_v<Law, core::PiecewiseLinearPlasticity>) {
    if (!m.rate_values.empty()) {
      kernel(
          [&](std::size_t p) { return detail::rate_table_at(m, shell_strain_rate(s, p, s.dt)); });
      return;
    }
  }
  const CowperSymonds rate{m.rate_c, m.rate_p};
  detail::with_hardening(m, [&](const auto& h) {
    if (rate.on() && s.dt > 0.0) {
      kernel([&](std::size_t p) {
        return detail::scaled(h, rate.factor(shell_strain_rate(s, p, s.dt)));
      });
    } else {
      kernel([&](std::size_t) { return h; });
    }
  });
}

// ---------------------------------------------------------------------------------------------
// Orthotropic plane stress in the material axes (a at angle t from x, b = n x a, c = n).
// Strains to the material axes (tensor shear), c = cos t, s = sin t:
//   e_a = c^2 e_xx + s^2 e_yy + 2 c s e_xy,  e_b = s^2 e_xx + c^2 e_yy - 2 c s e_xy,
//   e_ab = c s (e_yy - e_xx) + (c^2 - s^2) e_xy,  e_ca = c e_zx + s e_yz,  e_bc = c e_yz - s e_zx.
// Reduced stiffness (sigma_c = 0), with the compliance S_aa = 1/EA, S_bb = 1/EB,
// S_ab = -PRBA/EB: Q_aa = EA / D, Q_bb = EB / D, Q_ab = PRBA EA / D, D = 1 - PRBA^2 EA / EB;
// s_ab = 2 GAB e_ab, s_ca = 2 GCA e_ca, s_bc = 2 GBC e_bc. Back to x, y:
//   s_xx = c^2 s_a + s^2 s_b - 2 c s s_ab,  s_yy = s^2 s_a + c^2 s_b + 2 c s s_ab,
//   s_xy = c s (s_a - s_b) + (c^2 - s^2) s_ab,  s_zx = c s_ca - s s_bc,  s_yz = s s_ca + c s_bc.
// Thickness: e_c = S_ca s_a + S_cb s_b = -(PRCA/EC) s_a - (PRCB/EC) s_b.
// ---------------------------------------------------------------------------------------------
struct OrthoConstants {
  double qaa, qbb, qab, two_gab, two_gca, two_gbc, sca, scb;
};

void orthotropic_kernel(std::size_t n, OrthoConstants k, const double* __restrict cos_t,
                        const double* __restrict sin_t, const double* __restrict dxx,
                        const double* __restrict dyy, const double* __restrict dxy,
                        const double* __restrict dyz, const double* __restrict dzx,
                        double* __restrict sxx, double* __restrict syy, double* __restrict sxy,
                        double* __restrict syz, double* __restrict szx, double* __restrict dzz) {
  for (std::size_t p = 0; p < n; ++p) {
    const double c = cos_t[p], s = sin_t[p];
    const double cc = c * c, ss = s * s, cs = c * s;
    const double ea = cc * dxx[p] + ss * dyy[p] + 2.0 * cs * dxy[p];
    const double eb = ss * dxx[p] + cc * dyy[p] - 2.0 * cs * dxy[p];
    const double eab = cs * (dyy[p] - dxx[p]) + (cc - ss) * dxy[p];
    const double eca = c * dzx[p] + s * dyz[p];
    const double ebc = c * dyz[p] - s * dzx[p];
    const double sa = k.qaa * ea + k.qab * eb;
    const double sb = k.qab * ea + k.qbb * eb;
    const double sab = k.two_gab * eab;
    const double sca = k.two_gca * eca;
    const double sbc = k.two_gbc * ebc;
    sxx[p] += cc * sa + ss * sb - 2.0 * cs * sab;
    syy[p] += ss * sa + cc * sb + 2.0 * cs * sab;
    sxy[p] += cs * (sa - sb) + (cc - ss) * sab;
    szx[p] += c * sca - s * sbc;
    syz[p] += s * sca + c * sbc;
    dzz[p] = k.sca * sa + k.scb * sb;
  }
}

}  // namespace

void shell_update(const core::ElasticMaterial& m, std::size_t n, const ShellPoints& pts) {
  detail::plane_stress_trial(m.young, m.poisson, n, pts);
}

void shell_update(const core::PiecewiseLinearPlasticity& m, std::size_t n, const ShellPoints& pts) {
  shell_j2(m, n, pts);
}

void shell_update(const core::PowerLawPlasticity& m, std::size_t n, const ShellPoints& pts) {
  shell_j2(m, n, pts);
}

namespace {

// The plane-stress constants of *MAT_004 at the temperatures met in one call, remembered in a
// small direct-mapped table: the points of an element share their thickness points'
// temperatures (ELFORM 16's four in-plane columns; every point of a thin thermal shell), and the
// table search and divisions of constants_at cost more than the point's elastic trial.
class ThermalConstantsMemo {
 public:
  struct Entry {
    double young, nu, sigy, hardening;  // constants_at's
    double c11, c12, two_g, nu_zz;      // the elastic trial's (plane_stress_trial's)
  };
  explicit ThermalConstantsMemo(const core::ElasticPlasticThermal& m) : m_(m) {}
  const Entry& at(double t) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &t, sizeof bits);
    const std::size_t slot = static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 60);
    if (!filled_[slot] || key_[slot] != bits) {
      const ThermalPlasticConstants c = constants_at(m_, t);
      const double nu = c.poisson;
      const double c11 = c.young / (1.0 - nu * nu);
      entry_[slot] = {c.young,        nu, c.sigy, c.hardening, c11, nu * c11, c.young / (1.0 + nu),
                      nu / (1.0 - nu)};
      key_[slot] = bits;
      filled_[slot] = true;
    }
    return entry_[slot];
  }

 private:
  static constexpr std::size_t kSlots = 16;
  const core::ElasticPlasticThermal& m_;
  std::uint64_t key_[kSlots] = {};
  bool filled_[kSlots] = {};
  Entry entry_[kSlots];
};

}  // namespace

// The constants at each point's temperature, then the elastic trial over a block of points at
// once, then the yielding points' plane-stress returns of *MAT_024 together.
void shell_update(const core::ElasticPlasticThermal& m, std::size_t n, const ShellPoints& pts) {
  detail::LinearPlaneStressBatch batch(pts.sxx, pts.syy, pts.sxy, pts.eps_p, pts.dzz);
  ThermalConstantsMemo memo(m);
  constexpr std::size_t kBlock = 64;
  // Per point of the block: the trial's constants and the yield's (copied: a later temperature
  // may take the memo's slot).
  double c11[kBlock], c12[kBlock], two_g[kBlock], nu_zz[kBlock];
  double young[kBlock], nu[kBlock], sigy[kBlock], hardening[kBlock];
  for (std::size_t p0 = 0; p0 < n; p0 += kBlock) {
    const std::size_t block = std::min(kBlock, n - p0);
    for (std::size_t i = 0; i < block; ++i) {
      const ThermalConstantsMemo::Entry& c = memo.at(pts.temperature[p0 + i]);
      young[i] = c.young;
      nu[i] = c.nu;
      sigy[i] = c.sigy;
      hardening[i] = c.hardening;
      c11[i] = c.c11;
      c12[i] = c.c12;
      two_g[i] = c.two_g;
      nu_zz[i] = c.nu_zz;
    }
    double* __restrict sxx = pts.sxx + p0;
    double* __restrict syy = pts.syy + p0;
    double* __restrict sxy = pts.sxy + p0;
    double* __restrict syz = pts.syz + p0;
    double* __restrict szx = pts.szx + p0;
    double* __restrict dzz = pts.dzz + p0;
    const double* __restrict dxx = pts.dxx + p0;
    const double* __restrict dyy = pts.dyy + p0;
    const double* __restrict dxy = pts.dxy + p0;
    const double* __restrict dyz = pts.dyz + p0;
    const double* __restrict dzx = pts.dzx + p0;
    for (std::size_t i = 0; i < block; ++i) {
      sxx[i] += c11[i] * dxx[i] + c12[i] * dyy[i];
      syy[i] += c12[i] * dxx[i] + c11[i] * dyy[i];
      sxy[i] += two_g[i] * dxy[i];
      syz[i] += two_g[i] * dyz[i];
      szx[i] += two_g[i] * dzx[i];
      dzz[i] = -nu_zz[i] * (dxx[i] + dyy[i]);
    }
    for (std::size_t i = 0; i < block; ++i) {
      const std::size_t p = p0 + i;
      const double x = pts.sxx[p], y = pts.syy[p], t = pts.sxy[p];
      const double psi2 = x * x + y * y - x * y + 3.0 * t * t;
      const double sy_n = sigy[i] + hardening[i] * pts.eps_p[p];
      if (psi2 > sy_n * sy_n)
        batch.add(p, young[i], nu[i], sigy[i], hardening[i], x + y, x - y, t, std::sqrt(psi2));
    }
  }
}

void shell_update(const core::OrthotropicElasticMaterial& m, std::size_t n, const ShellPoints& pts,
                  const double* cos_t, const double* sin_t) {
  const double den = 1.0 - m.prba * m.prba * m.ea / m.eb;
  const OrthoConstants k{m.ea / den,  m.eb / den,  m.prba * m.ea / den, 2.0 * m.gab,
                         2.0 * m.gca, 2.0 * m.gbc, -m.prca / m.ec,      -m.prcb / m.ec};
  orthotropic_kernel(n, k, cos_t, sin_t, pts.dxx, pts.dyy, pts.dxy, pts.dyz, pts.dzx, pts.sxx,
                     pts.syy, pts.sxy, pts.syz, pts.szx, pts.dzz);
}

}  // namespace plyform::material
