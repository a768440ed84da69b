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

/// lumped_mass at the reference geometry with fresh block states: the masses, rotary
/// inertias and elements' step factors a run starts with (what `plyform check` reads of the
/// step and the contacts' votes).
struct ReferenceMasses {
  element::NodalView view;  ///< the reference geometry (pointers into the model)
  std::vector<element::SolidBlockState> solids;
  std::vector<element::ShellBlockState> shells;
  std::vector<double> mass, inertia;
  MassResult result;
};
ReferenceMasses lumped_mass_at_reference(const core::Model& model);

/// Each deformable block's share of the nodal masses lumped_mass gave (mass scaling included,
/// from the blocks' dt_factor): the block's nodes in the order its elements name them, with
/// the mass and rotary inertia its elements put there. Summed over the blocks they are the
/// nodal masses of lumped_mass (the part energies of matsum.csv add up to glstat's books).
struct BlockMass {
  std::vector<core::Index> nodes;
  std::vector<double> mass, inertia;
};
void block_masses(const core::Model& model, const element::NodalView& nodes,
                  const std::vector<element::SolidBlockState>& solids,
                  const std::vector<element::ShellBlockState>& shells,
                  std::vector<BlockMass>& solid_mass, std::vector<BlockMass>& shell_mass);

}  // namespace plyform::engine
