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

}  // namespace plyform::engine
