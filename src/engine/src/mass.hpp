#pragma once
// Lumped nodal masses from the elements, and mass scaling (*CONTROL_TIMESTEP DT2MS).

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/element/shell_kernels.hpp"
#include "plyform/element/solid_kernels.hpp"

namespace plyform::engine {

struct MassResult {
  double physical = 0.0;  ///< total mass of the elements
  double added = 0.0;     ///< added by mass scaling
};

/// Fills `mass` (node_count) with rho V0 / 8 per element node. With DT2MS != 0, elements whose
/// stable step times TSSFAC is below TSSFAC |DT2MS| get their density raised so that it is not
/// (mass added, never removed).
/// `solids` and `shells` receive each element's step factor sqrt(scale) in dt_factor. Shell
/// nodes also get a rotary inertia m (t^2 + A) / 12 per element share (LS-DYNA's scaling, so
/// that rotations do not govern the step).
MassResult lumped_mass(const core::Model& model, const element::NodalView& nodes,
                       std::vector<double>& mass, std::vector<double>& inertia,
                       std::vector<element::SolidBlockState>& solids,
                       std::vector<element::ShellBlockState>& shells);

}  // namespace plyform::engine
