// The contact's share of the heat: the conduction links across the interfaces (the slave node
// to the segment's nodes, by its projection) and the friction's dissipation turned to heat.

#include <cmath>
#include <vector>

#include "pass_runtime.hpp"

namespace plyform::contact {

namespace {

// The shape functions of slave k's projection on its segment pr.st.seg[k], as the heat reads
// them: the engine takes a thermal step between cycles, after the elements and before the
// contact (Simulation::State::cycle_once), so the last projection is that of the last
// apply(), which swapped it into prev_shape at the end of the pass (the arrays are swapped
// for the next cycle's warm start and first half of the work). Before the first apply() of a
// pass (the thermal step of the first cycle, a thermal-only run, a pass not yet born) the
// projection is start()'s, which measures without swapping: in shape. `measured` is set by
// apply() only, in the same pass as the swap, and is in the checkpoint with both arrays.
const double* located_shape(const PassRuntime& pr, std::size_t k) {
  return pr.st.measured ? &pr.st.prev_shape[4 * k] : &pr.st.shape[4 * k];
}

}  // namespace

void ContactSet::heat_links(const double* packed, std::vector<core::ContactHeatLink>& out) const {
  out.clear();
  // A face's area vector: half the cross product of its diagonals (a triangle, N3 = N4,
  // included), from the packed positions (x y z vx vy vz per node).
  const auto area_vector = [&](const core::Index* f) {
    const auto x = [&](core::Index n, int c) {
      return packed[6 * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)];
    };
    double d1[3], d2[3];
    for (int c = 0; c < 3; ++c) {
      d1[c] = x(f[2], c) - x(f[0], c);
      d2[c] = x(f[3], c) - x(f[1], c);
    }
    return std::array<double, 3>{0.5 * (d1[1] * d2[2] - d1[2] * d2[1]),
                                 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                                 0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
  };
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    const core::ContactHeat& heat = pr.iface->heat;
    if (!heat.enabled)
      continue;
    // A one-way link (ALGO 1) keeps the deck's master side: only the first pass (the deck's
    // slave against its master) carries heat, with the whole slave area.
    if ((heat.one_way && pr.pass != &pr.iface->passes.front()) || pr.guard)
      continue;
    // A guard pass (core::ContactPass::guard) carries no heat: the first pass has the area.
    const auto heat_passes = std::count_if(pr.iface->passes.begin(), pr.iface->passes.end(),
                                           [](const core::ContactPass& p) { return !p.guard; });
    const double share = heat.one_way ? 1.0 : 1.0 / static_cast<double>(heat_passes);
    const std::size_t ns = pr.pass->slave_count();
    for (std::size_t k = 0; k < ns; ++k) {
      const core::Index sg = pr.st.seg[k];
      if (sg < 0 || pr.st.gap[k] > heat.lmax)
        continue;
      core::ContactHeatLink l;
      l.slave = pr.pass->slave_nodes[k];
      const double* w = located_shape(pr, k);
      for (std::size_t j = 0; j < 4; ++j) {
        l.master[j] = pr.pass->segments[4 * static_cast<std::size_t>(sg) + j];
        l.weight[j] = w[j];
      }
      // The area the node presents to its segment: its share of each face around it,
      // projected on the segment's plane (a solid's side faces, at right angles to the
      // interface, carry no heat across it). A node-set slave has no faces: its area.
      const core::ContactPass& cp = *pr.pass;
      double area = cp.slave_area[k];
      if (!cp.slave_face_start.empty()) {
        const std::array<double, 3> nseg =
            area_vector(&cp.segments[4 * static_cast<std::size_t>(sg)]);
        const double ln = std::sqrt(nseg[0] * nseg[0] + nseg[1] * nseg[1] + nseg[2] * nseg[2]);
        area = 0.0;
        for (std::size_t e = cp.slave_face_start[k]; e < cp.slave_face_start[k + 1]; ++e) {
          const core::Index* f =
              &cp.slave_faces[4 * static_cast<std::size_t>(cp.slave_face_index[e])];
          const std::array<double, 3> af = area_vector(f);
          const double corners = f[2] == f[3] ? 3.0 : 4.0;
          if (ln > 0.0)
            area += std::abs(af[0] * nseg[0] + af[1] * nseg[1] + af[2] * nseg[2]) / ln / corners;
        }
      }
      l.area = share * area;
      l.gap = pr.st.gap[k];
      l.pressure = pr.st.pressure[k];
      l.heat = &heat;
      out.push_back(l);
    }
  }
}

void ContactSet::take_friction_heat(std::vector<double>& energy) {
  for (const auto& pp : passes_) {
    PassRuntime& pr = *pp;
    const core::ContactHeat& heat = pr.iface->heat;
    if (!heat.enabled || !heat.friction_heat || pr.guard)
      continue;
    // The swapped pass of a two-way contact has the deck's master nodes as its slaves.
    const double to_slave = pr.pass->slave_side_sign > 0 ? heat.ftosa : 1.0 - heat.ftosa;
    const std::size_t ns = pr.pass->slave_count();
    for (std::size_t k = 0; k < ns; ++k) {
      const double d = pr.hist.e_friction[k] - pr.st.friction_heated[k];
      if (d == 0.0)
        continue;
      pr.st.friction_heated[k] = pr.hist.e_friction[k];
      const core::Index sg = pr.st.seg[k];
      const double slave_part = sg >= 0 ? to_slave : 1.0;
      energy[static_cast<std::size_t>(pr.pass->slave_nodes[k])] += slave_part * d;
      if (sg < 0)
        continue;
      const double* w = located_shape(pr, k);
      for (std::size_t j = 0; j < 4; ++j)
        energy[static_cast<std::size_t>(pr.pass->segments[4 * static_cast<std::size_t>(sg) + j])] +=
            (1.0 - slave_part) * d * w[j];
    }
  }
}

}  // namespace plyform::contact
