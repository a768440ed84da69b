#include "rank_balance.hpp"

#include <algorithm>
#include <numeric>

namespace plyform::engine {

RankBalance::RankBalance(std::vector<double> cost, double price, long every)
    : cost_(std::move(cost)), window_(cost_.size(), 0.0), price_(price), every_(every) {}

std::vector<double> RankBalance::look(std::span<const double> seconds, long cycle) {
  if (every_ < 0 || seconds.size() != window_.size() || window_.size() < 2)
    return {};
  for (std::size_t r = 0; r < window_.size(); ++r)
    window_[r] += std::max(0.0, seconds[r]);
  const double total = std::accumulate(window_.begin(), window_.end(), 0.0);
  const double mean = total / static_cast<double>(window_.size());
  const double slowest = *std::max_element(window_.begin(), window_.end());
  if (!(mean > 0.0))
    return {};
  const double imbalance = slowest / mean;
  bool split = false;
  if (every_ > 0) {
    split = cycle - split_cycle_ >= every_;
  } else if (imbalance < kNoise) {
    // Balanced: the next look measures afresh.
    last_imbalance_ = imbalance;
    if (first_imbalance_ == 0.0)
      first_imbalance_ = imbalance;
    std::fill(window_.begin(), window_.end(), 0.0);
    return {};
  } else {
    // The seconds the ranks spent waiting, on average, since the window began: (slowest - mean).
    // Until they would pay for a split, the window grows (and its imbalance firms up).
    split = slowest - mean >= kPayback * price_;
  }
  if (!split)
    return {};
  last_imbalance_ = imbalance;
  if (first_imbalance_ == 0.0)
    first_imbalance_ = imbalance;
  // Each rank's speed: its cost over its seconds; a rank that measured nothing is taken at the
  // fastest speed measured. The new shares go as the speeds.
  std::vector<double> speed(window_.size(), 0.0);
  double fastest = 0.0;
  for (std::size_t r = 0; r < window_.size(); ++r) {
    if (window_[r] > 0.0)
      speed[r] = cost_[r] / window_[r];
    fastest = std::max(fastest, speed[r]);
  }
  if (!(fastest > 0.0))
    return {};
  for (double& s : speed)
    s = s > 0.0 ? s : fastest;
  // No rank below a tenth of an even share: a rank slowed for a moment by another process must
  // not be starved of work. The floored ranks keep the floor, the others share the rest in
  // proportion to their speeds (again while that floors another one).
  const double floor = 0.1 / static_cast<double>(speed.size());
  std::vector<double> shares(speed.size(), 0.0);
  std::vector<char> floored(speed.size(), 0);
  for (std::size_t pass = 0; pass < speed.size(); ++pass) {
    double free_speed = 0.0, left = 1.0;
    for (std::size_t r = 0; r < speed.size(); ++r) {
      if (floored[r] != 0)
        left -= floor;
      else
        free_speed += speed[r];
    }
    bool more = false;
    for (std::size_t r = 0; r < speed.size(); ++r) {
      shares[r] = floored[r] != 0 ? floor : left * speed[r] / free_speed;
      if (floored[r] == 0 && shares[r] < floor) {
        floored[r] = 1;
        more = true;
      }
    }
    if (!more)
      break;
  }
  std::fill(window_.begin(), window_.end(), 0.0);
  return shares;
}

void RankBalance::split_done(std::vector<double> cost, long cycle) {
  const double total = std::accumulate(cost.begin(), cost.end(), 0.0);
  shares_.assign(cost.size(), 0.0);
  for (std::size_t r = 0; r < cost.size(); ++r)
    shares_[r] = total > 0.0 ? cost[r] / total : 0.0;
  cost_ = std::move(cost);
  split_cycle_ = cycle;
  ++splits_;
}

}  // namespace plyform::engine
