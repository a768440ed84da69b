#pragma once
// The isotropic plane-stress elastic step of the shell laws that start from an elastic trial
// (the elastic law and the trial of the J2-type returns: *MAT_024, *MAT_003, *MAT_037, *MAT_036,
// *MAT_122):
//   d sxx = E/(1 - nu^2) (dxx + nu dyy), d syy likewise, d sxy = 2 G dxy, transverse shear
//   2 G, dzz = -nu/(1 - nu)(dxx + dyy).
// Private to plyform_material.

#include <cstddef>

#include "plyform/material/shell.hpp"

namespace plyform::material::detail {

// The arrays never overlap (a law's points' own fields): __restrict lets the loop run across
// SIMD lanes without runtime overlap checks. Always inlined: the laws' files are compiled with
// different floating-point contraction (src/material/CMakeLists.txt), and one out-of-line copy
// shared by them would round as one of them only.
[[gnu::always_inline]] inline void plane_stress_trial_kernel(
    std::size_t n, double c11, double c12, double two_g, double nu_zz, const double* __restrict dxx,
    const double* __restrict dyy, const double* __restrict dxy, const double* __restrict dyz,
    const double* __restrict dzx, double* __restrict sxx, double* __restrict syy,
    double* __restrict sxy, double* __restrict syz, double* __restrict szx,
    double* __restrict dzz) {
  for (std::size_t p = 0; p < n; ++p) {
    sxx[p] += c11 * dxx[p] + c12 * dyy[p];
    syy[p] += c12 * dxx[p] + c11 * dyy[p];
    sxy[p] += two_g * dxy[p];
    syz[p] += two_g * dyz[p];
    szx[p] += two_g * dzx[p];
    dzz[p] = -nu_zz * (dxx[p] + dyy[p]);
  }
}

[[gnu::always_inline]] inline void plane_stress_trial(double young, double nu, std::size_t n,
                                                      const ShellPoints& s) {
  const double c11 = young / (1.0 - nu * nu);
  plane_stress_trial_kernel(n, c11, nu * c11, young / (1.0 + nu), nu / (1.0 - nu), s.dxx, s.dyy,
                            s.dxy, s.dyz, s.dzx, s.sxx, s.syy, s.sxy, s.syz, s.szx, s.dzz);
}

}  // namespace plyform::material::detail
