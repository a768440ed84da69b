// The metal plasticity kernels against closed forms, one material point driven in uniaxial
// stress (the lateral strain solved so that the lateral stresses stay 0):
//  - *MAT_PLASTIC_KINEMATIC (003), solids and shells: the cyclic loop (tension past yield,
//    compression, tension) of bilinear mixed hardening, whose reverse yield stress is
//    sigma_max - 2 SIGY (BETA 0), -sigma_max (BETA 1) and sigma_max - 2 (SIGY + BETA E_p e1)
//    between; the Cowper-Symonds factor at two strain rates; a pure spin turns the back stress;
//  - *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (037), shells: the plastic strain ratio R in
//    uniaxial tension, the equibiaxial yield stress sigma_y sqrt((1 + R)/2), R = 1 against the
//    J2 law of *MAT_024 to round-off.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "plasticity_helpers.hpp"
#include "plyform/material/metal_plasticity.hpp"

namespace plyform::material {
namespace {

using test::secant;

constexpr double kE = 210000.0, kNu = 0.3, kSigy = 250.0, kEtan = 2100.0;

core::PlasticKinematic kinematic(double beta) {
  core::PlasticKinematic m;
  m.density = 7.85e-9;
  m.young = kE;
  m.poisson = kNu;
  m.sigy = kSigy;
  m.etan = kEtan;
  m.beta = beta;
  return m;
}

// One point with its back stress (6 slots, as the blocks keep it).
struct Point {
  std::array<double, 6> s{};
  double eps_p = 0.0;
  std::array<double, 6> back{};
};

// Solid: axial increment dx, the lateral ones dl (both lateral, symmetric); returns s_yy.
void solid_step(const core::PlasticKinematic& m, Point& p, double dx, double dl, double dt = 1.0) {
  const std::array<double, 6> d{dx / dt, dl / dt, dl / dt, 0.0, 0.0, 0.0};
  const std::array<double, 3> w{};
  solid_update(m, 1, ConstSymView{&d[0], &d[1], &d[2], &d[3], &d[4], &d[5]}, &w[0], &w[1], &w[2],
               dt, SymView{&p.s[0], &p.s[1], &p.s[2], &p.s[3], &p.s[4], &p.s[5]}, &p.eps_p,
               p.back.data());
}

// Shell: in-plane increments dxx, dyy; returns dzz.
template <class M>
double shell_step(const M& m, Point& p, double dxx, double dyy, double dt = 0.0) {
  const std::array<double, 5> d{dxx, dyy, 0.0, 0.0, 0.0};
  double dzz = 0.0;
  ShellPoints pts{&d[0],   &d[1],   &d[2],   &d[3],   &d[4],    &p.s[0],
                  &p.s[1], &p.s[2], &p.s[3], &p.s[4], &p.eps_p, &dzz};
  if constexpr (std::is_same_v<M, core::PlasticKinematic>) {
    pts.history = p.back.data();
    shell_update(m, 1, pts, dt);
  } else {
    shell_update(m, 1, pts);
  }
  return dzz;
}

// One uniaxial-stress step of axial strain increment dx: the lateral increment solved so that
// the lateral stress stays 0 (the law is piecewise linear in it: the secant converges).
template <class Step>
void uniaxial_step(Point& p, double dx, Step&& step) {
  const auto lateral_stress = [&](double dl) {
    Point trial = p;
    step(trial, dx, dl);
    return trial.s[1];
  };
  const double dl = secant(lateral_stress, -kNu * dx, -0.5 * dx, 1e-10 * kSigy);
  step(p, dx, dl);
}

// The closed form of the cyclic uniaxial loop of bilinear mixed hardening (1D: stress sigma,
// back stress a, radius k): tension to strain e_a, compression to -e_a, tension to e_a.
struct Loop {
  double sigma_max, reverse_yield, sigma_min, second_yield, sigma_end;
};
Loop closed_form_loop(double beta, double e_a) {
  const double ep = kE * kEtan / (kE - kEtan);
  // Tension: sigma = SIGY + E_p e1 = E (e_a - e1).
  const double e1 = (kE * e_a - kSigy) / (kE + ep);
  const double a1 = (1.0 - beta) * ep * e1, k1 = kSigy + beta * ep * e1;
  Loop l;
  l.sigma_max = a1 + k1;
  l.reverse_yield = a1 - k1;  // = sigma_max - 2 k1
  // Compression by the plastic strain d: sigma = reverse_yield - E_p d = E(-e_a - (e1 - d)).
  const double d = (l.reverse_yield + kE * (e_a + e1)) / (kE + ep);
  l.sigma_min = l.reverse_yield - ep * d;
  const double a2 = a1 - (1.0 - beta) * ep * d, k2 = k1 + beta * ep * d;
  l.second_yield = a2 + k2;
  // Tension again by d2: sigma = second_yield + E_p d2 = E(e_a - (e1 - d + d2)).
  const double d2 = (kE * (e_a - e1 + d) - l.second_yield) / (kE + ep);
  l.sigma_end = l.second_yield + ep * d2;
  return l;
}

// Runs the loop in n steps per leg and measures the same five values: the reverse yield
// stresses at the first step whose plastic strain grows after a reversal, sigma_k + (-) E_p
// d eps_p (the stress the step's plastic strain hardened from, exact for linear hardening).
template <class Step>
Loop measured_loop(double e_a, int n, Step&& step) {
  const double ep = kE * kEtan / (kE - kEtan);
  Point p;
  Loop l{};
  const double de = e_a / n;
  for (int i = 0; i < n; ++i)
    uniaxial_step(p, de, step);
  l.sigma_max = p.s[0];
  bool yielded = false;
  for (int i = 0; i < 2 * n; ++i) {
    const double e0 = p.eps_p;
    uniaxial_step(p, -de, step);
    if (!yielded && p.eps_p > e0) {
      l.reverse_yield = p.s[0] + ep * (p.eps_p - e0);
      yielded = true;
    }
  }
  l.sigma_min = p.s[0];
  yielded = false;
  for (int i = 0; i < 2 * n; ++i) {
    const double e0 = p.eps_p;
    uniaxial_step(p, de, step);
    if (!yielded && p.eps_p > e0) {
      l.second_yield = p.s[0] - ep * (p.eps_p - e0);
      yielded = true;
    }
  }
  l.sigma_end = p.s[0];
  return l;
}

void expect_loop(const Loop& got, const Loop& want, double tol) {
  const double scale = std::abs(want.sigma_max);
  EXPECT_NEAR(got.sigma_max, want.sigma_max, tol * scale);
  EXPECT_NEAR(got.reverse_yield, want.reverse_yield, tol * scale);
  EXPECT_NEAR(got.sigma_min, want.sigma_min, tol * scale);
  EXPECT_NEAR(got.second_yield, want.second_yield, tol * scale);
  EXPECT_NEAR(got.sigma_end, want.sigma_end, tol * scale);
}

class KinematicLoop : public ::testing::TestWithParam<double> {};

TEST_P(KinematicLoop, SolidFollowsTheClosedForm) {
  const double beta = GetParam();
  const core::PlasticKinematic m = kinematic(beta);
  const double e_a = 0.02;
  const Loop want = closed_form_loop(beta, e_a);
  const Loop got =
      measured_loop(e_a, 400, [&](Point& p, double dx, double dl) { solid_step(m, p, dx, dl); });
  expect_loop(got, want, 1e-9);
  if (beta == 0.0) {
    EXPECT_NEAR(want.reverse_yield, want.sigma_max - 2.0 * kSigy, 1e-9 * kSigy);
  }
  if (beta == 1.0) {
    EXPECT_NEAR(want.reverse_yield, -want.sigma_max, 1e-9 * kSigy);
  }
}

TEST_P(KinematicLoop, ShellFollowsTheClosedForm) {
  const double beta = GetParam();
  const core::PlasticKinematic m = kinematic(beta);
  const double e_a = 0.02;
  const Loop want = closed_form_loop(beta, e_a);
  const Loop got =
      measured_loop(e_a, 400, [&](Point& p, double dx, double dl) { shell_step(m, p, dx, dl); });
  expect_loop(got, want, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Beta, KinematicLoop, ::testing::Values(0.0, 0.4, 1.0), [](const auto& p) {
  return "beta_" + std::to_string(static_cast<int>(10 * p.param));
});

// A point pulled in uniaxial stress by `steps` axial increments of 1e-4 (past yield).
template <class Step>
Point pulled(int steps, Step&& step) {
  Point p;
  for (int i = 0; i < steps; ++i)
    uniaxial_step(p, 1e-4, step);
  return p;
}

// The back stress of the shell stays on the yield surface's centre: after tension, the
// point is on the surface |sigma - a| = k with a = (1 - BETA) E_p eps_p in the axial slot.
TEST(PlasticKinematic, ShellBackStressIsTheKinematicHardening) {
  const core::PlasticKinematic m = kinematic(0.25);
  Point p = pulled(200, [&](Point& q, double dx, double dl) { shell_step(m, q, dx, dl); });
  const double ep = kE * kEtan / (kE - kEtan);
  EXPECT_NEAR(p.back[0], 0.75 * ep * p.eps_p, 1e-9 * kSigy);
  EXPECT_NEAR(p.back[1], 0.0, 1e-9 * kSigy);
  EXPECT_NEAR(p.s[0] - p.back[0], kSigy + 0.25 * ep * p.eps_p, 1e-9 * kSigy);
}

// A pure spin turns the stress and the back stress together: the relative stress keeps its
// invariant, so the point stays on the yield surface and no plastic strain grows.
TEST(PlasticKinematic, SolidBackStressTurnsWithTheStress) {
  const core::PlasticKinematic m = kinematic(0.0);
  Point p = pulled(100, [&](Point& q, double dx, double dl) { solid_step(m, q, dx, dl); });
  const double e0 = p.eps_p;
  const std::array<double, 6> d{};
  const std::array<double, 3> w{0.7, 0.0, 0.0};  // W_12: about z
  for (int i = 0; i < 200; ++i)
    solid_update(m, 1, ConstSymView{&d[0], &d[1], &d[2], &d[3], &d[4], &d[5]}, &w[0], &w[1], &w[2],
                 0.01, SymView{&p.s[0], &p.s[1], &p.s[2], &p.s[3], &p.s[4], &p.s[5]}, &p.eps_p,
                 p.back.data());
  EXPECT_DOUBLE_EQ(p.eps_p, e0);
  std::array<double, 6> xi{};
  const double mean = (p.s[0] + p.s[1] + p.s[2]) / 3.0;
  for (int i = 0; i < 6; ++i)
    xi[i] = p.s[i] - (i < 3 ? mean : 0.0) - p.back[i];
  EXPECT_NEAR(test::von_mises6(xi), kSigy, 1e-9 * kSigy);
  EXPECT_GT(std::abs(p.back[3]), 1.0);  // the back stress turned off the axes
}

// Shells: a pure spin turns the back stress as the element turned the stress (by the Cayley
// angle 2 atan(phi / 2)): the relative stress keeps its invariant, the point stays on the yield
// surface and no plastic strain grows.
TEST(PlasticKinematic, ShellBackStressTurnsWithTheStress) {
  const core::PlasticKinematic m = kinematic(0.0);
  Point p = pulled(100, [&](Point& q, double dx, double dl) { shell_step(m, q, dx, dl); });
  const double e0 = p.eps_p;
  const double phi = 0.05, angle = 2.0 * std::atan(0.5 * phi);
  const double c = std::cos(angle), sn = std::sin(angle);
  const std::array<double, 5> d{};
  double dzz = 0.0;
  for (int i = 0; i < 20; ++i) {
    const double x = p.s[0], y = p.s[1], t = p.s[2];  // the element's turn of the stress
    p.s[0] = c * c * x + sn * sn * y - 2.0 * c * sn * t;
    p.s[1] = sn * sn * x + c * c * y + 2.0 * c * sn * t;
    p.s[2] = c * sn * (x - y) + (c * c - sn * sn) * t;
    ShellPoints pts{&d[0],   &d[1],   &d[2],   &d[3],   &d[4],    &p.s[0],
                    &p.s[1], &p.s[2], &p.s[3], &p.s[4], &p.eps_p, &dzz};
    pts.history = p.back.data();
    pts.spin = &phi;
    shell_update(m, 1, pts, 0.0);
  }
  EXPECT_EQ(p.eps_p, e0);
  // The shell's back stress: xx, yy, xy in the slots 0, 1, 3.
  const double ex = p.s[0] - p.back[0], ey = p.s[1] - p.back[1], et = p.s[2] - p.back[3];
  EXPECT_NEAR(std::sqrt(ex * ex + ey * ey - ex * ey + 3.0 * et * et), kSigy, 1e-9 * kSigy);
  EXPECT_NEAR(std::atan2(2.0 * p.back[3], p.back[0] - p.back[1]), 2.0 * 20.0 * angle, 1e-10);
}

// Many points in one call (the element passes a chunk's points at once; the yielding ones are
// solved together in batches) give each point exactly what it gives alone: a point's result does
// not depend on the points beside it, so none depends on the chunking or the thread count.
TEST(PlasticKinematic, ShellPointsInOneCallGiveWhatEachGivesAlone) {
  const core::PlasticKinematic m = kinematic(0.3);
  constexpr std::size_t kN = 150;  // several blocks and batches, elastic and plastic points
  std::array<double, kN> dxx{}, dyy{}, dxy{}, dyz{}, dzx{}, spin{};
  std::vector<Point> all(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    const double u = static_cast<double>(i) / kN;
    dxx[i] = 2e-3 * std::sin(7.0 * u) * (i % 3 == 0 ? 0.1 : 1.0);
    dyy[i] = 1e-3 * std::cos(5.0 * u);
    dxy[i] = 5e-4 * std::sin(11.0 * u);
    spin[i] = i % 4 == 0 ? 0.0 : 0.01 * std::cos(3.0 * u);
    all[i].s = {150.0 * u, -80.0 * u, 40.0 * u, 0.0, 0.0, 0.0};  // shell_step's layout
    all[i].back = {30.0 * u, -10.0 * u, 0.0, 5.0 * u, 0.0, 0.0};
    all[i].eps_p = 0.01 * u;
  }
  std::vector<Point> alone = all;
  // In one call: the fields as the element lays them out, one array each.
  std::array<double, kN> sxx{}, syy{}, sxy{}, syz{}, szx{}, eps_p{}, dzz{};
  std::vector<double> history(6 * kN);
  for (std::size_t i = 0; i < kN; ++i) {
    sxx[i] = all[i].s[0];
    syy[i] = all[i].s[1];
    sxy[i] = all[i].s[2];
    eps_p[i] = all[i].eps_p;
    std::copy(all[i].back.begin(), all[i].back.end(), history.begin() + 6 * i);
  }
  ShellPoints pts{dxx.data(), dyy.data(), dxy.data(), dyz.data(), dzx.data(),   sxx.data(),
                  syy.data(), sxy.data(), syz.data(), szx.data(), eps_p.data(), dzz.data()};
  pts.history = history.data();
  pts.spin = spin.data();
  shell_update(m, kN, pts, 0.0);
  std::size_t plastic = 0;
  for (std::size_t i = 0; i < kN; ++i) {
    Point& q = alone[i];
    double dzz_alone = 0.0;
    ShellPoints one{&dxx[i], &dyy[i], &dxy[i], &dyz[i], &dzx[i],  &q.s[0],
                    &q.s[1], &q.s[2], &q.s[3], &q.s[4], &q.eps_p, &dzz_alone};
    one.history = q.back.data();
    one.spin = &spin[i];
    shell_update(m, 1, one, 0.0);
    plastic += q.eps_p > all[i].eps_p ? 1 : 0;
    EXPECT_EQ(sxx[i], q.s[0]) << i;
    EXPECT_EQ(syy[i], q.s[1]) << i;
    EXPECT_EQ(sxy[i], q.s[2]) << i;
    EXPECT_EQ(eps_p[i], q.eps_p) << i;
    EXPECT_EQ(dzz[i], dzz_alone) << i;
    for (std::size_t k = 0; k < 6; ++k)
      EXPECT_EQ(history[6 * i + k], q.back[k]) << i << " slot " << k;
  }
  EXPECT_GT(plastic, kN / 4);
  EXPECT_LT(plastic, kN);
}

// Cowper-Symonds: perfectly plastic (ETAN 0) in isochoric extension d = r (1, -1/2, -1/2)
// (sqrt(D : D) = r sqrt(3/2); the shell's D_zz = -(D_xx + D_yy) makes it the same); the flow
// stress is SIGY (1 + (r sqrt(3/2) / C)^(1/P)).
TEST(PlasticKinematic, CowperSymondsFactorAtTwoRates) {
  core::PlasticKinematic m = kinematic(1.0);
  m.etan = 0.0;
  m.src = 40.0;
  m.srp = 5.0;
  for (const double r : {10.0, 1000.0}) {
    const double factor = 1.0 + std::pow(r * std::sqrt(1.5) / m.src, 1.0 / m.srp);
    EXPECT_NEAR(cowper_symonds_factor(m, r * std::sqrt(1.5)), factor, 1e-14 * factor);
    const double dt = 1e-4 / r;  // strain 1e-4 per step
    Point solid, shell;
    for (int i = 0; i < 100; ++i) {
      solid_step(m, solid, r * dt, -0.5 * r * dt, dt);
      shell_step(m, shell, r * dt, -0.5 * r * dt, dt);
    }
    const double q = solid.s[0] - solid.s[1];  // the equivalent stress of this state
    EXPECT_NEAR(q, kSigy * factor, 1e-9 * kSigy) << "solid at rate " << r;
    // The shell (plane stress) flows on the scaled yield surface.
    EXPECT_GT(shell.eps_p, 0.0);
    EXPECT_NEAR(test::von_mises_ps(shell.s[0], shell.s[1], shell.s[2]), kSigy * factor,
                1e-9 * kSigy)
        << "shell at rate " << r;
  }
  core::PlasticKinematic off = m;
  off.src = 0.0;
  EXPECT_EQ(cowper_symonds_factor(off, 1e6), 1.0);
}

// --- *MAT_037 ------------------------------------------------------------------------------

core::TransverselyAnisotropicPlastic hill(double r) {
  core::TransverselyAnisotropicPlastic m;
  m.density = 7.85e-9;
  m.young = kE;
  m.poisson = kNu;
  m.sigy = kSigy;
  m.etan = kEtan;
  m.r = r;
  return m;
}

class HillR : public ::testing::TestWithParam<double> {};

// Uniaxial tension along x: d eps^p_yy / d eps^p_zz = R (the elastic parts, -nu sigma / E
// both, taken off the total increments).
TEST_P(HillR, UniaxialTensionHasThePlasticStrainRatioR) {
  const double r = GetParam();
  const auto m = hill(r);
  Point p;
  double eyy = 0.0, ezz = 0.0;
  const auto step = [&](Point& q, double dx, double dl) { shell_step(m, q, dx, dl); };
  for (int i = 0; i < 100; ++i)
    uniaxial_step(p, 1e-4, step);
  const double s0 = p.s[0];
  for (int i = 0; i < 200; ++i) {
    // The step again with its solved lateral increment, to keep dzz.
    const auto lateral = [&](double dl) {
      Point t = p;
      shell_step(m, t, 1e-4, dl);
      return t.s[1];
    };
    const double dl = secant(lateral, -0.5e-4, -0.6e-4, 1e-10 * kSigy);
    ezz += shell_step(m, p, 1e-4, dl);
    eyy += dl;
  }
  const double elastic = -kNu * (p.s[0] - s0) / kE;
  const double ratio = (eyy - elastic) / (ezz - elastic);
  EXPECT_NEAR(ratio, r, 1e-9 * r);
  EXPECT_NEAR(p.s[0], yield_stress(m, p.eps_p), 1e-9 * kSigy);  // uniaxial: sigma_eq = sxx
}

// Equibiaxial stretching, perfectly plastic: the stress rises to sigma_y sqrt((1 + R)/2).
TEST_P(HillR, EquibiaxialYieldStress) {
  const double r = GetParam();
  auto m = hill(r);
  m.etan = 0.0;
  Point p;
  for (int i = 0; i < 100; ++i)
    shell_step(m, p, 1e-4, 1e-4);
  const double want = kSigy * std::sqrt((1.0 + r) / 2.0);
  EXPECT_NEAR(p.s[0], want, 1e-9 * want);
  EXPECT_NEAR(p.s[1], want, 1e-9 * want);
}

INSTANTIATE_TEST_SUITE_P(R, HillR, ::testing::Values(0.5, 1.0, 1.8, 2.6), [](const auto& p) {
  return "r_" + std::to_string(static_cast<int>(10 * p.param));
});

// R = 1 is von Mises: the same path through *MAT_037 and *MAT_024 (bilinear, and with the
// same curve) gives the same stresses, plastic strain and thickness strain to round-off.
TEST(Hill, RIsOneReproducesJ2) {
  core::TransverselyAnisotropicPlastic h = hill(1.0);
  core::PiecewiseLinearPlasticity j2{7.85e-9, kE, kNu, kSigy, kEtan, {}};
  h.etan = kE * kEtan / (kE - kEtan);  // *MAT_037's ETAN is the plastic modulus
  for (int curve = 0; curve < 2; ++curve) {
    if (curve == 1) {
      h.curve.plastic_strain = j2.curve.plastic_strain = {0.0, 0.01, 0.05, 0.2};
      h.curve.yield_stress = j2.curve.yield_stress = {250.0, 300.0, 360.0, 420.0};
    }
    Point a;
    test::ShellState c;
    for (int i = 0; i < 300; ++i) {
      const double t = 0.05 * i;
      const std::array<double, 5> d{2e-4 * std::cos(t), 1e-4 * std::sin(1.3 * t),
                                    1.5e-4 * std::cos(0.7 * t), 1e-5, -2e-5};
      double dzz_h = 0.0;
      ShellPoints ph{&d[0],   &d[1],   &d[2],   &d[3],   &d[4],    &a.s[0],
                     &a.s[1], &a.s[2], &a.s[3], &a.s[4], &a.eps_p, &dzz_h};
      shell_update(h, 1, ph);
      const double dzz_j = test::shell_step(j2, c, d);
      for (int k = 0; k < 5; ++k)
        ASSERT_NEAR(a.s[k], c.s[k], 1e-12 * kSigy) << "step " << i << " component " << k;
      ASSERT_NEAR(a.eps_p, c.eps_p, 1e-13) << "step " << i;
      ASSERT_NEAR(dzz_h, dzz_j, 1e-15) << "step " << i;
    }
    EXPECT_GT(c.eps_p, 0.01);
  }
}

}  // namespace
}  // namespace plyform::material
