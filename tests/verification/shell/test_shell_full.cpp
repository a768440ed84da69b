// The fully integrated shell (ELFORM 16) against closed forms: the membrane patch test on a
// distorted mesh, a rigid rotation (objectivity), a free element's stiffness with exactly the
// six rigid-body zero modes (no hourglass modes), the cantilever tip deflection P L^3 / (3 E I)
// on a coarse mesh, and the same at L / t = 1000 (no shear locking, MITC4).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include "plyform/element/shell_kernels.hpp"
#include "recording_sink.hpp"
#include "shell_models.hpp"
#include "solid_models.hpp"

namespace plyform {
namespace test_shell_full {

constexpr double kE = 210000.0, kNu = 0.3, kRho = 7.85e-9;
const core::ElasticMaterial kSteel{kRho, kE, kNu};

core::Model full_plate(double lx, double ly, int nx, int ny, double t, int nip = 3) {
  core::Model m = test::plate(lx, ly, nx, ny, t, kSteel, nip);
  m.shell_blocks[0].formulation = core::ShellFormulation::fully_integrated;
  m.shell_blocks[0].hourglass.qm = 0.0;
  return m;
}

// Internal forces of one kernel call from zero stress at velocities `packed` (positions and
// velocities, 6 per node) and nodal spins w.
struct KernelForces {
  std::vector<double> fx, fy, fz, mx, my, mz;
  element::ShellBlockState st;
  element::ShellResult r;
};
KernelForces kernel_forces(const core::Model& m, const std::vector<double>& packed,
                           const std::array<std::vector<double>, 3>& w, double dt) {
  const std::size_t n = m.node_count();
  KernelForces k;
  for (auto* v : {&k.fx, &k.fy, &k.fz, &k.mx, &k.my, &k.mz})
    v->assign(n, 0.0);
  element::NodalView view{nullptr,     nullptr, nullptr, m.x0.data(), m.y0.data(),
                          m.z0.data(), nullptr, nullptr, nullptr};
  view.packed = packed.data();
  k.st.resize(m.shell_blocks[0]);
  k.r = element::shell_forces(m.shell_blocks[0], m.materials[0], k.st, view,
                              {w[0].data(), w[1].data(), w[2].data()}, dt, 0,
                              m.shell_blocks[0].size(), {k.fx.data(), k.fy.data(), k.fz.data()},
                              {k.mx.data(), k.my.data(), k.mz.data()});
  return k;
}

TEST(ShellFullPatch, MembraneStressIsExactAtEveryPointAndInteriorForcesCancel) {
  core::Model m = full_plate(2.0, 2.0, 2, 2, 0.1);
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
  const double l[2][2] = {{1.0, 0.4}, {-0.1, -0.6}};
  std::vector<double> packed(6 * n);
  for (std::size_t i = 0; i < n; ++i) {
    packed[6 * i] = m.x0[i];
    packed[6 * i + 1] = m.y0[i];
    packed[6 * i + 3] = l[0][0] * m.x0[i] + l[0][1] * m.y0[i];
    packed[6 * i + 4] = l[1][0] * m.x0[i] + l[1][1] * m.y0[i];
  }
  const double dt = 1e-6;
  const std::array<std::vector<double>, 3> w{
      std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  const KernelForces k = kernel_forces(m, packed, w, dt);
  ASSERT_FALSE(k.r.failed);
  ASSERT_EQ(k.st.s[0].size(), 4u * 4u * 3u);  // 4 elements x 4 Gauss points x NIP 3
  const double c = kE / (1 - kNu * kNu), g = kE / (2 * (1 + kNu));
  const double h = 0.5 * dt;
  const double a00 = 1 - h * l[0][0], a01 = -h * l[0][1], a10 = -h * l[1][0], a11 = 1 - h * l[1][1];
  const double det2 = a00 * a11 - a01 * a10;
  const double i00 = a11 / det2, i01 = -a01 / det2, i10 = -a10 / det2, i11 = a00 / det2;
  const double lm[2][2] = {{l[0][0] * i00 + l[0][1] * i10, l[0][0] * i01 + l[0][1] * i11},
                           {l[1][0] * i00 + l[1][1] * i10, l[1][0] * i01 + l[1][1] * i11}};
  const double dxx = lm[0][0] * dt, dyy = lm[1][1] * dt, dxy = 0.5 * (lm[0][1] + lm[1][0]) * dt;
  const double sxx = c * (dxx + kNu * dyy), syy = c * (dyy + kNu * dxx), sxy = 2 * g * dxy;
  const double trace = sxx + syy, det = sxx * syy - sxy * sxy;
  for (std::size_t q = 0; q < k.st.s[0].size(); ++q) {
    EXPECT_NEAR(k.st.s[0][q] + k.st.s[1][q], trace, 1e-9 * std::abs(trace)) << q;
    EXPECT_NEAR(k.st.s[0][q] * k.st.s[1][q] - k.st.s[2][q] * k.st.s[2][q], det,
                1e-9 * std::abs(det))
        << q;
    EXPECT_NEAR(k.st.s[3][q], 0.0, 1e-12 * std::abs(trace));
    EXPECT_NEAR(k.st.s[4][q], 0.0, 1e-12 * std::abs(trace));
  }
  const double scale = std::abs(sxx) * 0.1;
  EXPECT_NEAR(k.fx[centre], 0.0, 1e-9 * scale);
  EXPECT_NEAR(k.fy[centre], 0.0, 1e-9 * scale);
  EXPECT_NEAR(k.fz[centre], 0.0, 1e-9 * scale);
}

// A triangle (N3 = N4, the degenerate quadrilateral) takes a linear membrane field exactly at
// its four points too, and a rigid rotation rate of it gives no stress.
TEST(ShellFullPatch, DegenerateTriangleIsExactInMembraneAndRigidInRotation) {
  core::Model m = full_plate(1.0, 1.0, 1, 1, 0.1);
  m.x0 = {0.0, 1.3, 0.2, 0.0};  // the triangle 1-2-3 (node 4 unused)
  m.y0 = {0.0, 0.1, 0.9, 0.0};
  auto& conn = m.shell_blocks[0].connectivity;
  conn = {0, 1, 2, 2};
  const std::size_t n = m.node_count();
  const double dt = 1e-6;
  const std::array<std::vector<double>, 3> w{
      std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  for (const double spin : {0.0, 1.0}) {
    // Stretch, or a rigid spin about z: v = L x.
    const double l[2][2] = {{spin == 0.0 ? 1.0 : 0.0, spin == 0.0 ? 0.3 : -1.0},
                            {spin == 0.0 ? 0.2 : 1.0, spin == 0.0 ? -0.5 : 0.0}};
    std::vector<double> packed(6 * n);
    for (std::size_t i = 0; i < n; ++i) {
      packed[6 * i] = m.x0[i];
      packed[6 * i + 1] = m.y0[i];
      packed[6 * i + 3] = l[0][0] * m.x0[i] + l[0][1] * m.y0[i];
      packed[6 * i + 4] = l[1][0] * m.x0[i] + l[1][1] * m.y0[i];
      if (spin != 0.0) {
        // A rigid step: x_{n+1} = R(dt) X, v = (x_{n+1} - X) / dt (the mid-step mapping turns
        // it into an exactly skew rate; v = W x_{n+1} alone would stretch at order dt^2).
        const double c = std::cos(dt), sn = std::sin(dt);
        packed[6 * i] = c * m.x0[i] - sn * m.y0[i];
        packed[6 * i + 1] = sn * m.x0[i] + c * m.y0[i];
        packed[6 * i + 3] = (packed[6 * i] - m.x0[i]) / dt;
        packed[6 * i + 4] = (packed[6 * i + 1] - m.y0[i]) / dt;
      }
    }
    const KernelForces k = kernel_forces(m, packed, w, dt);
    ASSERT_FALSE(k.r.failed);
    double lo = 1e300, hi = -1e300;
    for (std::size_t q = 0; q < k.st.s[0].size(); ++q) {
      const double trace = k.st.s[0][q] + k.st.s[1][q];
      lo = std::min(lo, trace);
      hi = std::max(hi, trace);
      if (spin != 0.0) {
        for (int c = 0; c < 5; ++c)
          EXPECT_NEAR(k.st.s[c][q], 0.0, 1e-9) << "component " << c;
      }
    }
    if (spin == 0.0) {
      const double c = kE / (1 - kNu);  // sxx + syy = E/(1 - nu) (dxx + dyy)
      EXPECT_NEAR(lo, hi, 1e-9 * std::abs(hi));
      EXPECT_NEAR(hi, c * 0.5 * dt, 2e-6 * std::abs(hi));  // tr L = 0.5 (mid-step: O(dt))
    }
  }
}

// Eigenvalues of a symmetric matrix (cyclic Jacobi; small matrices only).
std::vector<double> symmetric_eigenvalues(std::vector<std::vector<double>> a) {
  const std::size_t n = a.size();
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0;
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = p + 1; q < n; ++q)
        off += a[p][q] * a[p][q];
    if (off < 1e-30)
      break;
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = p + 1; q < n; ++q) {
        if (a[p][q] == 0.0)
          continue;
        const double theta = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1.0 / std::sqrt(t * t + 1), s = t * c;
        for (std::size_t k = 0; k < n; ++k) {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (std::size_t k = 0; k < n; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
      }
  }
  std::vector<double> ev(n);
  for (std::size_t i = 0; i < n; ++i)
    ev[i] = a[i][i];
  std::sort(ev.begin(), ev.end());
  return ev;
}

// The stiffness of one free distorted element from the kernel: column j is the force (the
// kernel's nodal forces are the internal forces, B^T sigma) of unit
// velocity in dof j over a tiny step from zero stress, divided by the step. Of the 20 dofs that
// carry stiffness (3 translations and the 2 in-plane rotations per node; the drilling rotation
// has none in either formulation) exactly 6 are rigid: the one-point element (no hourglass
// control) has 4 more.
std::vector<double> single_element_spectrum(core::ShellFormulation f) {
  core::Model m = test::plate(2.0, 1.5, 1, 1, 0.2, kSteel, 3);
  m.shell_blocks[0].formulation = f;
  m.shell_blocks[0].hourglass.qm = 0.0;
  m.x0 = {0.0, 2.1, -0.2, 1.8};  // nodes x fastest: element 1-2-4-3
  m.y0 = {0.0, 0.3, 1.2, 1.6};
  const double dt = 1e-9;
  std::vector<std::vector<double>> k(20, std::vector<double>(20, 0.0));
  for (std::size_t j = 0; j < 20; ++j) {
    const std::size_t node = j / 5, dof = j % 5;
    std::vector<double> packed(24, 0.0);
    for (std::size_t i = 0; i < 4; ++i) {
      packed[6 * i] = m.x0[i];
      packed[6 * i + 1] = m.y0[i];
    }
    std::array<std::vector<double>, 3> w{std::vector<double>(4, 0.0), std::vector<double>(4, 0.0),
                                         std::vector<double>(4, 0.0)};
    if (dof < 3)
      packed[6 * node + 3 + dof] = 1.0;
    else
      w[dof - 3][node] = 1.0;
    // Positions at t_{n+1}: the kernel evaluates rates there and maps them to mid-step.
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t d = 0; d < 3; ++d)
        packed[6 * i + d] += packed[6 * i + 3 + d] * dt;
    const KernelForces kf = kernel_forces(m, packed, w, dt);
    EXPECT_FALSE(kf.r.failed);
    for (std::size_t i = 0; i < 4; ++i) {
      k[5 * i][j] = kf.fx[i] / dt;
      k[5 * i + 1][j] = kf.fy[i] / dt;
      k[5 * i + 2][j] = kf.fz[i] / dt;
      k[5 * i + 3][j] = kf.mx[i] / dt;
      k[5 * i + 4][j] = kf.my[i] / dt;
    }
  }
  // Symmetric part (the step's geometric terms are of order dt).
  for (std::size_t i = 0; i < 20; ++i)
    for (std::size_t j = i + 1; j < 20; ++j)
      k[i][j] = k[j][i] = 0.5 * (k[i][j] + k[j][i]);
  return symmetric_eigenvalues(k);
}

std::size_t zero_modes(const std::vector<double>& ev) {
  const double big = std::max(std::abs(ev.front()), std::abs(ev.back()));
  std::size_t zeros = 0;
  for (double e : ev)
    zeros += std::abs(e) < 1e-8 * big ? 1u : 0u;
  return zeros;
}

TEST(ShellFullStiffness, AFreeElementHasExactlySixRigidModes) {
  const std::vector<double> full =
      single_element_spectrum(core::ShellFormulation::fully_integrated);
  EXPECT_EQ(zero_modes(full), 6u);
  for (double e : full)
    EXPECT_GT(e, -1e-8 * std::abs(full.back()));  // positive semi-definite
  // The check itself sees hourglass modes: the one-point element without control has them.
  EXPECT_GT(zero_modes(single_element_spectrum(core::ShellFormulation::belytschko_tsay)), 6u);
}

TEST(ShellFullObjectivity, RigidInPlaneRotationLeavesNoStress) {
  core::Model m = full_plate(10.0, 2.0, 5, 1, 0.5);
  const double end = 2e-4, theta_end = 2.0 * M_PI / 3.0;
  const int k = 4000;
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
  EXPECT_LT(worst, 0.02);  // as the BT test: the tabulated chords' 7e-3 MPa, nothing more
}

// A free square tumbling about an in-plane axis (a rigid rotation out of its plane): the
// nodes' velocities and spins of the rotation, no stress after turning through 2 rad.
TEST(ShellFullObjectivity, TumblingAboutAnInPlaneAxisLeavesNoStress) {
  core::Model m = full_plate(10.0, 10.0, 2, 2, 0.5);
  const std::size_t n = m.node_count();
  const double omega = 10.0;  // about the x axis through the plate's centre line
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 0.0);
  m.w0x.assign(n, omega);
  m.w0y.assign(n, 0.0);
  m.w0z.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double y = m.y0[i] - 5.0;
    m.v0y[i] = 0.0;
    m.v0z[i] = omega * y;
  }
  m.controls.end_time = 2.0 / omega;
  m.output.d3plot_dt = m.controls.end_time / 4;
  test::RecordingSink sink;
  double worst = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    for (const auto& c : (*s.shells)[0].s)
      for (double v : c)
        worst = std::max(worst, std::abs(v));
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  // The centripetal stretch of the spinning plate is rho omega^2 (L/2)^2 ~ 2e-5 MPa; a
  // spurious strain of 1e-8 would be 2e-3 MPa.
  EXPECT_LT(worst, 1e-3);
}

// Cantilever strip, tip load applied slowly: the static deflection P L^3 / (3 E I) on a coarse
// 10 x 2 mesh, thick (L / t = 100) and thin (L / t = 1000, where a fully integrated element
// without assumed shear strains locks).
class ShellFullCantilever : public ::testing::TestWithParam<double> {};

TEST_P(ShellFullCantilever, TipDeflection) {
  const double l = 100.0, b = 10.0, t = GetParam();
  const double i_area = b * t * t * t / 12.0;
  const double p = 0.01 * 3 * kE * i_area / (l * l * l);  // tip deflection L / 100
  core::Model m = full_plate(l, b, 10, 2, t);
  std::vector<core::Index> tip;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const auto node = static_cast<core::Index>(i);
    if (m.x0[i] < 1e-9)
      m.fixed.push_back({node, 63u});
    if (m.x0[i] > l - 1e-9)
      tip.push_back(node);
  }
  const double omega1 = 1.8751 * 1.8751 * std::sqrt(kE * i_area / (kRho * b * t)) / (l * l);
  const double period = 2 * M_PI / omega1;
  std::vector<double> tt, ff;
  for (int s = 0; s <= 200; ++s) {
    const double x = s / 200.0;
    tt.push_back(3 * period * x);
    ff.push_back(x * x * (3 - 2 * x));
  }
  tt.push_back(1e3 * period);
  ff.push_back(1.0);
  const core::Index curve = test::add_curve(m, tt, ff);
  for (core::Index node : tip)
    m.loads.push_back({node, 2, curve, p / static_cast<double>(tip.size())});
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
  const double got = sum / count;
  std::printf("[ELFORM 16 cantilever L/t = %g] tip %.6g, P L^3/(3EI) %.6g, error %.3g %%\n", l / t,
              got, expected, 100.0 * (got - expected) / expected);
  EXPECT_NEAR(got, expected, 0.02 * expected);
}

INSTANTIATE_TEST_SUITE_P(ThickAndThin, ShellFullCantilever, ::testing::Values(1.0, 0.1),
                         [](const ::testing::TestParamInfo<double>& i) {
                           return i.param == 1.0 ? std::string("L_over_t_100")
                                                 : std::string("L_over_t_1000");
                         });

// Simply supported square plate vibrating in its first mode: frequency within 2 % of
// (pi/2)(2/a^2) sqrt(D/(rho t)) and the total energy kept (no hourglass control to damp it).
TEST(ShellFullPlate, SimplySupportedFirstFrequencyAndEnergy) {
  const double a = 100.0, t = 1.0;
  core::Model m = full_plate(a, a, 16, 16, t);  // the BT test's mesh
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
    m.w0x[i] = 100.0 * M_PI / a * std::sin(M_PI * x / a) * std::cos(M_PI * y / a);
    m.w0y[i] = -100.0 * M_PI / a * std::cos(M_PI * x / a) * std::sin(M_PI * y / a);
    if (test::near(x, a / 2) && test::near(y, a / 2))
      centre = static_cast<core::Index>(i);
    if (x < 1e-9 || y < 1e-9 || x > a - 1e-9 || y > a - 1e-9)
      m.fixed.push_back({static_cast<core::Index>(i), core::dof_z});
  }
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
    if (s.time > 0.0 && last_w != 0.0 && (w > 0) != (last_w > 0))
      crossings.push_back(last_t + (s.time - last_t) * last_w / (last_w - w));
    last_w = w;
    last_t = s.time;
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_GE(crossings.size(), 4u);
  const double f = 1.0 / (crossings[3] - crossings[1]);
  std::printf("[ELFORM 16 plate 16 x 16] f %.6g Hz, f11 %.6g Hz, error %.3g %%\n", f, f11,
              100.0 * (f - f11) / f11);
  EXPECT_NEAR(f, f11, 0.02 * f11);
  const double e0 = sink.energies.front().total;
  double drift = 0.0;
  for (const auto& e : sink.energies)
    drift = std::max(drift, std::abs(e.total - e0) / e0);
  std::printf("[ELFORM 16 plate 16 x 16] worst energy drift %.3g %%\n", 100.0 * drift);
  EXPECT_LT(drift, 0.01);
  EXPECT_EQ(sink.energies.back().hourglass, 0.0);
}

}  // namespace test_shell_full
}  // namespace plyform
