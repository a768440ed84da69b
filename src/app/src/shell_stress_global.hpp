#pragma once
// A shell point's stress from the element's co-rotational frame, in which
// element::ShellBlockState keeps it, to global axes: elout.csv, the states and the dynain file
// write global components.

#include <cstddef>

#include "plyform/core/model.hpp"
#include "plyform/engine/nodal_state.hpp"

namespace plyform::app {

/// sigma_g = sum_ab e_a l_ab e_b (rows e1, e2, e3 in `axes`; `l` the local tensor, szz = 0), as
/// xx, yy, zz, xy, yz, zx.
void shell_stress_to_global(const double* const axes[3], const double l[3][3], double* out);

/// The frame of shell e of `blk` at the current positions; the global axes for a collapsed
/// element (its stresses are then written as they are kept).
void current_shell_frame(const core::ShellBlock& blk, const engine::NodalState& ns, std::size_t e,
                         double e1[3], double e2[3], double e3[3]);

}  // namespace plyform::app
