// Energy: a free elastic block vibrating from an initial velocity field keeps its total energy
// (kinetic + internal + hourglass) within 0.5 % over 2000 cycles; the energy ratio stays 1.
#include <gtest/gtest.h>

#include <cmath>

#include "recording_sink.hpp"
#include "solid_models.hpp"

namespace plyform::engine {
namespace {

struct Case {
  core::SolidFormulation form;
  int ihq;
};

class EnergyConservation : public ::testing::TestWithParam<Case> {};

TEST_P(EnergyConservation, TotalEnergyIsKeptOver2000Cycles) {
  core::Model m = test::box(20.0, 4.0, 2.0, 40, 8, 4, core::ElasticMaterial{7.85e-9, 210000.0, 0.3},
                            GetParam().form);
  m.solid_blocks[0].hourglass.ihq = GetParam().ihq;
  const std::size_t n = m.node_count();
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    m.v0x[i] = 1000.0 * std::cos(M_PI * m.x0[i] / 20.0);     // first axial mode
    m.v0y[i] = 500.0 * std::sin(2 * M_PI * m.x0[i] / 20.0);  // and some bending
  }
  m.controls.end_cycle = 2000;
  m.controls.end_time = 1.0;
  m.output.glstat_dt = 1e-7;
  test::RecordingSink sink;
  const RunResult r = run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.cycles, 2000);
  ASSERT_GT(sink.energies.size(), 10u);
  const double e0 = sink.energies.front().total;
  double max_internal = 0.0;
  for (const Energies& e : sink.energies) {
    EXPECT_NEAR(e.total, e0, 0.005 * e0) << "t = " << e.time;
    EXPECT_NEAR(e.ratio, 1.0, 0.005);
    max_internal = std::max(max_internal, e.internal);
  }
  EXPECT_GT(max_internal, 0.2 * e0);  // energy really goes back and forth
}

INSTANTIATE_TEST_SUITE_P(Formulations, EnergyConservation,
                         ::testing::Values(Case{core::SolidFormulation::selective_reduced, 1},
                                           Case{core::SolidFormulation::one_point, 4}));

}  // namespace
}  // namespace plyform::engine
