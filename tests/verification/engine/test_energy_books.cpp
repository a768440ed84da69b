// The energy books a run judges itself by (docs/energy.md):
// - a clamped elastic plate given a velocity at t = 0 (a jump: the edges stop at once and the
//   mesh's highest modes ring): the central differences conserve 1/2 m v_{n-1/2} v_{n+1/2}
//   plus the stored energy exactly for a linear system, so the books close to round-off until
//   the last two steps are cut to land on the end time (the mean velocity's 1/2 m v_n^2 read
//   1.02-1.03 throughout at TSSFAC 0.9);
// - a run that gains energy (a step above the stability limit) stops once its energy ratio
//   leaves the band, naming a node and keeping a last state; ENDENG narrows the band;
// - a run whose hourglass energy exceeds 10 % of its largest internal energy ends with its
//   books distrusted, the reason and the time it first held.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "recording_sink.hpp"
#include "shell_models.hpp"

namespace plyform {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kRho = 7.85e-9;  // mm, s, t, MPa
const core::ElasticMaterial kSteel{kRho, kE, kNu};
constexpr double kUnstableTssfac = 1.05;

// A square plate 40 x 40 mm, 1 mm thick, 8 x 8 Belytschko-Tsay shells, every edge node
// clamped (translations and rotations).
core::Model clamped_plate() {
  core::Model m = test::plate(40.0, 40.0, 8, 8, 1.0, kSteel, 3);
  const std::size_t n = m.node_count();
  for (std::size_t i = 0; i < n; ++i) {
    const bool edge =
        m.x0[i] < 1e-9 || m.x0[i] > 40.0 - 1e-9 || m.y0[i] < 1e-9 || m.y0[i] > 40.0 - 1e-9;
    if (edge)
      m.fixed.push_back(core::FixedDofs{
          static_cast<core::Index>(i),
          core::dof_x | core::dof_y | core::dof_z | core::dof_rx | core::dof_ry | core::dof_rz});
  }
  // Given 1 mm/ms out of plane, the edges held at once; 1 ms, glstat every 10 us.
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 1000.0);
  m.controls.end_time = 1e-3;
  m.output.glstat_dt = 1e-5;
  return m;
}

TEST(EnergyBooks, ClampedPlateGivenAVelocityClosesToRoundOff) {
  // 1 mm/ms across the plate, its edges held: amplitude about 0.03 thicknesses (linear).
  // First period about 0.18 ms; run 1 ms. Belytschko-Tsay with stiffness hourglass control
  // (IHQ 4) and the fully integrated shell: no velocity-dependent force (docs/energy.md: a
  // viscous one's work is booked at the step's velocity, which the integrator's own books of
  // a mesh ringing at its highest modes do not match).
  for (const double tssfac : {0.9, 0.45}) {
    for (const bool full : {false, true}) {
      core::Model m = clamped_plate();
      if (full)
        m.shell_blocks[0].formulation = core::ShellFormulation::fully_integrated;
      else
        m.shell_blocks[0].hourglass = core::HourglassControl{4, 0.1};
      m.controls.tssfac = tssfac;
      test::RecordingSink sink;
      const engine::RunResult r = engine::run(m, sink, {});
      ASSERT_TRUE(r.ok) << r.error;
      // Every row before the last, and the last, where the last two steps are cut to land on
      // the end time: each force booked on dt_avg / 2 each side of its time, the books follow
      // the step's change exactly (on the steps' own halves the end read 1e-3).
      double worst = 0.0;
      for (std::size_t k = 0; k + 1 < sink.energies.size(); ++k)
        worst = std::max(worst, std::abs(sink.energies[k].ratio - 1.0));
      const double end = std::abs(sink.energies.back().ratio - 1.0);
      std::printf(
          "clamped plate (%s), TSSFAC %.2f: ratio within %.2e of 1 before the end, "
          "%.2e at the end (the mean velocity's kinetic energy read 1.02-1.03 at 0.9)\n",
          full ? "ELFORM 16" : "BT, IHQ 4", tssfac, worst, end);
      EXPECT_LT(worst, 1e-4);
      EXPECT_LT(end, 1e-4);
      EXPECT_TRUE(r.distrust.empty());
      EXPECT_GT(sink.energies.back().internal, 0.0);
    }
  }
}

TEST(EnergyBooks, ARunThatGainsEnergyStopsWithADiagnosis) {
  // TSSFAC above 1: every step beyond the elements' stability limit. The highest modes grow
  // from round-off; the run stops once its ratio leaves 1 +- 0.5, with the books and the
  // fastest node, before the geometry turns to NaN.
  core::Model m = clamped_plate();
  m.shell_blocks[0].hourglass = core::HourglassControl{4, 0.1};
  m.controls.tssfac = kUnstableTssfac;
  test::RecordingSink sink;
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_FALSE(r.ok);
  std::printf("%s\n", r.error.c_str());
  EXPECT_NE(r.error.find("the energy ratio"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("left the band 1 +- 0.5 at"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("the fastest node is"), std::string::npos) << r.error;
  EXPECT_FALSE(sink.state_times.empty());  // the last state is written
  EXPECT_LT(r.time, m.controls.end_time);

  // ENDENG 5 (per cent): the same run stops no later, at its band.
  m.controls.energy_change_limit = 0.05;
  test::RecordingSink sink2;
  const engine::RunResult r2 = engine::run(m, sink2, {});
  ASSERT_FALSE(r2.ok);
  std::printf("%s\n", r2.error.c_str());
  EXPECT_NE(r2.error.find("left the band 1 +- 0.05 (*CONTROL_TERMINATION ENDENG)"),
            std::string::npos)
      << r2.error;
  EXPECT_LE(r2.time, r.time);
}

TEST(EnergyBooks, HourglassBeyondTenPercentDistrustsTheResults) {
  // The clamped plate on one-point shells with the default viscous hourglass control: the
  // jump at its edges rings the elements' hourglass modes, whose energy passes 10 % of the
  // largest internal energy (19 % at the end). The run reaches its end; its results are not
  // to be trusted, and it says so with the time.
  core::Model m = clamped_plate();
  test::RecordingSink sink;
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  double peak_internal = 0.0;
  double first_over = -1.0;  // the first glstat time with hourglass > 10 % of the peak so far
  for (const engine::Energies& e : sink.energies) {
    peak_internal = std::max(peak_internal, e.internal);
    if (first_over < 0.0 && e.hourglass > 0.1 * peak_internal)
      first_over = e.time;
  }
  std::printf(
      "hourglass %.4g against the largest internal energy %.4g; first above 10 %% at "
      "%.4g\n",
      sink.energies.back().hourglass, peak_internal, first_over);
  ASSERT_GT(first_over, 0.0);
  ASSERT_FALSE(r.distrust.empty());
  EXPECT_NE(r.distrust.front().reason.find("hourglass"), std::string::npos);
  // Judged at every glstat row and every 100 cycles: first held within a row of the sink's.
  EXPECT_LE(r.distrust.front().time, first_over + 1e-12);
  EXPECT_GT(r.distrust.front().time, first_over - 1e-5 - 1e-12);
}

}  // namespace
}  // namespace plyform
