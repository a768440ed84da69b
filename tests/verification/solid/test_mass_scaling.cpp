// Mass scaling (*CONTROL_TIMESTEP DT2MS): on a uniform mesh every element has the same stable
// step dt_e, so reaching a target T needs the density times (T / dt_e)^2 everywhere: the added
// mass is m (T^2 / dt_e^2 - 1), the step becomes TSSFAC T, and the run stays stable and
// conservative.
#include <gtest/gtest.h>

#include <cmath>

#include "plyform/element/solid_kernels.hpp"
#include "recording_sink.hpp"
#include "solid_models.hpp"

namespace plyform::engine {
namespace {

TEST(MassScaling, AddsTheClosedFormMassAndRaisesTheStep) {
  core::Model m =
      test::box(40.0, 4.0, 4.0, 20, 2, 2, core::ElasticMaterial{7.85e-9, 210000.0, 0.3});
  const element::NodalView view{m.x0.data(), m.y0.data(), m.z0.data(), m.x0.data(), m.y0.data(),
                                m.z0.data(), m.x0.data(), m.y0.data(), m.z0.data()};
  const double dte = element::solid_stable_dt(m.solid_blocks[0], m.materials[0], view, 0);
  const double target = 4.0 * dte;
  m.controls.dt2ms = -target;
  m.controls.end_cycle = 500;
  m.controls.end_time = 1.0;
  m.output.glstat_dt = 1e-9;
  const std::size_t n = m.node_count();
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    m.v0x[i] = 100.0 * std::sin(M_PI * m.x0[i] / 40.0);
  test::RecordingSink sink;
  const RunResult r = run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  const double physical = 7.85e-9 * 640.0;
  EXPECT_NEAR(r.physical_mass, physical, 1e-12 * physical);
  EXPECT_NEAR(r.added_mass, physical * 15.0, 1e-9 * physical);
  // The step of the elements in compression is the bulk viscosity's, L / (Q + sqrt(Q^2 + c^2))
  // with Q = Q2 c + Q1 l |tr D| (Q2 0.06; the quadratic term is 4e-6 of c here).
  const double q = 0.06;
  EXPECT_NEAR(r.dt_first, 0.9 * target / (q + std::sqrt(1.0 + q * q)), 1e-5 * target);
  const double e0 = sink.energies.front().total;
  for (const Energies& e : sink.energies)
    EXPECT_NEAR(e.total, e0, 0.005 * e0);
}

}  // namespace
}  // namespace plyform::engine
