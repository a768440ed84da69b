#pragma once
// Plane-stress anisotropic yield functions of the sheet-metal laws, in the material axes
// (a = 1 rolling, b = 2 transverse): the equivalent stress phi(s), homogeneous of degree 1 in
// s = (s11, s22, s12) (s12 the tensor shear stress), with its gradient and Hessian. The gradient
// is the flow direction in the strain measure (e11, e22, gamma12): d eps^p = dlam grad phi, so
// the plastic work s : d eps^p = phi dlam and dlam is the effective plastic strain increment.
// Private to plyform_material. Derivations: docs/materials.md.

#include <algorithm>
#include <cmath>

namespace plyform::material::detail {

/// phi, its gradient g (3) and Hessian hs (3 x 3, row-major) at s.
struct YieldState {
  double phi = 0.0;
  double g[3] = {};
  double hs[9] = {};
};

/// Hill 1948, plane stress, normalised to G + H = 1:
/// phi^2 = s11^2 - 2 H s11 s22 + (F + H) s22^2 + 2 N s12^2 = s^T P s.
struct Hill48Yield {
  double f, h, n;  // F, H, N (G = 1 - H)

  /// From the Lankford ratios at 0, 45 and 90 degrees to the rolling direction.
  static Hill48Yield from_r(double r00, double r45, double r90) {
    const double h = r00 / (1.0 + r00);
    const double f = h / r90;
    const double g = 1.0 - h;
    return {f, h, (f + g) * (r45 + 0.5)};
  }

  [[nodiscard]] double value(const double* s) const {
    const double q =
        s[0] * s[0] - 2.0 * h * s[0] * s[1] + (f + h) * s[1] * s[1] + 2.0 * n * s[2] * s[2];
    return std::sqrt(q > 0.0 ? q : 0.0);
  }

  /// Whether s lies outside the surface of radius sy.
  [[nodiscard]] bool exceeds(const double* s, double sy) const { return value(s) > sy; }

  // grad phi = P s / phi, Hessian (P - g g^T) / phi (skipped without `hessian`).
  void evaluate(const double* s, YieldState& y, bool hessian = true) const {
    const double ps[3] = {s[0] - h * s[1], -h * s[0] + (f + h) * s[1], 2.0 * n * s[2]};
    const double phi = std::sqrt(std::max(s[0] * ps[0] + s[1] * ps[1] + s[2] * ps[2], 1e-300));
    y.phi = phi;
    const double inv = 1.0 / phi;
    for (int i = 0; i < 3; ++i)
      y.g[i] = ps[i] * inv;
    if (!hessian)
      return;
    const double p[9] = {1.0, -h, 0.0, -h, f + h, 0.0, 0.0, 0.0, 2.0 * n};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        y.hs[3 * i + j] = (p[3 * i + j] - y.g[i] * y.g[j]) * inv;
  }
};

/// Barlat and Lian 1989: 2 phi^m = a |K1 + K2|^m + a |K1 - K2|^m + c |2 K2|^m,
/// K1 = (s11 + h s22) / 2, K2 = sqrt(X^2 + Y^2), X = (s11 - h s22) / 2, Y = p s12.
/// phi = F^(1/m) with F = (a |u1|^m + a |u2|^m + c |u3|^m) / 2, u1 = K1 + K2, u2 = K1 - K2,
/// u3 = 2 K2. m >= 2 keeps the Hessian finite; K2 is regularised by 1e-12 of the stress scale
/// (a relative change of phi below 1e-24) where it vanishes (equibiaxial stress with h = 1).
struct Barlat89Yield {
  double a, c, h, p, m;

  // x^e for x >= 0: by squaring when m is a whole number (the exponents of real cards, 6 and
  // 8, and m - 2), else std::pow. The powers are most of the law's cost.
  [[nodiscard]] double power(double x, double e) const {
    if (whole()) {
      auto n = static_cast<unsigned>(e);
      double r = 1.0, b = x;
      while (n != 0) {
        if (n & 1u)
          r *= b;
        b *= b;
        n >>= 1u;
      }
      return r;
    }
    return std::pow(x, e);
  }
  [[nodiscard]] bool whole() const { return m == std::floor(m) && m <= 64.0; }

  // 2 phi^m = F(s) * 2: the sum of the three terms, without the root.
  [[nodiscard]] double big_f(const double* s) const {
    const double k1 = 0.5 * (s[0] + h * s[1]);
    const double k2 = std::hypot(0.5 * (s[0] - h * s[1]), p * s[2]);
    return 0.5 * (a * power(std::abs(k1 + k2), m) + a * power(std::abs(k1 - k2), m) +
                  c * power(2.0 * k2, m));
  }

  [[nodiscard]] double value(const double* s) const { return std::pow(big_f(s), 1.0 / m); }

  /// Whether s lies outside the surface of radius sy (phi^m against sy^m: no root taken).
  [[nodiscard]] bool exceeds(const double* s, double sy) const { return big_f(s) > power(sy, m); }

  void evaluate(const double* s, YieldState& y, bool hessian = true) const {
    const double scale = std::abs(s[0]) + std::abs(s[1]) + std::abs(s[2]) + 1e-300;
    const double k1 = 0.5 * (s[0] + h * s[1]);
    const double x = 0.5 * (s[0] - h * s[1]), yy = p * s[2];
    const double tiny = 1e-12 * scale;
    const double k2 = std::sqrt(x * x + yy * yy + tiny * tiny);
    const double u[3] = {k1 + k2, k1 - k2, 2.0 * k2};
    const double w[3] = {a, a, c};
    double big_f = 0.0, fu[3], fuu[3];
    for (int i = 0; i < 3; ++i) {
      const double au = std::abs(u[i]);
      const double pm2 = power(au, m - 2.0);  // |u|^(m-2)
      big_f += 0.5 * w[i] * pm2 * au * au;
      fu[i] = 0.5 * w[i] * m * pm2 * u[i];  // dF/du = (w m / 2) |u|^(m-2) u
      fuu[i] = 0.5 * w[i] * m * (m - 1.0) * pm2;
    }
    // F in (K1, K2): dF/dK1 = F1 + F2, dF/dK2 = F1 - F2 + 2 F3.
    const double f_k1 = fu[0] + fu[1], f_k2 = fu[0] - fu[1] + 2.0 * fu[2];
    const double f_11 = fuu[0] + fuu[1], f_12 = fuu[0] - fuu[1];
    const double f_22 = fuu[0] + fuu[1] + 4.0 * fuu[2];
    // dK1/ds, dK2/ds; d2K2/ds2 = L^T (I - z z^T) L / K2, L = [[1/2, -h/2, 0], [0, 0, p]].
    const double dk1[3] = {0.5, 0.5 * h, 0.0};
    const double zx = x / k2, zy = yy / k2;
    const double dk2[3] = {0.5 * zx, -0.5 * h * zx, p * zy};
    const double l0[3] = {0.5, -0.5 * h, 0.0}, l1[3] = {0.0, 0.0, p};
    const double m00 = (1.0 - zx * zx) / k2, m01 = -zx * zy / k2, m11 = (1.0 - zy * zy) / k2;
    double gf[3], hf[9];
    for (int i = 0; i < 3; ++i)
      gf[i] = f_k1 * dk1[i] + f_k2 * dk2[i];
    const double phi = std::pow(big_f, 1.0 / m);
    const double k = phi / (m * big_f);
    y.phi = phi;
    for (int i = 0; i < 3; ++i)
      y.g[i] = k * gf[i];
    if (!hessian)
      return;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double d2k2 =
            l0[i] * m00 * l0[j] + l0[i] * m01 * l1[j] + l1[i] * m01 * l0[j] + l1[i] * m11 * l1[j];
        hf[3 * i + j] = f_11 * dk1[i] * dk1[j] + f_12 * (dk1[i] * dk2[j] + dk2[i] * dk1[j]) +
                        f_22 * dk2[i] * dk2[j] + f_k2 * d2k2;
      }
    }
    // phi = F^(1/m): grad phi = phi / (m F) grad F (above),
    // Hess phi = phi / (m F) (Hess F + (1/m - 1) grad F grad F^T / F).
    const double kk = (1.0 / m - 1.0) / big_f;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        y.hs[3 * i + j] = k * (hf[3 * i + j] + kk * gf[i] * gf[j]);
  }
};

}  // namespace plyform::material::detail
