// Re-healing under pressure (paper eq. 4, 5, 8): full recovery from beta_0 after
// (1 - beta_0) / (zeta P); none in tension; re-sticking from beta = 0; the healed intensity
// beta_h gives the quasi-static peak sigma_max beta_h^(3/2) on the next opening.
#include <gtest/gtest.h>

#include <cmath>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

constexpr double kPenalty = 1000.0;

Increment hold(double gap, double dt) {
  Increment in;
  in.gap = gap;
  in.dt = dt;
  in.temperature = 300.0;
  in.k_normal = kPenalty;
  in.k_tangent = kPenalty;
  return in;
}

TEST(Healing, ConstantPressureRecoversFullyInTheClosedFormTime) {
  Parameters p = test::probe_parameters();
  p.zeta = {4.0, 4.0, -1};  // 1/(MPa s)
  for (double beta0 : {0.0, 0.3, 0.75}) {
    p.beta0 = beta0;
    const Law law(p);
    NodeHistory h = law.initial_history(0.0);
    const double pressure = 0.5, dt = 1e-3;  // g = -P / k
    const double expected = (1.0 - beta0) / (4.0 * pressure);
    double t = 0.0;
    while (h.beta < 1.0 && t < 10.0) {
      const Response r = law.update(hold(-pressure / kPenalty, dt), h);
      ASSERT_NEAR(r.pressure, pressure, 1e-12);
      t += dt;
    }
    EXPECT_EQ(h.beta, 1.0);
    EXPECT_LE(std::abs(t - expected), dt + 1e-12) << "beta0 = " << beta0;
    EXPECT_NEAR(h.e_healing, test::omega(p) * (1.0 - beta0), 1e-15);
  }
}

// Healing forms new bonds where the layers are: a held shear opening under pressure keeps
// the elastic energy of the adhesive shear spring C_T beta^2 (conservation: no work is done
// while nothing moves), it does not grow with beta^2. Before the opening was rescaled, the
// stored energy grew by (1/beta0)^2 = 4 times here while no work entered.
TEST(Healing, AHeldShearOpeningKeepsItsElasticEnergy) {
  Parameters p = test::probe_parameters();
  p.zeta = {4.0, 4.0, -1};
  p.ct = p.cn;
  p.beta0 = 0.5;
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);
  const double pressure = 0.5, dt = 1e-3;
  Increment in = hold(-pressure / kPenalty, dt);
  in.slip[0] = 0.2 * test::critical_gap(p);  // one shear increment, below the damage threshold
  Response r = law.update(in, h);
  in.slip[0] = 0.0;
  const double normal = 0.5 * kPenalty * in.gap * in.gap;
  // The first step healed already: its stored energy is the one the opening was made with.
  const double shear0 = r.stored - normal;
  double t = 0.0;
  while (h.beta < 1.0 && t < 10.0) {
    r = law.update(in, h);
    t += dt;
  }
  ASSERT_EQ(h.beta, 1.0);
  EXPECT_NEAR(r.stored - normal, shear0, 1e-12 * shear0);
  EXPECT_GT(shear0, 0.0);
}

TEST(Healing, NoHealingInTension) {
  Parameters p = test::probe_parameters();
  p.zeta = {4.0, 4.0, -1};
  p.beta0 = 0.6;
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);
  // Opening below the damage threshold omega / (C_N beta): beta is frozen.
  for (int i = 0; i < 100; ++i)
    law.update(hold(0.5 * test::critical_gap(p), 1e-2), h);
  EXPECT_EQ(h.state, NodeState::separating);
  EXPECT_EQ(h.beta, 0.6);
  EXPECT_EQ(h.e_healing, 0.0);
}

TEST(Healing, TemperatureDependentRate) {
  Parameters p = test::probe_parameters();
  p.zeta = {1.0, 9.0, -1};
  p.beta0 = 0.0;
  const Law law(p);
  for (double t : {300.0, 400.0, 500.0}) {
    NodeHistory h = law.initial_history(0.0);
    Increment in = hold(-1e-4, 1e-3);  // P = 0.1
    in.temperature = t;
    law.update(in, h);
    EXPECT_NEAR(h.beta, evaluate(p.zeta, p, t) * 0.1 * 1e-3, 1e-15);
  }
}

TEST(Healing, ResticksFromFullDebondingAndTheNextPeakReflectsTheHealedBeta) {
  Parameters p = test::probe_parameters(1e-12);
  p.zeta = {2.0, 2.0, -1};
  const Law law(p);
  const double gc = test::critical_gap(p);
  std::vector<PathPoint> path;
  double t = 0.0;
  const auto add = [&](double g) {
    PathPoint pt;
    pt.time = t;
    pt.gap = g;
    pt.temperature = 300.0;
    path.push_back(pt);
    t += 1e-4;
  };
  for (int i = 0; i <= 4000; ++i)
    add(40 * gc * i / 4000.0);  // pull to 40 g_c: debonded
  for (int i = 0; i <= 400; ++i)
    add(40 * gc * (1.0 - i / 400.0) - 0.2 / kPenalty * (i == 400));
  // Hold at P = 0.2 MPa long enough for beta_h = zeta P t_hold = 0.49.
  const double t_hold = 0.49 / (2.0 * 0.2);
  const int n_hold = static_cast<int>(std::round(t_hold / 1e-4));
  for (int i = 0; i < n_hold; ++i)
    add(-0.2 / kPenalty);
  const std::size_t reopen = path.size();
  for (int i = 1; i <= 8000; ++i)
    add(10 * gc * i / 8000.0);

  const auto run = drive(law, path, {kPenalty});
  EXPECT_EQ(run[4000].history.state, NodeState::detached);
  EXPECT_EQ(run[4000].history.beta, 0.0);
  const double beta_h = run[reopen - 1].history.beta;
  EXPECT_NEAR(beta_h, 0.49, 2.0 * 0.2 * 1e-4 + 1e-12);
  double peak = 0.0;
  for (std::size_t i = reopen; i < run.size(); ++i)
    peak = std::max(peak, -run[i].response.pressure);
  const double expected = 0.3 * std::pow(beta_h, 1.5);
  EXPECT_NEAR(peak, expected, 0.005 * expected);
  EXPECT_NEAR(run.back().history.e_healing, test::omega(p) * beta_h, 1e-12);
}

}  // namespace
}  // namespace plyform::law
