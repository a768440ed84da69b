// Unconditional stability of the backward-Euler damage update: for dt/eta over twelve decades
// beta stays in [0, 1], never rises while opening, and large dt/eta gives the rate-independent
// omega / (C_N g^2).
#include <gtest/gtest.h>

#include <cmath>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

TEST(Stability, BetaStaysBoundedAndMonotoneForAnyStepRatio) {
  for (double ratio = 1e-6; ratio <= 1.0001e6; ratio *= 10.0) {
    const double dt = 1e-4;
    Parameters p = test::probe_parameters(dt / ratio);
    const Law law(p);
    // 500 steps from 0 to 50 g_c: dt fixed, so the rate is 1e-3 mm per step.
    const auto run =
        drive(law, test::opening_path(50 * 0.01 / (500 * dt), 50 * 0.01, 500), {1000.0});
    double last = 1.0;
    for (const auto& s : run) {
      const double b = s.history.beta;
      ASSERT_GE(b, 0.0) << "dt/eta = " << ratio;
      ASSERT_LE(b, 1.0) << "dt/eta = " << ratio;
      ASSERT_LE(b, last) << "beta rose while opening, dt/eta = " << ratio;
      ASSERT_TRUE(std::isfinite(s.response.pressure));
      last = b;
    }
    if (ratio >= 1e6) {
      // Quasi-static limit: beta = omega / (C_N g^2) to O(eta / (dt Y)).
      for (const auto& s : run) {
        const double g = s.at.gap;
        if (g < 1.2 * test::critical_gap(p) || s.history.beta == 0.0)
          continue;
        const double qs = test::omega(p) / (p.cn * g * g);
        EXPECT_NEAR(s.history.beta, qs, 1e-3 * qs) << "g = " << g;
      }
    }
  }
}

TEST(Stability, OneHugeStepLandsOnTheQuasiStaticBranch) {
  const Parameters p = test::probe_parameters(1e-9);
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);
  Increment in;
  in.gap = 3 * test::critical_gap(p);
  in.dt = 1.0;  // dt / eta = 1e9
  in.k_normal = 1000.0;
  in.temperature = 300.0;
  const Response r = law.update(in, h);
  EXPECT_NEAR(h.beta, 1.0 / 9.0, 1e-7);  // error (1 - 1/9) / (1 + dt Y / eta)
  EXPECT_NEAR(-r.pressure, 0.3 / 27.0, 1e-8);
}

}  // namespace
}  // namespace plyform::law
