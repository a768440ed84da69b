#include "plyform/element/element_strain.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace plyform::element {
namespace {

void fill_nan(StrainTensor out) {
  for (int c = 0; c < 6; ++c)
    out[c] = std::numeric_limits<double>::quiet_NaN();
}

/// The centre tangents dX/dxi, dX/deta of a bilinear quad and their unit normal.
bool quad_frame(const double p[4][3], Eigen::Vector3d& t1, Eigen::Vector3d& t2,
                Eigen::Vector3d& n) {
  for (int d = 0; d < 3; ++d) {
    t1[d] = 0.25 * (-p[0][d] + p[1][d] + p[2][d] - p[3][d]);
    t2[d] = 0.25 * (-p[0][d] - p[1][d] + p[2][d] + p[3][d]);
  }
  n = t1.cross(t2);
  const double area = n.norm();
  if (!(area > 0.0))
    return false;
  n /= area;
  return true;
}

}  // namespace

bool log_strain(const double F[3][3], StrainTensor out) {
  Eigen::Matrix3d f;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      f(i, j) = F[i][j];
  if (!(f.determinant() > 0.0)) {
    fill_nan(out);
    return false;
  }
  // B = F F^T is symmetric positive definite: ln B through its eigenvectors.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(f * f.transpose());
  const Eigen::Vector3d half_log = 0.5 * eig.eigenvalues().array().log().matrix();
  const Eigen::Matrix3d e =
      eig.eigenvectors() * half_log.asDiagonal() * eig.eigenvectors().transpose();
  out[0] = e(0, 0);
  out[1] = e(1, 1);
  out[2] = e(2, 2);
  out[3] = e(0, 1);
  out[4] = e(1, 2);
  out[5] = e(2, 0);
  return true;
}

bool hex8_log_strain(const HexCoords& reference, const HexCoords& current, StrainTensor out) {
  UniformGradient g{};
  if (!uniform_gradient(reference, g)) {
    fill_nan(out);
    return false;
  }
  double F[3][3] = {};
  const double* x[3] = {current.x, current.y, current.z};
  for (int node = 0; node < 8; ++node) {
    const double b[3] = {g.bx[node], g.by[node], g.bz[node]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        F[i][j] += x[i][node] * b[j];
  }
  return log_strain(F, out);
}

bool shell_log_strain(const double reference[4][3], const double current[4][3],
                      double thickness_ratio, StrainTensor out) {
  Eigen::Vector3d T1, T2, N, t1, t2, n;
  if (!quad_frame(reference, T1, T2, N) || !quad_frame(current, t1, t2, n) ||
      !(thickness_ratio > 0.0)) {
    fill_nan(out);
    return false;
  }
  Eigen::Matrix3d from, to;
  from << T1, T2, N;
  to << t1, t2, thickness_ratio * n;
  const Eigen::Matrix3d f = to * from.inverse();
  double F[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      F[i][j] = f(i, j);
  return log_strain(F, out);
}

}  // namespace plyform::element
