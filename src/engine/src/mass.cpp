#include "mass.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "plyform/material/law_registry.hpp"

namespace plyform::engine {

namespace {

// Every deformable element's mass shares: scale(solid, block, element, mass) gives the
// element's mass-scaling factor (>= 1), emit(solid, block, node, mass, inertia) receives each
// node's share of the scaled mass and rotary inertia. One place for the shares, so that the
// masses of the blocks (block_masses) add up to the nodal masses (lumped_mass).
template <class Scale, class Emit>
void visit_element_masses(const core::Model& model, const element::NodalView& nodes,
                          const std::vector<element::ShellBlockState>& shells, Scale&& scale,
                          Emit&& emit) {
  for (std::size_t bi = 0; bi < model.solid_blocks.size(); ++bi) {
    const core::SolidBlock& b = model.solid_blocks[bi];
    const core::Material& m = model.materials[static_cast<std::size_t>(b.material)];
    if (std::holds_alternative<core::RigidMaterial>(m))
      continue;  // the rigid body's own mass
    const double rho = material::density(m);
    for (std::size_t e = 0; e < b.size(); ++e) {
      const double me = rho * element::solid_reference_volume(b, nodes, e);
      const double f = scale(true, bi, e, me);
      for (int i = 0; i < 8; ++i)
        emit(true, bi, b.connectivity[8 * e + static_cast<std::size_t>(i)], 0.125 * me * f, 0.0);
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
      const double f = scale(false, bi, e, me);
      // A triangle (N3 = N4) gives its third node two shares: 1/3 of the element each.
      const bool triangle = b.connectivity[4 * e + 2] == b.connectivity[4 * e + 3];
      for (int i = 0; i < 4; ++i) {
        const double share = triangle ? (i >= 2 ? 1.0 / 6.0 : 1.0 / 3.0) : 0.25;
        emit(false, bi, b.connectivity[4 * e + static_cast<std::size_t>(i)], share * me * f,
             share * me * f * (t * t + area) / 12.0);
      }
    }
  }
}

}  // namespace

MassResult lumped_mass(const core::Model& model, const element::NodalView& nodes,
                       std::vector<double>& mass, std::vector<double>& inertia,
                       std::vector<element::SolidBlockState>& solids,
                       std::vector<element::ShellBlockState>& shells) {
  MassResult r;
  mass.assign(model.node_count(), 0.0);
  inertia.assign(model.node_count(), 0.0);
  const double target = std::abs(model.controls.dt2ms);  // the step mass scaling aims for
  const auto scale = [&](bool solid, std::size_t bi, std::size_t e, double me) {
    double f = 1.0;
    if (target > 0.0) {
      // dt scales with sqrt(mass): raise the mass until dt_e reaches the target.
      const core::Material& m = model.materials[static_cast<std::size_t>(
          solid ? model.solid_blocks[bi].material : model.shell_blocks[bi].material)];
      const double dte = solid ? element::solid_stable_dt(model.solid_blocks[bi], m, nodes, e)
                               : element::shell_stable_dt(model.shell_blocks[bi], m, nodes, e);
      if (dte < target)
        f = (target / dte) * (target / dte);
    }
    (solid ? solids[bi].dt_factor[e] : shells[bi].dt_factor[e]) = std::sqrt(f);
    r.physical += me;
    r.added += me * (f - 1.0);
    return f;
  };
  visit_element_masses(model, nodes, shells, scale,
                       [&](bool, std::size_t, core::Index node, double m, double j) {
                         mass[static_cast<std::size_t>(node)] += m;
                         inertia[static_cast<std::size_t>(node)] += j;
                       });
  return r;
}

void block_masses(const core::Model& model, const element::NodalView& nodes,
                  const std::vector<element::SolidBlockState>& solids,
                  const std::vector<element::ShellBlockState>& shells,
                  std::vector<BlockMass>& solid_mass, std::vector<BlockMass>& shell_mass) {
  solid_mass.assign(model.solid_blocks.size(), {});
  shell_mass.assign(model.shell_blocks.size(), {});
  // Per block, node -> its slot (grown as the block's elements name them).
  std::vector<core::Index> slot(model.node_count(), -1);
  std::vector<core::Index> touched;
  const auto scale = [&](bool solid, std::size_t bi, std::size_t e, double) {
    const double f = solid ? solids[bi].dt_factor[e] : shells[bi].dt_factor[e];
    return f * f;
  };
  bool last_solid = true;
  std::size_t last_block = static_cast<std::size_t>(-1);
  const auto reset = [&] {
    for (core::Index i : touched)
      slot[static_cast<std::size_t>(i)] = -1;
    touched.clear();
  };
  visit_element_masses(
      model, nodes, shells, scale,
      [&](bool solid, std::size_t bi, core::Index node, double m, double j) {
        if (solid != last_solid || bi != last_block) {  // the elements come block by block
          reset();
          last_solid = solid;
          last_block = bi;
        }
        BlockMass& b = solid ? solid_mass[bi] : shell_mass[bi];
        core::Index& k = slot[static_cast<std::size_t>(node)];
        if (k < 0) {
          k = static_cast<core::Index>(b.nodes.size());
          touched.push_back(node);
          b.nodes.push_back(node);
          b.mass.push_back(0.0);
          b.inertia.push_back(0.0);
        }
        b.mass[static_cast<std::size_t>(k)] += m;
        b.inertia[static_cast<std::size_t>(k)] += j;
      });
}

ReferenceMasses lumped_mass_at_reference(const core::Model& model) {
  ReferenceMasses r{
      {model.x0.data(), model.y0.data(), model.z0.data(), model.x0.data(), model.y0.data(),
       model.z0.data(), model.x0.data(), model.y0.data(), model.z0.data()},
      {},
      {},
      {},
      {},
      {}};
  r.solids.resize(model.solid_blocks.size());
  for (std::size_t b = 0; b < r.solids.size(); ++b) {
    const core::SolidBlock& block = model.solid_blocks[b];
    r.solids[b].resize(block, material::history_per_point(
                                  model.materials[static_cast<std::size_t>(block.material)]));
  }
  r.shells.resize(model.shell_blocks.size());
  for (std::size_t b = 0; b < r.shells.size(); ++b) {
    const core::ShellBlock& block = model.shell_blocks[b];
    r.shells[b].resize(block, material::history_per_point(
                                  model.materials[static_cast<std::size_t>(block.material)]));
  }
  r.result = lumped_mass(model, r.view, r.mass, r.inertia, r.solids, r.shells);
  return r;
}

}  // namespace plyform::engine
