// *DATABASE_EXTENT_BINARY: what the states hold, and the strain tensor STRFLG asks for.
// The logarithmic strain 1/2 ln(F F^T) against closed forms: stretches (ln of each), a
// stretch followed by a rotation (R ln(U) R^T), simple shear (ln(l) / sqrt(4 + g^2) [[g, 2],
// [2, -g]], l = g/2 + sqrt(1 + g^2/4)), homogeneous deformations of a distorted hexahedron and
// of a skewed shell in a tilted plane (exact: the element's mean F is the applied F), rigid
// rotations (zero). Then `plyform run` on a hexahedron and a shell stretched along x: the
// state's `strain` is ln(L / L0) along x (the stretch read from the state's own
// displacements), the shell's zz is ln(h / h0) of its written thickness, and SIGFLG 3 /
// EPSFLG 2 leave out what they say.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "plyform/app/commands.hpp"
#include "plyform/element/element_strain.hpp"
#include "temp_dir.hpp"
#include "vtu_arrays.hpp"

namespace plyform {
namespace {

using Eigen::Matrix3d;

Matrix3d rotation(double angle, Eigen::Vector3d axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// The six components as a symmetric matrix.
Matrix3d as_matrix(const double e[6]) {
  Matrix3d m;
  m << e[0], e[3], e[5], e[3], e[1], e[4], e[5], e[4], e[2];
  return m;
}

double strain_of(const Matrix3d& f, Matrix3d& out) {
  double F[3][3], e[6];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      F[i][j] = f(i, j);
  const bool ok = element::log_strain(F, e);
  out = as_matrix(e);
  return ok ? 1.0 : 0.0;
}

TEST(LogStrain, StretchesGiveTheirLogarithms) {
  Matrix3d e;
  ASSERT_TRUE(strain_of(Eigen::Vector3d(1.3, 0.8, 1.05).asDiagonal(), e));
  const Matrix3d closed =
      Eigen::Vector3d(std::log(1.3), std::log(0.8), std::log(1.05)).asDiagonal();
  EXPECT_LT((e - closed).norm(), 1e-14);
}

TEST(LogStrain, StretchThenRotationIsTheRotatedLogarithmOfTheStretch) {
  // F = R U: the Eulerian strain is ln V = R ln U R^T (the Lagrangian one would be ln U).
  const Matrix3d r = rotation(0.7, {1.0, 2.0, -0.5});
  Matrix3d u;
  u << 1.2, 0.1, 0.0, 0.1, 0.9, 0.05, 0.0, 0.05, 1.1;
  Eigen::SelfAdjointEigenSolver<Matrix3d> eig(u);
  const Matrix3d ln_u = eig.eigenvectors() * eig.eigenvalues().array().log().matrix().asDiagonal() *
                        eig.eigenvectors().transpose();
  Matrix3d e;
  ASSERT_TRUE(strain_of(r * u, e));
  EXPECT_LT((e - r * ln_u * r.transpose()).norm(), 1e-14);
  // A rigid rotation alone strains nothing.
  ASSERT_TRUE(strain_of(r, e));
  EXPECT_LT(e.norm(), 1e-15);
}

TEST(LogStrain, SimpleShearHasItsClosedForm) {
  for (double g : {0.01, 0.5, 2.0}) {
    Matrix3d f = Matrix3d::Identity();
    f(0, 1) = g;
    Matrix3d e;
    ASSERT_TRUE(strain_of(f, e));
    const double l = g / 2.0 + std::sqrt(1.0 + g * g / 4.0);
    const double k = std::log(l) / std::sqrt(4.0 + g * g);
    Matrix3d closed = Matrix3d::Zero();
    closed(0, 0) = k * g;
    closed(1, 1) = -k * g;
    closed(0, 1) = closed(1, 0) = 2.0 * k;
    EXPECT_LT((e - closed).norm(), 1e-14) << "gamma " << g;
  }
}

TEST(LogStrain, InvertedDeformationHasNone) {
  Matrix3d e;
  EXPECT_FALSE(strain_of(Eigen::Vector3d(1.0, 1.0, -0.5).asDiagonal(), e));
  EXPECT_TRUE(std::isnan(e(0, 0)));
}

TEST(LogStrain, HexahedronUnderHomogeneousDeformationGivesTheAppliedStrain) {
  // A distorted hexahedron (no two faces parallel), moved by x = F X + c.
  element::HexCoords ref{}, cur{};
  const double jitter[8][3] = {{0.0, 0.0, 0.0},   {0.1, -0.05, 0.02}, {-0.08, 0.1, 0.0},
                               {0.05, 0.0, -0.1}, {0.0, 0.07, 0.05},  {-0.06, 0.0, 0.09},
                               {0.04, -0.1, 0.0}, {0.0, 0.03, -0.04}};
  for (int i = 0; i < 8; ++i) {
    ref.x[i] = 2.0 * (element::kHexNodeXi[i][0] + 1.0) + jitter[i][0];
    ref.y[i] = 1.0 * (element::kHexNodeXi[i][1] + 1.0) + jitter[i][1];
    ref.z[i] = 0.5 * (element::kHexNodeXi[i][2] + 1.0) + jitter[i][2];
  }
  Matrix3d u;
  u << 1.15, 0.2, -0.05, 0.0, 0.9, 0.1, 0.03, 0.0, 1.02;
  for (const Matrix3d& f : {Matrix3d(u), Matrix3d(rotation(1.1, {0.3, -1.0, 0.4}) * u),
                            Matrix3d(rotation(2.0, {1.0, 1.0, 1.0}))}) {
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d x =
          f * Eigen::Vector3d(ref.x[i], ref.y[i], ref.z[i]) + Eigen::Vector3d(5.0, -3.0, 1.0);
      cur.x[i] = x[0];
      cur.y[i] = x[1];
      cur.z[i] = x[2];
    }
    double e[6];
    ASSERT_TRUE(element::hex8_log_strain(ref, cur, e));
    Matrix3d closed;
    ASSERT_TRUE(strain_of(f, closed));
    EXPECT_LT((as_matrix(e) - closed).norm(), 1e-13);
  }
}

TEST(LogStrain, ShellInATiltedPlaneGivesTheAppliedStrainAndItsThicknessStretch) {
  // A skewed quad in a tilted plane (and a triangle, node 3 = node 4); in its own axes
  // (a1, a2 in the plane, n normal) the deformation is U = [[1.2, 0.15], [0.15, 0.85]] in the
  // plane and h / h0 = 0.93 along n, then the whole turned by R.
  const Matrix3d tilt = rotation(0.6, {1.0, -0.5, 0.2});
  const Eigen::Vector3d a1 = tilt.col(0), a2 = tilt.col(1);
  const double plane[4][2] = {{0.0, 0.0}, {2.0, 0.3}, {2.4, 1.5}, {0.2, 1.1}};
  Matrix3d u_local = Matrix3d::Zero();
  u_local.topLeftCorner<2, 2>() << 1.2, 0.15, 0.15, 0.85;
  u_local(2, 2) = 0.93;
  const Matrix3d r = rotation(0.9, {0.0, 1.0, 1.0});
  const Matrix3d f = r * tilt * u_local * tilt.transpose();
  Matrix3d closed;
  ASSERT_TRUE(strain_of(f, closed));
  for (bool triangle : {false, true}) {
    double ref[4][3], cur[4][3];
    for (int i = 0; i < 4; ++i) {
      const int k = triangle && i == 3 ? 2 : i;
      const Eigen::Vector3d x0 = plane[k][0] * a1 + plane[k][1] * a2 + Eigen::Vector3d(1, 2, 3);
      const Eigen::Vector3d x = f * x0 + Eigen::Vector3d(-4.0, 0.5, 2.0);
      for (int d = 0; d < 3; ++d) {
        ref[i][d] = x0[d];
        cur[i][d] = x[d];
      }
    }
    double e[6];
    ASSERT_TRUE(element::shell_log_strain(ref, cur, 0.93, e));
    EXPECT_LT((as_matrix(e) - closed).norm(), 1e-13) << (triangle ? "triangle" : "quad");
  }
}

// --- `plyform run`: the arrays of the states.
constexpr double kEnd = 5.0e-4, kRho = 7.85e-9, kE = 210000.0;

std::string stretched_deck(double speed) {
  std::ostringstream os;
  os.precision(17);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n"
     << kEnd << "\n*DATABASE_BINARY_D3PLOT\n"
     << kEnd / 4 << "\n*DATABASE_EXTENT_BINARY\n"
     << "0,0,3,1,3,2,1,1\n"
     << "*DEFINE_CURVE\n1\n0,0\n"
     << kEnd / 4 << ",1\n"
     << kEnd << ",1\n";
  // Part 1: a unit cube of hexahedra (Poisson's ratio 0: no contraction). Part 2: a unit
  // square shell 0.5 thick (Poisson's ratio 0.3: it narrows and thins).
  os << "*PART\ncube\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1," << kRho << "," << kE
     << ",0.0\n*PART\nsheet\n2,2,2\n*SECTION_SHELL\n2,2,0.8333,3\n0.5,0.5,0.5,0.5\n"
     << "*MAT_ELASTIC\n2," << kRho << "," << kE << ",0.3\n*NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i)
        os << 1 + i + 2 * j + 4 * k << "," << i << "," << j << "," << k << "\n";
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 1; ++i)
      os << 11 + i + 2 * j << "," << i << "," << j + 3 << ",0\n";
  os << "*ELEMENT_SOLID\n1,1,1,2,4,3,5,6,8,7\n*ELEMENT_SHELL\n2,2,11,12,14,13\n";
  os << "*BOUNDARY_SPC_NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      os << 1 + 2 * j + 4 * k << ",0,1," << (j == 0) << "," << (k == 0) << "\n";
  os << "11,0,1,1,1,1,1,1\n13,0,1,0,1,1,1,1\n12,0,0,1,1,1,1,1\n14,0,0,0,1,1,1,1\n";
  os << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int node : {2, 4, 6, 8, 12, 14})
    os << node << ",1,0,1," << speed << "\n";
  os << "*END\n";
  return os.str();
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(DeckExtentBinary, StrainOfStretchedElementsAndTheFlagsOfTheStates) {
  test::TempDir dir;
  app::RunOptions o;
  o.deck = dir.write("stretch.k", stretched_deck(0.1 / (0.875 * kEnd)));
  o.output = dir.path() / "out";
  o.progress = false;
  std::ostringstream out, err;
  ASSERT_EQ(app::run_deck(o, out, err), 0) << err.str();
  const auto arrays = test::appended_arrays(read_text(*o.output / "results_0004.vtu"));
  EXPECT_FALSE(arrays.contains("plastic_strain")) << "EPSFLG 2";
  ASSERT_TRUE(arrays.contains("stress")) << "SIGFLG 3 keeps the solids'";
  ASSERT_TRUE(arrays.contains("strain")) << "STRFLG 1";
  ASSERT_TRUE(arrays.contains("thickness"));
  const auto stress = test::as_doubles(arrays.at("stress"));
  const auto strain = test::as_doubles(arrays.at("strain"));
  const auto u = test::as_doubles(arrays.at("displacement"));
  const auto h = test::as_doubles(arrays.at("thickness"));
  ASSERT_EQ(strain.size(), 12u);
  EXPECT_GT(stress[0], 1000.0) << "the cube is stretched: sxx";
  EXPECT_TRUE(std::isnan(stress[6])) << "SIGFLG 3: no shell stress";
  // The cube (cell 0): node 2 (index 1) carries the stretch; nothing across (Poisson 0).
  const double cube_stretch = 1.0 + u[3 * 1];
  EXPECT_GT(cube_stretch, 1.09);
  EXPECT_NEAR(strain[0], std::log(cube_stretch), 1e-12);
  for (int c = 1; c < 6; ++c)
    EXPECT_NEAR(strain[c], 0.0, 1e-9) << c;
  // The shell (cell 1): nodes 11-14 are indices 8-11; 12 pulled, 13 across the width.
  const double length = 1.0 + u[3 * 9], width = 1.0 + u[3 * 10 + 1];
  EXPECT_LT(width, 0.99) << "the sheet narrows";
  EXPECT_NEAR(strain[6], std::log(length), 1e-12);
  EXPECT_NEAR(strain[7], std::log(width), 1e-12);
  EXPECT_NEAR(strain[8], std::log(h[1] / 0.5), 1e-12);
  EXPECT_LT(strain[8], -0.01) << "the sheet thins";
  // Uniaxial stress of the elastic sheet: both contractions are -nu times the stretch.
  EXPECT_NEAR(strain[7], -0.3 * strain[6], 1e-4);
  EXPECT_NEAR(strain[8], -0.3 * strain[6], 1e-4);
  std::printf("cube: xx %.6f = ln %.6f; sheet: xx %.6f, yy %.6f, zz %.6f (ln h/h0)\n", strain[0],
              cube_stretch, strain[6], strain[7], strain[8]);
}

}  // namespace
}  // namespace plyform
