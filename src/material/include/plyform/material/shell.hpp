#pragma once
// Batched plane-stress updates of shell integration points, in the shell's co-rotational frame
// (x, y in the shell plane, z along the normal). The stresses are stored in that frame, so no
// objective rotation is applied here: the element rotates its frame with the shell.
//
// Conventions (all laws):
//  - strain increments over the step, tensor shear components: dxy = (du_x/dy + du_y/dx) / 2,
//    the same for dyz, dzx (half the engineering shear);
//  - szz = 0 (plane stress) and is not stored;
//  - transverse shear is elastic for every law: syz += 2 G dyz, szx += 2 G dzx (for the
//    orthotropic law 2 G_bc, 2 G_ca in the material axes). The element applies its shear
//    correction factor (SHRF, default 5/6) to the transverse increments it passes
//    (dyz <- SHRF dyz); the kernels apply none;
//  - dzz (out, overwritten): the through-thickness strain increment of the step, for the
//    thickness update: dzz = -(nu/E) (d sxx + d syy) - (d eps_xx^p + d eps_yy^p) for the
//    isotropic laws (elastic Poisson part plus plastic incompressibility), with d sxx, d syy the
//    in-plane stress changes of the step; for the orthotropic law
//    dzz = -(PRCA/EC) d s_aa - (PRCB/EC) d s_bb.
//
// Units: consistent (e.g. mm, t, s, MPa). Derivations: docs/materials.md.

#include <cstddef>

#include "plyform/core/material.hpp"

namespace plyform::material {

/// n shell integration points, structure of arrays. Every array has n entries; the output and
/// in/out arrays must not overlap each other or the inputs.
struct ShellPoints {
  const double* dxx;  ///< in-plane strain increments over the step (tensor shear)
  const double* dyy;
  const double* dxy;
  const double* dyz;  ///< transverse shear strain increments (tensor), elastic
  const double* dzx;
  double* sxx;  ///< stress in the co-rotational frame, in/out (szz = 0)
  double* syy;
  double* sxy;
  double* syz;
  double* szx;
  double* eps_p;  ///< effective plastic strain, in/out (unused by the elastic laws; may be null)
  double* dzz;    ///< out: through-thickness strain increment
  /// Laws with material axes (needs_material_axes): axis a at angle t from the local x axis,
  /// cos t and sin t per point; null otherwise.
  const double* cos_t = nullptr;
  const double* sin_t = nullptr;
  double* history = nullptr;  ///< the law's own history, its history.size() per point
  /// Laws that read temperatures (needs_temperature): per point, at t_{n+1}; null otherwise.
  const double* temperature = nullptr;
  /// Laws that carry directions (needs_spin): the rotation of the material relative to the
  /// co-rotational frame over the step, radians about the normal, per point (the element has
  /// already turned the stored stresses by it); null otherwise.
  const double* spin = nullptr;
  /// Laws that keep material lines (needs_frame_turn), per point: the material's own spin over
  /// the step (radians about the normal: dt (L_yx - L_xy) / 2 of the mid-step velocity gradient
  /// in the frame at t_{n+1}), and the tangent of the angle through which the co-rotational
  /// frame turned over the step (exact for motion in the shell's plane). With them a direction
  /// carried in the frame at t_n is turned into the frame at t_{n+1} exactly and then pushed
  /// forward by the step's deformation: the fibres stay material lines to round-off, however
  /// large the step's strain and turn together. Null otherwise.
  const double* material_spin = nullptr;
  const double* frame_turn = nullptr;
  /// The step the increments were taken over (their rate, for the laws' strain-rate effects:
  /// Cowper-Symonds); 0 when unknown (no rate effect).
  double dt = 0.0;
};

/// *MAT_ELASTIC, plane stress: d sxx = E/(1 - nu^2) (dxx + nu dyy), d syy likewise,
/// d sxy = 2 G dxy, dzz = -nu/(1 - nu) (dxx + dyy).
void shell_update(const core::ElasticMaterial& m, std::size_t n, const ShellPoints& pts);

/// *MAT_PIECEWISE_LINEAR_PLASTICITY (024), plane-stress J2 with isotropic hardening: elastic
/// trial, then the consistent plane-stress return (Simo-Taylor): the plastic multiplier solves
/// the plane-stress yield condition sigma_eq(sxx, syy, sxy) = sigma_y(eps_p + d eps_p) by a
/// scalar Newton iteration (bisection-safeguarded), so szz = 0 exactly and the stress lies on
/// the von Mises surface to round-off. Yield curve as yield_stress(); it must not soften. With
/// Cowper-Symonds constants the yield curve is scaled at each point by the factor of its strain
/// rate (shell_strain_rate, cowper_symonds in constitutive.hpp).
void shell_update(const core::PiecewiseLinearPlasticity& m, std::size_t n, const ShellPoints& pts);

/// *MAT_POWER_LAW_PLASTICITY (018), the same plane-stress return with
/// sigma_y = k (eps_yp + eps_p)^n.
void shell_update(const core::PowerLawPlasticity& m, std::size_t n, const ShellPoints& pts);

/// *MAT_ORTHOTROPIC_ELASTIC (002), plane stress in the material axes a, b (c = shell normal).
/// cos_t[p], sin_t[p]: material axis a at angle t from the local x axis (unit vector
/// (cos t, sin t) in the shell plane), per point. Poisson's ratios as LS-DYNA: PRBA = nu_ba
/// with compliance entry S_ab = -nu_ba / E_b = -nu_ab / E_a, i.e. under uniaxial stress along b
/// the strain along a is -PRBA eps_b, under uniaxial stress along a the strain along b is
/// -(PRBA EA / EB) eps_a; PRCA, PRCB likewise (S_ac = -PRCA / EC, S_bc = -PRCB / EC).
/// Transverse shear: s_bc += 2 GBC d_bc, s_ca += 2 GCA d_ca in the material axes.
void shell_update(const core::OrthotropicElasticMaterial& m, std::size_t n, const ShellPoints& pts,
                  const double* cos_t, const double* sin_t);

}  // namespace plyform::material
