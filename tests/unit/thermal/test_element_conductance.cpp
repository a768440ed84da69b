// The element matrices of heat conduction against closed forms: a hexahedron's conductance
// has zero row sums (a uniform temperature carries no flux), gives a linear temperature field
// the flux k grad T through its faces, and is what a uniform bar of one element gives
// (k A / L between its ends); the thin shell's likewise; the orthotropic tensor turns with
// the element's axes.
#include <gtest/gtest.h>

#include <cmath>

#include "plyform/thermal/element_conductance.hpp"

namespace plyform::thermal {
namespace {

// A box [0, lx] x [0, ly] x [0, lz] in LS-DYNA's node order, sheared by `shear` in x with z.
std::array<Vec3, 8> box(double lx, double ly, double lz, double shear = 0.0) {
  std::array<Vec3, 8> x{};
  const double xs[8] = {0, 1, 1, 0, 0, 1, 1, 0}, ys[8] = {0, 0, 1, 1, 0, 0, 1, 1},
               zs[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  for (std::size_t i = 0; i < 8; ++i)
    x[i] = {lx * xs[i] + shear * zs[i], ly * ys[i], lz * zs[i]};
  return x;
}

Tensor3 isotropic(double k) {
  Tensor3 t{};
  for (std::size_t i = 0; i < 3; ++i)
    t[i][i] = k;
  return t;
}

TEST(Hex8Conductance, RowsSumToZeroAndTheMatrixIsSymmetric) {
  double K[8][8];
  const double v = hex8_conductance(box(0.02, 0.01, 0.005, 0.003), isotropic(40.0), false, K);
  EXPECT_NEAR(v, 0.02 * 0.01 * 0.005, 1e-18);
  for (int i = 0; i < 8; ++i) {
    double sum = 0.0;
    for (int j = 0; j < 8; ++j) {
      sum += K[i][j];
      EXPECT_DOUBLE_EQ(K[i][j], K[j][i]);
    }
    EXPECT_NEAR(sum, 0.0, 1e-12 * K[i][i]);
    EXPECT_GT(K[i][i], 0.0);
  }
}

TEST(Hex8Conductance, ALinearFieldGivesTheFluxThroughTheEndFaces) {
  // T = g x on a box: the nodal heat K T is -q A / 4 at each x = 0 node and +q A / 4 at each
  // x = lx node (q = k g, A = ly lz), exact for both rules since the field is linear; the
  // sheared box still carries it exactly (an affine map).
  const double k = 25.0, g = 300.0, lx = 0.03, ly = 0.02, lz = 0.01;
  for (bool one_point : {false, true}) {
    for (double shear : {0.0, 0.004}) {
      const std::array<Vec3, 8> x = box(lx, ly, lz, shear);
      double K[8][8];
      hex8_conductance(x, isotropic(k), one_point, K);
      for (int i = 0; i < 8; ++i) {
        double r = 0.0;
        for (int j = 0; j < 8; ++j)
          r += K[i][j] * g * x[static_cast<std::size_t>(j)][0];
        const bool far = x[static_cast<std::size_t>(i)][0] > 0.5 * lx;
        EXPECT_NEAR(r, (far ? 1.0 : -1.0) * k * g * ly * lz / 4.0, 1e-9)
            << "node " << i << (one_point ? " one point" : " 2x2x2") << " shear " << shear;
      }
    }
  }
}

TEST(ShellConductance, ALinearFieldGivesTheFluxThroughTheEdgesForQuadsAndTriangles) {
  const double k = 40.0, g = 200.0, t = 0.002, lx = 0.04, ly = 0.01;
  const std::array<Vec3, 4> quad{Vec3{0, 0, 0}, Vec3{lx, 0, 0}, Vec3{lx, ly, 0}, Vec3{0, ly, 0}};
  double K[4][4];
  EXPECT_NEAR(shell_conductance(quad, false, isotropic(k), t, K), lx * ly, 1e-15);
  for (int i = 0; i < 4; ++i) {
    double r = 0.0;
    for (int j = 0; j < 4; ++j)
      r += K[i][j] * g * quad[static_cast<std::size_t>(j)][0];
    EXPECT_NEAR(r, (quad[static_cast<std::size_t>(i)][0] > 0 ? 1 : -1) * k * g * ly * t / 2, 1e-9);
  }
  // A triangle tilted out of the xy plane: a uniform field carries no heat, rows sum to 0.
  const std::array<Vec3, 4> tri{Vec3{0, 0, 0}, Vec3{0.02, 0, 0.01}, Vec3{0, 0.02, 0},
                                Vec3{0, 0.02, 0}};
  double Kt[4][4];
  EXPECT_GT(shell_conductance(tri, true, isotropic(k), t, Kt), 0.0);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(Kt[i][0] + Kt[i][1] + Kt[i][2], 0.0, 1e-12);
  EXPECT_EQ(Kt[3][3], 0.0);
}

TEST(ConductivityTensor, TheOrthotropicTensorFollowsTheElementAxes) {
  core::ThermalMaterial m;
  m.orthotropic = true;
  m.conductivity = {10.0, 1.0, 0.5};
  // AOPT 0: a along nodes 1-2, here at 45 degrees in the xy plane.
  const Tensor3 k = conductivity_tensor(m, {0, 0, 0}, {1, 1, 0}, {-1, 1, 0}, 2.0);
  EXPECT_NEAR(k[0][0], 2.0 * 5.5, 1e-12);
  EXPECT_NEAR(k[0][1], 2.0 * 4.5, 1e-12);
  EXPECT_NEAR(k[2][2], 2.0 * 0.5, 1e-12);
  m.aopt = 2;
  m.a = {0, 0, 1};
  m.d = {1, 0, 0};
  const Tensor3 k2 = conductivity_tensor(m, {}, {}, {}, 1.0);
  EXPECT_NEAR(k2[2][2], 10.0, 1e-12);  // a along z
  EXPECT_NEAR(k2[0][0], 1.0, 1e-12);   // b = c x a with c = a x d = y: b along x
  EXPECT_NEAR(k2[1][1], 0.5, 1e-12);
}

}  // namespace
}  // namespace plyform::thermal
