#pragma once
// The orthotropic sheet-metal laws of forming decks, shells, plane stress in the material axes
// (a rolling, b transverse, at angle t from the co-rotational x axis: ShellPoints::cos_t,
// sin_t):
//  - *MAT_3-PARAMETER_BARLAT (036): the Barlat-Lian 1989 yield function with exponent m, its
//    coefficients a, c, h, p from the Lankford ratios R00, R45, R90 (or given directly);
//  - *MAT_HILL_3R (122): Hill's 1948 yield function from R00, R45, R90.
// Both: isotropic elasticity, associated flow, isotropic hardening by the rule HR
// (core::SheetHardening), the backward-Euler return of the stress onto the surface solved by
// Newton's method on the stress and the plastic multiplier (exact to round-off), the effective
// plastic strain the work-conjugate of the equivalent stress. Conventions of the shell updates:
// plyform/material/shell.hpp. Derivations: docs/materials.md.

#include <cstddef>

#include "plyform/core/material.hpp"
#include "plyform/material/shell.hpp"

namespace plyform::material {

/// Barlat-Lian 1989 coefficients.
struct Barlat89Coefficients {
  double a = 1.0, c = 1.0, h = 1.0, p = 1.0;
};

/// The coefficients that reproduce the Lankford ratios r00, r45, r90 (all > 0) with exponent m
/// (>= 2): a = 2 - 2 sqrt(r00 r90 / ((1 + r00)(1 + r90))), c = 2 - a,
/// h = sqrt(r00 (1 + r90) / ((1 + r00) r90)) (closed forms, any m), and p the root of
/// r45(p) = r45 (the ratio of the flow at 45 degrees, increasing in p), by bisection to 1e-14.
[[nodiscard]] Barlat89Coefficients barlat89_coefficients(double r00, double r45, double r90,
                                                         double m);

/// The Barlat 89 equivalent stress of (s_aa, s_bb, s_ab) in the material axes.
[[nodiscard]] double barlat89_equivalent_stress(const Barlat89Coefficients& k, double m,
                                                double s_aa, double s_bb, double s_ab);

/// The Lankford ratio of the Barlat 89 flow under uniaxial stress at `angle` (radians) from the
/// rolling direction.
[[nodiscard]] double barlat89_r_value(const Barlat89Coefficients& k, double m, double angle);

/// The yield stress of the reference direction at effective plastic strain eps_p.
[[nodiscard]] double yield_stress(const core::SheetHardening& h, double eps_p);

/// *MAT_036 for shells: the plane-stress elastic trial, then the Barlat 89 return in the
/// material axes (pts.cos_t, pts.sin_t), the yield stress scaled by the Cowper-Symonds factor of
/// the point's strain rate when RATE C and P are given.
void shell_update(const core::Barlat89Plastic& m, std::size_t n, const ShellPoints& pts);

/// *MAT_122 for shells: the plane-stress elastic trial, then the Hill 1948 return in the
/// material axes.
void shell_update(const core::Hill3RPlastic& m, std::size_t n, const ShellPoints& pts);

}  // namespace plyform::material
