// Conservation: along press - pull apart - press and hold (re-healing) - pull apart, with a
// constant tangential velocity throughout, friction, normal damping and viscous adhesion,
// the work done on the interface equals what it stores plus what it dissipates (damage,
// viscous, friction, damping), to the time-discretisation error.
#include <gtest/gtest.h>

#include <cmath>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

// Piecewise-linear gap history through (time, gap) knots, sampled every dt.
std::vector<PathPoint> piecewise(const std::vector<std::pair<double, double>>& knots, double dt,
                                 double slip_rate) {
  std::vector<PathPoint> path;
  const double t_end = knots.back().first;
  const auto n = static_cast<int>(std::round(t_end / dt));
  std::size_t k = 1;
  for (int i = 0; i <= n; ++i) {
    PathPoint pt;
    pt.time = t_end * i / n;
    while (k + 1 < knots.size() && pt.time > knots[k].first)
      ++k;
    const auto [t0, g0] = knots[k - 1];
    const auto [t1, g1] = knots[k];
    pt.gap = g0 + (g1 - g0) * (pt.time - t0) / (t1 - t0);
    pt.slip[0] = slip_rate * pt.time;
    pt.slip[1] = -0.5 * slip_rate * pt.time;
    pt.temperature = 300.0;
    path.push_back(pt);
  }
  return path;
}

TEST(EnergyBalance, WorkEqualsStoredPlusDissipated) {
  Parameters p = test::probe_parameters(3e-6);
  p.bond_tol = 0.0;
  p.zeta = {3.0, 3.0, -1};
  p.mu = {0.3, 0.3, -1};
  p.vdc = 10.0;
  const Law law(p);
  const double gc = test::critical_gap(p);
  const double pressed = -1e-3;  // P = 1 MPa with k = 1000
  const auto path = piecewise({{0.0, 2 * gc},
                               {0.1, pressed},
                               {0.2, pressed},
                               {0.5, 60 * gc},
                               {0.6, pressed},
                               {0.8, pressed},  // heals by zeta P t = 0.6
                               {1.1, 60 * gc}},
                              2e-6, 0.05);
  const DriverSettings settings{1000.0, 500.0, 1.0, 1e-9};
  const auto run = drive(law, path, settings);
  const NodeHistory& h = run.back().history;
  const double work = interface_work(run);
  const double books =
      run.back().response.stored + h.e_damage + h.e_viscous + h.e_friction + h.e_damping;
  EXPECT_EQ(h.state, NodeState::detached);
  EXPECT_NEAR(h.e_healing, 0.6 * test::omega(p), 0.01 * test::omega(p));
  EXPECT_GT(h.e_damage, 1.5 * test::omega(p));  // debonded twice, healed in between
  EXPECT_GT(h.e_friction, 0.0);
  EXPECT_GT(h.e_viscous, 0.0);
  EXPECT_GT(h.e_damping, 0.0);
  EXPECT_NEAR(work, books, 0.01 * work);
}

}  // namespace
}  // namespace plyform::law
