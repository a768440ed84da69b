// The split of a model into domains (domain/decomposition.hpp), checked against what the split
// must guarantee, recomputed here by brute force: every deformable element owned once, every
// shared node known to all the domains that touch it, every master segment within a slave node's
// search box available to the node's domain, the stacked layers of a sandwich kept together, and
// the cost balanced when the elements' costs differ.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <variant>

#include "layered_models.hpp"
#include "plyform/domain/decomposition.hpp"

namespace plyform::domain {
namespace {

std::vector<core::Index> nodes_of(const core::Model& m, const ElementRef& e) {
  const auto& c = e.shell ? m.shell_blocks[static_cast<std::size_t>(e.block)].connectivity
                          : m.solid_blocks[static_cast<std::size_t>(e.block)].connectivity;
  const std::size_t k = e.shell ? 4 : 8;
  return {c.begin() + static_cast<std::ptrdiff_t>(k * static_cast<std::size_t>(e.element)),
          c.begin() + static_cast<std::ptrdiff_t>(k * static_cast<std::size_t>(e.element) + k)};
}

Decomposition split(const core::Model& m, int domains) {
  DecomposeResult r = decompose(m, domains);
  EXPECT_TRUE(r.error.empty()) << r.error;
  return std::move(r.decomposition);
}

class LayeredBlankSplit : public ::testing::TestWithParam<int> {
 protected:
  core::Model model = test::layered_blank({});
};

TEST_P(LayeredBlankSplit, EveryDeformableElementIsOwnedOnce) {
  const int domains = GetParam();
  const Decomposition d = split(model, domains);
  std::set<std::pair<core::Index, core::Index>> seen;
  std::size_t deformable = 0;
  for (std::size_t b = 0; b < model.shell_blocks.size(); ++b) {
    const bool rigid = std::holds_alternative<core::RigidMaterial>(
        model.materials[static_cast<std::size_t>(model.shell_blocks[b].material)]);
    deformable += rigid ? 0 : model.shell_blocks[b].size();
  }
  ASSERT_EQ(d.elements.size(), deformable);
  ASSERT_EQ(d.element_domain.size(), deformable);
  std::vector<std::size_t> count(static_cast<std::size_t>(domains), 0);
  for (std::size_t e = 0; e < d.elements.size(); ++e) {
    EXPECT_TRUE(d.elements[e].shell);
    EXPECT_TRUE(seen.insert({d.elements[e].block, d.elements[e].element}).second);
    ASSERT_GE(d.element_domain[e], 0);
    ASSERT_LT(d.element_domain[e], domains);
    ++count[static_cast<std::size_t>(d.element_domain[e])];
  }
  for (int a = 0; a < domains; ++a) {
    EXPECT_GT(count[static_cast<std::size_t>(a)], 0u) << "domain " << a << " is empty";
    EXPECT_EQ(d.summary[static_cast<std::size_t>(a)].elements, count[static_cast<std::size_t>(a)]);
  }
  // The rigid tool's block is not split: it lives on every rank.
  for (const ElementRef& e : d.elements)
    EXPECT_NE(e.block, 3);
}

TEST_P(LayeredBlankSplit, EverySharedNodeIsKnownToAllTheDomainsThatTouchIt) {
  const int domains = GetParam();
  const Decomposition d = split(model, domains);
  std::vector<std::set<int>> touching(model.node_count());
  for (std::size_t e = 0; e < d.elements.size(); ++e)
    for (core::Index n : nodes_of(model, d.elements[e]))
      touching[static_cast<std::size_t>(n)].insert(d.element_domain[e]);
  std::vector<std::size_t> shared(static_cast<std::size_t>(domains), 0);
  for (std::size_t n = 0; n < model.node_count(); ++n) {
    const std::vector<int> listed(
        d.node_domains.begin() + static_cast<std::ptrdiff_t>(d.node_domain_start[n]),
        d.node_domains.begin() + static_cast<std::ptrdiff_t>(d.node_domain_start[n + 1]));
    EXPECT_EQ(listed, std::vector<int>(touching[n].begin(), touching[n].end())) << "node " << n;
    EXPECT_EQ(d.node_owner[n], touching[n].empty() ? -1 : *touching[n].begin()) << "node " << n;
    if (touching[n].size() > 1)
      for (int a : touching[n])
        ++shared[static_cast<std::size_t>(a)];
  }
  for (int a = 0; a < domains; ++a)
    EXPECT_EQ(d.summary[static_cast<std::size_t>(a)].shared_nodes,
              shared[static_cast<std::size_t>(a)]);
  if (domains > 1) {
    const std::size_t total = std::accumulate(shared.begin(), shared.end(), std::size_t{0});
    EXPECT_GT(total, 0u) << "domains of one blank share nodes";
  }
}

TEST_P(LayeredBlankSplit, GhostSegmentsCoverEverySlaveNodesSearchBox) {
  const int domains = GetParam();
  const Decomposition d = split(model, domains);
  std::size_t checked = 0, across = 0;
  for (std::size_t c = 0; c < model.contacts.size(); ++c) {
    const core::ContactPass& pass = model.contacts[c].passes[0];
    const PassHalo& h = d.contact[c][0];
    const std::vector<double> reach = segment_reach(model, pass);
    for (std::size_t i = 0; i < pass.slave_count(); ++i) {
      const auto n = static_cast<std::size_t>(pass.slave_nodes[i]);
      const int owner = h.slave_owner[i];
      ASSERT_EQ(owner, d.node_owner[n]);
      const std::vector<core::Index> ghosts(
          h.ghost.begin() +
              static_cast<std::ptrdiff_t>(h.ghost_start[static_cast<std::size_t>(owner)]),
          h.ghost.begin() +
              static_cast<std::ptrdiff_t>(h.ghost_start[static_cast<std::size_t>(owner) + 1]));
      for (std::size_t s = 0; s < pass.segment_count(); ++s) {
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
        for (int k = 0; k < 4; ++k) {
          const auto q =
              static_cast<std::size_t>(pass.segments[4 * s + static_cast<std::size_t>(k)]);
          const double p[3] = {model.x0[q], model.y0[q], model.z0[q]};
          for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p[a] - reach[s]);
            hi[a] = std::max(hi[a], p[a] + reach[s]);
          }
        }
        const double x[3] = {model.x0[n], model.y0[n], model.z0[n]};
        bool inside = true;
        for (int a = 0; a < 3; ++a)
          inside = inside && x[a] >= lo[a] && x[a] <= hi[a];
        if (!inside)
          continue;
        ++checked;
        const int so = h.segment_owner[s];
        if (so < 0 || so == owner)
          continue;  // a rigid body's segment (on every rank) or the domain's own
        ++across;
        EXPECT_TRUE(std::binary_search(ghosts.begin(), ghosts.end(), static_cast<core::Index>(s)))
            << "interface " << c << ": slave node " << n << " of domain " << owner
            << " reaches segment " << s << " of domain " << so << ", not among its ghosts";
      }
    }
  }
  EXPECT_GT(checked, 0u);
  if (domains > 1) {
    EXPECT_GT(across, 0u) << "some slave nodes reach across a domain boundary";
  }
}

TEST_P(LayeredBlankSplit, StackedLayersFallIntoTheSameDomain) {
  const int domains = GetParam();
  const Decomposition d = split(model, domains);
  // A split in plan view cuts the interface edges only along the domains' boundary lines: a
  // few per cent of them at these sizes (24 x 24 elements a layer); a split through the stack
  // would cut whole areas.
  ASSERT_GT(d.interface_edges, 1000u);
  EXPECT_LE(static_cast<double>(d.interface_edges_cut),
            0.05 * static_cast<double>(d.interface_edges));
  // The same from the geometry: a skin element and the core element under its centre share a
  // domain for nearly all skin elements.
  std::vector<int> core_domain(model.shell_blocks[1].size(), -1);
  for (std::size_t e = 0; e < d.elements.size(); ++e)
    if (d.elements[e].block == 1) {
      core_domain[static_cast<std::size_t>(d.elements[e].element)] = d.element_domain[e];
    }
  const test::LayeredBlankOptions o;
  std::size_t same = 0, skins = 0;
  for (std::size_t e = 0; e < d.elements.size(); ++e) {
    if (d.elements[e].block == 1)
      continue;
    const auto k = static_cast<std::size_t>(d.elements[e].element);
    const double cx = (static_cast<double>(k % static_cast<std::size_t>(o.nx)) + 0.5) * o.size;
    const double cy = (static_cast<double>(k / static_cast<std::size_t>(o.nx)) + 0.5) * o.size;
    const auto ci = std::clamp(static_cast<int>((cx - o.size / 3.0) / o.size), 0, o.nx - 2);
    const auto cj = std::clamp(static_cast<int>((cy - o.size / 3.0) / o.size), 0, o.ny - 2);
    ++skins;
    same += core_domain[static_cast<std::size_t>(cj * (o.nx - 1) + ci)] == d.element_domain[e];
  }
  EXPECT_GE(static_cast<double>(same), 0.9 * static_cast<double>(skins));
}

TEST_P(LayeredBlankSplit, IsBalancedAndDeterministic) {
  const int domains = GetParam();
  const Decomposition a = split(model, domains);
  const Decomposition b = split(model, domains);
  EXPECT_EQ(a.element_domain, b.element_domain);
  EXPECT_LE(a.imbalance, 1.06);
  double total = 0.0;
  for (double c : a.element_cost)
    total += c;
  double summed = 0.0;
  for (const DomainSummary& s : a.summary)
    summed += s.cost;
  EXPECT_NEAR(summed, total, 1e-9 * total);
}

INSTANTIATE_TEST_SUITE_P(Domains, LayeredBlankSplit, ::testing::Values(1, 2, 3, 4, 8));

TEST(Decomposition, BalancesCostNotElementCount) {
  // Two plates of 24 x 24 elements apart: one Belytschko-Tsay, one ELFORM 16 (2.65 times the
  // cost). Shared by cost, one domain takes the BT plate and 0.31 of the other: 1.31 N elements
  // against 0.69 N.
  core::Model m;
  m.materials.push_back(core::PiecewiseLinearPlasticity{});
  for (int k = 0; k < 2; ++k) {
    core::ShellBlock b;
    b.formulation =
        k == 0 ? core::ShellFormulation::belytschko_tsay : core::ShellFormulation::fully_integrated;
    b.part = k;
    test::add_layer_mesh(m, b, 24, 24, 1.0, 0.0, 100.0 * k, 0.0, 1.0);
    m.parts.push_back(core::Part{k + 1, "plate", 0});
    m.shell_blocks.push_back(std::move(b));
  }
  const Decomposition d = split(m, 2);
  EXPECT_LE(d.imbalance, 1.06);
  EXPECT_NEAR(shell_cost(m, m.shell_blocks[1]) / shell_cost(m, m.shell_blocks[0]), 2.65, 1e-12);
  const double big = static_cast<double>(std::max(d.summary[0].elements, d.summary[1].elements));
  const double small = static_cast<double>(std::min(d.summary[0].elements, d.summary[1].elements));
  EXPECT_NEAR(big / small, 1.31 / 0.69, 0.15);
}

TEST(Decomposition, RefusesCountsItCannotHonour) {
  const core::Model m = test::layered_blank({});
  EXPECT_NE(decompose(m, 0).error.find("1 or more"), std::string::npos);
  const std::size_t elements = m.deformable_element_count();
  const DecomposeResult r = decompose(m, static_cast<int>(elements) + 1);
  EXPECT_NE(r.error.find("at least one"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace plyform::domain
