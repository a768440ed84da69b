// A longitudinal wave in a bar under uniaxial strain (lateral motion suppressed) travels at
// c = sqrt(E (1 - nu) / (rho (1 + nu)(1 - 2 nu))): the half-amplitude point of a velocity step
// reaches the middle of the bar at L / (2 c). Also: the run is identical with 1 and 2 threads.
#include <gtest/gtest.h>

#include <cmath>

#include "recording_sink.hpp"
#include "solid_models.hpp"

namespace plyform::engine {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kRho = 7.85e-9;  // MPa, t/mm^3
constexpr double kLength = 400.0;                           // mm, 400 elements of 1 mm

core::Model bar(core::SolidFormulation form) {
  core::Model m =
      test::box(kLength, 1.0, 1.0, 400, 1, 1, core::ElasticMaterial{kRho, kE, kNu}, form);
  test::fix(m, test::nodes_where(m, [](double, double, double) { return true; }),
            core::dof_y | core::dof_z);
  const core::Index c = test::add_curve(m, {0.0, 1.0}, {1.0, 1.0});
  test::prescribe(m, test::nodes_where(m, [](double x, double, double) { return x < 1e-9; }), 0,
                  core::MotionKind::velocity, c, 1000.0);  // 1 m/s step at x = 0
  m.controls.end_time = 0.8 * kLength / std::sqrt(kE / kRho);
  m.output.nodout_dt = 1e-8;
  m.output.history_nodes = test::nodes_where(m, [](double x, double y, double z) {
    return test::near(x, kLength / 2) && y < 1e-9 && z < 1e-9;
  });
  return m;
}

class WaveBar : public ::testing::TestWithParam<core::SolidFormulation> {};

TEST_P(WaveBar, FrontTravelsAtTheDilatationalSpeed) {
  const core::Model m = bar(GetParam());
  test::RecordingSink sink;
  const core::Index probe = m.output.history_nodes.at(0);
  double arrival = -1.0;
  sink.on_nodout = [&](const Snapshot& s) {
    if (arrival < 0.0 && s.nodes->vnx[static_cast<std::size_t>(probe)] >= 500.0)
      arrival = s.time;
  };
  const RunResult r = run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  const double c = std::sqrt(kE * (1 - kNu) / (kRho * (1 + kNu) * (1 - 2 * kNu)));
  ASSERT_GT(arrival, 0.0);
  const double measured = (kLength / 2) / arrival;
  EXPECT_NEAR(measured, c, 0.01 * c);
}

TEST_P(WaveBar, OneAndTwoThreadsGiveTheSameNumbers) {
  const core::Model m = bar(GetParam());
  std::vector<double> final_state[2];
  for (int threads : {1, 2}) {
    test::RecordingSink sink;
    auto& out = final_state[threads - 1];
    sink.on_state = [&](const Snapshot& s) {
      out = s.nodes->ux;
      out.insert(out.end(), s.nodes->vx.begin(), s.nodes->vx.end());
      out.insert(out.end(), (*s.solids)[0].s[0].begin(), (*s.solids)[0].s[0].end());
    };
    SolverOptions o;
    o.threads = threads;
    const RunResult r = run(m, sink, o);
    ASSERT_TRUE(r.ok) << r.error;
  }
  ASSERT_EQ(final_state[0].size(), final_state[1].size());
  for (std::size_t i = 0; i < final_state[0].size(); ++i) {
    ASSERT_EQ(final_state[0][i], final_state[1][i]) << i;
  }
}

INSTANTIATE_TEST_SUITE_P(BothFormulations, WaveBar,
                         ::testing::Values(core::SolidFormulation::one_point,
                                           core::SolidFormulation::selective_reduced));

}  // namespace
}  // namespace plyform::engine
