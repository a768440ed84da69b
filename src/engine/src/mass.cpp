#include "mass.hpp"

#include <cmath>
#include <variant>

namespace plyform::engine {

MassResult lumped_mass(const core::Model& model, const element::NodalView& nodes,
                       std::vector<double>& mass, std::vector<element::SolidBlockState>& solids) {
  MassResult r;
  mass.assign(model.node_count(), 0.0);
  const double target = std::abs(model.controls.dt2ms);  // the step mass scaling aims for
  for (std::size_t bi = 0; bi < model.solid_blocks.size(); ++bi) {
    const core::SolidBlock& b = model.solid_blocks[bi];
    const core::Material& m = model.materials[static_cast<std::size_t>(b.material)];
    const double rho = core::density(m);
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
  return r;
}

}  // namespace plyform::engine
