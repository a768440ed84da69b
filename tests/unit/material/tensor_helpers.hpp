#pragma once
// Small dense 3x3 helpers for the material tests: an independent reference (plain matrices,
// no structure of arrays) and one-point wrappers around the batched kernels.

#include <array>
#include <cmath>
#include <cstddef>

#include "plyform/material/constitutive.hpp"

namespace plyform::material::test {

using Mat3 = std::array<std::array<double, 3>, 3>;

inline Mat3 identity() {
  return Mat3{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
}

inline Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        c[i][j] += a[i][k] * b[k][j];
  return c;
}

inline Mat3 transpose(const Mat3& a) {
  Mat3 t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      t[i][j] = a[j][i];
  return t;
}

inline Mat3 add(const Mat3& a, const Mat3& b, double sb = 1.0) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      c[i][j] = a[i][j] + sb * b[i][j];
  return c;
}

inline double norm(const Mat3& a) {
  double s = 0.0;
  for (const auto& row : a)
    for (double v : row)
      s += v * v;
  return std::sqrt(s);
}

inline double trace(const Mat3& a) {
  return a[0][0] + a[1][1] + a[2][2];
}

inline double det(const Mat3& a) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

inline double von_mises(const Mat3& s) {
  const double m = trace(s) / 3.0;
  double j2 = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double dev = s[i][j] - (i == j ? m : 0.0);
      j2 += 0.5 * dev * dev;
    }
  return std::sqrt(3.0 * j2);
}

/// Matrix exponential by scaling and squaring of a Taylor series (reference rotations).
inline Mat3 expm(const Mat3& a) {
  int squarings = 0;
  double scale = 1.0;
  while (norm(a) * scale > 0.25) {
    scale *= 0.5;
    ++squarings;
  }
  Mat3 term = identity();
  Mat3 sum = identity();
  for (int k = 1; k < 20; ++k) {
    term = mul(term, a);
    for (auto& row : term)
      for (double& v : row)
        v *= scale / k;
    sum = add(sum, term);
  }
  for (int i = 0; i < squarings; ++i)
    sum = mul(sum, sum);
  return sum;
}

/// Rotation about unit-normalised axis (x, y, z) by angle (Rodrigues).
inline Mat3 rotation(double x, double y, double z, double angle) {
  const double l = std::sqrt(x * x + y * y + z * z);
  x /= l;
  y /= l;
  z /= l;
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  return Mat3{{{t * x * x + c, t * x * y - s * z, t * x * z + s * y},
               {t * x * y + s * z, t * y * y + c, t * y * z - s * x},
               {t * x * z - s * y, t * y * z + s * x, t * z * z + c}}};
}

/// Symmetric 6-vector (xx, yy, zz, xy, yz, zx) <-> matrix.
inline Mat3 from_voigt(const std::array<double, 6>& v) {
  return Mat3{{{v[0], v[3], v[5]}, {v[3], v[1], v[4]}, {v[5], v[4], v[2]}}};
}
inline std::array<double, 6> to_voigt(const Mat3& m) {
  return {m[0][0], m[1][1], m[2][2], m[0][1], m[1][2], m[2][0]};
}

/// Cauchy stress of Mooney-Rivlin for one deformation gradient (n = 1 call of the kernel).
inline Mat3 mooney_rivlin(const core::MooneyRivlinMaterial& m, const Mat3& f) {
  double fv[9];
  const double* fp[9];
  for (int k = 0; k < 9; ++k) {
    fv[k] = f[k / 3][k % 3];
    fp[k] = &fv[k];
  }
  std::array<double, 6> s{};
  mooney_rivlin_cauchy(m, 1, fp, SymView{&s[0], &s[1], &s[2], &s[3], &s[4], &s[5]});
  return from_voigt(s);
}

/// One elastic Jaumann step for one point (n = 1 call); returns the updated stress.
/// w = (W_12, W_23, W_31).
inline Mat3 jaumann_step(const core::ElasticMaterial& m, const Mat3& sigma, const Mat3& d,
                         const std::array<double, 3>& w, double dt) {
  std::array<double, 6> s = to_voigt(sigma);
  const std::array<double, 6> dv = to_voigt(d);
  elastic_jaumann(m, 1, ConstSymView{&dv[0], &dv[1], &dv[2], &dv[3], &dv[4], &dv[5]}, &w[0], &w[1],
                  &w[2], dt, SymView{&s[0], &s[1], &s[2], &s[3], &s[4], &s[5]});
  return from_voigt(s);
}

/// Spin tensor from (W_12, W_23, W_31).
inline Mat3 spin(const std::array<double, 3>& w) {
  return Mat3{{{0.0, w[0], -w[2]}, {-w[0], 0.0, w[1]}, {w[2], -w[1], 0.0}}};
}

}  // namespace plyform::material::test
