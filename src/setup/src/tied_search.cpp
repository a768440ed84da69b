#include "tied_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <fmt/format.h>

#include "node_roles.hpp"
#include "plyform/contact/segment_projection.hpp"

namespace plyform::setup {

using core::Index;

namespace {

// A projection may fall this far outside the segment (parametric measure) and still hold the
// node: a node on a shared edge of two segments projects onto both.
constexpr double kOutside = 1e-3;

std::int64_t cell_key(std::int64_t i, std::int64_t j, std::int64_t k) {
  return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
}

}  // namespace

std::vector<TieFound> find_ties(const core::Model& m, std::span<const Index> slaves,
                                std::span<const double> slave_thickness,
                                std::span<const Index> segments,
                                std::span<const double> segment_thickness, double sst, double mst) {
  std::vector<TieFound> found(slaves.size());
  const std::size_t ns = segments.size() / 4;
  if (ns == 0)
    return found;
  const auto point = [&](Index n) {
    const auto i = static_cast<std::size_t>(n);
    return std::array<double, 3>{m.x0[i], m.y0[i], m.z0[i]};
  };
  // Segment centroids in a grid of cells no smaller than the largest reach (half a diagonal
  // plus the search distance): a segment within reach of a node has its centroid in one of the
  // 27 cells around the node's.
  double max_t = 0.0;
  for (double t : slave_thickness)
    max_t = std::max(max_t, t);
  std::vector<std::array<double, 3>> centre(ns);
  std::vector<double> diagonal(ns);
  double cell = 0.0;
  for (std::size_t s = 0; s < ns; ++s) {
    const Index* q = &segments[4 * s];
    const int nn = q[2] == q[3] ? 3 : 4;
    std::array<double, 3> c{};
    double d = 0.0;
    for (int a = 0; a < nn; ++a) {
      const auto pa = point(q[a]);
      for (std::size_t k = 0; k < 3; ++k)
        c[k] += pa[k] / nn;
      for (int b = 0; b < a; ++b) {
        const auto pb = point(q[b]);
        d = std::max(d, std::hypot(pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]));
      }
    }
    centre[s] = c;
    diagonal[s] = d;
    const double reach = std::max(
        0.6 * ((sst > 0.0 ? sst : max_t) + (mst > 0.0 ? mst : segment_thickness[s])), 0.05 * d);
    cell = std::max(cell, 0.5 * d + reach);
  }
  if (!(cell > 0.0))
    return found;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> grid;
  const auto index = [&](double v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
  for (std::size_t s = 0; s < ns; ++s)
    grid[cell_key(index(centre[s][0]), index(centre[s][1]), index(centre[s][2]))].push_back(s);

  for (std::size_t k = 0; k < slaves.size(); ++k) {
    const auto p = point(slaves[k]);
    const double ts = sst > 0.0 ? sst : slave_thickness[k];
    const std::int64_t ci = index(p[0]), cj = index(p[1]), ck = index(p[2]);
    double best = 0.0;
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t dk = -1; dk <= 1; ++dk) {
          const auto it = grid.find(cell_key(ci + di, cj + dj, ck + dk));
          if (it == grid.end())
            continue;
          for (const std::size_t s : it->second) {
            const Index* q = &segments[4 * s];
            if (std::find(q, q + 4, slaves[k]) != q + 4)
              continue;
            std::array<std::array<double, 3>, 4> c{};
            for (std::size_t a = 0; a < 4; ++a)
              c[a] = point(q[a]);
            const contact::SegmentPoint sp =
                q[2] == q[3]
                    ? contact::project_triangle(p.data(), c[0].data(), c[1].data(), c[2].data())
                    : [&] {
                        const double* corners[4] = {c[0].data(), c[1].data(), c[2].data(),
                                                    c[3].data()};
                        return contact::project_quad(p.data(), corners);
                      }();
            if (sp.degenerate || sp.outside > kOutside)
              continue;
            const double reach =
                std::max(0.6 * (ts + (mst > 0.0 ? mst : segment_thickness[s])), 0.05 * diagonal[s]);
            const double d = std::abs(sp.distance);
            if (d > reach)
              continue;
            // The nearest; between equals (a node on a shared edge), the lower segment index.
            if (found[k].segment < 0 || d < best ||
                (d == best && static_cast<long>(s) < found[k].segment)) {
              best = d;
              found[k].segment = static_cast<long>(s);
              found[k].distance = d;
              for (std::size_t a = 0; a < 4; ++a)
                found[k].weight[a] = sp.shape[a];
            }
          }
        }
  }
  return found;
}

void drop_conflicting_slaves(const model::ModelDesc& desc, core::Model& m,
                             std::vector<keyword::Diagnostic>& warnings) {
  if (m.tied.empty())
    return;
  const std::vector<unsigned char> role = node_roles(m);
  std::vector<unsigned char> master(m.node_count(), 0), held(m.node_count(), 0);
  for (const core::TiedInterface& t : m.tied)
    for (const auto& q : t.segment)
      for (Index v : q)
        master[static_cast<std::size_t>(v)] = 1;
  std::vector<const model::ContactDesc*> decks;
  for (const model::ContactDesc& c : desc.contacts)
    if (model::is_tied(c.kind))
      decks.push_back(&c);
  for (std::size_t k = 0; k < m.tied.size() && k < decks.size(); ++k) {
    core::TiedInterface& t = m.tied[k];
    std::size_t moved = 0, chained = 0, twice = 0;
    core::TiedInterface kept = t;
    kept.slaves.clear();
    kept.segment.clear();
    kept.weight.clear();
    for (std::size_t s = 0; s < t.slaves.size(); ++s) {
      const auto i = static_cast<std::size_t>(t.slaves[s]);
      if (role[i] == kRigidNode || role[i] == kHeldNode) {
        ++moved;
      } else if (master[i]) {
        ++chained;
      } else if (held[i]) {
        ++twice;
      } else {
        held[i] = 1;
        kept.slaves.push_back(t.slaves[s]);
        kept.segment.push_back(t.segment[s]);
        kept.weight.push_back(t.weight[s]);
      }
    }
    const model::ContactDesc& c = *decks[k];
    const std::string name = c.id != 0 ? fmt::format("tied contact {}", c.id) : "a tied contact";
    const auto warn = [&](std::size_t count, const char* why) {
      if (count > 0)
        warnings.push_back(
            {c.card1, c.keyword, "SSID",
             fmt::format("{}: {} slave nodes {}: they are not tied", name, count, why)});
    };
    warn(moved, "are moved by a rigid body, a constraint or a prescribed motion");
    warn(chained, "are nodes of a tie's master segments (a tie does not hold a tie)");
    warn(twice, "are tied by an earlier tied contact already");
    t = std::move(kept);
  }
}

}  // namespace plyform::setup
