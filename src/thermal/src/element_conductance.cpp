#include "plyform/thermal/element_conductance.hpp"

#include <algorithm>
#include <cmath>

#include "plyform/element/hex8_geometry.hpp"

namespace plyform::thermal {
namespace {

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

// The element's nodes, one array per direction (the mechanics' hexahedron geometry).
element::HexCoords coords(const std::array<Vec3, 8>& x) {
  element::HexCoords c{};
  for (std::size_t i = 0; i < 8; ++i) {
    c.x[i] = x[i][0];
    c.y[i] = x[i][1];
    c.z[i] = x[i][2];
  }
  return c;
}

// K += w (grad N_i . k grad N_j), upper triangle, for gradients bx, by, bz.
void add_point(const double* bx, const double* by, const double* bz, const Tensor3& k, double w,
               double (&K)[8][8]) {
  for (int j = 0; j < 8; ++j) {
    const double kx = k[0][0] * bx[j] + k[0][1] * by[j] + k[0][2] * bz[j];
    const double ky = k[1][0] * bx[j] + k[1][1] * by[j] + k[1][2] * bz[j];
    const double kz = k[2][0] * bx[j] + k[2][1] * by[j] + k[2][2] * bz[j];
    for (int i = 0; i <= j; ++i)
      K[i][j] += w * (bx[i] * kx + by[i] * ky + bz[i] * kz);
  }
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
  const element::HexCoords c = coords(x);
  double volume = 0.0;
  if (one_point) {
    // The exact volume-average gradient (Flanagan-Belytschko), as the one-point solid uses.
    element::UniformGradient g;
    if (!element::uniform_gradient(c, g))
      return std::min(g.volume, 0.0);
    add_point(g.bx, g.by, g.bz, k, g.volume, K);
    volume = g.volume;
  } else {
    element::GaussGradients g;
    if (!element::gauss_gradients(c, g))
      return 0.0;  // a non-positive Jacobian at a Gauss point
    for (int q = 0; q < 8; ++q) {
      add_point(g.bx[q], g.by[q], g.bz[q], k, g.weight_det[q], K);
      volume += g.weight_det[q];
    }
  }
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < i; ++j)
      K[i][j] = K[j][i];
  return volume;
}

double hex8_volume(const std::array<Vec3, 8>& x) {
  element::UniformGradient g;
  element::uniform_gradient(coords(x), g);
  return g.volume;  // exact for the trilinear element, raw when not positive
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

namespace plyform::thermal {

Vec3 face_normal(const std::array<Vec3, 4>& x, bool triangle) {
  return triangle ? unit(cross(sub(x[1], x[0]), sub(x[2], x[0])))
                  : unit(cross(sub(x[2], x[0]), sub(x[3], x[1])));
}

// The quadratic profile through the thickness, L_b = z (z - 1) / 2, L_m = 1 - z^2,
// L_t = z (z + 1) / 2 on z in [-1, 1]: its conductance per area is (k_n / (3 t)) times
// [[7, -8, 1], [-8, 16, -8], [1, -8, 7]]. The in-plane conduction and the capacity lump the
// profile with Simpson's weights t (1/6, 2/3, 1/6), so a profile uniform through the thickness
// gives the thin shell's matrix; the through-thickness part lumps the area on the corners.
double thick_shell_conductance(const std::array<Vec3, 4>& x, bool triangle, const Tensor3& k,
                               double t, double (&K)[12][12]) {
  for (auto& row : K)
    for (double& v : row)
      v = 0.0;
  double plane[4][4];
  const double area = shell_conductance(x, triangle, k, 1.0, plane);
  if (!(area > 0.0) || !(t > 0.0))
    return 0.0;
  const int corners = triangle ? 3 : 4;
  const double layer_share[3] = {2.0 * t / 3.0, t / 6.0, t / 6.0};  // middle, bottom, top
  for (int layer = 0; layer < 3; ++layer)
    for (int i = 0; i < corners; ++i)
      for (int j = 0; j < corners; ++j)
        K[4 * layer + i][4 * layer + j] = layer_share[layer] * plane[i][j];
  const Vec3 n = face_normal(x, triangle);
  double kn = 0.0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      kn += n[i] * k[i][j] * n[j];
  // In the order (middle, bottom, top).
  constexpr double kz[3][3] = {{16.0, -8.0, -8.0}, {-8.0, 7.0, 1.0}, {-8.0, 1.0, 7.0}};
  const double scale = kn / (3.0 * t) * area / corners;
  for (int i = 0; i < corners; ++i)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        K[4 * a + i][4 * b + i] += scale * kz[a][b];
  return area;
}

}  // namespace plyform::thermal
