// The shells' surface strains for the formability outputs (element/shell_surface_strain.hpp)
// against closed forms, on small grids of quads laid on known surfaces:
// - a flat sheet rolled onto a cylinder of radius R without stretching its generators: the
//   fitted curvature is 1 / (R cos(dtheta / 2)) (the elements are the circle's chords, their
//   centres on the radius R cos(dtheta / 2)), the membrane strain along the arc the chord's
//   ln(2 sin(dtheta / 2) / dtheta), so top and bottom are those plus and minus h / 2 times it,
//   the same after any rigid motion; h / (2R) itself within dtheta^2 / 8;
// - a sphere cap kept a sphere cap (no strain at all) and a flat sheet bent onto it (both
//   principal curvatures 1 / R to dtheta^2);
// - a cylinder unrolled flat: the curvature change is -1 / R (the reference's curvature comes
//   off);
// - the twisted surface z = k x y, which bilinear quads represent exactly: principal
//   curvatures +-k / sqrt(1 + k^2 a^2) at 45 degrees and no membrane strain;
// - a homogeneous stretch of a skewed quad in a tilted plane: the middle's principal strains
//   are the in-plane eigenvalues of element_strain.hpp's shell strain, to round-off.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "plyform/element/element_strain.hpp"
#include "plyform/element/shell_surface_strain.hpp"

namespace plyform {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Map = std::function<Vector3d(double u, double v)>;

/// A grid of (n x n) quads of size a in the (u, v) plane, centred on the origin; each
/// configuration places node (u, v) with a map. Element (i, j) runs counter-clockwise seen
/// from +z in (u, v).
struct Grid {
  int n;
  double a;
  Vector3d node(const Map& map, int i, int j) const {
    return map((i - 0.5 * n) * a, (j - 0.5 * n) * a);
  }
  element::ShellCentre centre(const Map& map, int i, int j) const {
    double p[4][3];
    const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
    for (int k = 0; k < 4; ++k) {
      const Vector3d x = node(map, i + di[k], j + dj[k]);
      for (int d = 0; d < 3; ++d)
        p[k][d] = x[d];
    }
    element::ShellCentre c{};
    EXPECT_TRUE(element::shell_centre(p, c));
    return c;
  }
  /// The covariant curvature of element (i, j) fitted to its edge neighbours in the grid.
  void curvature(const Map& map, int i, int j, double b[3]) const {
    double c[4][3], nn[4][3];
    int count = 0;
    const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int p = i + di[k], q = j + dj[k];
      if (p < 0 || q < 0 || p >= n || q >= n)
        continue;
      const element::ShellCentre o = centre(map, p, q);
      for (int d = 0; d < 3; ++d) {
        c[count][d] = o.centre[d];
        nn[count][d] = o.normal[d];
      }
      ++count;
    }
    element::fit_curvature(centre(map, i, j), count, c, nn, b);
  }
  element::SurfaceStrains strains(const Map& reference, const Map& current, int i, int j,
                                  double h) const {
    double b0[3], b[3];
    curvature(reference, i, j, b0);
    curvature(current, i, j, b);
    element::SurfaceStrains s{};
    EXPECT_TRUE(element::shell_surface_strains(centre(reference, i, j), b0, centre(current, i, j),
                                               b, h, s));
    return s;
  }
};

const Map flat = [](double u, double v) { return Vector3d(u, v, 0.0); };

/// The sheet rolled about an axis along v, the curvature's centre at height R above it (the
/// normal, +z at first, points towards it: the top is the inside), moved rigidly by (r, c).
Map rolled(double radius, const Matrix3d& r = Matrix3d::Identity(),
           const Vector3d& c = Vector3d::Zero()) {
  return [=](double u, double v) {
    const double t = u / radius;
    return Vector3d(r * Vector3d(radius * std::sin(t), v, radius * (1.0 - std::cos(t))) + c);
  };
}

constexpr double kH = 1.0;

TEST(ShellSurfaceStrain, RolledOntoACylinderTheSurfacesStrainByHalfTheThicknessOverTheRadius) {
  const double radius = 20.0, a = 1.0, dtheta = a / radius;
  const Grid grid{5, a};
  const double kappa = 1.0 / (radius * std::cos(0.5 * dtheta));
  const double chord = std::log(2.0 * std::sin(0.5 * dtheta) / dtheta);
  const Matrix3d turn = Eigen::AngleAxisd(0.8, Vector3d(1.0, -2.0, 0.5).normalized()).matrix();
  for (const Map& current : {rolled(radius), rolled(radius, turn, Vector3d(3.0, -1.0, 7.0))}) {
    // Every element: the edge ones fit one-sided differences, exact on a circle as well.
    for (int i = 0; i < grid.n; ++i) {
      for (int j = 0; j < grid.n; ++j) {
        const element::SurfaceStrains s = grid.strains(flat, current, i, j, kH);
        // Top (inside): the arc shortened, nothing across; bottom (outside): stretched.
        EXPECT_NEAR(s.major[2], 0.0, 1e-13);
        EXPECT_NEAR(s.minor[2], chord - 0.5 * kH * kappa, 1e-13);
        EXPECT_NEAR(s.major[0], chord + 0.5 * kH * kappa, 1e-13);
        EXPECT_NEAR(s.minor[0], 0.0, 1e-13);
        EXPECT_NEAR(s.minor[1], chord, 1e-13);
        EXPECT_NEAR(s.major[1], 0.0, 1e-13);
        // The bending part against h / (2R) itself: the chord's dtheta^2 / 8 (3.1e-4 here).
        EXPECT_NEAR((s.major[0] - s.minor[1]) / (0.5 * kH / radius), 1.0,
                    dtheta * dtheta / 8.0 + 1e-6);
      }
    }
  }
}

TEST(ShellSurfaceStrain, TheReferenceCurvatureComesOff) {
  const double radius = 10.0, a = 0.5, dtheta = a / radius;
  const Grid grid{4, a};
  // A sphere cap (azimuthal map of the plane onto the sphere) kept as it is: nothing strains.
  const Map cap = [=](double u, double v) {
    const double rho = std::hypot(u, v), t = rho / radius;
    const double s = rho > 0.0 ? radius * std::sin(t) / rho : 1.0;
    return Vector3d(s * u, s * v, radius * (1.0 - std::cos(t)));
  };
  const element::SurfaceStrains same = grid.strains(cap, cap, 1, 2, kH);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(same.major[k], 0.0, 1e-15) << k;
    EXPECT_NEAR(same.minor[k], 0.0, 1e-15) << k;
  }
  // A flat sheet bent onto the cap: both directions curve by 1 / R (the top is the inside).
  const element::SurfaceStrains bent = grid.strains(flat, cap, 1, 1, kH);
  const double b = 0.5 * kH / radius, tol = b * dtheta * dtheta;
  EXPECT_NEAR(bent.major[0] - bent.major[1], b, tol);
  EXPECT_NEAR(bent.minor[0] - bent.minor[1], b, tol);
  EXPECT_NEAR(bent.major[2] - bent.major[1], -b, tol);
  EXPECT_NEAR(bent.minor[2] - bent.minor[1], -b, tol);
  // A cylinder unrolled flat: the top, the inside before, now stretched by h / (2R) along the
  // arc (the middle's major: the chords stretched back to the arc's length), the bottom
  // shortened by as much (its minor).
  const element::SurfaceStrains unrolled = grid.strains(rolled(radius), flat, 1, 2, kH);
  EXPECT_GT(unrolled.major[1], 0.0);
  EXPECT_NEAR(unrolled.major[2] - unrolled.major[1], b, tol);
  EXPECT_NEAR(unrolled.minor[0] - unrolled.major[1], -b, tol);
  std::printf(
      "h/(2R) %.4f; sphere: bottom %.3e, %.3e off; unrolled: top %.3e off (tolerance %.1e)\n", b,
      bent.major[0] - bent.major[1] - b, bent.minor[0] - bent.minor[1] - b,
      unrolled.major[2] - unrolled.major[1] - b, tol);
}

TEST(ShellSurfaceStrain, TwistedSurfaceHasPrincipalCurvaturesAtFortyFiveDegrees) {
  // z = k x y: bilinear quads lie on it exactly; its normal gradient at the centre of the
  // middle element is [[0, -k], [-k, 0]] / sqrt(1 + (k a)^2) fitted from the neighbours'
  // centres (a apart), so the surfaces' principal strains are +-k h / 2 over that root.
  const double k = 0.02, a = 1.0;
  const Grid grid{3, a};
  const Map twisted = [=](double u, double v) { return Vector3d(u, v, k * u * v); };
  const element::SurfaceStrains s = grid.strains(flat, twisted, 1, 1, kH);
  const double b = 0.5 * kH * k / std::sqrt(1.0 + k * a * k * a);
  for (int surface : {0, 2}) {
    EXPECT_NEAR(s.major[surface], b, 1e-16) << surface;
    EXPECT_NEAR(s.minor[surface], -b, 1e-16) << surface;
  }
  EXPECT_NEAR(s.major[1], 0.0, 1e-15);
  EXPECT_NEAR(s.minor[1], 0.0, 1e-15);
}

TEST(ShellSurfaceStrain, MiddleIsTheMembraneOfTheShellStrainTensor) {
  // A skewed quad in a tilted plane, stretched homogeneously in its plane and turned.
  const Matrix3d tilt = Eigen::AngleAxisd(0.6, Vector3d(1.0, -0.5, 0.2).normalized()).matrix();
  const Vector3d a1 = tilt.col(0), a2 = tilt.col(1);
  const double plane[4][2] = {{0.0, 0.0}, {2.0, 0.3}, {2.4, 1.5}, {0.2, 1.1}};
  Matrix3d u_local = Matrix3d::Identity();
  u_local.topLeftCorner<2, 2>() << 1.3, 0.2, 0.2, 0.8;
  const Matrix3d f = Eigen::AngleAxisd(0.9, Vector3d(0.0, 1.0, 1.0).normalized()).matrix() * tilt *
                     u_local * tilt.transpose();
  double ref[4][3], cur[4][3];
  for (int i = 0; i < 4; ++i) {
    const Vector3d x0 = plane[i][0] * a1 + plane[i][1] * a2;
    const Vector3d x = f * x0;
    for (int d = 0; d < 3; ++d) {
      ref[i][d] = x0[d];
      cur[i][d] = x[d];
    }
  }
  double e[6];
  ASSERT_TRUE(element::shell_log_strain(ref, cur, 1.0, e));
  Matrix3d strain;
  strain << e[0], e[3], e[5], e[3], e[1], e[4], e[5], e[4], e[2];
  const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(strain);  // ascending; one is ln 1 = 0
  element::ShellCentre c0{}, c{};
  ASSERT_TRUE(element::shell_centre(ref, c0));
  ASSERT_TRUE(element::shell_centre(cur, c));
  const double none[3] = {0.0, 0.0, 0.0};
  element::SurfaceStrains s{};
  ASSERT_TRUE(element::shell_surface_strains(c0, none, c, none, 0.7, s));
  EXPECT_NEAR(s.major[1], eig.eigenvalues()[2], 1e-14);
  EXPECT_NEAR(s.minor[1], eig.eigenvalues()[0], 1e-14);
  EXPECT_GT(s.major[1], 0.0);
  EXPECT_LT(s.minor[1], 0.0);
  EXPECT_EQ(s.major[0], s.major[2]) << "no curvature: the surfaces strain as the middle";
  // A collapsed element has no strain.
  double collapsed[4][3] = {};
  element::ShellCentre none_centre{};
  EXPECT_FALSE(element::shell_centre(collapsed, none_centre));
  EXPECT_FALSE(element::shell_surface_strains(c0, none, none_centre, none, 0.7, s));
  EXPECT_TRUE(std::isnan(s.major[2]));
}

}  // namespace
}  // namespace plyform
