// The contact at t = 0 (ContactSet::start): the nodal normals, the first search and measure,
// the _TIEBREAK option's ties of the nodes in contact, and the initial penetrations (IGNORE).

#include <sstream>
#include <string>
#include <vector>

#include "contact_search.hpp"
#include "kinematics.hpp"
#include "pass_runtime.hpp"
#include "surface_normals.hpp"

namespace plyform::contact {

namespace {

// The _TIEBREAK option at t = 0: a slave node in contact (its surface gap, penetration or
// opening, within 5 % of its segment's shorter diagonal, LS-DYNA's tolerance of tied contacts)
// is tied where it is, so the mesh as given starts at rest.
void tie_initial_contacts(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  const TieArrays tie = pr.ties();
  for (std::size_t k = 0; k < cp.slave_count(); ++k) {
    const core::Index s = pr.st.seg[k];
    if (s < 0)
      continue;
    const core::Index* q = &cp.segments[4 * static_cast<std::size_t>(s)];
    const auto dist = [&](core::Index a, core::Index b) {
      const double *pa = at(packed, a), *pb = at(packed, b);
      return std::hypot(pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]);
    };
    // A triangle (N3 = N4): its shortest edge at N1 stands in for the diagonal.
    const double diagonal = q[2] == q[3] ? std::min(dist(q[0], q[1]), dist(q[0], q[2]))
                                         : std::min(dist(q[0], q[2]), dist(q[1], q[3]));
    if (std::abs(pr.st.gap[k]) <= 0.05 * diagonal)
      tie_node(pr.hist, tie, k, pr.st.gap[k]);
  }
}

// IGNORE 1 and 2: a node that penetrates at t = 0 keeps that depth as its tolerance (the law
// sees gap 0 there), so the penalty acts only on deeper penetration and nothing is pushed out;
// the tolerance shrinks as the node comes out (measure()). IGNORE 2 lists each node with the
// position that would have cleared it (moved out along the contact normal).
void track_initial_penetrations(PassRuntime& pr, const double* packed, const core::Model& model,
                                std::vector<std::string>& warnings) {
  const core::ContactPass& cp = *pr.pass;
  std::size_t count = 0, listed = 0;
  double deepest = 0.0;
  for (std::size_t k = 0; k < cp.slave_count(); ++k) {
    if (pr.st.seg[k] < 0 || pr.st.gap[k] >= 0.0)
      continue;
    const double g = pr.st.gap[k];
    pr.st.arrival_depth[k] = g;
    pr.st.gap[k] = 0.0;
    ++count;
    deepest = std::min(deepest, g);
    if (pr.iface->ignore == 2 && listed < 50) {
      ++listed;
      const core::Index node = cp.slave_nodes[k];
      const double* p = at(packed, node);
      const double* n = &pr.st.frame[9 * k];  // towards the slave's side
      std::ostringstream os;
      os << pr.iface->keyword << " " << pr.iface->id << ": node "
         << model.node_id[static_cast<std::size_t>(node)] << " penetrates " << -g << " at (" << p[0]
         << ", " << p[1] << ", " << p[2] << "); clear at (" << p[0] - g * n[0] << ", "
         << p[1] - g * n[1] << ", " << p[2] - g * n[2] << "): tracked (IGNORE 2)";
      warnings.push_back(os.str());
    }
  }
  if (count > 0) {
    std::ostringstream os;
    os << pr.iface->keyword << " " << pr.iface->id << ": " << count
       << " slave nodes penetrate at t = 0 (deepest " << -deepest << "): tracked ("
       << (pr.iface->ignore == 0 ? std::string("IGNORE 0 could not move them clear")
                                 : "IGNORE " + std::to_string(pr.iface->ignore))
       << "), the penalty acts only beyond that depth, which shrinks as they come out";
    if (listed < count && pr.iface->ignore == 2)
      os << " (" << listed << " listed)";
    warnings.push_back(os.str());
  }
}

}  // namespace

void ContactSet::start(const double* packed, bool track_leftovers) {
  for (auto& pp : passes_) {
    PassRuntime& pr = *pp;
    init_nodal_normals(pr, packed);
    search(pr, packed, mass_, rigid_, rot_, tssfac_);
    ++searches_;
    const std::size_t ns = pr.pass->slave_count();
    measure(pr, 0.0, packed, nullptr, mass_, rigid_, rot_);
    // IGNORE 0: setup moved the penetrating nodes out (setup::build_contacts); what it could
    // not clear (coplanar flanges of two parts, each moved into the other's band) is tracked
    // as IGNORE 1 does: pushed out, it gave the model energy from nowhere (the crush box deck:
    // 18 nodes, 156 J at once). A cohesive or tiebreak interface bonds instead.
    if (pr.iface->ignore > 0 || (track_leftovers && pr.iface->leftovers_tracked &&
                                 !pr.iface->cohesive && !pr.iface->tiebreak.enabled()))
      track_initial_penetrations(pr, packed, model_, warnings_);
    pr.law.initialize_batch(ns, pr.st.gap.data(), pr.hist);
    if (pr.iface->tiebreak.enabled())
      tie_initial_contacts(pr, packed);
    // Initial penetrations of nodes that are not bonded: the penalty will push them out in
    // the first cycles (a jolt the user should know about).
    std::size_t count = 0;
    double deepest = 0.0;
    core::Index where = -1;
    for (std::size_t k = 0; k < ns; ++k) {
      // Round-off of nodes placed on the surface (or moved onto it, IGNORE = 0) is no
      // penetration.
      if (pr.st.seg[k] < 0 || pr.st.gap[k] >= -1e-9 * pr.margin)
        continue;
      if (static_cast<law::NodeState>(pr.hist.state[k]) == law::NodeState::contact && pr.bonds &&
          pr.law.parameters().bond_tol >= -pr.st.gap[k])
        continue;  // bonded at t = 0 within BOND_TOL
      if (!pr.st.tie_state.empty() && static_cast<TieState>(pr.st.tie_state[k]) == TieState::tied)
        continue;  // tied where it is
      ++count;
      if (pr.st.gap[k] < deepest) {
        deepest = pr.st.gap[k];
        where = pr.pass->slave_nodes[k];
      }
    }
    if (count > 0) {
      std::ostringstream os;
      os << pr.iface->keyword << " " << pr.iface->id << ": " << count
         << " slave nodes penetrate at t = 0 (deepest " << -deepest << " at node "
         << model_.node_id[static_cast<std::size_t>(where)] << ")";
      warnings_.push_back(os.str());
    }
  }
}

void ContactSet::initial_penetrations(std::vector<InitialPenetration>& out) const {
  out.clear();
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    if (pr.iface->ignore != 0 || pr.iface->cohesive)
      continue;
    const auto index = static_cast<std::size_t>(pr.iface - model_.contacts.data());
    const auto is_rigid = [&](core::Index v) {
      return rigid_ != nullptr && rigid_[static_cast<std::size_t>(v)] != 0;
    };
    for (std::size_t k = 0; k < pr.pass->slave_count(); ++k) {
      const core::Index node = pr.pass->slave_nodes[k];
      if (pr.st.seg[k] < 0 || !(pr.st.gap[k] < 0.0))
        continue;
      if (!pr.st.tie_state.empty() && static_cast<TieState>(pr.st.tie_state[k]) == TieState::tied)
        continue;
      const double* n = &pr.st.frame[9 * k];  // towards the slave's side
      const double d = -pr.st.gap[k];
      if (!is_rigid(node)) {
        out.push_back({node, index, d, {d * n[0], d * n[1], d * n[2]}});
        continue;
      }
      // A rigid node (a tool's) in a deformable surface: that surface's nodes move away.
      const core::Index* q = &pr.pass->segments[4 * static_cast<std::size_t>(pr.st.seg[k])];
      for (int j = 0; j < (q[2] == q[3] ? 3 : 4); ++j) {
        if (!is_rigid(q[j]))
          out.push_back({q[j], index, d, {-d * n[0], -d * n[1], -d * n[2]}});
      }
    }
  }
}

}  // namespace plyform::contact
