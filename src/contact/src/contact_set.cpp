// The contact passes' set-up (ContactSet's constructor): each interface's passes with their
// law, search reach, offsets, penalty data and per-slave arrays; the tiebreak passes' count per
// node; the shells' thickness and rotations the passes follow. The cycle's jobs have their own
// files (docs/architecture.md, "Contact").

#include "plyform/contact/contact_set.hpp"

#include <algorithm>
#include <cmath>

#include "pass_runtime.hpp"
#include "plyform/core/invariant.hpp"
#include "resting_nodes.hpp"
#include "slave_share.hpp"
#include "surface_geometry.hpp"

namespace plyform::contact {

namespace {

// The law of a cohesive interface's guard pass: the same normal damping, pressure only.
law::Parameters guard_law(const law::Parameters& bonded) {
  law::Parameters p = bonded;
  p.beta0 = 0.0;  // no adhesion, ever: beta stays 0
  p.bond_tol = 0.0;
  p.zeta = {0.0, 0.0, -1};
  p.mu = {0.0, 0.0, -1};
  p.friction = law::FrictionModel::coulomb;
  p.ct = 0.0;
  p.decay_dc = 0.0;
  p.friction_limit = 0.0;
  p.release_gap = kInf;
  p.vdc = 0.0;
  return p;
}

// The largest sigma_max of a law over its temperature range (the cohesive capture distance).
double largest_sigma_max(const law::Parameters& p) {
  if (p.sigma_max.curve >= 0) {
    const law::Curve& c = p.curves[static_cast<std::size_t>(p.sigma_max.curve)];
    double m = 0.0;
    for (double y : c.y())
      m = std::max(m, y);
    return m;
  }
  return std::max(p.sigma_max.lo, p.sigma_max.hi);
}

}  // namespace

ContactSet::ContactSet(const core::Model& model, const std::vector<double>& mass,
                       const unsigned char* rigid, double dt0, double tssfac)
    : model_(model), mass_(mass), rigid_(rigid) {
  for (const core::ContactInterface& ci : model.contacts) {
    // The search reaches the cohesive band: beyond 2 g_c / sqrt(BETA_MIN) a bonded node has
    // lost all but a negligible part of its adhesion, and the law releases it there.
    double bond_capture = 0.0;
    law::Parameters bond_params = ci.law;
    if (ci.cohesive) {
      const double gc = largest_sigma_max(bond_params) / bond_params.cn;
      bond_capture = 2.0 * gc / std::sqrt(std::max(bond_params.beta_min, 1e-12));
      bond_params.release_gap = std::min(bond_params.release_gap, bond_capture);
    }
    for (const core::ContactPass& cp : ci.passes) {
      const bool bonds = ci.cohesive && !cp.guard;
      const double capture = bonds ? bond_capture : 0.0;
      const law::Parameters params = cp.guard ? guard_law(ci.law) : bond_params;
      if constexpr (core::kCheckInvariants) {
        const auto in_range = [&](core::Index n) {
          return n >= 0 && static_cast<std::size_t>(n) < model.node_count();
        };
        for (core::Index n : cp.slave_nodes)
          PLYFORM_INVARIANT(in_range(n), "slave node indices in range");
        for (core::Index n : cp.segments)
          PLYFORM_INVARIANT(in_range(n), "segment node indices in range");
        PLYFORM_INVARIANT(cp.segments.size() == 4 * cp.segment_offset.size() &&
                              cp.slave_offset.size() == cp.slave_count() &&
                              cp.slave_area.size() == cp.slave_count(),
                          "a pass's arrays of matching lengths");
      }
      auto pr = std::make_unique<PassRuntime>(params);
      pr->iface = &ci;
      pr->pass = &cp;
      pr->bonds = bonds;
      pr->guard = cp.guard;
      pr->dt0 = dt0;
      const std::size_t ns = cp.slave_count();
      const std::size_t nseg = cp.segment_count();
      pr->history = law::HistoryStore(ns);
      pr->hist = pr->history.view();
      // Margin: half the mean segment size, so that a re-search is needed only after the
      // surfaces moved that far relative to each other.
      double size_sum = 0.0;
      for (std::size_t s = 0; s < nseg; ++s) {
        const core::Index* q = &cp.segments[4 * s];
        const auto d = [&](core::Index a, core::Index b) {
          const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
          const double dx = model.x0[i] - model.x0[j], dy = model.y0[i] - model.y0[j],
                       dz = model.z0[i] - model.z0[j];
          return std::sqrt(dx * dx + dy * dy + dz * dz);
        };
        size_sum += std::max(d(q[0], q[2]), d(q[1], q[3]));
      }
      pr->margin = nseg > 0 ? 0.5 * size_sum / static_cast<double>(nseg) : 0.0;
      pr->capture = capture;
      pr->st.slave_offset = cp.slave_offset;
      pr->st.seg_offset = cp.segment_offset;
      double max_slave_offset = 0.0;
      for (double o : cp.slave_offset)
        max_slave_offset = std::max(max_slave_offset, o);
      // Each segment's neighbours: the segments that share a corner with it.
      {
        std::vector<std::vector<core::Index>> at_node;
        for (std::size_t sg = 0; sg < nseg; ++sg)
          for (int j = 0; j < 4; ++j) {
            const auto n =
                static_cast<std::size_t>(cp.segments[4 * sg + static_cast<std::size_t>(j)]);
            if (at_node.size() <= n)
              at_node.resize(n + 1);
            if (at_node[n].empty() || at_node[n].back() != static_cast<core::Index>(sg))
              at_node[n].push_back(static_cast<core::Index>(sg));
          }
        pr->nb_start.assign(nseg + 1, 0);
        std::vector<core::Index> mine;
        for (std::size_t sg = 0; sg < nseg; ++sg) {
          mine.clear();
          for (int j = 0; j < 4; ++j)
            for (core::Index o : at_node[static_cast<std::size_t>(
                     cp.segments[4 * sg + static_cast<std::size_t>(j)])])
              if (o != static_cast<core::Index>(sg))
                mine.push_back(o);
          std::sort(mine.begin(), mine.end());
          mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
          pr->nb.insert(pr->nb.end(), mine.begin(), mine.end());
          pr->nb_start[sg + 1] = pr->nb.size();
        }
        pr->folded.assign(nseg, 0);
        pr->rigid_master = rigid != nullptr && !cp.segments.empty() &&
                           std::all_of(cp.segments.begin(), cp.segments.end(), [&](core::Index n) {
                             return rigid[static_cast<std::size_t>(n)] != 0;
                           });
        pr->fold_centroid.assign(3 * nseg, 0.0);
        pr->fold_normal.assign(3 * nseg, 0.0);
      }
      pr->st.seg_radius.resize(nseg);
      double max_radius = 0.0;
      for (std::size_t s = 0; s < nseg; ++s) {
        // A touching node is within the two offsets of the segment's mid-surface (a deeper
        // one is closer still); the cohesive band; the margin for motion between searches.
        pr->st.seg_radius[s] = cp.segment_offset[s] + max_slave_offset + capture + pr->margin;
        max_radius = std::max(max_radius, pr->st.seg_radius[s]);
      }
      // Just beyond the band where the law releases a bonded node: the node is released, and
      // the elastic energy it is booked as giving up is that of its spring at the band's edge
      // (a gap far beyond would book an energy the interface never held).
      pr->far_gap = bonds ? params.release_gap * (1.0 + 1e-9) + 1.0e-30
                          : 2.0 * (capture + max_radius) + 1.0e-30;
      // Nodes whose motion can bring a slave node within reach of a new segment.
      std::vector<char> mark(model.node_count(), 0);
      for (core::Index n : cp.slave_nodes)
        mark[static_cast<std::size_t>(n)] = 1;
      for (core::Index n : cp.segments)
        mark[static_cast<std::size_t>(n)] = 2;  // a master's node (tracked_master)
      for (std::size_t i = 0; i < mark.size(); ++i) {
        if (mark[i]) {
          pr->tracked_nodes.push_back(static_cast<core::Index>(i));
          pr->tracked_master.push_back(mark[i] == 2 ? 1 : 0);
        }
      }
      pr->st.tracked_ref.assign(3 * pr->tracked_nodes.size(), 0.0);
      pr->st.seg.assign(ns, -1);
      pr->st.prev_seg.assign(ns, -1);
      pr->st.shape.assign(4 * ns, 0.0);
      pr->st.friction_heated.assign(ns, 0.0);
      if (ci.tiebreak.enabled()) {
        pr->st.tie_state.assign(ns, static_cast<std::int8_t>(TieState::free));
        pr->st.tie_gap0.assign(ns, 0.0);
      }
      pr->st.prev_shape.assign(4 * ns, 0.0);
      pr->may_rest = may_rest(*pr);
      pr->rest_reach = rest_reach(*pr);
      pr->own_slaves = ns;
      pr->st.resting.assign(ns, 0);
      pr->st.rest_wait.assign(ns, 0);
      pr->st.rest_room.assign(ns, 0.0);
      pr->st.rest_from.assign(3 * ns, 0.0);
      pr->st.frame.assign(9 * ns, 0.0);
      pr->st.side.assign(ns, 0);
      for (auto* v :
           {&pr->st.gap, &pr->st.slip_x, &pr->st.slip_y, &pr->st.temperature, &pr->st.k_normal,
            &pr->st.k_tangent, &pr->st.m_eff, &pr->st.pressure, &pr->st.tau_x, &pr->st.tau_y,
            &pr->st.stored, &pr->st.work_part, &pr->st.end_power, &pr->st.arrival_depth,
            &pr->st.gap_jump, &pr->st.surface_part})
        v->assign(ns, 0.0);
      pr->st.force.assign(3 * ns, 0.0);
      pr->st.prev_force.assign(3 * ns, 0.0);
      pr->st.rs.assign(3 * ns, 0.0);
      pr->st.prev_rs.assign(3 * ns, 0.0);
      pr->st.slave_normal.assign(3 * ns, 0.0);
      pr->st.slave_face_normal.assign(3 * (cp.slave_faces.size() / 4), 0.0);
      pr->slave_face_sign.assign(cp.slave_face_index.size(), 1);
      pr->slave_face_normals_absent = cp.slave_face_start.empty() || cp.slave_face_index.empty();
      for (double o : cp.segment_offset)
        pr->master_offsets = pr->master_offsets || o > 0.0;
      if (cp.offsets_follow_thickness) {
        for (double f : cp.segment_offset_factor)
          pr->master_offsets = pr->master_offsets || f > 0.0;
      }
      if (pr->master_offsets) {
        std::vector<core::Index> local(model.node_count(), -1);
        pr->corner.resize(cp.segments.size());
        std::vector<std::size_t> count;
        for (std::size_t c = 0; c < cp.segments.size(); ++c) {
          const auto node = static_cast<std::size_t>(cp.segments[c]);
          if (local[node] < 0) {
            local[node] = static_cast<core::Index>(pr->master_nodes.size());
            pr->master_nodes.push_back(cp.segments[c]);
            count.push_back(0);
          }
          pr->corner[c] = local[node];
          // A triangle's repeated corner counts once.
          if (c % 4 != 3 || cp.segments[c] != cp.segments[c - 1])
            ++count[static_cast<std::size_t>(local[node])];
        }
        pr->node_seg_start.assign(pr->master_nodes.size() + 1, 0);
        for (std::size_t i = 0; i < count.size(); ++i)
          pr->node_seg_start[i + 1] = pr->node_seg_start[i] + count[i];
        pr->node_seg.resize(pr->node_seg_start.back());
        std::vector<std::size_t> fill(pr->node_seg_start.begin(), pr->node_seg_start.end() - 1);
        for (std::size_t c = 0; c < cp.segments.size(); ++c) {
          if (c % 4 == 3 && cp.segments[c] == cp.segments[c - 1])
            continue;
          const auto i = static_cast<std::size_t>(pr->corner[c]);
          pr->node_seg[fill[i]++] = static_cast<core::Index>(c / 4);
        }
        pr->st.master_normal.assign(3 * pr->master_nodes.size(), 0.0);
        pr->st.seg_normal.assign(3 * (cp.segments.size() / 4), 0.0);
        pr->corner_sign.assign(cp.segments.size(), 1);
        pr->node_seg_sign.assign(pr->node_seg.size(), 1);
        update_node_offsets(*pr);
      }
      passes_.push_back(std::move(pr));
    }
  }
  count_tie_passes();
  tssfac_ = tssfac;
}

void ContactSet::count_tie_passes() {
  std::vector<char> mark;
  for (const auto& pr : passes_) {
    if (pr->st.tie_state.empty())
      continue;
    if (tie_passes_at_.empty())
      tie_passes_at_.assign(model_.node_count(), 0);
    mark.assign(model_.node_count(), 0);
    for (core::Index n : pr->pass->slave_nodes)
      mark[static_cast<std::size_t>(n)] = 1;
    for (core::Index n : pr->pass->segments)
      mark[static_cast<std::size_t>(n)] = 1;
    for (std::size_t i = 0; i < mark.size(); ++i)
      if (mark[i] && tie_passes_at_[i] < 255)
        ++tie_passes_at_[i];
    pr->ties_at = tie_passes_at_.data();
  }
}

ContactSet::~ContactSet() = default;

void ContactSet::follow_shell_thickness(std::vector<const double*> thickness) {
  shell_thickness_ = std::move(thickness);
}

void ContactSet::follow_rotations(const Rotations& rotations) {
  rot_ = rotations;
}

void ContactSet::follow_thickness(PassRuntime& pr) const {
  const core::ContactPass& cp = *pr.pass;
  const auto t = [&](core::Index shell) {
    return *shell_thickness_[static_cast<std::size_t>(shell)];
  };
  for (std::size_t s = 0; s < cp.segment_shell.size(); ++s) {
    if (cp.segment_shell[s] >= 0)
      pr.st.seg_offset[s] = cp.segment_offset_factor[s] * t(cp.segment_shell[s]);
  }
  if (pr.master_offsets)
    update_node_offsets(pr);
  const std::size_t ns = cp.slave_count();
  for (std::size_t k = 0; k < ns; ++k) {
    const std::size_t b = cp.slave_shell_start[k], e = cp.slave_shell_start[k + 1];
    if (e == b)
      continue;
    double sum = 0.0;
    for (std::size_t j = b; j < e; ++j)
      sum += t(cp.slave_shells[j]);
    pr.st.slave_offset[k] = cp.slave_offset_factor[k] * sum / static_cast<double>(e - b);
  }
}

std::size_t ContactSet::slave_count() const {
  std::size_t n = 0;
  for (const auto& p : passes_)
    n += p->pass->slave_count();
  return n;
}

void ContactSet::share_slaves(const comm::Communicator& comm, std::span<const int> node_owner) {
  if (comm.size() < 2)
    return;
  shares_.clear();
  for (auto& pp : passes_) {
    const core::ContactPass& cp = *pp->pass;
    std::vector<int> owner(cp.slave_count());
    for (std::size_t k = 0; k < owner.size(); ++k) {
      const int o = node_owner[static_cast<std::size_t>(cp.slave_nodes[k])];
      owner[k] = o >= 0 ? o : static_cast<int>(k % static_cast<std::size_t>(comm.size()));
    }
    shares_.push_back(std::make_unique<SlaveShare>(comm, owner));
    pp->mine = shares_.back()->mine().data();
    pp->own_slaves = static_cast<std::size_t>(
        std::count(pp->mine, pp->mine + owner.size(), static_cast<unsigned char>(1)));
    // A node this rank takes over is measured twice again before it is passed over as far
    // (pass_runtime.hpp): its count here is from when it was last this rank's.
    pp->far_cycles.assign(cp.slave_count(), 0);
  }
  gathered_at_ = applies_;
}

}  // namespace plyform::contact
