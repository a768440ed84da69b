// Belytschko-Tsay shells against closed forms: the membrane patch test on a distorted mesh, a
// rigid in-plane rotation through 120 degrees (objectivity), the first frequency of a simply
// supported plate, the tip deflection of a cantilever strip, and uniaxial plastic tension.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "plyform/element/shell_kernels.hpp"
#include "plyform/material/plasticity.hpp"
#include "recording_sink.hpp"
#include "shell_models.hpp"
#include "solid_models.hpp"

namespace plyform {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kRho = 7.85e-9;
const core::ElasticMaterial kSteel{kRho, kE, kNu};

TEST(ShellPatch, MembraneStressIsExactAndInteriorForcesCancel) {
  core::Model m = test::plate(2.0, 2.0, 2, 2, 0.1, kSteel, 3);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::size_t centre = 0;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    if (test::near(m.x0[i], 1.0) && test::near(m.y0[i], 1.0))
      centre = i;
    m.x0[i] += u(rng);
    m.y0[i] += u(rng);
  }
  const std::size_t n = m.node_count();
  // v = L x with an in-plane velocity gradient (stretch, shear, spin).
  const double l[2][2] = {{1.0, 0.4}, {-0.1, -0.6}};
  std::vector<double> packed(6 * n), w(n, 0.0), fx(n, 0.0), fy(n, 0.0), fz(n, 0.0), mx(n, 0.0),
      my(n, 0.0), mz(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    packed[6 * i] = m.x0[i];
    packed[6 * i + 1] = m.y0[i];
    packed[6 * i + 2] = 0.0;
    packed[6 * i + 3] = l[0][0] * m.x0[i] + l[0][1] * m.y0[i];
    packed[6 * i + 4] = l[1][0] * m.x0[i] + l[1][1] * m.y0[i];
    packed[6 * i + 5] = 0.0;
  }
  element::NodalView view{nullptr,     nullptr, nullptr, m.x0.data(), m.y0.data(),
                          m.z0.data(), nullptr, nullptr, nullptr};
  view.packed = packed.data();
  element::ShellBlockState st;
  st.resize(m.shell_blocks[0]);
  const double dt = 1e-6;
  const element::ShellResult r = element::shell_forces(
      m.shell_blocks[0], m.materials[0], st, view, {w.data(), w.data(), w.data()}, dt, 0, 4,
      {fx.data(), fy.data(), fz.data()}, {mx.data(), my.data(), mz.data()});
  ASSERT_FALSE(r.failed);
  // Plane-stress stress of the strain increment in global x, y (the element frame rotates it):
  // compare invariants, which do not depend on the frame.
  const double c = kE / (1 - kNu * kNu), g = kE / (2 * (1 + kNu));
  // On the mid-step configuration (I - dt/2 L) X, where the element evaluates the rate:
  // L_m = L (I - dt/2 L)^-1.
  const double h = 0.5 * dt;
  const double a00 = 1 - h * l[0][0], a01 = -h * l[0][1], a10 = -h * l[1][0], a11 = 1 - h * l[1][1];
  const double det2 = a00 * a11 - a01 * a10;
  const double i00 = a11 / det2, i01 = -a01 / det2, i10 = -a10 / det2, i11 = a00 / det2;
  const double lm[2][2] = {{l[0][0] * i00 + l[0][1] * i10, l[0][0] * i01 + l[0][1] * i11},
                           {l[1][0] * i00 + l[1][1] * i10, l[1][0] * i01 + l[1][1] * i11}};
  const double dxx = lm[0][0] * dt, dyy = lm[1][1] * dt, dxy = 0.5 * (lm[0][1] + lm[1][0]) * dt;
  const double sxx = c * (dxx + kNu * dyy), syy = c * (dyy + kNu * dxx), sxy = 2 * g * dxy;
  const double trace = sxx + syy, det = sxx * syy - sxy * sxy;
  for (std::size_t q = 0; q < st.s[0].size(); ++q) {
    EXPECT_NEAR(st.s[0][q] + st.s[1][q], trace, 1e-9 * std::abs(trace));
    EXPECT_NEAR(st.s[0][q] * st.s[1][q] - st.s[2][q] * st.s[2][q], det, 1e-9 * std::abs(det));
  }
  const double scale = std::abs(sxx) * 0.1;
  EXPECT_NEAR(fx[centre], 0.0, 1e-9 * scale);
  EXPECT_NEAR(fy[centre], 0.0, 1e-9 * scale);
}

TEST(ShellObjectivity, RigidInPlaneRotationLeavesNoStress) {
  // Every node follows x(t) = R(theta(t)) X about the z axis, theta to 120 degrees.
  core::Model m = test::plate(10.0, 2.0, 5, 1, 0.5, kSteel, 3);
  const double end = 2e-4, theta_end = 2.0 * M_PI / 3.0;
  const int k = 4000;  // the curves' chords shorten the strip by theta_step^2 / 8
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    std::vector<double> t, ux, uy;
    for (int s = 0; s <= k; ++s) {
      const double tt = end * s / k, th = theta_end * s / k;
      t.push_back(tt);
      ux.push_back(std::cos(th) * m.x0[i] - std::sin(th) * m.y0[i] - m.x0[i]);
      uy.push_back(std::sin(th) * m.x0[i] + std::cos(th) * m.y0[i] - m.y0[i]);
    }
    const auto node = static_cast<core::Index>(i);
    test::prescribe(m, {node}, 0, core::MotionKind::displacement, test::add_curve(m, t, ux));
    test::prescribe(m, {node}, 1, core::MotionKind::displacement, test::add_curve(m, t, uy));
    m.fixed.push_back({node, core::dof_z | core::dof_rx | core::dof_ry});
  }
  m.controls.end_time = end;
  m.output.d3plot_dt = end / 4;
  test::RecordingSink sink;
  double worst = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    for (const auto& c : (*s.shells)[0].s)
      for (double v : c)
        worst = std::max(worst, std::abs(v));
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  // A stretch of 1e-6 would give 0.2 MPa; the tabulated rotation's chords account for about
  // 7e-3 MPa, the element for nothing more.
  EXPECT_LT(worst, 0.02);
}

// Simply supported square plate, initial velocity in its first mode: the centre deflection
// crosses zero at intervals of half the period 1 / f11, f11 = (pi/2)(2/a^2) sqrt(D/(rho t)).
class ShellPlateRule : public ::testing::TestWithParam<core::ThicknessRule> {};

TEST_P(ShellPlateRule, SimplySupportedFirstFrequency) {
  const double a = 100.0, t = 1.0;
  core::Model m = test::plate(a, a, 16, 16, t, kSteel, 3);
  m.shell_blocks[0].rule = GetParam();  // 3 Gauss or 3 Lobatto points: both exact in bending
  const std::size_t n = m.node_count();
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 0.0);
  m.w0x.assign(n, 0.0);
  m.w0y.assign(n, 0.0);
  m.w0z.assign(n, 0.0);
  core::Index centre = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = m.x0[i], y = m.y0[i];
    m.v0z[i] = 100.0 * std::sin(M_PI * x / a) * std::sin(M_PI * y / a);
    // The Kirchhoff rotations of the mode: theta_x = dw/dy, theta_y = -dw/dx.
    m.w0x[i] = 100.0 * M_PI / a * std::sin(M_PI * x / a) * std::cos(M_PI * y / a);
    m.w0y[i] = -100.0 * M_PI / a * std::cos(M_PI * x / a) * std::sin(M_PI * y / a);
    if (test::near(x, a / 2) && test::near(y, a / 2))
      centre = static_cast<core::Index>(i);
    const bool edge = x < 1e-9 || y < 1e-9 || x > a - 1e-9 || y > a - 1e-9;
    if (edge)
      m.fixed.push_back({static_cast<core::Index>(i), core::dof_z});
  }
  // In-plane rigid motion removed at two corners.
  m.fixed.push_back({0, core::dof_x | core::dof_y});
  m.fixed.push_back({16, core::dof_y});
  const double d = kE * t * t * t / (12 * (1 - kNu * kNu));
  const double f11 = M_PI / 2 * 2 / (a * a) * std::sqrt(d / (kRho * t));
  m.controls.end_time = 2.2 / f11;
  m.output.nodout_dt = 1e-7;
  m.output.glstat_dt = 1e-6;
  m.output.history_nodes = {centre};
  test::RecordingSink sink;
  std::vector<double> crossings;
  double last_w = 0.0, last_t = 0.0;
  sink.on_nodout = [&](const engine::Snapshot& s) {
    const double w = s.nodes->uz[static_cast<std::size_t>(centre)];
    if (s.time > 0.0 && last_w != 0.0 && (w > 0) != (last_w > 0)) {
      crossings.push_back(last_t + (s.time - last_t) * last_w / (last_w - w));
    }
    last_w = w;
    last_t = s.time;
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_GE(crossings.size(), 4u);
  const double period = 2.0 * (crossings[3] - crossings[1]) / 2.0;
  const double f = 1.0 / period;
  EXPECT_NEAR(f, f11, 0.02 * f11) << "f = " << f << " Hz, f11 = " << f11 << " Hz";
  // No damping: the total energy is kept (hourglass control does not engage in this mode).
  const double e0 = sink.energies.front().total;
  for (const auto& e : sink.energies)
    EXPECT_NEAR(e.total, e0, 0.01 * e0) << "t = " << e.time;
}

INSTANTIATE_TEST_SUITE_P(GaussAndLobatto, ShellPlateRule,
                         ::testing::Values(core::ThicknessRule::gauss,
                                           core::ThicknessRule::lobatto));

// Cantilever strip under a slowly applied tip load: the static deflection P L^3 / (3 E I).
TEST(ShellPlate, CantileverTipDeflection) {
  const double l = 100.0, b = 10.0, t = 1.0, p = 0.1;
  core::Model m = test::plate(l, b, 40, 4, t, kSteel, 3);
  std::vector<core::Index> tip;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const auto node = static_cast<core::Index>(i);
    if (m.x0[i] < 1e-9)
      m.fixed.push_back({node, 63u});
    if (m.x0[i] > l - 1e-9)
      tip.push_back(node);
  }
  const double i_area = b * t * t * t / 12.0;
  const double omega1 = 1.8751 * 1.8751 * std::sqrt(kE * i_area / (kRho * b * t)) / (l * l);
  const double period = 2 * M_PI / omega1;
  std::vector<double> tt, ff;
  for (int s = 0; s <= 200; ++s) {
    const double x = s / 200.0;
    tt.push_back(3 * period * x);
    ff.push_back(x * x * (3 - 2 * x));
  }
  tt.push_back(10.0);
  ff.push_back(1.0);
  const core::Index curve = test::add_curve(m, tt, ff);
  for (core::Index node : tip) {
    m.loads.push_back({node, 2, curve, p / static_cast<double>(tip.size())});
  }
  m.controls.end_time = 4 * period;
  m.output.nodout_dt = period / 200;
  m.output.history_nodes = {tip[tip.size() / 2]};
  test::RecordingSink sink;
  double sum = 0.0;
  int count = 0;
  sink.on_nodout = [&](const engine::Snapshot& s) {
    if (s.time < 3 * period)
      return;  // the mean over the last period: the static deflection
    sum += s.nodes->uz[static_cast<std::size_t>(m.output.history_nodes[0])];
    ++count;
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_GT(count, 50);
  const double expected = p * l * l * l / (3 * kE * i_area);
  EXPECT_NEAR(sum / count, expected, 0.02 * expected);
}

// A strip pulled slowly past yield with a piecewise-linear hardening curve: the stress follows
// the curve, the thickness strain is about minus half the plastic strain (incompressibility),
// unloading is elastic with slope E.
TEST(ShellPlasticity, UniaxialTensionFollowsTheCurve) {
  core::PiecewiseLinearPlasticity mat;
  mat.density = kRho;
  mat.young = kE;
  mat.poisson = kNu;
  mat.curve.plastic_strain = {0.0, 0.02, 0.05, 0.2};
  mat.curve.yield_stress = {200.0, 260.0, 300.0, 360.0};
  const double l = 20.0, b = 4.0, t = 1.0;
  core::Model m = test::plate(l, b, 4, 1, t, mat, 5);
  std::vector<core::Index> right;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const auto node = static_cast<core::Index>(i);
    if (m.x0[i] < 1e-9)
      m.fixed.push_back({node, core::dof_x});
    if (m.x0[i] > l - 1e-9)
      right.push_back(node);
    m.fixed.push_back({node, core::dof_z | core::dof_rx | core::dof_ry | core::dof_rz});
  }
  m.fixed.push_back({0, core::dof_y});
  // Pull to 8 % and back by 0.1 % (smooth ramps), slowly against the strip axial period.
  const double end = 2e-3;
  std::vector<double> tt, uu;
  for (int s = 0; s <= 400; ++s) {
    const double x = s / 400.0;
    tt.push_back(0.8 * end * x);
    uu.push_back(0.08 * l * x * x * (3 - 2 * x));
  }
  for (int s = 1; s <= 100; ++s) {
    const double x = s / 100.0;
    tt.push_back(0.8 * end + 0.2 * end * x);
    uu.push_back(0.08 * l - 0.001 * l * x * x * (3 - 2 * x));
  }
  const core::Index curve = test::add_curve(m, tt, uu);
  test::prescribe(m, right, 0, core::MotionKind::displacement, curve);
  m.controls.end_time = end;
  m.output.d3plot_dt = end / 50;
  test::RecordingSink sink;
  int checked = 0;
  double peak_stress = 0.0, peak_strain = 0.0, last_stress = 0.0, last_strain = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    const auto& st = (*s.shells)[0];
    // Logarithmic strain: the stress is a Cauchy stress.
    const double strain = std::log(1.0 + s.nodes->ux[static_cast<std::size_t>(right[0])] / l);
    const double sxx = st.s[0][2];  // element 1, middle point
    const double eps_p = st.eps_p[2];
    if (strain >= peak_strain) {
      if (eps_p > 0.005) {
        const double expected = material::yield_stress(mat, eps_p);
        EXPECT_NEAR(sxx, expected, 0.01 * expected) << "eps_p " << eps_p;
        // Thickness: elastic -nu sigma / E plus plastic -eps_p / 2.
        const double thick = std::log(st.thickness[0] / t);
        const double expected_thick = -0.5 * eps_p - kNu * sxx / kE;
        EXPECT_NEAR(thick, expected_thick, 0.02 * std::abs(expected_thick)) << "eps_p " << eps_p;
        ++checked;
      }
      peak_stress = sxx;
      peak_strain = strain;
    }
    last_stress = sxx;
    last_strain = strain;
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GT(checked, 10);
  // Unloading from the largest strain: elastic, slope E (uniaxial stress).
  const double slope = (peak_stress - last_stress) / (peak_strain - last_strain);
  EXPECT_NEAR(slope, kE, 0.01 * kE);
}

}  // namespace
}  // namespace plyform

namespace plyform {
namespace {

// A shell block with a material the shell kernel has no law for (setup refuses such a part; a
// model built in code can still hold one): the run stops at once and says so, naming the element
// and part, instead of reporting a collapsed element.
TEST(ShellKernel, AMaterialWithoutAShellLawIsReportedAsSuch) {
  core::Model m =
      test::plate(2.0, 1.0, 2, 1, 0.1, core::MooneyRivlinMaterial{1e-9, 0.49, 0.5, 0.1});
  m.controls.end_time = 1e-6;
  test::RecordingSink sink;
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.error.find("the shell kernel has no law for the material of shell element 1 "
                         "(part 1)"),
            std::string::npos)
      << r.error;
  EXPECT_EQ(r.error.find("volume"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace plyform
