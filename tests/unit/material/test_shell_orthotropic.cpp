// *MAT_ORTHOTROPIC_ELASTIC shell update against the compliance in the material axes (LS-DYNA's
// convention S_ab = -PRBA / EB), rotated with plain matrices.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "plasticity_helpers.hpp"
#include "tensor_helpers.hpp"

namespace plyform::material::test {
namespace {

core::OrthotropicElasticMaterial ply() {
  core::OrthotropicElasticMaterial m;
  m.density = 1.6e-9;
  m.ea = 140000.0;
  m.eb = 10000.0;
  m.ec = 9000.0;
  m.prba = 0.02;  // minor: strain along a under stress along b is -0.02 eps_b
  m.prca = 0.015;
  m.prcb = 0.4;
  m.gab = 5000.0;
  m.gbc = 3500.0;
  m.gca = 4500.0;
  return m;
}

TEST(ShellOrthotropic, UniaxialAlongA) {
  const auto m = ply();
  const double e = 1e-3;
  const double dyy = secant(
      [&](double y) {
        ShellState t;
        shell_step_ortho(m, t, {e, y, 0.0, 0.0, 0.0}, 0.0);
        return t.s[1];
      },
      0.0, -1e-4, 1e-12);
  ShellState st;
  const double dzz = shell_step_ortho(m, st, {e, dyy, 0.0, 0.0, 0.0}, 0.0);
  EXPECT_NEAR(st.s[0], m.ea * e, 1e-10 * m.ea * e);
  EXPECT_NEAR(dyy, -m.prba * m.ea / m.eb * e, 1e-12);  // nu_ab = PRBA EA / EB
  EXPECT_NEAR(dzz, -m.prca / m.ec * st.s[0], 1e-14);
  EXPECT_EQ(st.s[2], 0.0);
}

TEST(ShellOrthotropic, UniaxialAlongB) {
  const auto m = ply();
  const double e = 1e-3;
  const double dxx = secant(
      [&](double x) {
        ShellState t;
        shell_step_ortho(m, t, {x, e, 0.0, 0.0, 0.0}, 0.0);
        return t.s[0];
      },
      0.0, -1e-5, 1e-12);
  ShellState st;
  const double dzz = shell_step_ortho(m, st, {dxx, e, 0.0, 0.0, 0.0}, 0.0);
  EXPECT_NEAR(st.s[1], m.eb * e, 1e-10 * m.eb * e);
  EXPECT_NEAR(dxx, -m.prba * e, 1e-14);
  EXPECT_NEAR(dzz, -m.prcb / m.ec * st.s[1], 1e-14);
}

// Rotated axes: the strain from the returned stress through the rotated compliance
// (R^T S(R sigma R^T) R) equals the imposed increments, in-plane, transverse and through the
// thickness.
TEST(ShellOrthotropic, RotatedAxesGiveRotatedCompliance) {
  const auto m = ply();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 20; ++k) {
    const double angle = 3.0 * u(rng);
    const ShellInc d{1e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng)};
    ShellState st;
    const double dzz = shell_step_ortho(m, st, d, angle);
    const double c = std::cos(angle), s = std::sin(angle);
    const Mat3 r{{{c, s, 0.0}, {-s, c, 0.0}, {0.0, 0.0, 1.0}}};  // rows: a, b, c
    const Mat3 sig = from_voigt({st.s[0], st.s[1], 0.0, st.s[2], st.s[3], st.s[4]});
    const Mat3 sm = mul(mul(r, sig), transpose(r));
    Mat3 em{};
    em[0][0] = sm[0][0] / m.ea - m.prba / m.eb * sm[1][1] - m.prca / m.ec * sm[2][2];
    em[1][1] = -m.prba / m.eb * sm[0][0] + sm[1][1] / m.eb - m.prcb / m.ec * sm[2][2];
    em[2][2] = -m.prca / m.ec * sm[0][0] - m.prcb / m.ec * sm[1][1] + sm[2][2] / m.ec;
    em[0][1] = em[1][0] = sm[0][1] / (2.0 * m.gab);
    em[1][2] = em[2][1] = sm[1][2] / (2.0 * m.gbc);
    em[2][0] = em[0][2] = sm[2][0] / (2.0 * m.gca);
    const Mat3 el = mul(mul(transpose(r), em), r);
    const double tol = 1e-13;
    EXPECT_NEAR(el[0][0], d[0], tol);
    EXPECT_NEAR(el[1][1], d[1], tol);
    EXPECT_NEAR(el[0][1], d[2], tol);
    EXPECT_NEAR(el[1][2], d[3], tol);
    EXPECT_NEAR(el[2][0], d[4], tol);
    EXPECT_NEAR(el[2][2], dzz, tol);
  }
}

}  // namespace
}  // namespace plyform::material::test
