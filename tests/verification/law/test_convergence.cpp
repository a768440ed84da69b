// Backward Euler is first order: against an independent RK4 solution of the damage ODE
// eta beta' = -(C_N (v t)^2 beta - omega), the error of the viscous peak halves with dt.
#include <gtest/gtest.h>

#include <cmath>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

// Peak tension of the exact (RK4, fine step) solution for opening at rate v.
double reference_peak(const Parameters& p, double v) {
  const double sigma = p.sigma_max.lo;
  const double om = sigma * sigma / p.cn;
  const double tc = (sigma / p.cn) / v;  // damage starts at g_c
  const auto rate = [&](double t, double b) {
    const double y = p.cn * v * t * v * t;
    return y * b > om ? -(y * b - om) / p.eta : 0.0;
  };
  const int n = 2'000'000;
  const double t_end = 20 * tc, h = (t_end - tc) / n;
  double b = 1.0, t = tc, peak = sigma;
  for (int i = 0; i < n; ++i) {
    const double k1 = rate(t, b), k2 = rate(t + h / 2, b + h / 2 * k1),
                 k3 = rate(t + h / 2, b + h / 2 * k2), k4 = rate(t + h, b + h * k3);
    b += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    t += h;
    peak = std::max(peak, p.cn * v * t * b * b);
  }
  return peak;
}

TEST(Convergence, ViscousPeakConvergesAtFirstOrder) {
  const Parameters p = test::probe_parameters(3e-5);  // Lambda = 1 at v = 1
  const Law law(p);
  const double v = 1.0, gc = test::critical_gap(p);
  const double ref = reference_peak(p, v);
  EXPECT_GT(ref, 1.1 * 0.3);
  std::vector<double> errors;
  for (int per_gc : {25, 50, 100, 200, 400}) {
    const auto run = drive(law, test::opening_path(v, 20 * gc, 20 * per_gc), {1000.0});
    errors.push_back(std::abs(test::peak_tension(run).tension - ref));
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    EXPECT_NEAR(order, 1.0, 0.15) << "refinement " << i << ": errors " << errors[i - 1] << " -> "
                                  << errors[i];
  }
  EXPECT_LT(errors.back() / ref, 2e-3);
}

}  // namespace
}  // namespace plyform::law
