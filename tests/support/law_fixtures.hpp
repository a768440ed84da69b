#pragma once
// Shared set-ups for the contact-law tests: a parameter set of the paper's order of magnitude
// (soft acrylic probe layer, sigma_max = 0.3 MPa; units mm, s, MPa, N) and path builders.

#include <cmath>
#include <vector>

#include "plyform/law/law.hpp"
#include "plyform/law/point_driver.hpp"

namespace plyform::test {

/// sigma_max = 0.3 MPa, C_N = 30 MPa/mm: g_c = 0.01 mm, omega = 3e-3 N/mm.
inline law::Parameters probe_parameters(double eta = 1e-6) {
  law::Parameters p;
  p.cn = 30.0;
  p.sigma_max = {0.3, 0.3, -1};
  p.t_lo = 300.0;
  p.t_hi = 500.0;
  p.eta = eta;
  p.zeta = {0.0, 0.0, -1};
  p.beta0 = 1.0;
  p.bond_tol = 1e-6;
  return p;
}

inline double critical_gap(const law::Parameters& p) {
  return p.sigma_max.lo / p.cn;
}
inline double omega(const law::Parameters& p) {
  return p.sigma_max.lo * p.sigma_max.lo / p.cn;
}

/// Opening at constant rate v from gap 0 to g_end in n steps, constant temperature.
inline std::vector<law::PathPoint> opening_path(double v, double g_end, int n,
                                                double temperature = 300.0) {
  std::vector<law::PathPoint> path(static_cast<std::size_t>(n) + 1);
  const double t_end = g_end / v;
  for (int i = 0; i <= n; ++i) {
    auto& pt = path[static_cast<std::size_t>(i)];
    pt.time = t_end * i / n;
    pt.gap = v * pt.time;
    pt.temperature = temperature;
  }
  return path;
}

/// Largest cohesive tension along a run, and the gap where it occurs.
struct Peak {
  double tension = 0.0;
  double gap = 0.0;
};
inline Peak peak_tension(const std::vector<law::PathSample>& s) {
  Peak pk;
  for (const auto& x : s) {
    if (-x.response.pressure > pk.tension) {
      pk.tension = -x.response.pressure;
      pk.gap = x.at.gap;
    }
  }
  return pk;
}

}  // namespace plyform::test
