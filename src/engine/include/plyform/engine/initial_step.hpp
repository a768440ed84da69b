#pragma once
// The stable time step a run starts with, for `plyform check`: each deformable element's step
// at its reference geometry, with mass scaling (*CONTROL_TIMESTEP DT2MS) applied by the same
// function the run uses (lumped_mass), so that the announced cycle count is the run's.

#include <cstddef>

#include "plyform/core/model.hpp"

namespace plyform::engine {

struct InitialStep {
  /// Smallest element step after mass scaling, before TSSFAC; 1e300 without deformable
  /// elements.
  double dt = 1e300;
  core::GlobalId element = 0;  ///< the element that sets it
  double dt_unscaled = 1e300;  ///< the same without mass scaling
  core::GlobalId element_unscaled = 0;
  std::size_t scaled_elements = 0;  ///< elements whose mass scaling raised the density
  double physical_mass = 0.0;       ///< of the deformable elements
  double added_mass = 0.0;          ///< by mass scaling
};

/// The model's initial element steps and mass scaling, as `Simulation` sets them up.
InitialStep initial_stable_step(const core::Model& model);

}  // namespace plyform::engine
