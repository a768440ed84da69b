#include "element_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "plyform/contact/bucket_search.hpp"

namespace plyform::domain::detail {

namespace {

bool rigid(const core::Model& m, core::Index material) {
  return std::holds_alternative<core::RigidMaterial>(
      m.materials[static_cast<std::size_t>(material)]);
}

// The deformable elements in block order, shells first, with their own cost.
void list_elements(const core::Model& m, ElementGraph& g) {
  for (std::size_t b = 0; b < m.shell_blocks.size(); ++b) {
    const core::ShellBlock& block = m.shell_blocks[b];
    if (rigid(m, block.material))
      continue;
    const double c = shell_cost(m, block);
    for (std::size_t e = 0; e < block.size(); ++e) {
      g.elements.push_back({true, static_cast<core::Index>(b), static_cast<core::Index>(e)});
      g.cost.push_back(c);
    }
  }
  for (std::size_t b = 0; b < m.solid_blocks.size(); ++b) {
    const core::SolidBlock& block = m.solid_blocks[b];
    if (rigid(m, block.material))
      continue;
    const double c = solid_cost(m, block);
    for (std::size_t e = 0; e < block.size(); ++e) {
      g.elements.push_back({false, static_cast<core::Index>(b), static_cast<core::Index>(e)});
      g.cost.push_back(c);
    }
  }
}

// Each node's deformable elements (a triangle's repeated node counted once).
void node_to_elements(const core::Model& m, ElementGraph& g) {
  const std::size_t nn = m.node_count();
  g.node_start.assign(nn + 1, 0);
  const auto each_node = [&](std::size_t e, auto&& f) {
    const std::span<const core::Index> nodes = element_nodes(m, g.elements[e]);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (std::find(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(k), nodes[k]) ==
          nodes.begin() + static_cast<std::ptrdiff_t>(k))
        f(static_cast<std::size_t>(nodes[k]));
    }
  };
  for (std::size_t e = 0; e < g.elements.size(); ++e)
    each_node(e, [&](std::size_t n) { ++g.node_start[n + 1]; });
  for (std::size_t n = 0; n < nn; ++n)
    g.node_start[n + 1] += g.node_start[n];
  g.node_elements.resize(g.node_start[nn]);
  std::vector<std::size_t> fill(g.node_start.begin(), g.node_start.end() - 1);
  for (std::size_t e = 0; e < g.elements.size(); ++e)
    each_node(e, [&](std::size_t n) { g.node_elements[fill[n]++] = static_cast<core::Index>(e); });
}

// The deformable element a master segment is a face of (-1: a rigid body's face): the one that
// holds both ends of its first diagonal.
core::Index segment_element(const core::Model& m, const ElementGraph& g, const core::Index* seg) {
  const auto n0 = static_cast<std::size_t>(seg[0]);
  for (std::size_t k = g.node_start[n0]; k < g.node_start[n0 + 1]; ++k) {
    const core::Index e = g.node_elements[k];
    const std::span<const core::Index> nodes =
        element_nodes(m, g.elements[static_cast<std::size_t>(e)]);
    if (std::find(nodes.begin(), nodes.end(), seg[2]) != nodes.end())
      return e;
  }
  return -1;
}

double squared_distance(const std::vector<double>& xyz, std::size_t node, const double* c) {
  const double dx = xyz[3 * node] - c[0], dy = xyz[3 * node + 1] - c[1],
               dz = xyz[3 * node + 2] - c[2];
  return dx * dx + dy * dy + dz * dz;
}

// Per pass: each segment's element, each slave node's candidates, the slave nodes' cost, and the
// interface edge of each deformable slave node to the nearest deformable segment in reach.
void contact_couplings(const core::Model& m, ElementGraph& g) {
  std::vector<double> xyz(3 * m.node_count());
  for (std::size_t n = 0; n < m.node_count(); ++n) {
    xyz[3 * n] = m.x0[n];
    xyz[3 * n + 1] = m.y0[n];
    xyz[3 * n + 2] = m.z0[n];
  }
  g.segment_element.resize(m.contacts.size());
  g.candidates.resize(m.contacts.size());
  for (std::size_t c = 0; c < m.contacts.size(); ++c) {
    for (const core::ContactPass& pass : m.contacts[c].passes) {
      const std::size_t nseg = pass.segment_count();
      std::vector<core::Index>& seg_el = g.segment_element[c].emplace_back(nseg, -1);
      std::vector<double> centroid(3 * nseg, 0.0);
      for (std::size_t s = 0; s < nseg; ++s) {
        seg_el[s] = segment_element(m, g, &pass.segments[4 * s]);
        for (int k = 0; k < 4; ++k)
          for (int d = 0; d < 3; ++d)
            centroid[3 * s + static_cast<std::size_t>(d)] +=
                0.25 * xyz[3 * static_cast<std::size_t>(
                                   pass.segments[4 * s + static_cast<std::size_t>(k)]) +
                           static_cast<std::size_t>(d)];
      }
      PassCandidates& pc = g.candidates[c].emplace_back();
      contact::BucketSearch grid;
      grid.build(pass.segments, xyz.data(), 3, segment_reach(m, pass));
      grid.query(pass.slave_nodes, xyz.data(), 3, pc.start, pc.segments);
      for (std::size_t i = 0; i < pass.slave_count(); ++i) {
        const auto node = static_cast<std::size_t>(pass.slave_nodes[i]);
        const std::size_t first = g.node_start[node], last = g.node_start[node + 1];
        if (first == last)
          continue;  // a rigid body's node
        const double share = kSlaveNodeCost / static_cast<double>(last - first);
        for (std::size_t k = first; k < last; ++k)
          g.cost[static_cast<std::size_t>(g.node_elements[k])] += share;
        core::Index nearest = -1;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = pc.start[i]; k < pc.start[i + 1]; ++k) {
          const auto s = static_cast<std::size_t>(pc.segments[k]);
          if (seg_el[s] < 0)
            continue;
          const double d2 = squared_distance(xyz, node, &centroid[3 * s]);
          if (d2 < best) {
            best = d2;
            nearest = seg_el[s];
          }
        }
        const core::Index own = g.node_elements[first];
        if (nearest >= 0 && nearest != own)
          g.interface_edges.push_back({std::min(own, nearest), std::max(own, nearest)});
      }
    }
  }
  std::sort(g.interface_edges.begin(), g.interface_edges.end());
  g.interface_edges.erase(std::unique(g.interface_edges.begin(), g.interface_edges.end()),
                          g.interface_edges.end());
}

// The CSR graph: each element's neighbours through shared nodes (weight: the nodes they share)
// and through the interface edges (kInterfaceEdgeWeight each).
void build_csr(const core::Model& m, ElementGraph& g) {
  const std::size_t ne = g.elements.size();
  std::vector<std::vector<core::Index>> across(ne);
  for (const auto& [a, b] : g.interface_edges) {
    across[static_cast<std::size_t>(a)].push_back(b);
    across[static_cast<std::size_t>(b)].push_back(a);
  }
  g.xadj.assign(1, 0);
  std::vector<std::int32_t> slot(ne, -1);  // the neighbour's position in adjncy, for this element
  for (std::size_t e = 0; e < ne; ++e) {
    const std::size_t row = g.adjncy.size();
    const auto add = [&](core::Index o, std::int32_t w) {
      const auto oi = static_cast<std::size_t>(o);
      if (oi == e)
        return;
      if (slot[oi] < 0) {
        slot[oi] = static_cast<std::int32_t>(g.adjncy.size());
        g.adjncy.push_back(o);
        g.adjwgt.push_back(0);
      }
      g.adjwgt[static_cast<std::size_t>(slot[oi])] += w;
    };
    const std::span<const core::Index> nodes = element_nodes(m, g.elements[e]);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (std::find(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(k), nodes[k]) !=
          nodes.begin() + static_cast<std::ptrdiff_t>(k))
        continue;
      const auto n = static_cast<std::size_t>(nodes[k]);
      for (std::size_t j = g.node_start[n]; j < g.node_start[n + 1]; ++j)
        add(g.node_elements[j], 1);
    }
    for (core::Index o : across[e])
      add(o, kInterfaceEdgeWeight);
    for (std::size_t j = row; j < g.adjncy.size(); ++j)
      slot[static_cast<std::size_t>(g.adjncy[j])] = -1;
    g.xadj.push_back(static_cast<std::int32_t>(g.adjncy.size()));
  }
}

}  // namespace

std::span<const core::Index> element_nodes(const core::Model& m, const ElementRef& e) {
  if (e.shell) {
    const auto& c = m.shell_blocks[static_cast<std::size_t>(e.block)].connectivity;
    return {c.data() + 4 * static_cast<std::size_t>(e.element), 4};
  }
  const auto& c = m.solid_blocks[static_cast<std::size_t>(e.block)].connectivity;
  return {c.data() + 8 * static_cast<std::size_t>(e.element), 8};
}

ElementGraph element_graph(const core::Model& model) {
  ElementGraph g;
  list_elements(model, g);
  node_to_elements(model, g);
  contact_couplings(model, g);
  build_csr(model, g);
  return g;
}

}  // namespace plyform::domain::detail

namespace plyform::domain {

std::vector<double> segment_reach(const core::Model& m, const core::ContactPass& pass) {
  double max_slave_offset = 0.0;
  for (double o : pass.slave_offset)
    max_slave_offset = std::max(max_slave_offset, o);
  std::vector<double> reach(pass.segment_count());
  for (std::size_t s = 0; s < reach.size(); ++s) {
    const core::Index* n = &pass.segments[4 * s];
    double longest = 0.0;
    for (int k = 0; k < 4; ++k) {
      const auto a = static_cast<std::size_t>(n[k]), b = static_cast<std::size_t>(n[(k + 1) % 4]);
      longest =
          std::max(longest, std::hypot(m.x0[a] - m.x0[b], m.y0[a] - m.y0[b], m.z0[a] - m.z0[b]));
    }
    reach[s] = pass.segment_offset[s] + max_slave_offset + longest;
  }
  return reach;
}

}  // namespace plyform::domain
