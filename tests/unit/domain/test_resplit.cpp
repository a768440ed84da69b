// A running model split again with target shares (domain/resplit.hpp), the re-balancing of a run
// over several ranks: each domain takes its share of the estimated cost (within METIS's
// tolerance), every node's owner is the lowest domain whose elements touch it (recomputed here
// from the elements), equal shares split as the first split does, and a split is the same every
// time (every rank computes it on its own and all must agree).

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <variant>
#include <vector>

#include "layered_models.hpp"
#include "plyform/domain/decomposition.hpp"
#include "plyform/domain/resplit.hpp"

namespace plyform::domain {
namespace {

// Per node, the lowest domain among the elements that touch it, from the elements' domains.
std::vector<int> owners_from(const core::Model& m, const Decomposition& d,
                             const std::vector<int>& part) {
  std::vector<int> owner(m.node_count(), -1);
  for (std::size_t e = 0; e < d.elements.size(); ++e) {
    const ElementRef& x = d.elements[e];
    const auto& c = x.shell ? m.shell_blocks[static_cast<std::size_t>(x.block)].connectivity
                            : m.solid_blocks[static_cast<std::size_t>(x.block)].connectivity;
    const std::size_t k = x.shell ? 4 : 8;
    for (std::size_t j = 0; j < k; ++j) {
      const auto n = static_cast<std::size_t>(c[k * static_cast<std::size_t>(x.element) + j]);
      owner[n] = owner[n] < 0 ? part[e] : std::min(owner[n], part[e]);
    }
  }
  return owner;
}

TEST(Resplit, EachDomainTakesItsShareOfTheCost) {
  const core::Model m = test::layered_blank({});
  const Resplitter splitter(m);
  for (const std::vector<double>& shares :
       {std::vector<double>{0.3, 0.7}, std::vector<double>{0.5, 0.25, 0.25},
        std::vector<double>{0.1, 0.2, 0.3, 0.4}}) {
    const OwnerSplit s = splitter.split(shares);
    ASSERT_TRUE(s.error.empty()) << s.error;
    ASSERT_EQ(s.cost.size(), shares.size());
    const double total = std::accumulate(s.cost.begin(), s.cost.end(), 0.0);
    for (std::size_t d = 0; d < shares.size(); ++d) {
      // METIS's default tolerance is 3 % over the target; an element's cost is the grain.
      EXPECT_LE(s.cost[d] / total, shares[d] * 1.03 + 0.01) << "domain " << d;
      EXPECT_GE(s.cost[d] / total, shares[d] * 0.9 - 0.01) << "domain " << d;
    }
  }
}

TEST(Resplit, OwnersAreTheLowestDomainTouchingEachNode) {
  const core::Model m = test::layered_blank({});
  const Decomposition first = decompose(m, 3).decomposition;
  const Resplitter splitter(m);
  const std::vector<double> shares{0.2, 0.5, 0.3};
  const OwnerSplit s = splitter.split(shares);
  ASSERT_TRUE(s.error.empty()) << s.error;
  ASSERT_EQ(s.element_domain.size(), first.elements.size());
  EXPECT_EQ(s.node_owner, owners_from(m, first, s.element_domain));
  // Every rank computes the split on its own: the same shares give the same split.
  const OwnerSplit again = splitter.split(shares);
  EXPECT_EQ(s.element_domain, again.element_domain);
  EXPECT_EQ(s.cost, again.cost);
  // Every node a deformable element touches has an owner in range; the others (the rigid tool's)
  // none, as in the first split.
  ASSERT_EQ(s.node_owner.size(), m.node_count());
  for (std::size_t n = 0; n < m.node_count(); ++n) {
    EXPECT_EQ(s.node_owner[n] < 0, first.node_owner[n] < 0) << "node " << n;
    EXPECT_LT(s.node_owner[n], 3);
  }
}

TEST(Resplit, EqualSharesSplitAsTheFirstSplit) {
  const core::Model m = test::layered_blank({});
  const Decomposition first = decompose(m, 4).decomposition;
  const OwnerSplit s = Resplitter(m).split(std::vector<double>(4, 0.25));
  ASSERT_TRUE(s.error.empty()) << s.error;
  EXPECT_EQ(s.node_owner, owners_from(m, first, first.element_domain));
  EXPECT_EQ(s.node_owner, first.node_owner);
  for (std::size_t d = 0; d < 4; ++d)
    EXPECT_NEAR(s.cost[d], first.summary[d].cost, 1e-9 * first.summary[d].cost);
}

TEST(Resplit, RefusesSharesItCannotHonour) {
  const core::Model m = test::layered_blank({});
  const Resplitter splitter(m);
  EXPECT_NE(splitter.split(std::vector<double>{0.5, 0.0}).error.find("positive"),
            std::string::npos);
  EXPECT_NE(splitter.split(std::vector<double>(m.deformable_element_count() + 1, 1.0))
                .error.find("at least one"),
            std::string::npos);
}

}  // namespace
}  // namespace plyform::domain
