// Rigid bodies through the engine: a rigid part turned about an axis by a prescribed rotation
// keeps its nodes on their circles (to round-off), and a rigid punch driving the central nodes
// of a clamped elasto-plastic plate leaves a plastic strain field with the plate's symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "recording_sink.hpp"
#include "shell_models.hpp"
#include "solid_models.hpp"

namespace plyform {
namespace {

TEST(EngineRigid, PrescribedRotationKeepsNodesOnCircles) {
  // A rigid hex block turned about the global z axis through its centre at 200 rad/s.
  core::Model m = test::box(4.0, 2.0, 1.0, 4, 2, 1, core::RigidMaterial{7.85e-9, 210000.0, 0.3});
  for (std::size_t i = 0; i < m.node_count(); ++i)
    m.x0[i] += 10.0;  // off the origin
  const core::Index curve = test::add_curve(m, {0.0, 1.0}, {200.0, 200.0});
  m.rigid_motions.push_back({0, 5, core::MotionKind::velocity, curve, 1.0, 0.0, 1e28});
  m.controls.end_time = 0.01;  // 2 rad
  m.controls.dt_init = 1e-6;
  m.output.d3plot_dt = 0.0025;
  test::RecordingSink sink;
  double worst = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    const double th = 200.0 * s.time;
    for (std::size_t i = 0; i < m.node_count(); ++i) {
      const double rx = m.x0[i] - 12.0, ry = m.y0[i] - 1.0;
      const double ex = 12.0 + std::cos(th) * rx - std::sin(th) * ry;
      const double ey = 1.0 + std::sin(th) * rx + std::cos(th) * ry;
      worst = std::max(worst, std::hypot(s.nodes->x[i] - ex, s.nodes->y[i] - ey));
      worst = std::max(worst, std::abs(s.nodes->z[i] - m.z0[i]));
    }
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(sink.state_times.size(), 5u);
  EXPECT_LT(worst, 1e-11);
}

TEST(EngineRigid, PunchOnAPlasticPlateGivesASymmetricPlasticStrainField) {
  core::PiecewiseLinearPlasticity steel;
  steel.density = 7.85e-9;
  steel.young = 210000.0;
  steel.poisson = 0.3;
  steel.sigy = 200.0;
  steel.etan = 1000.0;
  const double a = 40.0;
  core::Model m = test::plate(a, a, 20, 20, 1.0, steel, 5);
  // The punch: a rigid shell sharing the four nodes of the plate's central 2 x 2 patch corners,
  // free to move in z only (CMO = 1, CON1 = 4: x and y fixed, CON2 = 7: no rotation).
  m.materials.push_back(core::RigidMaterial{7.85e-9, 210000.0, 0.3, 1.0, 4, 7});
  m.parts.push_back(core::Part{2, "punch", 1});
  core::ShellBlock punch;
  punch.part = 1;
  punch.material = 1;
  punch.nip = 1;
  std::map<std::pair<int, int>, core::Index> node_at;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    node_at[{static_cast<int>(std::lround(m.x0[i])), static_cast<int>(std::lround(m.y0[i]))}] =
        static_cast<core::Index>(i);
  }
  punch.element_id.push_back(1000);
  for (auto xy : {std::pair{18, 18}, std::pair{22, 18}, std::pair{22, 22}, std::pair{18, 22}}) {
    punch.connectivity.push_back(node_at.at(xy));
    punch.thickness.push_back(1.0);
  }
  m.shell_blocks.push_back(std::move(punch));
  core::colour_element_blocks(m);
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const double x = m.x0[i], y = m.y0[i];
    if (x < 1e-9 || y < 1e-9 || x > a - 1e-9 || y > a - 1e-9) {
      m.fixed.push_back({static_cast<core::Index>(i), 63u});  // clamped
    }
  }
  // The punch moves down 2 mm on a smooth velocity ramp.
  std::vector<double> tt, vv;
  const double end = 2e-3;
  for (int k = 0; k <= 100; ++k) {
    const double s = k / 100.0;
    tt.push_back(end * s);
    vv.push_back(-2.0 / end * 6.0 * s * (1.0 - s));
  }
  const core::Index curve = test::add_curve(m, tt, vv);
  m.rigid_motions.push_back({1, 2, core::MotionKind::velocity, curve, 1.0, 0.0, 1e28});
  m.controls.end_time = end;
  test::RecordingSink sink;
  std::vector<double> eps;  // per plate element: max over the thickness
  sink.on_state = [&](const engine::Snapshot& s) {
    const auto& st = (*s.shells)[0];
    eps.assign(m.shell_blocks[0].size(), 0.0);
    for (std::size_t e = 0; e < eps.size(); ++e)
      for (int k = 0; k < st.nip; ++k) {
        eps[e] = std::max(
            eps[e], st.eps_p[e * static_cast<std::size_t>(st.nip) + static_cast<std::size_t>(k)]);
      }
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  // Field by element centre, compared with its mirror images in x, y and the diagonal.
  const core::ShellBlock& plate = m.shell_blocks[0];
  std::map<std::pair<int, int>, double> field;
  double peak = 0.0;
  for (std::size_t e = 0; e < plate.size(); ++e) {
    double cx = 0.0, cy = 0.0;
    for (int k = 0; k < 4; ++k) {
      cx += 0.25 *
            m.x0[static_cast<std::size_t>(plate.connectivity[4 * e + static_cast<std::size_t>(k)])];
      cy += 0.25 *
            m.y0[static_cast<std::size_t>(plate.connectivity[4 * e + static_cast<std::size_t>(k)])];
    }
    field[{static_cast<int>(std::lround(2 * cx)), static_cast<int>(std::lround(2 * cy))}] = eps[e];
    peak = std::max(peak, eps[e]);
  }
  ASSERT_GT(peak, 1e-3) << "the punch must yield the plate";
  const int l2 = static_cast<int>(std::lround(2 * a));
  for (const auto& [c, v] : field) {
    const auto [x, y] = c;
    EXPECT_NEAR(field.at({l2 - x, y}), v, 1e-6 * peak) << x << " " << y;
    EXPECT_NEAR(field.at({x, l2 - y}), v, 1e-6 * peak) << x << " " << y;
    EXPECT_NEAR(field.at({y, x}), v, 1e-6 * peak) << x << " " << y;
  }
}

}  // namespace
}  // namespace plyform
