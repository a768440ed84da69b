#include "plyform/material/plasticity.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "hardening.hpp"
#include "plyform/material/strain_rate.hpp"
#include "plyform/material/thermal_plasticity.hpp"

namespace plyform::material {

double yield_stress(const core::PiecewiseLinearPlasticity& m, double eps_p) {
  return detail::with_hardening(m, [&](const auto& h) { return h.value(eps_p); });
}
double yield_slope(const core::PiecewiseLinearPlasticity& m, double eps_p) {
  return detail::with_hardening(m, [&](const auto& h) { return h.slope(eps_p); });
}
double yield_stress(const core::PowerLawPlasticity& m, double eps_p) {
  return detail::with_hardening(m, [&](const auto& h) { return h.value(eps_p); });
}
double yield_slope(const core::PowerLawPlasticity& m, double eps_p) {
  return detail::with_hardening(m, [&](const auto& h) { return h.slope(eps_p); });
}
double power_law_offset(const core::PowerLawPlasticity& m) {
  return detail::with_hardening(m, [](const detail::PowerHardening& h) { return h.e0; });
}

// ---------------------------------------------------------------------------------------------
// 3D J2 radial return. After the elastic Jaumann trial (elastic_jaumann, one vectorised pass),
// each point with q_tr = sqrt(3/2 s_tr : s_tr) > sigma_y(eps_p) is returned along the trial
// deviator: s = s_tr (1 - 3 G dlam / q_tr), q = q_tr - 3 G dlam = sigma_y(eps_p + dlam)
// (backward Euler with the normal n = 3/2 s / q, which the radial return keeps fixed).
// ---------------------------------------------------------------------------------------------
namespace {

// `hardening(p)`: point p's yield curve (the law's, scaled by the point's Cowper-Symonds
// factor, or read from a rate table at the point's rate).
template <class Make>
void radial_return_kernel(const Make& hardening, double three_g, std::size_t n,
                          double* __restrict sxx, double* __restrict syy, double* __restrict szz,
                          double* __restrict sxy, double* __restrict syz, double* __restrict szx,
                          double* __restrict eps_p) {
  for (std::size_t p = 0; p < n; ++p) {
    const double mean = (sxx[p] + syy[p] + szz[p]) / 3.0;
    const double dxx = sxx[p] - mean, dyy = syy[p] - mean, dzz = szz[p] - mean;
    const double ss = dxx * dxx + dyy * dyy + dzz * dzz +
                      2.0 * (sxy[p] * sxy[p] + syz[p] * syz[p] + szx[p] * szx[p]);
    const double q_tr = std::sqrt(1.5 * ss);
    const auto h = hardening(p);
    const double sy_n = h.value(eps_p[p]);
    if (!(q_tr > sy_n))
      continue;
    const double dlam = detail::radial_return(h, three_g, q_tr, eps_p[p], sy_n);
    const double f = 1.0 - three_g * dlam / q_tr;
    sxx[p] = mean + f * dxx;
    syy[p] = mean + f * dyy;
    szz[p] = mean + f * dzz;
    sxy[p] *= f;
    syz[p] *= f;
    szx[p] *= f;
    eps_p[p] += dlam;
  }
}

template <class Law>
void solid_j2(const Law& m, std::size_t n, ConstSymView d, const double* w_xy, const double* w_yz,
              const double* w_zx, double dt, SymView sigma, double* eps_p) {
  elastic_jaumann(core::ElasticMaterial{m.density, m.young, m.poisson}, n, d, w_xy, w_yz, w_zx, dt,
                  sigma);
  const double three_g = 1.5 * m.young / (1.0 + m.poisson);
  const auto kernel = [&](const auto& hardening) {
    radial_return_kernel(hardening, three_g, n, sigma.xx, sigma.yy, sigma.zz, sigma.xy, sigma.yz,
                         sigma.zx, eps_p);
  };
  if constexpr (std::is_same_v<Law, core::PiecewiseLinearPlasticity>) {
    if (!m.rate_values.empty()) {
      kernel([&](std::size_t p) { return detail::rate_table_at(m, solid_strain_rate(d, p)); });
      return;
    }
  }
  const CowperSymonds rate{m.rate_c, m.rate_p};
  detail::with_hardening(m, [&](const auto& h) {
    if (rate.on())
      kernel(
          [&](std::size_t p) { return detail::scaled(h, rate.factor(solid_strain_rate(d, p))); });
    else
      kernel([&](std::size_t) { return h; });
  });
}

}  // namespace

ThermalPlasticConstants constants_at(const core::ElasticPlasticThermal& m, double t) {
  const std::vector<double>& x = m.temperature;
  std::size_t i = 0;
  double w = 0.0;  // the weight of point i + 1
  if (x.size() > 1 && t > x.front()) {
    if (t >= x.back()) {
      i = x.size() - 2;
      w = 1.0;
    } else {
      i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin()) - 1;
      w = (t - x[i]) / (x[i + 1] - x[i]);
    }
  }
  const auto at = [&](const std::vector<double>& v) {
    return v.size() > 1 ? v[i] + w * (v[i + 1] - v[i]) : v.front();
  };
  ThermalPlasticConstants c;
  c.young = at(m.young);
  c.poisson = at(m.poisson);
  c.sigy = at(m.sigy);
  const double etan = at(m.etan);
  c.hardening = c.young * etan / (c.young - etan);
  return c;
}

// Point by point: each point has its own constants. Views shifted to point p.
void solid_update(const core::ElasticPlasticThermal& m, std::size_t n, ConstSymView d,
                  const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                  const double* temperature, SymView sigma, double* eps_p) {
  for (std::size_t p = 0; p < n; ++p) {
    const ThermalPlasticConstants c = constants_at(m, temperature[p]);
    const ConstSymView dp{d.xx + p, d.yy + p, d.zz + p, d.xy + p, d.yz + p, d.zx + p};
    const SymView sp{sigma.xx + p, sigma.yy + p, sigma.zz + p,
                     sigma.xy + p, sigma.yz + p, sigma.zx + p};
    elastic_jaumann(core::ElasticMaterial{m.density, c.young, c.poisson}, 1, dp, w_xy + p, w_yz + p,
                    w_zx + p, dt, sp);
    const detail::LinearHardening h{c.sigy, c.hardening};
    radial_return_kernel([&](std::size_t) { return h; }, 1.5 * c.young / (1.0 + c.poisson), 1,
                         sp.xx, sp.yy, sp.zz, sp.xy, sp.yz, sp.zx, eps_p + p);
  }
}

void solid_update(const core::PiecewiseLinearPlasticity& m, std::size_t n, ConstSymView d,
                  const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                  SymView sigma, double* eps_p) {
  solid_j2(m, n, d, w_xy, w_yz, w_zx, dt, sigma, eps_p);
}

void solid_update(const core::PowerLawPlasticity& m, std::size_t n, ConstSymView d,
                  const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                  SymView sigma, double* eps_p) {
  solid_j2(m, n, d, w_xy, w_yz, w_zx, dt, sigma, eps_p);
}

}  // namespace plyform::material
