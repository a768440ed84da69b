#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "element_graph.hpp"
#include "metis_split.hpp"
#include "plyform/domain/decomposition.hpp"

namespace plyform::domain {

namespace {

// Every node's domains, its owner (the lowest) and each domain's node counts.
void own_nodes(const core::Model& m, const detail::ElementGraph& g, Decomposition& d) {
  const std::size_t nn = m.node_count();
  d.node_owner.assign(nn, -1);
  d.node_domain_start.assign(nn + 1, 0);
  d.node_domains.clear();
  std::vector<int> here;
  std::vector<std::vector<char>> touches(static_cast<std::size_t>(d.domains));
  for (auto& t : touches)
    t.assign(static_cast<std::size_t>(d.domains), 0);
  for (std::size_t n = 0; n < nn; ++n) {
    here.clear();
    for (std::size_t k = g.node_start[n]; k < g.node_start[n + 1]; ++k)
      here.push_back(d.element_domain[static_cast<std::size_t>(g.node_elements[k])]);
    std::sort(here.begin(), here.end());
    here.erase(std::unique(here.begin(), here.end()), here.end());
    d.node_domains.insert(d.node_domains.end(), here.begin(), here.end());
    d.node_domain_start[n + 1] = d.node_domains.size();
    if (here.empty())
      continue;
    d.node_owner[n] = here.front();
    for (int a : here) {
      DomainSummary& s = d.summary[static_cast<std::size_t>(a)];
      ++s.nodes;
      s.owned_nodes += a == here.front() ? 1 : 0;
      s.shared_nodes += here.size() > 1 ? 1 : 0;
      for (int b : here)
        touches[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)] = a != b;
    }
  }
  for (std::size_t a = 0; a < touches.size(); ++a)
    d.summary[a].neighbours =
        static_cast<std::size_t>(std::count(touches[a].begin(), touches[a].end(), 1));
}

// Each pass's slave and segment owners and every domain's ghost segments.
void contact_halos(const core::Model& m, const detail::ElementGraph& g, Decomposition& d) {
  const auto nd = static_cast<std::size_t>(d.domains);
  d.contact.resize(m.contacts.size());
  std::vector<std::vector<core::Index>> ghosts(nd);
  for (std::size_t c = 0; c < m.contacts.size(); ++c) {
    for (std::size_t p = 0; p < m.contacts[c].passes.size(); ++p) {
      const core::ContactPass& pass = m.contacts[c].passes[p];
      const detail::PassCandidates& pc = g.candidates[c][p];
      PassHalo& h = d.contact[c].emplace_back();
      h.slave_owner.resize(pass.slave_count());
      for (std::size_t i = 0; i < pass.slave_count(); ++i)
        h.slave_owner[i] = d.node_owner[static_cast<std::size_t>(pass.slave_nodes[i])];
      const std::vector<core::Index>& seg_el = g.segment_element[c][p];
      h.segment_owner.resize(seg_el.size());
      for (std::size_t s = 0; s < seg_el.size(); ++s)
        h.segment_owner[s] =
            seg_el[s] < 0 ? -1 : d.element_domain[static_cast<std::size_t>(seg_el[s])];
      for (auto& list : ghosts)
        list.clear();
      for (std::size_t i = 0; i < pass.slave_count(); ++i) {
        const int owner = h.slave_owner[i];
        if (owner < 0)
          continue;
        ++d.summary[static_cast<std::size_t>(owner)].slave_nodes;
        for (std::size_t k = pc.start[i]; k < pc.start[i + 1]; ++k) {
          const core::Index s = pc.segments[k];
          const int so = h.segment_owner[static_cast<std::size_t>(s)];
          if (so >= 0 && so != owner)
            ghosts[static_cast<std::size_t>(owner)].push_back(s);
        }
      }
      h.ghost_start.assign(1, 0);
      for (std::size_t a = 0; a < nd; ++a) {
        std::vector<core::Index>& list = ghosts[a];
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        h.ghost.insert(h.ghost.end(), list.begin(), list.end());
        h.ghost_start.push_back(h.ghost.size());
        d.summary[a].ghost_segments += list.size();
      }
    }
  }
}

}  // namespace

DecomposeResult decompose(const core::Model& model, int domains) {
  DecomposeResult r;
  if (domains < 1) {
    r.error = "the number of domains must be 1 or more, got " + std::to_string(domains);
    return r;
  }
  detail::ElementGraph g = detail::element_graph(model);
  if (g.elements.size() < static_cast<std::size_t>(domains)) {
    r.error = std::to_string(domains) + " domains for " + std::to_string(g.elements.size()) +
              " deformable elements: each domain needs at least one";
    return r;
  }
  Decomposition& d = r.decomposition;
  d.domains = domains;
  r.error = detail::metis_split(g, domains, {}, d.element_domain);
  if (!r.error.empty())
    return r;
  d.elements = g.elements;
  d.element_cost = g.cost;
  d.summary.assign(static_cast<std::size_t>(domains), {});
  for (std::size_t e = 0; e < d.elements.size(); ++e) {
    DomainSummary& s = d.summary[static_cast<std::size_t>(d.element_domain[e])];
    ++s.elements;
    s.cost += g.cost[e];
  }
  own_nodes(model, g, d);
  contact_halos(model, g, d);
  const double total = std::accumulate(d.summary.begin(), d.summary.end(), 0.0,
                                       [](double a, const DomainSummary& s) { return a + s.cost; });
  double largest = 0.0;
  for (const DomainSummary& s : d.summary)
    largest = std::max(largest, s.cost);
  d.imbalance = total > 0.0 ? largest * domains / total : 1.0;
  d.interface_edges = g.interface_edges.size();
  for (const auto& [a, b] : g.interface_edges)
    d.interface_edges_cut += d.element_domain[static_cast<std::size_t>(a)] !=
                             d.element_domain[static_cast<std::size_t>(b)];
  return r;
}

}  // namespace plyform::domain
