#pragma once
// Batched constitutive updates of solids: one call per block of integration points, all arrays
// as structure of arrays (one array per component). The caller dispatches the material variant
// once per block; the loops inside carry no branch on the material and vectorise.
//
// Units: consistent (e.g. mm, t, s, MPa). Stresses in the unit of the moduli, rates in 1/time.
// The laws and their derivation: docs/materials.md.

#include <cstddef>

#include "plyform/core/material.hpp"

namespace plyform::material {

/// Symmetric tensors as 6 arrays in the order xx, yy, zz, xy, yz, zx (engineering order of
/// LS-DYNA). Shear entries are tensor components (xy = T_12), not engineering shears (2 T_12).
struct SymView {
  double* xx;
  double* yy;
  double* zz;
  double* xy;
  double* yz;
  double* zx;
};

/// Read-only symmetric tensors, same layout as SymView.
struct ConstSymView {
  const double* xx;
  const double* yy;
  const double* zz;
  const double* xy;
  const double* yz;
  const double* zx;
};

/// Hypoelastic isotropic elasticity (*MAT_ELASTIC) with the Jaumann rate:
///   sigma += dt (C : D + W sigma - sigma W),  C : D = lambda tr(D) I + 2 mu D.
/// d: rate of deformation (symmetric, 1/time; d.xy = D_12), w: spin as
/// (w_xy, w_yz, w_zx) = (W_12, W_23, W_31), W = (L - L^T) / 2 with L_ij = dv_i/dx_j.
/// The rotation part is integrated with the Hughes-Winget incremental rotation
/// Q = (I - dt W / 2)^-1 (I + dt W / 2), sigma <- Q sigma Q^T + dt C : D, which equals the
/// formula above to first order in dt and is exactly orthogonal (a pure spin keeps the stress
/// invariants to round-off for any step).
/// sigma (in/out) must not overlap d or w. n may be 0.
void elastic_jaumann(const core::ElasticMaterial& m, std::size_t n, ConstSymView d,
                     const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                     SymView sigma);

/// Mooney-Rivlin rubber (*MAT_MOONEY-RIVLIN_RUBBER, LS-DYNA's compressible form
///   W = A (I1 - 3) + B (I2 - 3) + C (III^-2 - 1) + D (III - 1)^2,
///   C = A / 2 + B,  D = (A (5 nu - 2) + B (11 nu - 5)) / (2 (1 - 2 nu)),
/// I1, I2, III the invariants of C = F^T F): Cauchy stress from the deformation gradient,
///   sigma = (2/J) [(A + B I1) b - B b^2] + [4 D J (J^2 - 1) - 4 C J^-5] I,  b = F F^T.
/// f: 9 arrays, row-major F_ij = dx_i/dX_j (f[3 i + j]). The stress is total (overwritten).
/// J = det F must be positive (the element checks its Jacobian); otherwise the result is
/// undefined (inf/NaN). sigma must not overlap f. n may be 0.
void mooney_rivlin_cauchy(const core::MooneyRivlinMaterial& m, std::size_t n,
                          const double* const f[9], SymView sigma);

/// Wave speed for the stable time step: sqrt((K + 4/3 G) / rho) with the small-strain moduli
/// of material::bulk_modulus and material::shear_modulus (law_registry.hpp) (length/time).
[[nodiscard]] double dilatational_wave_speed(const core::Material& m);

}  // namespace plyform::material
