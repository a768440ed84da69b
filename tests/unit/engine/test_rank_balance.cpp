// When a run over several ranks splits its model again (rank_balance.hpp), look by look: a split
// within the seconds' noise stays; an imbalance is answered only once the waiting it caused pays
// for a split twice over, with shares that equalise the ranks' seconds when each rank's speed
// (cost per second) holds; a rank that measured nothing or was slowed for a moment is not
// starved; `every` splits on schedule and -1 never.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "rank_balance.hpp"

namespace plyform::engine {
namespace {

// The seconds each rank takes for its cost at its speed (cost per second).
std::vector<double> seconds_for(const std::vector<double>& cost, const std::vector<double>& speed) {
  std::vector<double> s(cost.size());
  for (std::size_t r = 0; r < cost.size(); ++r)
    s[r] = cost[r] / speed[r];
  return s;
}

TEST(RankBalance, ABalancedRunKeepsItsSplit) {
  RankBalance b({50.0, 50.0}, 0.001, 0);
  for (long c = 50; c <= 5000; c += 50)
    EXPECT_TRUE(b.look(std::vector<double>{1.0, 1.02}, c).empty());
  EXPECT_EQ(b.splits(), 0);
  EXPECT_NEAR(b.last_imbalance(), 1.02 / 1.01, 1e-12);
}

TEST(RankBalance, SharesGoAsTheSpeedsAndEqualiseTheSeconds) {
  // Rank 1 runs at 0.8 of rank 0's speed (a slower core, or costlier elements than estimated).
  const std::vector<double> speed{100.0, 80.0};
  RankBalance b({50.0, 50.0}, 0.01, 0);
  const std::vector<double> shares = b.look(seconds_for({50.0, 50.0}, speed), 50);
  ASSERT_EQ(shares.size(), 2u);
  EXPECT_NEAR(shares[0], 100.0 / 180.0, 1e-12);
  EXPECT_NEAR(shares[1], 80.0 / 180.0, 1e-12);
  // With the new split's costs, the ranks' seconds are equal and the next looks keep it.
  const std::vector<double> cost{100.0 * shares[0], 100.0 * shares[1]};
  b.split_done(cost, 50);
  EXPECT_EQ(b.splits(), 1);
  const std::vector<double> after = seconds_for(cost, speed);
  EXPECT_NEAR(after[0], after[1], 1e-12);
  EXPECT_TRUE(b.look(after, 100).empty());
  EXPECT_NEAR(b.shares()[0], shares[0], 1e-12);
}

TEST(RankBalance, WaitsUntilTheWaitingPaysForTheSplit) {
  // Each look the ranks' seconds differ by 10 %: 0.05 s of waiting per look against a split of
  // 1 s, paid twice over after 40 looks.
  RankBalance b({50.0, 50.0}, 1.0, 0);
  const std::vector<double> look{1.0, 1.1};  // mean 1.05: 0.05 s of waiting
  int looks = 0;
  std::vector<double> shares;
  while (shares.empty() && looks < 1000) {
    ++looks;
    shares = b.look(look, 50L * looks);
  }
  EXPECT_EQ(looks, 40);
  ASSERT_EQ(shares.size(), 2u);
  EXPECT_NEAR(shares[0], 1.1 / 2.1, 1e-12);  // speeds 50/1.0 and 50/1.1
}

TEST(RankBalance, NoRankIsStarved) {
  // Rank 1 measured nothing: it counts at the fastest speed. Rank 2 was 100 times slower (another
  // process on its core): it keeps a tenth of an even share.
  RankBalance b({10.0, 10.0, 10.0}, 0.0, 0);
  const std::vector<double> shares = b.look(std::vector<double>{1.0, 0.0, 100.0}, 50);
  ASSERT_EQ(shares.size(), 3u);
  EXPECT_NEAR(std::accumulate(shares.begin(), shares.end(), 0.0), 1.0, 1e-12);
  EXPECT_NEAR(shares[0], shares[1], 1e-12);
  EXPECT_NEAR(shares[2], 0.1 / 3.0, 1e-12);
}

TEST(RankBalance, OnScheduleOrNever) {
  RankBalance every({50.0, 50.0}, 100.0, 120);
  EXPECT_TRUE(every.look(std::vector<double>{1.0, 1.0}, 50).empty());
  EXPECT_TRUE(every.look(std::vector<double>{1.0, 1.0}, 100).empty());
  const std::vector<double> shares = every.look(std::vector<double>{1.0, 1.0}, 150);
  ASSERT_EQ(shares.size(), 2u);  // however balanced and however dear
  EXPECT_NEAR(shares[0], 0.5, 1e-12);
  every.split_done({50.0, 50.0}, 150);
  EXPECT_TRUE(every.look(std::vector<double>{1.0, 1.0}, 200).empty());
  EXPECT_FALSE(every.look(std::vector<double>{1.0, 1.0}, 300).empty());

  RankBalance never({50.0, 50.0}, 0.0, -1);
  for (long c = 50; c <= 500; c += 50)
    EXPECT_TRUE(never.look(std::vector<double>{1.0, 5.0}, c).empty());
}

}  // namespace
}  // namespace plyform::engine
