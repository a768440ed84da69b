#pragma once
// The logarithmic strain of every element for the states (*DATABASE_EXTENT_BINARY STRFLG):
// from the model's reference node positions and the current ones, in the states' cell order
// (solid blocks, then shell blocks).

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/element/shell_kernels.hpp"
#include "plyform/engine/nodal_state.hpp"

namespace plyform::app {

/// Fills `out` (6 per cell: xx yy zz xy yz zx, tensor shear) for the solids and shells of
/// `model`; a shell's thickness stretch is its current thickness over its initial one. An
/// inverted or collapsed element gets NaN.
void element_log_strains(const core::Model& model, const engine::NodalState& nodes,
                         const std::vector<element::ShellBlockState>& shells,
                         std::vector<double>& out);

}  // namespace plyform::app
