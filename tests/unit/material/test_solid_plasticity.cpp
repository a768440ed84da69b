// 3D J2 radial return of solids (*MAT_024, *MAT_018) against closed forms: uniaxial stress path
// on the curve, one-step closed form of linear hardening, pure spin, monotone plastic strain.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "plasticity_helpers.hpp"
#include "tensor_helpers.hpp"

namespace plyform::material::test {
namespace test_solid_plasticity {

constexpr double kE = 200000.0;
constexpr double kNu = 0.3;

core::PiecewiseLinearPlasticity curve_law() {
  core::PiecewiseLinearPlasticity m{7.85e-9, kE, kNu, 0.0, 0.0, {}};
  m.curve.plastic_strain = {0.0, 0.02, 0.05, 0.1};
  m.curve.yield_stress = {300.0, 360.0, 400.0, 420.0};
  return m;
}
core::PowerLawPlasticity power_law() {
  return core::PowerLawPlasticity{7.85e-9, kE, kNu, 600.0, 0.2, 250.0};
}
double ref_yield(const core::PiecewiseLinearPlasticity& m, double e) {
  return curve_ref(m.curve.plastic_strain, m.curve.yield_stress, e);
}
double ref_yield(const core::PowerLawPlasticity& m, double e) {
  const double e0 = std::pow(m.sigy / m.k, 1.0 / m.n);
  return m.k * std::pow(e0 + e, m.n);
}

template <class M>
void uniaxial(const M& m, const char* name) {
  SolidState st;
  double exx = 0.0;
  const double step = 2e-5;
  double worst_curve = 0.0, worst_ep = 0.0, worst_vol = 0.0;
  double ekk = 0.0;
  for (int i = 0; i < 7500; ++i) {  // eps_xx = 0.15
    const double lat = secant(
        [&](double y) {
          SolidState t = st;
          solid_step(m, t, {step, y, y, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0);
          return t.s[1];
        },
        -0.5 * step, -0.3 * step, 1e-11);
    solid_step(m, st, {step, lat, lat, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0);
    exx += step;
    ekk += step + 2.0 * lat;
    EXPECT_NEAR(st.s[2], st.s[1], 1e-12);
    const double sx = st.s[0];
    if (st.eps_p > 0.0) {
      worst_curve = std::max(worst_curve, std::abs(sx - ref_yield(m, st.eps_p)) / sx);
      worst_ep = std::max(worst_ep, std::abs(st.eps_p - (exx - sx / kE)));
      // Plastic flow is isochoric: tr eps = (1 - 2 nu) sxx / E.
      worst_vol = std::max(worst_vol, std::abs(ekk - (1.0 - 2.0 * kNu) * sx / kE));
    }
  }
  EXPECT_LT(worst_curve, 1e-6);
  EXPECT_LT(worst_ep, 1e-9);
  EXPECT_LT(worst_vol, 1e-9);
  EXPECT_GT(st.eps_p, 0.14);
  std::printf("[%s] solid uniaxial to 0.15: |s - s_y|/s %.2e, eps_p %.2e, volume %.2e\n", name,
              worst_curve, worst_ep, worst_vol);
}

TEST(SolidJ2, UniaxialFollowsCurve) {
  uniaxial(curve_law(), "MAT_024 curve");
  uniaxial(power_law(), "MAT_018");
}

TEST(SolidJ2, LinearHardeningOneStepClosedForm) {
  const core::PiecewiseLinearPlasticity m{7.85e-9, kE, kNu, 250.0, 2000.0, {}};
  const double g = kE / (2.0 * (1.0 + kNu));
  const double hp = kE * 2000.0 / (kE - 2000.0);
  SolidState st;
  st.eps_p = 0.01;
  // A deviatoric shear trial: q_tr = sqrt(3) * 2 G gamma.
  const double gam = 5e-3;
  solid_step(m, st, {0.0, 0.0, 0.0, gam, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0);
  const double q_tr = std::sqrt(3.0) * 2.0 * g * gam;
  const double sy_n = 250.0 + hp * 0.01;
  const double dlam = (q_tr - sy_n) / (3.0 * g + hp);
  EXPECT_NEAR(st.eps_p, 0.01 + dlam, 1e-15);
  EXPECT_NEAR(st.s[3], 2.0 * g * gam * (1.0 - 3.0 * g * dlam / q_tr), 1e-10);
  EXPECT_NEAR(von_mises6(st.s), sy_n + hp * dlam, 1e-10);
  EXPECT_EQ(st.s[0], 0.0);
}

TEST(SolidJ2, PureSpinKeepsInvariantsAndPlasticStrain) {
  const auto m = curve_law();
  SolidState st;
  st.s = {310.0, -40.0, 20.0, 35.0, -12.0, 8.0};
  st.eps_p = 0.03;
  ASSERT_GT(ref_yield(m, st.eps_p), von_mises6(st.s) - 1.0);  // at or inside the surface
  const Mat3 s0 = from_voigt(st.s);
  for (int i = 0; i < 2000; ++i)
    solid_step(m, st, {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, {3.0, -1.0, 2.0}, 1e-3);
  const Mat3 s1 = from_voigt(st.s);
  EXPECT_EQ(st.eps_p, 0.03);
  EXPECT_NEAR(trace(s1), trace(s0), 1e-9);
  EXPECT_NEAR(von_mises(s1), von_mises(s0), 1e-9);
  EXPECT_NEAR(det(s1), det(s0), 1e-8 * std::abs(det(s0)));
}

template <class M>
void random_monotone(const M& m) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SolidState st;
  double worst = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const double e_before = st.eps_p;
    std::array<double, 6> d{};
    for (double& v : d)
      v = 4e-4 * u(rng);
    solid_step(m, st, d, {u(rng), u(rng), u(rng)}, 1.0);
    EXPECT_GE(st.eps_p, e_before);
    const double q = von_mises6(st.s), sy = ref_yield(m, st.eps_p);
    EXPECT_LE(q, sy * (1.0 + 1e-12));
    if (st.eps_p > e_before)
      worst = std::max(worst, std::abs(q - sy) / sy);
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(st.eps_p, 0.0);
}

TEST(SolidJ2, PlasticStrainNeverDecreasesAndStressStaysOnSurface) {
  random_monotone(curve_law());
  random_monotone(power_law());
}

}  // namespace test_solid_plasticity
}  // namespace plyform::material::test
