// Shells (Belytschko-Tsay, ELFORM 2, and fully integrated, ELFORM 16) that turn fast and far
// keep their energy (a conservation law):
// - a free square tumbling about in-plane and oblique axes (a rigid rotation: nothing may
//   strain it, and its kinetic energy is constant). The mid-surface's velocity gradient is
//   mapped to the mid-step configuration as a whole 3 x 3; with its in-plane block alone the
//   turning plane saw a stretch rate omega^2 dt / 2 and the square gained 0.8 % of its energy
//   per 2 rad at omega dt = 0.0044;
// - a simply supported plate vibrating in its first mode at ten times its thickness (large
//   rotations, membrane stretching): it gained 20-35 % over five periods before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "recording_sink.hpp"
#include "shell_models.hpp"

namespace plyform {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kRho = 7.85e-9;  // mm, s, t, MPa
const core::ElasticMaterial kSteel{kRho, kE, kNu};

struct Books {
  double worst_ratio = 0.0;  // largest |total / (kinetic0 + external work) - 1|
  double most_internal = 0.0;
  double kinetic0 = 0.0;
};

Books books_of(const test::RecordingSink& sink) {
  Books b;
  b.kinetic0 = sink.energies.front().kinetic;
  for (const engine::Energies& e : sink.energies) {
    b.worst_ratio = std::max(b.worst_ratio, std::abs(e.ratio - 1.0));
    b.most_internal = std::max(b.most_internal, e.internal);
  }
  return b;
}

class ShellRotation : public ::testing::TestWithParam<core::ShellFormulation> {};

TEST_P(ShellRotation, FreeSquareTumblingKeepsItsEnergyAndStaysUnstrained) {
  // 10 mm square, 4 x 4 elements 0.5 thick, centred on the origin; omega dt about 0.0044.
  const double omega = 1.0e4;
  for (const auto& axis :
       {std::array<double, 3>{1.0, 0.0, 0.0}, std::array<double, 3>{0.6, 0.8, 0.0},
        std::array<double, 3>{0.6, 0.0, 0.8}}) {
    core::Model m = test::plate(10.0, 10.0, 4, 4, 0.5, kSteel, 3);
    m.shell_blocks[0].formulation = GetParam();
    const std::size_t n = m.node_count();
    for (std::size_t i = 0; i < n; ++i) {
      m.x0[i] -= 5.0;
      m.y0[i] -= 5.0;
    }
    const double w[3] = {omega * axis[0], omega * axis[1], omega * axis[2]};
    m.v0x.resize(n);
    m.v0y.resize(n);
    m.v0z.resize(n);
    m.w0x.assign(n, w[0]);
    m.w0y.assign(n, w[1]);
    m.w0z.assign(n, w[2]);
    for (std::size_t i = 0; i < n; ++i) {  // v = w x r
      const double r[3] = {m.x0[i], m.y0[i], m.z0[i]};
      m.v0x[i] = w[1] * r[2] - w[2] * r[1];
      m.v0y[i] = w[2] * r[0] - w[0] * r[2];
      m.v0z[i] = w[0] * r[1] - w[1] * r[0];
    }
    m.controls.end_time = 2.0 / omega;  // 2 rad
    m.output.glstat_dt = m.controls.end_time / 50;
    test::RecordingSink sink;
    const engine::RunResult r = engine::run(m, sink, {});
    ASSERT_TRUE(r.ok) << r.error;
    const Books b = books_of(sink);
    std::printf(
        "tumbling about (%.1f, %.1f, %.1f): energy within %.2e, internal energy up to "
        "%.2e of the kinetic\n",
        axis[0], axis[1], axis[2], b.worst_ratio, b.most_internal / b.kinetic0);
    EXPECT_LT(b.worst_ratio, 1e-4);
    EXPECT_LT(b.most_internal, 1e-3 * b.kinetic0);
  }
}

TEST_P(ShellRotation, PlateVibratingAtTenTimesItsThicknessKeepsItsEnergy) {
  // The first mode of a simply supported 100 mm square, 1 mm thick, 16 x 16, started at
  // 1e5 mm/s (an amplitude near 10 mm: membrane stiffening shortens the period to about
  // 0.8 ms), viscous hourglass control at its default (ELFORM 2; ELFORM 16 has none), five
  // periods.
  const double a = 100.0, v0 = 1.0e5;
  core::Model m = test::plate(a, a, 16, 16, 1.0, kSteel, 3);
  m.shell_blocks[0].hourglass.ihq = 1;
  m.shell_blocks[0].hourglass.qm = 0.1;
  m.shell_blocks[0].formulation = GetParam();
  const std::size_t n = m.node_count();
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 0.0);
  m.w0x.assign(n, 0.0);
  m.w0y.assign(n, 0.0);
  m.w0z.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = m.x0[i], y = m.y0[i];
    m.v0z[i] = v0 * std::sin(M_PI * x / a) * std::sin(M_PI * y / a);
    m.w0x[i] = v0 * M_PI / a * std::sin(M_PI * x / a) * std::cos(M_PI * y / a);
    m.w0y[i] = -v0 * M_PI / a * std::cos(M_PI * x / a) * std::sin(M_PI * y / a);
    const bool edge = x < 1e-9 || y < 1e-9 || x > a - 1e-9 || y > a - 1e-9;
    if (edge)
      m.fixed.push_back({static_cast<core::Index>(i), core::dof_z});
  }
  m.fixed.push_back({0, core::dof_x | core::dof_y});
  m.fixed.push_back({16, core::dof_y});
  m.controls.end_time = 4.0e-3;
  m.output.glstat_dt = 2.0e-5;
  test::RecordingSink sink;
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  const Books b = books_of(sink);
  std::printf("plate at large amplitude: energy within %.2e over %zu rows\n", b.worst_ratio,
              sink.energies.size());
  EXPECT_GT(b.most_internal, 0.5 * b.kinetic0);  // it does swing through its strain energy
  EXPECT_LT(b.worst_ratio, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Elform, ShellRotation,
                         ::testing::Values(core::ShellFormulation::belytschko_tsay,
                                           core::ShellFormulation::fully_integrated),
                         [](const ::testing::TestParamInfo<core::ShellFormulation>& i) {
                           return "ELFORM_" + std::to_string(static_cast<int>(i.param));
                         });

}  // namespace
}  // namespace plyform
