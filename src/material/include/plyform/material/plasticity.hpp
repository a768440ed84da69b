#pragma once
// J2 (von Mises) plasticity with isotropic hardening for solids: yield curves of
// *MAT_PIECEWISE_LINEAR_PLASTICITY (024) and *MAT_POWER_LAW_PLASTICITY (018), and the batched
// 3D update (Jaumann rotation, elastic trial, radial return). The shell (plane-stress) updates
// of the same laws are in plyform/material/shell.hpp. Derivations: docs/materials.md.
//
// Units: consistent (e.g. mm, t, s, MPa); stresses in the unit of E; strains dimensionless.

#include <cstddef>

#include "plyform/core/material.hpp"
#include "plyform/material/constitutive.hpp"

namespace plyform::material {

/// Yield stress sigma_y(eps_p) (stress) of *MAT_024 at effective plastic strain eps_p >= 0:
/// the curve when it has points (piecewise linear; beyond the last point extrapolated with the
/// last slope, before the first point with the first slope, one point = constant), else
/// bilinear SIGY + E_p eps_p, E_p = E ETAN / (E - ETAN).
[[nodiscard]] double yield_stress(const core::PiecewiseLinearPlasticity& m, double eps_p);
/// d sigma_y / d eps_p (stress) of *MAT_024; at a curve point the slope of the segment after it.
[[nodiscard]] double yield_slope(const core::PiecewiseLinearPlasticity& m, double eps_p);

/// Yield stress of *MAT_018: sigma_y = k (eps_yp + eps_p)^n with eps_yp = (SIGY / k)^(1/n) when
/// SIGY > 0, else (E / k)^(1/(n - 1)) (where the power law meets the elastic line).
[[nodiscard]] double yield_stress(const core::PowerLawPlasticity& m, double eps_p);
/// d sigma_y / d eps_p = n k (eps_yp + eps_p)^(n - 1) of *MAT_018.
[[nodiscard]] double yield_slope(const core::PowerLawPlasticity& m, double eps_p);
/// eps_yp of *MAT_018 (the strain offset of the power law, see yield_stress).
[[nodiscard]] double power_law_offset(const core::PowerLawPlasticity& m);

/// 3D J2 plasticity of solids with isotropic hardening, batched over n points:
///  1. Jaumann rotation and elastic trial exactly as elastic_jaumann (Hughes-Winget rotation,
///     sigma_tr = Q sigma Q^T + dt C : D, C isotropic with E, nu of the law);
///  2. radial return: q_tr = sqrt(3/2 s_tr : s_tr); if q_tr > sigma_y(eps_p), solve
///     q_tr - 3 G dlam = sigma_y(eps_p + dlam) for dlam >= 0 (scalar Newton safeguarded by
///     bisection; exact after one step for linear hardening), s = s_tr (1 - 3 G dlam / q_tr),
///     eps_p += dlam. The pressure stays the elastic trial's.
/// d: rate of deformation (tensor shear, 1/time); w: spin (W_12, W_23, W_31); dt: time step.
/// sigma (in/out) and eps_p (in/out, effective plastic strain, never decreases) must not
/// overlap d or w. The yield curve must not soften (nondecreasing sigma_y > 0). n may be 0.
void solid_update(const core::PiecewiseLinearPlasticity& m, std::size_t n, ConstSymView d,
                  const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                  SymView sigma, double* eps_p);
void solid_update(const core::PowerLawPlasticity& m, std::size_t n, ConstSymView d,
                  const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                  SymView sigma, double* eps_p);

}  // namespace plyform::material
