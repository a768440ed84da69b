#pragma once
// *MAT_REINFORCED_THERMOPLASTIC (249) for shells: the fibre families, the matrix and the shear
// between the families of a woven (or unidirectional) ply. Per point the law carries each
// family's fibre vector f_i in the shell's co-rotational frame (its length is the fibre stretch),
// turned with the frame and pushed forward every step by the step's deformation, so that it is
// F a0 (a material line) and never re-derived from the element's geometry. Derivation:
// docs/materials.md.

#include <cstddef>

#include "plyform/core/material.hpp"
#include "plyform/material/shell.hpp"

namespace plyform::material {

/// The per-point history of the law (WovenPlyHistory::count values per point, point-major).
struct WovenPlyHistory {
  static constexpr std::size_t fibre = 0;             ///< f_1x f_1y f_2x f_2y f_3x f_3y
  static constexpr std::size_t matrix = 6;            ///< the matrix stress s_xx s_yy s_xy
  static constexpr std::size_t jacobian = 9;          ///< J = V / V0 (0: not yet initialised)
  static constexpr std::size_t shear_plastic = 10;    ///< plastic shear angle, pairs 12 and 23
  static constexpr std::size_t shear_hardening = 12;  ///< accumulated plastic shear, 12 and 23
  static constexpr std::size_t count = 14;
};

/// Plane-stress update of n points (needs pts.cos_t/sin_t for the first step,
/// pts.material_spin and pts.frame_turn, and pts.temperature where the law has curves against
/// temperature; null temperatures read as 0). Per point:
///  1. the fibre vectors (set at the first call from the material axis and ALPHi) are turned
///     from the frame at t_n into the frame at t_{n+1} (by minus the frame's turn, exactly) and
///     pushed forward, f <- dF f with dF = (I - A/2)^-1 (I + A/2), A = d_eps + material spin
///     (the mid-step velocity gradient times dt: the exact increment of the point's
///     deformation gradient), so that f = F a0 to round-off: a material line on any mesh;
///  2. the matrix stress turns into the new frame and with the material's spin and takes the
///     plane-stress increment with E(T),
///     nu(T), returned to the yield curve (at T) when there is one; the thickness strain is the
///     matrix's; J *= exp(tr d_eps);
///  3. the in-plane stress is s_m + sum_i (lambda_i P_i / J) a_i a_i (P_i the nominal fibre stress
///     at the engineering strain lambda_i - 1, zero in compression) + sum_pairs tau / (J sin th)
///     ((a b + b a) - cos th (a a + b b)), tau the nominal shear stress at the shear angle
///     gamma = |th0| - |th| (th the angle from family i to i+1);
///  4. transverse shear: the matrix's 2 G increment plus each family's G31 along and G23 across
///     its fibres.
void shell_update(const core::ReinforcedThermoplastic& m, std::size_t n, const ShellPoints& pts);

/// The nominal shear stress (per unit reference volume) of a pair at shear angle `gamma`
/// (radians) and temperature t, for an elastic pair (linear G with locking, or METH 2); METH 3
/// pairs need their history (shell_update).
[[nodiscard]] double elastic_shear_stress(const core::ReinforcedThermoplastic::Shear& s,
                                          double gamma, double t);

/// The nominal fibre stress of a family at fibre strain `strain` (lambda - 1) and temperature t:
/// EF strain or the curve (its last slope beyond its end), zero in compression.
[[nodiscard]] double fibre_stress(const core::ReinforcedThermoplastic::Fibre& f, double strain,
                                  double t);

/// Per point results: the unit fibre direction of each family in the co-rotational frame, and
/// the shear angle of the pairs (radians). From one point's history (null: not yet initialised,
/// all zero).
struct WovenPlyState {
  double direction[3][2] = {};
  double shear_angle[2] = {};
  bool initialised = false;
};
[[nodiscard]] WovenPlyState woven_ply_state(const core::ReinforcedThermoplastic& m,
                                            const double* history);

}  // namespace plyform::material
