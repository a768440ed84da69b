// The orthotropic sheet-metal laws at one shell point, against closed forms written here
// independently of the library (the yield functions from their papers' formulas, their
// gradients by central differences):
//  - *MAT_HILL_3R and *MAT_3-PARAMETER_BARLAT in uniaxial stress at 0, 45 and 90 degrees to the
//    rolling direction (perfectly plastic): the flow stress sigma_y / phi(unit stress) and the
//    plastic width-to-thickness strain ratio, which must be the card's R00, R45, R90;
//  - equibiaxial stretching: the closed-form balanced biaxial yield stress;
//  - the yield locus: proportional strain paths end on phi = sigma_y with the plastic flow
//    normal to it;
//  - Barlat's coefficients: m = 2 is Hill 1948 (a, c, h, p in closed form);
//  - the hardening rules HR 2 (Swift, e0 from the elastic line) and HR 4 (Voce);
//  - *MAT_037's ETAN is the plastic hardening modulus.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "plyform/core/material.hpp"
#include "plyform/material/metal_plasticity.hpp"
#include "plyform/material/sheet_metal_plasticity.hpp"

namespace plyform::material {
namespace test_sheet_metal_plasticity {

constexpr double kE = 2.1e5, kNu = 0.3, kSigy = 200.0;  // MPa

// --- Independent yield functions (material axes; s12 the tensor shear stress) ---------------

struct BarlatRef {
  double a, c, h, p, m;
  double operator()(const std::array<double, 3>& s) const {
    const double k1 = (s[0] + h * s[1]) / 2.0;
    const double k2 = std::sqrt(std::pow((s[0] - h * s[1]) / 2.0, 2) + p * p * s[2] * s[2]);
    const double f = a * std::pow(std::abs(k1 + k2), m) + a * std::pow(std::abs(k1 - k2), m) +
                     c * std::pow(std::abs(2.0 * k2), m);
    return std::pow(f / 2.0, 1.0 / m);
  }
};

struct HillRef {
  double r00, r45, r90;
  double operator()(const std::array<double, 3>& s) const {
    const double h = r00 / (1.0 + r00), g = 1.0 / (1.0 + r00), f = h / r90;
    const double n = (f + g) * (r45 + 0.5);
    return std::sqrt(s[0] * s[0] - 2.0 * h * s[0] * s[1] + (f + h) * s[1] * s[1] +
                     2.0 * n * s[2] * s[2]);
  }
};

using Phi = std::function<double(const std::array<double, 3>&)>;

// grad phi in the strain measure (e11, e22, gamma12): d phi / d s12 is d gamma.
std::array<double, 3> gradient(const Phi& phi, const std::array<double, 3>& s) {
  std::array<double, 3> g{};
  const double d = 1e-6 * kSigy;
  for (int i = 0; i < 3; ++i) {
    auto up = s, dn = s;
    up[i] += d;
    dn[i] -= d;
    g[i] = (phi(up) - phi(dn)) / (2.0 * d);
  }
  return g;
}

// The unit uniaxial stress at angle t from the rolling direction, in the material axes.
std::array<double, 3> uniaxial(double t) {
  const double c = std::cos(t), s = std::sin(t);
  return {c * c, s * s, c * s};
}

// --- A shell point driven by strain increments ----------------------------------------------

struct Point {
  double s[5] = {};
  double eps_p = 0.0;
};

// One step of the law with in-plane increments (dxx, dyy, dxy tensor), the material axis at
// angle t from x. Returns the thickness strain increment.
template <class M>
double step(const M& m, Point& p, double t, double dxx, double dyy, double dxy) {
  const double d[5] = {dxx, dyy, dxy, 0.0, 0.0};
  const double ct = std::cos(t), st = std::sin(t);
  double dzz = 0.0;
  ShellPoints pts{&d[0],   &d[1],   &d[2],   &d[3],   &d[4],    &p.s[0],
                  &p.s[1], &p.s[2], &p.s[3], &p.s[4], &p.eps_p, &dzz};
  pts.cos_t = &ct;
  pts.sin_t = &st;
  shell_update(m, 1, pts);
  return dzz;
}

// Uniaxial stress along x: each step dxx given, (dyy, dxy) solved by Newton (the Jacobian by
// differences) so that syy = sxy = 0 after it. Returns (d eps_yy, d eps_zz) of the step.
template <class M>
std::array<double, 2> uniaxial_step(const M& m, Point& p, double t, double dxx) {
  double x[2] = {-0.5 * dxx, 0.0};
  const auto after = [&](const double* y, double* r) {
    Point q = p;
    step(m, q, t, dxx, y[0], y[1]);
    r[0] = q.s[1], r[1] = q.s[2];
  };
  for (int it = 0; it < 30; ++it) {
    double r[2];
    after(x, r);
    if (std::abs(r[0]) + std::abs(r[1]) < 1e-11 * kSigy)
      break;
    double j[4];
    const double h = 1e-3 * dxx;
    for (int k = 0; k < 2; ++k) {
      double y[2] = {x[0], x[1]}, rk[2];
      y[k] += h;
      after(y, rk);
      j[k] = (rk[0] - r[0]) / h;
      j[2 + k] = (rk[1] - r[1]) / h;
    }
    const double det = j[0] * j[3] - j[1] * j[2];
    x[0] -= (j[3] * r[0] - j[1] * r[1]) / det;
    x[1] -= (-j[2] * r[0] + j[0] * r[1]) / det;
  }
  const double dzz = step(m, p, t, dxx, x[0], x[1]);
  return {x[0], dzz};
}

core::SheetHardening perfectly_plastic() {
  core::SheetHardening h;
  h.sigy = kSigy;
  h.hp = 0.0;
  return h;
}

core::Hill3RPlastic hill3r(double r00, double r45, double r90) {
  core::Hill3RPlastic m;
  m.density = 7.85e-9;
  m.young = kE;
  m.poisson = kNu;
  m.hardening = perfectly_plastic();
  m.r00 = r00, m.r45 = r45, m.r90 = r90;
  return m;
}

core::Barlat89Plastic barlat(double r00, double r45, double r90, double exponent) {
  core::Barlat89Plastic m;
  m.density = 2.7e-9;
  m.young = kE;
  m.poisson = kNu;
  m.hardening = perfectly_plastic();
  m.m = exponent;
  const Barlat89Coefficients k = barlat89_coefficients(r00, r45, r90, exponent);
  m.a = k.a, m.c = k.c, m.h = k.h, m.p = k.p;
  return m;
}

// Pulled at angle t to 3 % (perfectly plastic: once at yield the stress holds, so the strain
// increments are plastic): the flow stress and the increments' width-to-thickness ratio.
template <class M>
void expect_uniaxial(const M& m, const Phi& phi, double t, double r_expected) {
  Point p;
  for (int i = 0; i < 50; ++i)
    uniaxial_step(m, p, t, 1e-4);
  double eyy = 0.0, ezz = 0.0;
  for (int i = 0; i < 250; ++i) {
    const auto [dyy, dzz] = uniaxial_step(m, p, t, 1e-4);
    eyy += dyy;
    ezz += dzz;
  }
  const double flow = kSigy / phi(uniaxial(t));
  EXPECT_NEAR(p.s[0], flow, 1e-9 * flow) << "angle " << t;
  EXPECT_NEAR(eyy / ezz, r_expected, 1e-7 * r_expected) << "angle " << t;
}

// Equibiaxial stretching in the material axes: both stresses rise to sigma_b.
template <class M>
void expect_equibiaxial(const M& m, double sigma_b) {
  Point p;
  double s0 = 0.0;
  for (int i = 0; i < 200; ++i) {
    // The strain ratio that keeps sxx = syy is the material's; hold the stresses equal by
    // solving dyy for the step.
    double lo = 0.0, hi = 3e-4;
    for (int k = 0; k < 80; ++k) {
      Point q = p;
      const double mid = 0.5 * (lo + hi);
      step(m, q, 0.0, 1e-4, mid, 0.0);
      (q.s[1] < q.s[0] ? lo : hi) = mid;
    }
    step(m, p, 0.0, 1e-4, 0.5 * (lo + hi), 0.0);
    s0 = p.s[0];
  }
  EXPECT_NEAR(s0, sigma_b, 1e-8 * sigma_b);
  EXPECT_NEAR(p.s[1], sigma_b, 1e-8 * sigma_b);
}

struct Ratios {
  double r00, r45, r90;
};

class Hill3R : public ::testing::TestWithParam<Ratios> {};

TEST_P(Hill3R, UniaxialAt0_45_90HasTheCardsRValuesAndFlowStresses) {
  const Ratios r = GetParam();
  const auto m = hill3r(r.r00, r.r45, r.r90);
  const HillRef phi{r.r00, r.r45, r.r90};
  expect_uniaxial(m, phi, 0.0, r.r00);
  expect_uniaxial(m, phi, 0.25 * std::numbers::pi, r.r45);
  expect_uniaxial(m, phi, 0.5 * std::numbers::pi, r.r90);
  // The closed forms of the flow stresses at 90 degrees and equibiaxially.
  EXPECT_NEAR(kSigy / phi(uniaxial(0.5 * std::numbers::pi)),
              kSigy * std::sqrt(r.r90 * (1.0 + r.r00) / (r.r00 * (1.0 + r.r90))), 1e-12 * kSigy);
  expect_equibiaxial(m, kSigy * std::sqrt(r.r90 * (1.0 + r.r00) / (r.r00 + r.r90)));
}

INSTANTIATE_TEST_SUITE_P(Steels, Hill3R,
                         ::testing::Values(Ratios{1.0, 1.0, 1.0}, Ratios{1.8, 1.3, 2.3},
                                           Ratios{0.7, 0.5, 0.9}, Ratios{1.124, 1.195, 1.013}));

class Barlat89 : public ::testing::TestWithParam<Ratios> {};

TEST_P(Barlat89, UniaxialAt0_45_90HasTheCardsRValuesAndFlowStresses) {
  const Ratios r = GetParam();
  for (const double exponent : {6.0, 8.0}) {
    const auto m = barlat(r.r00, r.r45, r.r90, exponent);
    const BarlatRef phi{m.a, m.c, m.h, m.p, m.m};
    expect_uniaxial(m, phi, 0.0, r.r00);
    expect_uniaxial(m, phi, 0.25 * std::numbers::pi, r.r45);
    expect_uniaxial(m, phi, 0.5 * std::numbers::pi, r.r90);
    // The closed forms: sigma_0 = sigma_y (a + c = 2), sigma_90 = sigma_y / h, and for
    // equibiaxial stress u1 = s, u2 = h s, u3 = |1 - h| s.
    EXPECT_NEAR(kSigy / phi(uniaxial(0.0)), kSigy, 1e-12 * kSigy);
    EXPECT_NEAR(kSigy / phi(uniaxial(0.5 * std::numbers::pi)), kSigy / m.h, 1e-12 * kSigy);
    const double sb =
        kSigy *
        std::pow(2.0 / (m.a + m.a * std::pow(m.h, m.m) + m.c * std::pow(std::abs(1.0 - m.h), m.m)),
                 1.0 / m.m);
    expect_equibiaxial(m, sb);
  }
}

INSTANTIATE_TEST_SUITE_P(Alloys, Barlat89,
                         ::testing::Values(Ratios{0.7, 0.6, 0.8}, Ratios{1.8, 1.5, 2.3},
                                           Ratios{0.55, 0.75, 0.65}));

// m = 2: Barlat 89 is Hill 1948, with a = 2 - 2 sqrt(H H90), h^2 = F + H and (a + 2c) p^2 = 2N
// (the shear term of phi^2): the p the library solves for equals the closed form.
TEST(Barlat89Coefficients, ExponentTwoIsHill48) {
  const double r00 = 1.7, r45 = 1.2, r90 = 2.1;
  const Barlat89Coefficients k = barlat89_coefficients(r00, r45, r90, 2.0);
  const double h = r00 / (1.0 + r00), g = 1.0 / (1.0 + r00), f = h / r90;
  const double n = (f + g) * (r45 + 0.5);
  EXPECT_NEAR(k.h * k.h, f + h, 1e-14);
  EXPECT_NEAR(k.a + k.c, 2.0, 1e-14);
  EXPECT_NEAR(k.p, std::sqrt(2.0 * n / (k.a + 2.0 * k.c)), 1e-12);
  // And the two yield functions agree everywhere.
  const BarlatRef b{k.a, k.c, k.h, k.p, 2.0};
  const HillRef hill{r00, r45, r90};
  for (const std::array<double, 3> s :
       {std::array<double, 3>{1.0, 0.3, 0.2}, {-0.4, 1.0, 0.7}, {0.5, 0.5, -0.9}})
    EXPECT_NEAR(b(s), hill(s), 1e-12);
}

// Proportional strain paths (with shear) in the material axes end on the yield locus with the
// plastic flow along its normal.
TEST(Barlat89, YieldLocusAndNormality) {
  const auto m = barlat(0.7, 0.6, 0.8, 8.0);
  const BarlatRef phi{m.a, m.c, m.h, m.p, m.m};
  for (int k = 0; k < 12; ++k) {
    const double alpha = 2.0 * std::numbers::pi * k / 12.0;
    const double dxx = 1e-4 * std::cos(alpha), dyy = 1e-4 * std::sin(alpha),
                 dxy = 0.3e-4 * std::sin(3.0 * alpha);
    Point p;
    for (int i = 0; i < 300; ++i)
      step(m, p, 0.0, dxx, dyy, dxy);
    const std::array<double, 3> s{p.s[0], p.s[1], p.s[2]};
    EXPECT_NEAR(phi(s), kSigy, 1e-9 * kSigy) << "path " << k;
    // Saturated: the increments are plastic; (dxx, dyy, 2 dxy) parallel to grad phi.
    const auto g = gradient(phi, s);
    const double dn = std::sqrt(dxx * dxx + dyy * dyy + 4.0 * dxy * dxy);
    const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const double cosine = (dxx * g[0] + dyy * g[1] + 2.0 * dxy * g[2]) / (dn * gn);
    EXPECT_NEAR(cosine, 1.0, 1e-7) << "path " << k;
  }
}

TEST(Hill3R, YieldLocusAndNormalityInRotatedAxes) {
  const auto m = hill3r(1.8, 1.3, 2.3);
  const HillRef phi{1.8, 1.3, 2.3};
  const double t = 0.4;  // the material axis 23 degrees from x
  for (int k = 0; k < 8; ++k) {
    const double alpha = 2.0 * std::numbers::pi * k / 8.0;
    const double dxx = 1e-4 * std::cos(alpha), dyy = 1e-4 * std::sin(alpha), dxy = 0.2e-4;
    Point p;
    for (int i = 0; i < 300; ++i)
      step(m, p, t, dxx, dyy, dxy);
    // The stress in the material axes.
    const double c = std::cos(t), s = std::sin(t);
    const std::array<double, 3> sm{c * c * p.s[0] + s * s * p.s[1] + 2.0 * c * s * p.s[2],
                                   s * s * p.s[0] + c * c * p.s[1] - 2.0 * c * s * p.s[2],
                                   c * s * (p.s[1] - p.s[0]) + (c * c - s * s) * p.s[2]};
    EXPECT_NEAR(phi(sm), kSigy, 1e-9 * kSigy) << "path " << k;
  }
}

// HR 2 (Swift, e0 where the curve meets the elastic line) and HR 4 (Voce): in uniaxial stress
// along the rolling direction the stress is the hardening curve at the point's plastic strain.
TEST(SheetHardening, SwiftAndVoceInUniaxialTension) {
  core::SheetHardening swift;
  swift.rule = core::SheetHardening::Rule::kSwift;
  swift.k = 550.0, swift.n = 0.22;
  swift.e0 = std::pow(kE / swift.k, 1.0 / (swift.n - 1.0));
  core::SheetHardening voce;
  voce.rule = core::SheetHardening::Rule::kVoce;
  voce.a = 320.0, voce.b = 120.0, voce.c = 15.0;
  const std::array<std::function<double(double)>, 2> curves{
      [&](double e) { return swift.k * std::pow(swift.e0 + e, swift.n); },
      [&](double e) { return voce.a - voce.b * std::exp(-voce.c * e); }};
  const std::array<core::SheetHardening, 2> rules{swift, voce};
  for (std::size_t i = 0; i < 2; ++i) {
    auto m = hill3r(1.5, 1.1, 1.9);
    m.hardening = rules[i];
    Point p;
    for (int k = 0; k < 400; ++k)
      uniaxial_step(m, p, 0.0, 2e-4);
    EXPECT_GT(p.eps_p, 0.07);
    EXPECT_NEAR(p.s[0], curves[i](p.eps_p), 1e-9 * p.s[0]) << "rule " << i;
    EXPECT_NEAR(yield_stress(rules[i], p.eps_p), curves[i](p.eps_p), 1e-12 * p.s[0]);
  }
}

// *MAT_037's ETAN is LS-DYNA's plastic hardening modulus (not a tangent modulus): in uniaxial
// tension along x the stress is SIGY + ETAN eps_p.
TEST(TransverselyAnisotropicEtan, IsThePlasticModulus) {
  core::TransverselyAnisotropicPlastic m;
  m.density = 7.85e-9;
  m.young = kE;
  m.poisson = kNu;
  m.sigy = kSigy;
  m.etan = 1500.0;
  m.r = 1.6;
  Point p;
  for (int i = 0; i < 300; ++i)
    uniaxial_step(m, p, 0.0, 2e-4);
  EXPECT_GT(p.eps_p, 0.05);
  EXPECT_NEAR(p.s[0], kSigy + 1500.0 * p.eps_p, 1e-9 * kSigy);
}

}  // namespace test_sheet_metal_plasticity
}  // namespace plyform::material
