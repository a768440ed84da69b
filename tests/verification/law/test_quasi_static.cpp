// Rate-independent limit (eta -> 0) of monotonic opening from beta = 1, against the closed
// forms of docs/contact-law.md: peak sigma_max at g_c = sigma_max / C_N, softening
// sigma_max (g_c/g)^3, work of separation omega = sigma_max^2 / C_N.
#include <gtest/gtest.h>

#include <cmath>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

using test::critical_gap;
using test::omega;

struct QuasiStatic : ::testing::Test {
  // Lambda = eta v / (omega g_c) = 1e-7: far in the quasi-static regime.
  Parameters p = test::probe_parameters(1e-7 * 3e-3 * 0.01 / 1.0);
  Law law{p};
  std::vector<PathSample> run = drive(law, test::opening_path(1.0, 40 * 0.01, 40000), {1000.0});

  double tension_at(double g) const {
    for (const auto& s : run) {
      if (std::abs(s.at.gap - g) < 1e-12)
        return -s.response.pressure;
    }
    ADD_FAILURE() << "no sample at g = " << g;
    return 0.0;
  }
};

TEST_F(QuasiStatic, PeakIsSigmaMaxAtTheCriticalGap) {
  const test::Peak pk = test::peak_tension(run);
  EXPECT_NEAR(pk.tension, 0.3, 0.005 * 0.3);
  EXPECT_NEAR(pk.gap, critical_gap(p), 0.01 * critical_gap(p));
}

TEST_F(QuasiStatic, SofteningFollowsTheCubicDecay) {
  const double gc = critical_gap(p);
  for (double x : {2.0, 4.0}) {
    const double expected = 0.3 / (x * x * x);
    EXPECT_NEAR(tension_at(x * gc), expected, 0.01 * expected) << "at g = " << x << " g_c";
  }
  // The elastic branch is linear with slope C_N.
  EXPECT_NEAR(tension_at(0.5 * gc), p.cn * 0.5 * gc, 1e-12);
}

TEST_F(QuasiStatic, WorkOfSeparationIsOmega) {
  ASSERT_EQ(run.back().history.state, NodeState::detached);
  const double w = interface_work(run);
  EXPECT_NEAR(w, omega(p), 0.01 * omega(p));
  // The law's own books agree: released adhesion energy omega (plus, at the BETA_MIN cut-off,
  // the elastic energy still held there, about omega BETA_MIN / 2), no viscous part to speak of.
  const NodeHistory& h = run.back().history;
  EXPECT_NEAR(h.e_damage, omega(p) * (1.0 + 0.5 * p.beta_min), 1e-6 * omega(p));
  EXPECT_LT(h.e_viscous, 1e-4 * omega(p));
}

TEST_F(QuasiStatic, RateIndependentLimitIsOmegaOverYBeyondTheCriticalGap) {
  for (const auto& s : run) {
    const double g = s.at.gap;
    if (g < 1.5 * critical_gap(p) || s.history.beta == 0.0)
      continue;
    const double expected = omega(p) / (p.cn * g * g);
    ASSERT_NEAR(s.history.beta, expected, 1e-6 * expected) << "g = " << g;
  }
}

TEST(QuasiStaticTemperature, PeakFollowsTheCubicInterpolationOfSigmaMax) {
  Parameters p = test::probe_parameters(1e-12);
  p.sigma_max = {0.5, 0.1, -1};
  const Law law(p);
  for (double t : {300.0, 350.0, 400.0, 450.0, 500.0}) {
    const double smax = evaluate(p.sigma_max, p, t);
    const double gc = smax / p.cn;
    const auto run = drive(law, test::opening_path(1.0, 5 * gc, 5000, t), {1000.0});
    const double expected =
        0.5 + (0.1 - 0.5) * [](double s) { return 3 * s * s - 2 * s * s * s; }((t - 300.0) / 200.0);
    EXPECT_NEAR(smax, expected, 1e-14);
    EXPECT_NEAR(test::peak_tension(run).tension, expected, 0.005 * expected) << "T = " << t;
  }
}

}  // namespace
}  // namespace plyform::law
