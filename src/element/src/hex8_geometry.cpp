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

// The non-zero terms of the volume form: for each node I, the pairs J < K with C_IJK != 0.
struct VolumeTerm {
  int j, k;
  double c;
};
struct VolumeTable {
  std::vector<VolumeTerm> terms[8];
};

VolumeTable make_volume_table() {
  // C_IJK = integral over the cube of det[grad N_I; grad N_J; grad N_K]; the integrand is at
  // most cubic in each natural coordinate, so 2x2x2 Gauss is exact.
  double c[8][8][8] = {};
  for (int q = 0; q < 8; ++q) {
    const double p[3] = {kGauss * kHexNodeXi[q][0], kGauss * kHexNodeXi[q][1],
                         kGauss * kHexNodeXi[q][2]};
    double dn[8][3];
    natural_gradients(p, dn);
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        for (int k = 0; k < 8; ++k) {
          const double* a = dn[i];
          const double* b = dn[j];
          const double* d = dn[k];
          c[i][j][k] += a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                        a[2] * (b[0] * d[1] - b[1] * d[0]);
        }
  }
  VolumeTable t;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = j + 1; k < 8; ++k) {
        // Entries are multiples of 1/12; round off the quadrature noise.
        const double v = std::round(c[i][j][k] * 12.0) / 12.0;
        if (v != 0.0)
          t.terms[i].push_back({j, k, v});
      }
  return t;
}

const VolumeTable& volume_table() {
  static const VolumeTable table = make_volume_table();
  return table;
}

}  // namespace

bool uniform_gradient(const HexCoords& c, UniformGradient& out) {
  // Coordinates relative to node 1 keep round-off independent of the position in space.
  double x[8], y[8], z[8];
  for (int i = 0; i < 8; ++i) {
    x[i] = c.x[i] - c.x[0];
    y[i] = c.y[i] - c.y[0];
    z[i] = c.z[i] - c.z[0];
  }
  // Cross products r_J x r_K for all pairs (28), then gradients from the table.
  double px[8][8], py[8][8], pz[8][8];
  for (int j = 0; j < 8; ++j)
    for (int k = j + 1; k < 8; ++k) {
      px[j][k] = y[j] * z[k] - z[j] * y[k];
      py[j][k] = z[j] * x[k] - x[j] * z[k];
      pz[j][k] = x[j] * y[k] - y[j] * x[k];
    }
  const VolumeTable& t = volume_table();
  double volume = 0.0;
  for (int i = 0; i < 8; ++i) {
    double gx = 0.0, gy = 0.0, gz = 0.0;
    for (const VolumeTerm& term : t.terms[i]) {
      gx += term.c * px[term.j][term.k];
      gy += term.c * py[term.j][term.k];
      gz += term.c * pz[term.j][term.k];
    }
    out.bx[i] = gx;
    out.by[i] = gy;
    out.bz[i] = gz;
    volume += x[i] * gx;  // V is linear in the x coordinates: V = sum x_I dV/dx_I
  }
  out.volume = volume;
  if (!(volume > 0.0))
    return false;
  const double inv = 1.0 / volume;
  for (int i = 0; i < 8; ++i) {
    out.bx[i] *= inv;
    out.by[i] *= inv;
    out.bz[i] *= inv;
  }
  return true;
}

const std::array<std::array<double, 8>, 4>& hourglass_base() {
  static const std::array<std::array<double, 8>, 4> h = [] {
    std::array<std::array<double, 8>, 4> v{};
    for (int i = 0; i < 8; ++i) {
      const double* n = kHexNodeXi[i];
      v[0][i] = n[1] * n[2];
      v[1][i] = n[2] * n[0];
      v[2][i] = n[0] * n[1];
      v[3][i] = n[0] * n[1] * n[2];
    }
    return v;
  }();
  return h;
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
