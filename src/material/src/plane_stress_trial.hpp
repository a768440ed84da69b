#pragma once
// The isotropic plane-stress elastic step of the shell laws that start from an elastic trial
// (the J2-type returns of *MAT_003, *MAT_037, *MAT_036, *MAT_122):
//   d sxx = E/(1 - nu^2) (dxx + nu dyy), d syy likewise, d sxy = 2 G dxy, transverse shear
//   2 G, dzz = -nu/(1 - nu)(dxx + dyy).
// Private to plyform_material.

#include <cstddef>

#include "plyform/material/shell.hpp"

namespace plyform::material::detail {

inline void plane_stress_trial(double young, double nu, std::size_t n, const ShellPoints& s) {
  const double c11 = young / (1.0 - nu * nu), c12 = nu * c11, two_g = young / (1.0 + nu);
  const double nu_zz = nu / (1.0 - nu);
  for (std::size_t p = 0; p < n; ++p) {
    s.sxx[p] += c11 * s.dxx[p] + c12 * s.dyy[p];
    s.syy[p] += c12 * s.dxx[p] + c11 * s.dyy[p];
    s.sxy[p] += two_g * s.dxy[p];
    s.syz[p] += two_g * s.dyz[p];
    s.szx[p] += two_g * s.dzx[p];
    s.dzz[p] = -nu_zz * (s.dxx[p] + s.dyy[p]);
  }
}

}  // namespace plyform::material::detail
