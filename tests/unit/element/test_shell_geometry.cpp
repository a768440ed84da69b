// The co-rotational frame and flat geometry of one quadrilateral shell (shell_common.hpp),
// against independent references: the area against the shoelace formula of the quadrilateral
// in its own plane, an orthonormal right-handed frame whose normal is the plane's, centre
// gradients that reproduce linear fields, a rigid motion that moves the frame with the element
// and leaves the local geometry unchanged, and LS-DYNA's shell length (area over the longest
// side) of a rectangle and a triangle.
#include <gtest/gtest.h>

#include <cmath>

#include "shell_common.hpp"

namespace plyform::element::shell_detail {
namespace {

// A convex, non-rectangular quadrilateral in the plane z = 0.
constexpr double kFlat[4][2] = {{0.0, 0.0}, {3.0, 0.4}, {2.6, 2.2}, {-0.3, 1.8}};

double shoelace() {
  double a = 0.0;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    a += kFlat[i][0] * kFlat[j][1] - kFlat[j][0] * kFlat[i][1];
  }
  return 0.5 * a;
}

// The quadrilateral turned by R (about the axis (1, 2, 2) / 3 by 0.7 rad) and moved by t.
void placed(double x[4][3], bool turned) {
  const double u[3] = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0}, c = std::cos(0.7), s = std::sin(0.7);
  double r[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      r[a][b] = (a == b ? c : 0.0) + (1.0 - c) * u[a] * u[b];
  r[0][1] -= s * u[2];
  r[0][2] += s * u[1];
  r[1][0] += s * u[2];
  r[1][2] -= s * u[0];
  r[2][0] -= s * u[1];
  r[2][1] += s * u[0];
  const double t[3] = {5.0, -2.0, 7.5};
  for (int i = 0; i < 4; ++i) {
    const double p[3] = {kFlat[i][0], kFlat[i][1], 0.0};
    for (int a = 0; a < 3; ++a)
      x[i][a] = turned ? r[a][0] * p[0] + r[a][1] * p[1] + r[a][2] * p[2] + t[a] : p[a];
  }
}

double dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

TEST(ShellGeometry, FrameAreaAndGradientsOfAFlatQuadrilateral) {
  double x[4][3];
  placed(x, false);
  Geometry g{};
  ASSERT_TRUE(geometry(x, g));
  EXPECT_NEAR(g.area, shoelace(), 1e-13);
  EXPECT_NEAR(std::abs(g.e3[2]), 1.0, 1e-15);
  for (const double* e : {g.e1, g.e2, g.e3})
    EXPECT_NEAR(dot(e, e), 1.0, 1e-14);
  EXPECT_NEAR(dot(g.e1, g.e2), 0.0, 1e-15);
  EXPECT_NEAR(dot(g.e1, g.e3), 0.0, 1e-15);
  // Right-handed: e1 x e2 = e3.
  const double c[3] = {g.e1[1] * g.e2[2] - g.e1[2] * g.e2[1], g.e1[2] * g.e2[0] - g.e1[0] * g.e2[2],
                       g.e1[0] * g.e2[1] - g.e1[1] * g.e2[0]};
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(c[d], g.e3[d], 1e-14);
  // Linear fields: sum b = 0, sum xl b1 = 1, sum yl b2 = 1, the mixed sums 0.
  double s1 = 0, s2 = 0, x1 = 0, y2 = 0, x2 = 0, y1 = 0;
  for (int i = 0; i < 4; ++i) {
    s1 += g.b1[i];
    s2 += g.b2[i];
    x1 += g.xl[i] * g.b1[i];
    y2 += g.yl[i] * g.b2[i];
    x2 += g.xl[i] * g.b2[i];
    y1 += g.yl[i] * g.b1[i];
  }
  EXPECT_NEAR(s1, 0.0, 1e-14);
  EXPECT_NEAR(s2, 0.0, 1e-14);
  EXPECT_NEAR(x1, 1.0, 1e-14);
  EXPECT_NEAR(y2, 1.0, 1e-14);
  EXPECT_NEAR(x2, 0.0, 1e-14);
  EXPECT_NEAR(y1, 0.0, 1e-14);
}

TEST(ShellGeometry, ARigidMotionMovesTheFrameAndKeepsTheLocalGeometry) {
  double x0[4][3], x1[4][3];
  placed(x0, false);
  placed(x1, true);
  Geometry g0{}, g1{};
  ASSERT_TRUE(geometry(x0, g0));
  ASSERT_TRUE(geometry(x1, g1));
  EXPECT_NEAR(g1.area, g0.area, 1e-13);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(g1.xl[i], g0.xl[i], 1e-13);
    EXPECT_NEAR(g1.yl[i], g0.yl[i], 1e-13);
    EXPECT_NEAR(g1.b1[i], g0.b1[i], 1e-13);
    EXPECT_NEAR(g1.b2[i], g0.b2[i], 1e-13);
  }
  // The normal is the turned plane's: perpendicular to every edge.
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const double e[3] = {x1[j][0] - x1[i][0], x1[j][1] - x1[i][1], x1[j][2] - x1[i][2]};
    EXPECT_NEAR(dot(e, g1.e3), 0.0, 1e-13);
  }
}

TEST(ShellGeometry, ShellLengthIsTheAreaOverTheLongestSide) {
  // A 4 x 1.5 rectangle: 6 / 4 = 1.5, the short side.
  const double rect[4][3] = {{0, 0, 0}, {4, 0, 0}, {4, 1.5, 0}, {0, 1.5, 0}};
  EXPECT_NEAR(characteristic_length(rect, 6.0, false), 1.5, 1e-15);
  // A triangle (N4 = N3) with sides 3, 4, 5: twice the area over 5, its height to the
  // hypotenuse, 12 / 5.
  const double tri[4][3] = {{0, 0, 0}, {3, 0, 0}, {0, 4, 0}, {0, 4, 0}};
  EXPECT_NEAR(characteristic_length(tri, 6.0, true), 2.4, 1e-15);
}

}  // namespace
}  // namespace plyform::element::shell_detail
