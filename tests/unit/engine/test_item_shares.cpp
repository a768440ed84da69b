// The element loop's items shared out over the threads (item_shares.hpp): contiguous runs that
// cover every item of a phase once, cut where the measured seconds balance (the largest run's
// cost within one item of the even share), by count before anything is measured, and cut anew
// from the seconds of the last window only.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "item_shares.hpp"

namespace plyform::engine {
namespace {

std::vector<std::size_t> cuts_of(const std::vector<double>& cost, std::size_t parts) {
  std::vector<std::size_t> cuts(parts + 1);
  balanced_cuts(cost.data(), cost.size(), parts, cuts.data());
  return cuts;
}

TEST(ItemShares, RunsBalanceTheMeasuredCost) {
  // A phase whose first third costs five times the rest (a plastic zone, a hot corner).
  std::vector<double> cost(30, 1.0);
  for (std::size_t i = 0; i < 10; ++i)
    cost[i] = 5.0;
  const double total = std::accumulate(cost.begin(), cost.end(), 0.0);
  const double largest = *std::max_element(cost.begin(), cost.end());
  for (const std::size_t parts : {1u, 2u, 3u, 4u}) {
    const std::vector<std::size_t> cuts = cuts_of(cost, parts);
    EXPECT_EQ(cuts.front(), 0u);
    EXPECT_EQ(cuts.back(), cost.size());
    for (std::size_t k = 0; k < parts; ++k) {
      EXPECT_LE(cuts[k], cuts[k + 1]);
      const double run = std::accumulate(cost.begin() + static_cast<long>(cuts[k]),
                                         cost.begin() + static_cast<long>(cuts[k + 1]), 0.0);
      EXPECT_LE(std::abs(run - total / static_cast<double>(parts)), largest) << parts << " " << k;
    }
  }
  // By count the two threads would take 15 items each: 55 against 15.
  EXPECT_EQ(cuts_of(cost, 2)[1], 7u);  // 35 against 35
}

TEST(ItemShares, ByCountBeforeAnythingIsMeasuredAndWithMoreThreadsThanItems) {
  EXPECT_EQ(cuts_of(std::vector<double>(10, 0.0), 3), (std::vector<std::size_t>{0, 3, 6, 10}));
  const std::vector<std::size_t> few = cuts_of({1.0, 1.0}, 4);
  EXPECT_EQ(few.front(), 0u);
  EXPECT_EQ(few.back(), 2u);
  EXPECT_TRUE(std::is_sorted(few.begin(), few.end()));
  EXPECT_EQ(cuts_of({}, 2), (std::vector<std::size_t>{0, 0, 0}));
}

TEST(ItemShares, CutAnewFromTheLastWindowOnly) {
  // Two phases of 4 and 2 items.
  ItemShares shares;
  shares.reset({0, 4, 6}, 2);
  EXPECT_EQ(shares.first(0, 1), 2u);  // by count
  EXPECT_EQ(shares.last(1, 0), 1u);
  // Long ago the first item was the dear one; in the last window the last one is.
  std::vector<double> seconds = {100.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  shares.update(seconds);  // the window starts here
  for (long c = 0; c < ItemShares::kEvery; ++c) {
    seconds[3] += 1.0;
    for (const std::size_t i : {0u, 1u, 2u, 4u, 5u})
      seconds[i] += 0.1;
    shares.update(seconds);
  }
  EXPECT_EQ(shares.first(0, 0), 0u);
  EXPECT_EQ(shares.last(0, 0), 3u);  // items 0-2 against the dear item 3
  EXPECT_EQ(shares.last(0, 1), 4u);
  EXPECT_EQ(shares.last(1, 0), 1u);
}

}  // namespace
}  // namespace plyform::engine
