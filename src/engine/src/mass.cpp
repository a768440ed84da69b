#include "mass.hpp"

#include <cmath>
#include <variant>

#include "plyform/material/law_registry.hpp"

namespace plyform::engine {

MassResult lumped_mass(const core::Model& model, const element::NodalView& nodes,
                       std::vector<double>& mass, std::vector<double>& inertia,
                       std::vector<element::SolidBlockState>& solids,
                       std::vector<element::ShellBlockState>& shells) {
  MassResult r;
  mass.assign(model.node_count(), 0.0);
  inertia.assign(model.node_count(), 0.0);
  const double target = std::abs(model.controls.dt2ms);  // the step mass scaling aims for
  for (std::size_t bi = 0; bi < model.solid_blocks.size(); ++bi) {
    const core::SolidBlock& b = model.solid_blocks[bi];
    const core::Material& m = model.materials[static_cast<std::size_t>(b.material)];
    if (std::holds_alternative<core::RigidMaterial>(m))
      continue;  // the rigid body's own mass
    const double rho = material::density(m);
    for (std::size_t e = 0; e < b.size(); ++e) {
      const double v0 = element::solid_reference_volume(b, nodes, e);
      const double me = rho * v0;
      double scale = 1.0;
      if (target > 0.0) {
        // dt scales with sqrt(mass): raise the mass until dt_e reaches the target.
        const double dte = element::solid_stable_dt(b, m, nodes, e);
        if (dte < target)
          scale = (target / dte) * (target / dte);
      }
      solids[bi].dt_factor[e] = std::sqrt(scale);
      r.physical += me;
      r.added += me * (scale - 1.0);
      for (int i = 0; i < 8; ++i) {
        mass[static_cast<std::size_t>(b.connectivity[8 * e + static_cast<std::size_t>(i)])] +=
            0.125 * me * scale;
      }
    }
  }
  for (std::size_t bi = 0; bi < model.shell_blocks.size(); ++bi) {
    const core::ShellBlock& b = model.shell_blocks[bi];
    const core::Material& m = model.materials[static_cast<std::size_t>(b.material)];
    if (std::holds_alternative<core::RigidMaterial>(m))
      continue;
    const double rho = material::density(m);
    for (std::size_t e = 0; e < b.size(); ++e) {
      const double area = element::shell_reference_area(b, nodes, e);
      const double t = shells[bi].thickness[e];
      const double me = rho * t * area;
      double scale = 1.0;
      if (target > 0.0) {
        const double dte = element::shell_stable_dt(b, m, nodes, e);
        if (dte < target)
          scale = (target / dte) * (target / dte);
      }
      shells[bi].dt_factor[e] = std::sqrt(scale);
      r.physical += me;
      r.added += me * (scale - 1.0);
      // A triangle (N3 = N4) gives its third node two shares: 1/3 of the element each.
      const bool triangle = b.connectivity[4 * e + 2] == b.connectivity[4 * e + 3];
      for (int i = 0; i < 4; ++i) {
        const double share = triangle ? (i >= 2 ? 1.0 / 6.0 : 1.0 / 3.0) : 0.25;
        const auto node =
            static_cast<std::size_t>(b.connectivity[4 * e + static_cast<std::size_t>(i)]);
        mass[node] += share * me * scale;
        inertia[node] += share * me * scale * (t * t + area) / 12.0;
      }
    }
  }
  return r;
}

}  // namespace plyform::engine
