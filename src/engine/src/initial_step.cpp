#include "plyform/engine/initial_step.hpp"

#include <variant>
#include <vector>

#include "mass.hpp"
#include "plyform/material/law_registry.hpp"

namespace plyform::engine {

InitialStep initial_stable_step(const core::Model& model) {
  const ReferenceMasses ref = lumped_mass_at_reference(model);
  const MassResult& masses = ref.result;
  const element::NodalView& view = ref.view;
  const auto& solids = ref.solids;
  const auto& shells = ref.shells;

  InitialStep r;
  r.physical_mass = masses.physical;
  r.added_mass = masses.added;
  // The run's element step is the element's own times its mass-scaling factor dt_factor.
  const auto take = [&r](double dt, double factor, core::GlobalId id) {
    if (dt < r.dt_unscaled) {
      r.dt_unscaled = dt;
      r.element_unscaled = id;
    }
    if (dt * factor < r.dt) {
      r.dt = dt * factor;
      r.element = id;
    }
    r.scaled_elements += factor > 1.0 ? 1 : 0;
  };
  for (std::size_t b = 0; b < model.solid_blocks.size(); ++b) {
    const core::SolidBlock& block = model.solid_blocks[b];
    const core::Material& m = model.materials[static_cast<std::size_t>(block.material)];
    if (std::holds_alternative<core::RigidMaterial>(m))
      continue;  // moves as a body
    for (std::size_t e = 0; e < block.size(); ++e)
      take(element::solid_stable_dt(block, m, view, e), solids[b].dt_factor[e],
           block.element_id[e]);
  }
  for (std::size_t b = 0; b < model.shell_blocks.size(); ++b) {
    const core::ShellBlock& block = model.shell_blocks[b];
    const core::Material& m = model.materials[static_cast<std::size_t>(block.material)];
    if (std::holds_alternative<core::RigidMaterial>(m))
      continue;
    for (std::size_t e = 0; e < block.size(); ++e)
      take(element::shell_stable_dt(block, m, view, e), shells[b].dt_factor[e],
           block.element_id[e]);
  }
  return r;
}

}  // namespace plyform::engine
