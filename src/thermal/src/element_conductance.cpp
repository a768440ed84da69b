#include "plyform/thermal/element_conductance.hpp"

#include <algorithm>
#include <cmath>

namespace plyform::thermal {
namespace {

constexpr double kXi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
constexpr double kEta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
constexpr double kZeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};

Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 unit(const Vec3& a) {
  const double l = std::sqrt(dot(a, a));
  return l > 0.0 ? Vec3{a[0] / l, a[1] / l, a[2] / l} : Vec3{0.0, 0.0, 0.0};
}

// Shape function gradients in global axes at (xi, eta, zeta) and det J.
double hex8_gradients(const std::array<Vec3, 8>& x, double xi, double eta, double zeta,
                      double (&g)[8][3]) {
  double dn[8][3];
  for (int i = 0; i < 8; ++i) {
    dn[i][0] = 0.125 * kXi[i] * (1 + eta * kEta[i]) * (1 + zeta * kZeta[i]);
    dn[i][1] = 0.125 * kEta[i] * (1 + xi * kXi[i]) * (1 + zeta * kZeta[i]);
    dn[i][2] = 0.125 * kZeta[i] * (1 + xi * kXi[i]) * (1 + eta * kEta[i]);
  }
  double j[3][3] = {};  // j[a][b] = d x_b / d xi_a
  for (int i = 0; i < 8; ++i)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        j[a][b] += dn[i][a] * x[static_cast<std::size_t>(i)][static_cast<std::size_t>(b)];
  const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                     j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                     j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
  if (!(std::abs(det) > 0.0))
    return 0.0;
  const double inv = 1.0 / det;
  double ji[3][3];
  ji[0][0] = (j[1][1] * j[2][2] - j[1][2] * j[2][1]) * inv;
  ji[0][1] = (j[0][2] * j[2][1] - j[0][1] * j[2][2]) * inv;
  ji[0][2] = (j[0][1] * j[1][2] - j[0][2] * j[1][1]) * inv;
  ji[1][0] = (j[1][2] * j[2][0] - j[1][0] * j[2][2]) * inv;
  ji[1][1] = (j[0][0] * j[2][2] - j[0][2] * j[2][0]) * inv;
  ji[1][2] = (j[0][2] * j[1][0] - j[0][0] * j[1][2]) * inv;
  ji[2][0] = (j[1][0] * j[2][1] - j[1][1] * j[2][0]) * inv;
  ji[2][1] = (j[0][1] * j[2][0] - j[0][0] * j[2][1]) * inv;
  ji[2][2] = (j[0][0] * j[1][1] - j[0][1] * j[1][0]) * inv;
  // dN/dx_b = sum_a dN/dxi_a * dxi_a/dx_b, with dxi/dx = j^-1 (transposed layout).
  for (int i = 0; i < 8; ++i)
    for (int b = 0; b < 3; ++b)
      g[i][b] = dn[i][0] * ji[b][0] + dn[i][1] * ji[b][1] + dn[i][2] * ji[b][2];
  return det;
}

}  // namespace

Tensor3 conductivity_tensor(const core::ThermalMaterial& m, const Vec3& x1, const Vec3& x2,
                            const Vec3& x4, double scale) {
  Tensor3 k{};
  if (!m.orthotropic) {
    for (int i = 0; i < 3; ++i)
      k[static_cast<std::size_t>(i)][static_cast<std::size_t>(i)] = m.conductivity[0] * scale;
    return k;
  }
  const Vec3 a0 = m.aopt == 2 ? m.a : sub(x2, x1);
  const Vec3 d0 = m.aopt == 2 ? m.d : sub(x4, x1);
  const Vec3 a = unit(a0);
  const Vec3 c = unit(cross(a0, d0));
  const Vec3 b = cross(c, a);
  const std::array<Vec3, 3> axes{a, b, c};
  for (std::size_t n = 0; n < 3; ++n)
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        k[i][j] += m.conductivity[n] * scale * axes[n][i] * axes[n][j];
  return k;
}

double hex8_conductance(const std::array<Vec3, 8>& x, const Tensor3& k, bool one_point,
                        double (&K)[8][8]) {
  for (auto& row : K)
    for (double& v : row)
      v = 0.0;
  const double gp = 1.0 / std::sqrt(3.0);
  const int points = one_point ? 1 : 8;
  double volume = 0.0;
  for (int p = 0; p < points; ++p) {
    const double xi = one_point ? 0.0 : gp * kXi[p];
    const double eta = one_point ? 0.0 : gp * kEta[p];
    const double zeta = one_point ? 0.0 : gp * kZeta[p];
    const double w = one_point ? 8.0 : 1.0;
    double g[8][3];
    const double det = hex8_gradients(x, xi, eta, zeta, g);
    if (!(det > 0.0))
      return std::min(det, 0.0);  // inverted (or non-finite: NaN)
    volume += w * det;
    double kg[8][3];  // k grad N_j
    for (int j = 0; j < 8; ++j)
      for (std::size_t a = 0; a < 3; ++a)
        kg[j][a] = k[a][0] * g[j][0] + k[a][1] * g[j][1] + k[a][2] * g[j][2];
    const double wd = w * det;
    for (int i = 0; i < 8; ++i)
      for (int j = i; j < 8; ++j)
        K[i][j] += wd * (g[i][0] * kg[j][0] + g[i][1] * kg[j][1] + g[i][2] * kg[j][2]);
  }
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < i; ++j)
      K[i][j] = K[j][i];
  return volume;
}

double hex8_volume(const std::array<Vec3, 8>& x) {
  const double gp = 1.0 / std::sqrt(3.0);
  double volume = 0.0;
  for (int p = 0; p < 8; ++p) {
    double g[8][3];
    volume += hex8_gradients(x, gp * kXi[p], gp * kEta[p], gp * kZeta[p], g);
  }
  return volume;
}

double shell_conductance(const std::array<Vec3, 4>& x, bool triangle, const Tensor3& k, double t,
                         double (&K)[4][4]) {
  for (auto& row : K)
    for (double& v : row)
      v = 0.0;
  // The element's plane: through its centre, normal to the diagonals' cross product (the
  // triangle's own plane); e1 along the side 1-2.
  const Vec3 n = triangle ? unit(cross(sub(x[1], x[0]), sub(x[2], x[0])))
                          : unit(cross(sub(x[2], x[0]), sub(x[3], x[1])));
  Vec3 e1 = sub(x[1], x[0]);
  const double along = dot(e1, n);
  e1 = unit(Vec3{e1[0] - along * n[0], e1[1] - along * n[1], e1[2] - along * n[2]});
  const Vec3 e2 = cross(n, e1);
  // The in-plane conductivity k2 = E^T k E with E = [e1 e2].
  double k2[2][2];
  const std::array<Vec3, 2> e{e1, e2};
  for (std::size_t a = 0; a < 2; ++a)
    for (std::size_t b = 0; b < 2; ++b) {
      double s = 0.0;
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
          s += e[a][i] * k[i][j] * e[b][j];
      k2[a][b] = s;
    }
  const int nodes = triangle ? 3 : 4;
  double px[4], py[4];
  for (int i = 0; i < nodes; ++i) {
    const Vec3 r = sub(x[static_cast<std::size_t>(i)], x[0]);
    px[i] = dot(r, e1);
    py[i] = dot(r, e2);
  }
  if (triangle) {
    const double twice = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
    if (!(twice > 0.0))
      return 0.0;
    const double area = 0.5 * twice;
    double g[3][2];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, m = (i + 2) % 3;
      g[i][0] = (py[j] - py[m]) / twice;
      g[i][1] = (px[m] - px[j]) / twice;
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        K[i][j] = t * area *
                  (g[i][0] * (k2[0][0] * g[j][0] + k2[0][1] * g[j][1]) +
                   g[i][1] * (k2[1][0] * g[j][0] + k2[1][1] * g[j][1]));
    return area;
  }
  const double gp = 1.0 / std::sqrt(3.0);
  constexpr double xs[4] = {-1, 1, 1, -1};
  constexpr double ys[4] = {-1, -1, 1, 1};
  double area = 0.0;
  for (int p = 0; p < 4; ++p) {
    const double xi = gp * xs[p], eta = gp * ys[p];
    double dn[4][2];
    for (int i = 0; i < 4; ++i) {
      dn[i][0] = 0.25 * xs[i] * (1 + eta * ys[i]);
      dn[i][1] = 0.25 * ys[i] * (1 + xi * xs[i]);
    }
    double j00 = 0, j01 = 0, j10 = 0, j11 = 0;  // j[a][b] = d x_b / d xi_a
    for (int i = 0; i < 4; ++i) {
      j00 += dn[i][0] * px[i];
      j01 += dn[i][0] * py[i];
      j10 += dn[i][1] * px[i];
      j11 += dn[i][1] * py[i];
    }
    const double det = j00 * j11 - j01 * j10;
    if (!(det > 0.0))
      return 0.0;
    area += det;
    double g[4][2];
    for (int i = 0; i < 4; ++i) {
      g[i][0] = (j11 * dn[i][0] - j01 * dn[i][1]) / det;
      g[i][1] = (-j10 * dn[i][0] + j00 * dn[i][1]) / det;
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        K[i][j] += t * det *
                   (g[i][0] * (k2[0][0] * g[j][0] + k2[0][1] * g[j][1]) +
                    g[i][1] * (k2[1][0] * g[j][0] + k2[1][1] * g[j][1]));
  }
  return area;
}

double face_area(const std::array<Vec3, 4>& x, bool triangle) {
  const Vec3 c =
      triangle ? cross(sub(x[1], x[0]), sub(x[2], x[0])) : cross(sub(x[2], x[0]), sub(x[3], x[1]));
  return 0.5 * std::sqrt(dot(c, c));
}

}  // namespace plyform::thermal
