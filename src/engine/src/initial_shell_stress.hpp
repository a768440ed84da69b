#pragma once
// *INITIAL_STRESS_SHELL at t = 0 (docs/outputs.md, "dynain"): each listed shell's stress and
// effective plastic strain, given in global axes at the card's points, interpolated to the
// block's points and turned into the element's co-rotational frame, in which
// element::ShellBlockState keeps them. Runs once when the run is set up, before the first
// element pass, so that pass already gives the stresses' nodal forces.

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/element/shell_kernels.hpp"

namespace plyform::engine {

/// Sets the stresses and plastic strains of model.initial_shell_stresses into `shells` (one
/// state per shell block, already sized), with the frames of the reference positions.
///
/// Through the thickness: linear in T between the card's points, the end points' values beyond
/// them (LS-DYNA interpolates too when NTHICK differs from the section's NIP); a card of the
/// section's own points (as plyform's dynain writes them) thus gives every point its own value.
/// In the plane: 4 card points to an ELFORM 16 element each Gauss point's, to ELFORM 2 their
/// mean; 1 card point to every in-plane point. The stress's components along the normal in the
/// element's frame (szz) are dropped: the shells are plane stress.
void apply_initial_shell_stresses(const core::Model& model,
                                  std::vector<element::ShellBlockState>& shells);

/// The elastic energy the initial stresses hold, per shell block (length 0 entries for blocks
/// without): at each point sigma : C^-1 : sigma / 2 of plane stress with the law's elastic
/// constants (E and nu from its bulk and shear moduli: exact for the isotropic elasticity of the
/// metal laws, an estimate for orthotropic ones), plus the transverse shears' tau^2 / (2 G),
/// times the point's share of the element's volume (its area after the first element pass
/// times its thickness and the point's weight). The engine books it as the internal energy of
/// t = 0: a formed part handed on holds it, and gives it back when it springs back, which the
/// energy balance would otherwise read as energy from nowhere (docs/energy.md).
std::vector<double> initial_stress_energy(const core::Model& model,
                                          const std::vector<element::ShellBlockState>& shells);

}  // namespace plyform::engine
