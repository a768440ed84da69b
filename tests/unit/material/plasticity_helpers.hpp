#pragma once
// One-point wrappers around the batched shell and solid plasticity kernels, independent yield
// curve references, and a small secant solver to drive uniaxial stress paths.

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

#include "plyform/material/plasticity.hpp"
#include "plyform/material/shell.hpp"

namespace plyform::material::test {

/// One shell point: stress (sxx, syy, sxy, syz, szx) and effective plastic strain.
struct ShellState {
  std::array<double, 5> s{};
  double eps_p = 0.0;
};

/// Strain increments (dxx, dyy, dxy, dyz, dzx), tensor shear.
using ShellInc = std::array<double, 5>;

inline ShellPoints shell_points(ShellState& st, const ShellInc& d, double& dzz) {
  return ShellPoints{&d[0],    &d[1],    &d[2],    &d[3],    &d[4],     &st.s[0],
                     &st.s[1], &st.s[2], &st.s[3], &st.s[4], &st.eps_p, &dzz};
}

/// One shell step of one point (n = 1); returns dzz.
template <class M>
double shell_step(const M& m, ShellState& st, const ShellInc& d) {
  double dzz = 0.0;
  shell_update(m, 1, shell_points(st, d, dzz));
  return dzz;
}

inline double shell_step_ortho(const core::OrthotropicElasticMaterial& m, ShellState& st,
                               const ShellInc& d, double angle) {
  double dzz = 0.0;
  const double c = std::cos(angle), s = std::sin(angle);
  shell_update(m, 1, shell_points(st, d, dzz), &c, &s);
  return dzz;
}

/// Plane-stress von Mises stress (szz = 0).
inline double von_mises_ps(double sxx, double syy, double sxy) {
  return std::sqrt(sxx * sxx + syy * syy - sxx * syy + 3.0 * sxy * sxy);
}

/// Reference piecewise-linear interpolation with end-slope extrapolation (written out plainly).
inline double curve_ref(const std::vector<double>& x, const std::vector<double>& y, double e) {
  if (x.size() == 1)
    return y[0];
  std::size_t i = 0;
  while (i + 2 < x.size() && e >= x[i + 1])
    ++i;
  return y[i] + (y[i + 1] - y[i]) * (e - x[i]) / (x[i + 1] - x[i]);
}

/// Secant solve of g(x) = 0 starting from x0, x1 (to |g| <= tol).
inline double secant(const std::function<double(double)>& g, double x0, double x1, double tol) {
  double g0 = g(x0);
  double g1 = g(x1);
  for (int it = 0; it < 60 && std::abs(g1) > tol; ++it) {
    if (g1 == g0)
      break;
    const double x2 = x1 - g1 * (x1 - x0) / (g1 - g0);
    x0 = x1;
    g0 = g1;
    x1 = x2;
    g1 = g(x1);
  }
  return x1;
}

/// One solid point: stress (xx, yy, zz, xy, yz, zx) and effective plastic strain.
struct SolidState {
  std::array<double, 6> s{};
  double eps_p = 0.0;
};

template <class M>
void solid_step(const M& m, SolidState& st, const std::array<double, 6>& d,
                const std::array<double, 3>& w, double dt) {
  solid_update(m, 1, ConstSymView{&d[0], &d[1], &d[2], &d[3], &d[4], &d[5]}, &w[0], &w[1], &w[2],
               dt, SymView{&st.s[0], &st.s[1], &st.s[2], &st.s[3], &st.s[4], &st.s[5]}, &st.eps_p);
}

/// 3D von Mises stress of a 6-vector.
inline double von_mises6(const std::array<double, 6>& s) {
  const double m = (s[0] + s[1] + s[2]) / 3.0;
  const double a = s[0] - m, b = s[1] - m, c = s[2] - m;
  return std::sqrt(1.5 * (a * a + b * b + c * c + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
}

}  // namespace plyform::material::test
