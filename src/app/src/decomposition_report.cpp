#include "decomposition_report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <array>
#include <cstddef>

namespace plyform::app {

namespace {

constexpr std::size_t kRowsUpTo = 16;

std::array<std::size_t, 6> columns(const domain::DomainSummary& s) {
  return {s.elements, s.nodes, s.shared_nodes, s.neighbours, s.slave_nodes, s.ghost_segments};
}

}  // namespace

void print_decomposition(const core::Model& model, const domain::Decomposition& d,
                         std::ostream& out) {
  std::size_t slave_total = 0;
  for (const auto& interface : d.contact)
    for (const domain::PassHalo& h : interface)
      slave_total += h.slave_owner.size();
  fmt::print(out,
             "decomposition: {} domains (METIS k-way over {} deformable elements, weighted by "
             "element and contact cost; rigid bodies on every rank)\n",
             d.domains, d.elements.size());
  double total = 0.0;
  for (const domain::DomainSummary& s : d.summary)
    total += s.cost;
  constexpr const char* header = "  {:>8} {:>10} {:>10} {:>8} {:>10} {:>11} {:>14} {:>7}\n";
  fmt::print(out, header, "domain", "elements", "nodes", "shared", "neighbours", "slave nodes",
             "ghost segments", "cost %");
  const auto row = [&](const std::string& name, const std::array<double, 6>& v, double cost) {
    fmt::print(out, "  {:>8} {:>10.0f} {:>10.0f} {:>8.0f} {:>10.0f} {:>11.0f} {:>14.0f} {:>7.2f}\n",
               name, v[0], v[1], v[2], v[3], v[4], v[5], cost);
  };
  std::array<double, 6> lo{}, hi{}, mean{};
  lo.fill(1e300);
  double cost_lo = 1e300, cost_hi = 0.0;
  for (std::size_t a = 0; a < d.summary.size(); ++a) {
    const domain::DomainSummary& s = d.summary[a];
    const std::array<std::size_t, 6> c = columns(s);
    std::array<double, 6> v{};
    for (std::size_t k = 0; k < 6; ++k) {
      v[k] = static_cast<double>(c[k]);
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
      mean[k] += v[k] / static_cast<double>(d.summary.size());
    }
    const double share = total > 0.0 ? 100.0 * s.cost / total : 0.0;
    cost_lo = std::min(cost_lo, share);
    cost_hi = std::max(cost_hi, share);
    if (d.summary.size() <= kRowsUpTo)
      row(std::to_string(a), v, share);
  }
  row("least", lo, cost_lo);
  row("mean", mean, 100.0 / static_cast<double>(d.summary.size()));
  row("largest", hi, cost_hi);
  fmt::print(out, "  imbalance: {:.3f} (the largest domain's cost over the mean)\n", d.imbalance);
  std::size_t rigid_nodes = 0;
  for (int o : d.node_owner)
    rigid_nodes += o < 0 ? 1 : 0;
  fmt::print(out, "  nodes on every rank (rigid bodies and unused): {} of {}\n", rigid_nodes,
             model.node_count());
  if (d.interface_edges > 0)
    fmt::print(out,
               "  layers held together: {} of {} interface edges cut ({:.2f} %; each joins a "
               "slave node's element to the element it faces across a contact)\n",
               d.interface_edges_cut, d.interface_edges,
               100.0 * static_cast<double>(d.interface_edges_cut) /
                   static_cast<double>(d.interface_edges));
  fmt::print(out, "  contact slave nodes: {} over {} interface{}\n", slave_total, d.contact.size(),
             d.contact.size() == 1 ? "" : "s");
  // What a run over these ranks does with the split today (docs/parallel.md).
  if (!model.contacts.empty() || model.thermal.enabled) {
    fmt::print(out, "  nodes: every rank moves every node ({} reads them all)\n",
               !model.contacts.empty() ? "the contact's search" : "the heat conduction");
  } else {
    fmt::print(out,
               "  nodes: each rank moves its own and its neighbours' around them, and the "
               "constrained, loaded, rigid, tied and walled nodes; the forces of those it does "
               "not own from their owners\n");
  }
  fmt::print(out,
             "  run it so: mpirun -np {} plyform run DECK -o OUTDIR (the element loop and the "
             "contact's slave nodes by these domains at first, split again while running as "
             "the ranks' speed shows, --rebalance; every rank holds the whole model; the "
             "files are those of one rank)\n",
             d.domains);
}

}  // namespace plyform::app
