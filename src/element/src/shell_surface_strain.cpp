#include "plyform/element/shell_surface_strain.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace plyform::element {
namespace {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

Vector3d vec(const double v[3]) {
  return {v[0], v[1], v[2]};
}

/// The orthonormal axes of a centre's tangent plane: e1 along t1, e2 = n x e1.
void tangent_axes(const ShellCentre& s, Vector3d& e1, Vector3d& e2) {
  e1 = vec(s.t1).normalized();
  e2 = vec(s.normal).cross(e1);
}

/// J(i, a) = e_i . t_a: the tangents' components on the tangent plane's axes.
Matrix2d tangent_components(const ShellCentre& s) {
  Vector3d e1, e2;
  tangent_axes(s, e1, e2);
  const Vector3d t1 = vec(s.t1), t2 = vec(s.t2);
  Matrix2d j;
  j << e1.dot(t1), e1.dot(t2), e2.dot(t1), e2.dot(t2);
  return j;
}

Matrix2d symmetric(const double v[3]) {
  Matrix2d m;
  m << v[0], v[2], v[2], v[1];
  return m;
}

void principal(const Matrix2d& e, double& major, double& minor) {
  const double mean = 0.5 * (e(0, 0) + e(1, 1));
  const double radius = std::hypot(0.5 * (e(0, 0) - e(1, 1)), e(0, 1));
  major = mean + radius;
  minor = mean - radius;
}

}  // namespace

bool shell_centre(const double p[4][3], ShellCentre& out) {
  const bool triangle = p[2][0] == p[3][0] && p[2][1] == p[3][1] && p[2][2] == p[3][2];
  const int distinct = triangle ? 3 : 4;
  for (int d = 0; d < 3; ++d) {
    out.t1[d] = 0.25 * (-p[0][d] + p[1][d] + p[2][d] - p[3][d]);
    out.t2[d] = 0.25 * (-p[0][d] - p[1][d] + p[2][d] + p[3][d]);
    double c = 0.0;
    for (int i = 0; i < distinct; ++i)
      c += p[i][d];
    out.centre[d] = c / distinct;
  }
  const Vector3d n = vec(out.t1).cross(vec(out.t2));
  const double area = n.norm();
  const bool ok = area > 0.0;
  for (int d = 0; d < 3; ++d)
    out.normal[d] = ok ? n[d] / area : std::numeric_limits<double>::quiet_NaN();
  return ok;
}

void fit_curvature(const ShellCentre& self, int count, const double (*centres)[3],
                   const double (*normals)[3], double b[3]) {
  // Unknowns k = (K11, K22, K12) of the symmetric normal gradient on the axes e1, e2; each
  // neighbour gives two equations, dn_1 = K11 d_1 + K12 d_2 and dn_2 = K12 d_1 + K22 d_2.
  Vector3d e1, e2;
  tangent_axes(self, e1, e2);
  const Vector3d c = vec(self.centre), n = vec(self.normal);
  Matrix3d normal_matrix = Matrix3d::Zero();
  Vector3d rhs = Vector3d::Zero();
  for (int k = 0; k < count; ++k) {
    const Vector3d d = vec(centres[k]) - c, dn = vec(normals[k]) - n;
    const double d1 = e1.dot(d), d2 = e2.dot(d);
    const Vector3d row1(d1, 0.0, d2), row2(0.0, d2, d1);
    normal_matrix += row1 * row1.transpose() + row2 * row2.transpose();
    rhs += row1 * e1.dot(dn) + row2 * e2.dot(dn);
  }
  // A direction no neighbour lies along (across a strip one element wide) leaves the system
  // singular: a regularisation of 1e-12 of its trace gives that direction no curvature rather
  // than round-off noise, and one step of refinement takes the regularisation back out of the
  // directions the neighbours determine (to 1e-24 of them).
  const double trace = normal_matrix.trace();
  Vector3d k = Vector3d::Zero();
  if (trace > 0.0) {
    const Matrix3d inverse = (normal_matrix + 1e-12 * trace * Matrix3d::Identity()).inverse();
    k = inverse * rhs;
    k += inverse * (rhs - normal_matrix * k);
  }
  Matrix2d grad;
  grad << k[0], k[2], k[2], k[1];
  const Matrix2d j = tangent_components(self);
  const Matrix2d cov = j.transpose() * grad * j;
  b[0] = cov(0, 0);
  b[1] = cov(1, 1);
  b[2] = 0.5 * (cov(0, 1) + cov(1, 0));
}

namespace {

/// The membrane strain 1/2 ln(B) and the change of curvature kappa on the current tangent
/// plane's axes (see shell_surface_strains). False for a collapsed element.
bool membrane_and_bending(const ShellCentre& reference, const double b_reference[3],
                          const ShellCentre& current, const double b_current[3], Matrix2d& membrane,
                          Matrix2d& kappa) {
  const Vector3d t1 = vec(reference.t1), t2 = vec(reference.t2);
  Matrix2d metric;  // G_ab = T_a . T_b
  metric << t1.dot(t1), t1.dot(t2), t2.dot(t1), t2.dot(t2);
  const Matrix2d j = tangent_components(current);
  const double det_g = metric.determinant(), det_j = j.determinant();
  if (!(det_g > 0.0) || !(det_j > 0.0))
    return false;
  // The in-plane left Cauchy-Green tensor B = F F^T = J G^-1 J^T on the current axes; its
  // logarithm is the membrane part of element_strain.hpp's shell strain.
  const Matrix2d left = j * metric.inverse() * j.transpose();
  // 1/2 ln(B) in closed form: B's eigenvalues are m +- r, so ln B = 1/2 ln(det B) I +
  // (ln(m + r) - ln(m - r)) / (2r) (B - m I), that quotient written atanh(r / m) / r, which
  // keeps its digits as r -> 0 (an equibiaxial stretch).
  const double mean = 0.5 * left.trace();
  const double radius = std::hypot(0.5 * (left(0, 0) - left(1, 1)), left(0, 1));
  const double slope = radius > 0.0 ? std::atanh(radius / mean) / radius : 1.0 / mean;
  membrane = 0.25 * std::log(left.determinant()) * Matrix2d::Identity() +
             0.5 * slope * (left - mean * Matrix2d::Identity());
  // The change of curvature, covariant (b - b0) turned to the current axes: kappa = J^-T db J^-1.
  const Matrix2d j_inv = j.inverse();
  kappa = j_inv.transpose() * (symmetric(b_current) - symmetric(b_reference)) * j_inv;
  return true;
}

}  // namespace

bool shell_surface_strains(const ShellCentre& reference, const double b_reference[3],
                           const ShellCentre& current, const double b_current[3], double thickness,
                           SurfaceStrains& out) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int s = 0; s < 3; ++s)
    out.major[s] = out.minor[s] = nan;
  Matrix2d membrane, kappa;
  if (!std::isfinite(thickness) ||
      !membrane_and_bending(reference, b_reference, current, b_current, membrane, kappa))
    return false;
  const double z[3] = {-0.5 * thickness, 0.0, 0.5 * thickness};
  for (int s = 0; s < 3; ++s)
    principal(membrane + z[s] * kappa, out.major[s], out.minor[s]);
  return true;
}

bool shell_surface_strain_tensors(const ShellCentre& reference, const double b_reference[3],
                                  const ShellCentre& current, const double b_current[3],
                                  double thickness, double thickness_strain, double bottom[6],
                                  double top[6]) {
  Matrix2d membrane, kappa;
  if (!std::isfinite(thickness) ||
      !membrane_and_bending(reference, b_reference, current, b_current, membrane, kappa))
    return false;
  Vector3d e1, e2;
  tangent_axes(current, e1, e2);
  const Vector3d n = vec(current.normal);
  static constexpr int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  const double z[2] = {-0.5 * thickness, 0.5 * thickness};
  double* out[2] = {bottom, top};
  for (int s = 0; s < 2; ++s) {
    const Matrix2d eps = membrane + z[s] * kappa;
    // eps_g = sum_ab e_a eps_ab e_b + eps_zz n n.
    const Matrix3d g = e1 * eps(0, 0) * e1.transpose() + e2 * eps(1, 1) * e2.transpose() +
                       eps(0, 1) * (e1 * e2.transpose() + e2 * e1.transpose()) +
                       thickness_strain * n * n.transpose();
    for (int c = 0; c < 6; ++c)
      out[s][c] = g(kPair[c][0], kPair[c][1]);
  }
  return true;
}

}  // namespace plyform::element
