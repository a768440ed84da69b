#include "plyform/element/hex8_geometry.hpp"

#include <cmath>
#include <vector>

namespace plyform::element {
namespace {

// dN_I / dxi_a at natural point p.
void natural_gradients(const double p[3], double dn[8][3]) {
  for (int i = 0; i < 8; ++i) {
    const double* n = kHexNodeXi[i];
    const double f0 = 1.0 + n[0] * p[0];
    const double f1 = 1.0 + n[1] * p[1];
    const double f2 = 1.0 + n[2] * p[2];
    dn[i][0] = 0.125 * n[0] * f1 * f2;
    dn[i][1] = 0.125 * f0 * n[1] * f2;
    dn[i][2] = 0.125 * f0 * f1 * n[2];
  }
}

constexpr double kGauss = 0.57735026918962576451;  // 1/sqrt(3)

}  // namespace

bool uniform_gradient(const HexCoords& c, UniformGradient& out) {
  // Coordinates relative to node 1 keep round-off independent of the position in space.
  double x[8], y[8], z[8];
  for (int i = 0; i < 8; ++i) {
    x[i] = c.x[i] - c.x[0];
    y[i] = c.y[i] - c.y[0];
    z[i] = c.z[i] - c.z[0];
  }
  double* gx = out.bx;
  double* gy = out.by;
  double* gz = out.bz;
  // 12 dV/dx_I written out from the exact volume form (scripts/gen_hex8_volume_gradient.py).
#define X(j) x[j]
#define Y(j) y[j]
#define Z(j) z[j]
#define GX(i) gx[i]
#define GY(i) gy[i]
#define GZ(i) gz[i]
#include "hex8_volume_gradient.inc"
#undef X
#undef Y
#undef Z
#undef GX
#undef GY
#undef GZ
  double volume12 = 0.0;
  for (int i = 0; i < 8; ++i)
    volume12 += x[i] * gx[i];  // V is linear in the x coordinates
  out.volume = volume12 / 12.0;
  if (!(volume12 > 0.0))
    return false;
  const double inv = 1.0 / volume12;
  for (int i = 0; i < 8; ++i) {
    gx[i] *= inv;
    gy[i] *= inv;
    gz[i] *= inv;
  }
  return true;
}

double characteristic_length(const UniformGradient& g) {
  double sum = 0.0;
  for (int i = 0; i < 8; ++i)
    sum += g.bx[i] * g.bx[i] + g.by[i] * g.by[i] + g.bz[i] * g.bz[i];
  return sum > 0.0 ? 1.0 / std::sqrt(2.0 * sum) : 0.0;
}

bool gauss_gradients(const HexCoords& c, GaussGradients& out) {
  for (int q = 0; q < 8; ++q) {
    const double p[3] = {kGauss * kHexNodeXi[q][0], kGauss * kHexNodeXi[q][1],
                         kGauss * kHexNodeXi[q][2]};
    double dn[8][3];
    natural_gradients(p, dn);
    double j[3][3] = {};
    for (int i = 0; i < 8; ++i)
      for (int a = 0; a < 3; ++a) {
        j[0][a] += c.x[i] * dn[i][a];
        j[1][a] += c.y[i] * dn[i][a];
        j[2][a] += c.z[i] * dn[i][a];
      }
    const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                       j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                       j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
    if (!(det > 0.0))
      return false;
    const double inv = 1.0 / det;
    // inverse of J: (J^-1)_{a i} = cof(J)_{i a} / det; dN/dx_i = sum_a dN/dxi_a (J^-1)_{a i}.
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
    for (int i = 0; i < 8; ++i) {
      out.bx[q][i] = dn[i][0] * ji[0][0] + dn[i][1] * ji[1][0] + dn[i][2] * ji[2][0];
      out.by[q][i] = dn[i][0] * ji[0][1] + dn[i][1] * ji[1][1] + dn[i][2] * ji[2][1];
      out.bz[q][i] = dn[i][0] * ji[0][2] + dn[i][1] * ji[1][2] + dn[i][2] * ji[2][2];
    }
    out.weight_det[q] = det;  // Gauss weights are 1 for 2 points per direction
  }
  return true;
}

}  // namespace plyform::element
