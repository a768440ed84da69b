// What a pass tells the engine and the outputs: its timing, its books (InterfaceReport), the
// cohesive state of its slave nodes, its energy and its step vote.

#include <algorithm>
#include <cmath>

#include "pass_runtime.hpp"

namespace plyform::contact {

double ContactSet::stable_step() const {
  double dt = kInf;
  for (const auto& p : passes_)
    dt = std::min(dt, p->st.dt_vote);
  return dt;
}

double ContactSet::energy() const {
  double e = 0.0;
  for (const auto& p : passes_)
    e += p->st.work;
  return e;
}

std::vector<InterfaceTiming> ContactSet::timing() const {
  std::vector<InterfaceTiming> out;
  const core::ContactInterface* last = nullptr;
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    if (pr.iface != last) {
      out.push_back({});
      out.back().index = static_cast<std::size_t>(pr.iface - model_.contacts.data());
      out.back().id = pr.iface->id;
      last = pr.iface;
    }
    InterfaceTiming& r = out.back();
    r.search += pr.seconds[0];
    r.projection += pr.seconds[1];
    r.law += pr.seconds[2];
    r.forces += pr.seconds[3];
  }
  return out;
}

std::vector<InterfaceReport> ContactSet::report() const {
  std::vector<InterfaceReport> out;
  const core::ContactInterface* last = nullptr;
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    if (pr.iface != last) {
      out.push_back({});
      out.back().id = pr.iface->id;
      last = pr.iface;
    }
    InterfaceReport& r = out.back();
    for (std::size_t c = 0; c < 3; ++c) {
      r.force[c] += pr.st.resultant[c];
      r.master_force[c] += pr.st.master_resultant[c];
    }
    r.work += pr.st.work;
    r.surface += pr.st.surface;
    const law::BatchHistory& h = pr.hist;
    const std::size_t ns = pr.pass->slave_count();
    for (std::size_t k = 0; k < ns; ++k) {
      r.stored += pr.st.stored[k];
      r.damage += h.e_damage[k];
      r.viscous += h.e_viscous[k];
      r.friction += h.e_friction[k];
      r.damping += h.e_damping[k];
      r.healing += h.e_healing[k];
      if (pr.guard)
        continue;  // the counts are the interface's points, the first pass's nodes
      const auto st = static_cast<law::NodeState>(h.state[k]);
      if (st == law::NodeState::contact && pr.st.pressure[k] > 0.0)
        ++r.in_contact;
      if (st == law::NodeState::separating)
        ++r.bonded;
    }
  }
  return out;
}

void ContactSet::cohesive_results(std::vector<SlaveNodeResult>& out) const {
  out.clear();
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    // A tiebreak's history is the law's too: beta 1 while a node is tied, 0 once it failed.
    if ((!pr.bonds && pr.iface->tiebreak.option == 0) || pr.guard)
      continue;
    const std::size_t ns = pr.pass->slave_count();
    for (std::size_t k = 0; k < ns; ++k) {
      SlaveNodeResult r;
      r.node = pr.pass->slave_nodes[k];
      r.interface = pr.iface->id;
      r.state = static_cast<law::NodeState>(pr.hist.state[k]);
      r.gap = pr.st.seg[k] >= 0 ? pr.st.gap[k] : std::numeric_limits<double>::quiet_NaN();
      r.pressure = pr.st.pressure[k];
      r.tau = std::hypot(pr.st.tau_x[k], pr.st.tau_y[k]);
      r.beta = pr.hist.beta[k];
      out.push_back(r);
    }
  }
}

}  // namespace plyform::contact
