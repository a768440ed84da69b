#pragma once
// When a run over several ranks splits its model again (docs/parallel.md, "Re-balancing").
//
// The first split weighs each element and contact slave node by a fixed estimate of its cost.
// What a rank's share really costs moves during a run (plastic zones, the contact zone under a
// tool), and the cores themselves may differ in speed; the ranks wait at every exchange for the
// slowest. So every few cycles the ranks compare the seconds each spent on its share of the work
// (its element pieces and its contact slave nodes), and when the time the others spent waiting
// since the last split would pay for a new one twice over, the model is split again with each
// rank's target share of the estimated cost in proportion to the speed it showed (its share of
// the cost over its seconds). The results do not depend on the split (rank_exchange.hpp), so a
// new one changes nothing in the files, only who computes what.
//
// Pure policy: the engine measures, exchanges the seconds and applies the split.

#include <span>
#include <vector>

namespace plyform::engine {

class RankBalance {
 public:
  /// Cycles between two looks (a look is one small exchange of two numbers per rank).
  static constexpr long kLookCycles = 50;
  /// Below this imbalance (the slowest rank's seconds over the mean) the split is left as it is:
  /// the seconds' noise on a shared machine.
  static constexpr double kNoise = 1.03;
  /// A new split must be paid for this many times by the waiting it removes.
  static constexpr double kPayback = 2.0;

  /// `cost`: each rank's share of the first split's estimated cost; `price`: the seconds a split
  /// takes (the first one's until a re-split is measured); `every`: 0 splits when it pays, N > 0
  /// at the first look N cycles or more after the last split whatever the imbalance (studies and
  /// tests), -1 never.
  RankBalance(std::vector<double> cost, double price, long every);

  /// At a look: every rank's seconds of its share since the last look (the same on every rank).
  /// Returns each rank's target share of the cost when the model should be split again, else
  /// an empty vector.
  [[nodiscard]] std::vector<double> look(std::span<const double> seconds, long cycle);
  /// The new split's cost per rank, at `cycle`.
  void split_done(std::vector<double> cost, long cycle);
  /// What the last split took (the largest over the ranks).
  void set_price(double price) { price_ = price; }

  [[nodiscard]] int splits() const { return splits_; }
  /// Each rank's share of the estimated cost in the last split (empty: none yet).
  [[nodiscard]] const std::vector<double>& shares() const { return shares_; }
  /// The imbalance the first and the last look found with enough seconds measured (0: none).
  [[nodiscard]] double first_imbalance() const { return first_imbalance_; }
  [[nodiscard]] double last_imbalance() const { return last_imbalance_; }

 private:
  std::vector<double> cost_, window_, shares_;
  double price_;
  long every_;
  long split_cycle_ = 0;
  int splits_ = 0;
  double first_imbalance_ = 0.0, last_imbalance_ = 0.0;
};

}  // namespace plyform::engine
