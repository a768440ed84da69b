#pragma once
// The metal plasticity laws of real forming decks:
//  - *MAT_PLASTIC_KINEMATIC (003): J2 with bilinear mixed (kinematic/isotropic by BETA)
//    hardening and Cowper-Symonds scaling of the yield stress, for solids (radial return about
//    the back stress) and shells (the exact plane-stress return about the back stress);
//  - *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (037): Hill's 1948 yield function with
//    normal anisotropy r for shells (the exact plane-stress return in the eigenframe of the
//    Hill matrix).
// Conventions of the shell updates: plyform/material/shell.hpp. Derivations: docs/materials.md.
//
// Units: consistent (e.g. mm, t, s, MPa).

#include <cstddef>

#include "plyform/core/material.hpp"
#include "plyform/material/constitutive.hpp"
#include "plyform/material/shell.hpp"

namespace plyform::material {

/// The Cowper-Symonds factor of *MAT_003: 1 + (rate / SRC)^(1 / SRP), 1 when SRC or SRP is 0
/// (no rate effect) or rate <= 0. rate: the effective strain rate sqrt(D : D), 1/time.
[[nodiscard]] double cowper_symonds_factor(const core::PlasticKinematic& m, double rate);

/// *MAT_003 for solids, batched over n points:
///  1. the Jaumann rotation of the stress and of the back stress (the same Hughes-Winget
///     rotation as elastic_jaumann) and the elastic trial sigma_tr = Q sigma Q^T + dt C : D;
///  2. with xi = dev(sigma_tr) - alpha and q = sqrt(3/2 xi : xi): if q > R = k (SIGY + BETA E_p
///     eps_p), k the Cowper-Symonds factor at sqrt(D : D), the radial return
///     dlam = (q - R) / (3 G + (1 - BETA) E_p + k BETA E_p) (exact: the hardening is linear),
///     s = s_tr - 3 G dlam xi / q, alpha += (1 - BETA) E_p dlam xi / q, eps_p += dlam.
/// back: the back stress, 6 per point, point-major (xx, yy, zz, xy, yz, zx; deviatoric).
void solid_update(const core::PlasticKinematic& m, std::size_t n, ConstSymView d,
                  const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                  SymView sigma, double* eps_p, double* back);

/// *MAT_003 for shells: elastic plane-stress trial, then the plane-stress return about the
/// back stress. history: 6 per point like the solid's (xx, yy, zz, xy, yz, zx), of which a
/// shell uses xx, yy, xy: the deviatoric back stress minus its zz component (a_xx - a_zz,
/// a_yy - a_zz, a_xy, the plane-stress shift, docs/materials.md), in the co-rotational frame;
/// turned by
/// pts.spin (radians about the normal, the element's in-plane rotation of the stresses) when
/// that is not null. dt: the step, for the strain rate (dt <= 0: no rate effect); the rate is
/// sqrt(D : D) with D_zz = -(D_xx + D_yy) (isochoric: the plastic flow, which the rate
/// factor acts on, is).
void shell_update(const core::PlasticKinematic& m, std::size_t n, const ShellPoints& pts,
                  double dt);

/// Yield stress of *MAT_037 at effective plastic strain eps_p: the curve (HLCID) when it has
/// points, else SIGY + ETAN eps_p (ETAN this law's plastic hardening modulus).
[[nodiscard]] double yield_stress(const core::TransverselyAnisotropicPlastic& m, double eps_p);

/// *MAT_037 for shells: elastic plane-stress trial, then the plane-stress Hill return: in
/// p = sxx + syy, q = sxx - syy, t = sxy the backward-Euler stress is p = p_tr / (1 + a gamma),
/// (q, t) = (q_tr, t_tr) / (1 + b gamma) with a = E / ((1 - nu)(1 + r)),
/// b = 2 G (1 + 2r)/(1 + r), and gamma solves sigma_eq(gamma) = sigma_y(eps_p + gamma
/// sigma_eq(gamma)) by the bisection-safeguarded Newton of the J2 return (exact to round-off).
void shell_update(const core::TransverselyAnisotropicPlastic& m, std::size_t n,
                  const ShellPoints& pts);

}  // namespace plyform::material
