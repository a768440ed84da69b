// The trilinear hexahedron's geometry (hex8_geometry.hpp) against independent references: the
// uniform gradient b_I = (1/V) dV/dx_I against central differences of the volume integrated by
// 2x2x2 Gauss quadrature (exact for the trilinear map's Jacobian), its consistency (a
// translation leaves V unchanged, and sum_I x_I b_I reproduces the identity), the Gauss
// gradients' partition of unity and volume average, and the characteristic length of a cube and of
// a thin plate against Flanagan and Belytschko's closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "plyform/element/hex8_geometry.hpp"

namespace plyform::element {
namespace {

// A distorted, skewed hexahedron (LS-DYNA's node order), every face warped.
HexCoords distorted() {
  HexCoords c{};
  const double base[8][3] = {{0.0, 0.0, 0.0},  {2.1, 0.2, -0.1}, {2.3, 1.9, 0.2}, {-0.2, 1.7, 0.1},
                             {0.1, -0.1, 1.4}, {2.0, 0.1, 1.6},  {2.4, 2.2, 1.9}, {0.2, 1.8, 1.5}};
  for (int i = 0; i < 8; ++i) {
    c.x[i] = base[i][0];
    c.y[i] = base[i][1];
    c.z[i] = base[i][2];
  }
  return c;
}

double gauss_volume(const HexCoords& c) {
  GaussGradients g{};
  EXPECT_TRUE(gauss_gradients(c, g));
  double v = 0.0;
  for (double w : g.weight_det)
    v += w;
  return v;
}

TEST(Hex8Geometry, UniformGradientIsTheVolumesDerivative) {
  const HexCoords c = distorted();
  UniformGradient u{};
  ASSERT_TRUE(uniform_gradient(c, u));
  const double v = gauss_volume(c);
  EXPECT_NEAR(u.volume, v, 1e-13 * v);
  const double h = 1e-6;
  for (int i = 0; i < 8; ++i) {
    for (int d = 0; d < 3; ++d) {
      HexCoords p = c, m = c;
      double* pp = d == 0 ? p.x : d == 1 ? p.y : p.z;
      double* mm = d == 0 ? m.x : d == 1 ? m.y : m.z;
      pp[i] += h;
      mm[i] -= h;
      const double dv = (gauss_volume(p) - gauss_volume(m)) / (2.0 * h);
      const double b = d == 0 ? u.bx[i] : d == 1 ? u.by[i] : u.bz[i];
      EXPECT_NEAR(b * u.volume, dv, 1e-8) << "node " << i << ", direction " << d;
    }
  }
}

TEST(Hex8Geometry, UniformGradientReproducesLinearFields) {
  const HexCoords c = distorted();
  UniformGradient u{};
  ASSERT_TRUE(uniform_gradient(c, u));
  // sum_I b_I = 0 (a translation changes nothing) and sum_I x_I b_I = I (the gradient of x is
  // the identity): what makes the one-point element pass the patch test.
  double s[3] = {0, 0, 0}, g[3][3] = {};
  for (int i = 0; i < 8; ++i) {
    s[0] += u.bx[i];
    s[1] += u.by[i];
    s[2] += u.bz[i];
    const double x[3] = {c.x[i], c.y[i], c.z[i]};
    const double b[3] = {u.bx[i], u.by[i], u.bz[i]};
    for (int a = 0; a < 3; ++a)
      for (int d = 0; d < 3; ++d)
        g[a][d] += x[a] * b[d];
  }
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(s[d], 0.0, 1e-14);
  for (int a = 0; a < 3; ++a)
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(g[a][d], a == d ? 1.0 : 0.0, 1e-13) << a << "," << d;
}

TEST(Hex8Geometry, GaussGradientsArePartitionsOfUnityWhoseAverageIsTheUniformGradient) {
  const HexCoords c = distorted();
  GaussGradients g{};
  ASSERT_TRUE(gauss_gradients(c, g));
  for (int q = 0; q < 8; ++q) {
    double s[3] = {0, 0, 0};
    for (int i = 0; i < 8; ++i) {
      s[0] += g.bx[q][i];
      s[1] += g.by[q][i];
      s[2] += g.bz[q][i];
    }
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(s[d], 0.0, 1e-13) << "point " << q;
  }
  // The uniform gradient is the volume average of grad N_I, which 2x2x2 Gauss points integrate
  // exactly on any hexahedron (grad N_I det J is a polynomial of degree at most 2 in each
  // natural coordinate): sum_q w_q det J_q grad N_I(q) = V b_I.
  UniformGradient u{};
  ASSERT_TRUE(uniform_gradient(c, u));
  for (int i = 0; i < 8; ++i) {
    double avg[3] = {0, 0, 0};
    for (int q = 0; q < 8; ++q) {
      avg[0] += g.weight_det[q] * g.bx[q][i];
      avg[1] += g.weight_det[q] * g.by[q][i];
      avg[2] += g.weight_det[q] * g.bz[q][i];
    }
    EXPECT_NEAR(avg[0], u.volume * u.bx[i], 1e-13) << "node " << i;
    EXPECT_NEAR(avg[1], u.volume * u.by[i], 1e-13) << "node " << i;
    EXPECT_NEAR(avg[2], u.volume * u.bz[i], 1e-13) << "node " << i;
  }
}

TEST(Hex8Geometry, CharacteristicLengthOfACubeAndOfAThinPlate) {
  // A cube of side a: |b_I|^2 = 3 / (4 a)^2 at each of the 8 nodes, so L = 1 / sqrt(2 * 8 * 3 /
  // (16 a^2)) = a / sqrt(3).
  const double a = 2.5;
  HexCoords cube{};
  for (int i = 0; i < 8; ++i) {
    cube.x[i] = 0.5 * a * (kHexNodeXi[i][0] + 1.0);
    cube.y[i] = 0.5 * a * (kHexNodeXi[i][1] + 1.0);
    cube.z[i] = 0.5 * a * (kHexNodeXi[i][2] + 1.0);
  }
  UniformGradient u{};
  ASSERT_TRUE(uniform_gradient(cube, u));
  EXPECT_NEAR(u.volume, a * a * a, 1e-12);
  EXPECT_NEAR(characteristic_length(u), a / std::sqrt(3.0), 1e-12);
  // A thin plate of side a and thickness t << a: L tends to t.
  const double t = 1e-3 * a;
  HexCoords plate = cube;
  for (int i = 0; i < 8; ++i)
    plate.z[i] = 0.5 * t * (kHexNodeXi[i][2] + 1.0);
  ASSERT_TRUE(uniform_gradient(plate, u));
  EXPECT_NEAR(characteristic_length(u), t, 1e-5 * t);
  // An inverted element is refused.
  HexCoords inverted = cube;
  for (int i = 0; i < 8; ++i)
    inverted.z[i] = -inverted.z[i];
  EXPECT_FALSE(uniform_gradient(inverted, u));
}

}  // namespace
}  // namespace plyform::element
