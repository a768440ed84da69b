#pragma once
// The element loop's items shared out over the threads of one process (simulation.cpp). Per
// phase each thread takes one contiguous run of the phase's items, the same run every cycle, so
// that an element's state and its nodes stay in that thread's core's caches (items handed out
// as threads came free moved them between cores every cycle, and on this project's machine,
// whose cores pass cache lines slowly, the 100 x 100 BT plate ran slower on two threads than on
// one). The runs are cut where the items' measured seconds balance, not where their counts do:
// plastic or hot zones, a woven core beside steel skins, a colour's short last item make items
// of one phase differ in cost by several times, and the threads wait at the phase's end for the
// slowest (the hot deep drawing on two threads: one thread busy 3.35 s, the other 2.32 s, with
// the runs cut by count). Which thread computes an item does not change a bit: the items of a
// phase share no node, and the books are summed in item order after the loop.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace plyform::engine {

/// Cuts items 0 .. n - 1 into `parts` contiguous runs [cuts[k], cuts[k + 1]) of about equal
/// total cost (each cut where the running sum comes closest to its share); by count where the
/// costs sum to zero (nothing measured yet). Writes parts + 1 entries: cuts[0] = 0,
/// cuts[parts] = n, never decreasing.
inline void balanced_cuts(const double* cost, std::size_t n, std::size_t parts, std::size_t* cuts) {
  std::fill(cuts, cuts + parts + 1, n);
  cuts[0] = 0;
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    total += cost[i];
  if (!(total > 0.0)) {
    for (std::size_t k = 1; k < parts; ++k)
      cuts[k] = n * k / parts;
    return;
  }
  std::size_t i = 0;
  double before = 0.0;  // the cost of items 0 .. i - 1
  for (std::size_t k = 1; k < parts; ++k) {
    const double target = total * static_cast<double>(k) / static_cast<double>(parts);
    while (i < n && before + cost[i] <= target) {
      before += cost[i];
      ++i;
    }
    // Item i straddles the target: it goes to the run whose sum it leaves closer to its share.
    if (i < n && before + cost[i] - target < target - before) {
      before += cost[i];
      ++i;
    }
    cuts[k] = i;
  }
}

/// Per phase, each thread's run of items; cut anew from the seconds the items took every
/// kEvery cycles.
class ItemShares {
 public:
  static constexpr long kEvery = 64;

  /// Item counts per phase as offsets (phase p's items are offset[p] .. offset[p + 1] - 1 of
  /// the run's item arrays); runs cut by count.
  void reset(const std::vector<std::size_t>& offset, std::size_t threads) {
    offset_ = offset;
    threads_ = threads;
    cuts_.assign((offset.size() - 1) * (threads + 1), 0);
    const std::vector<double> none(offset.empty() ? 0 : offset.back(), 0.0);
    cut(none.data());
    seconds_at_cut_.clear();
    cycles_ = 0;
  }

  [[nodiscard]] std::size_t threads() const { return threads_; }

  /// Thread t's items of phase p: [first, last) within the phase.
  [[nodiscard]] std::size_t first(std::size_t p, std::size_t t) const {
    return cuts_[p * (threads_ + 1) + t];
  }
  [[nodiscard]] std::size_t last(std::size_t p, std::size_t t) const {
    return cuts_[p * (threads_ + 1) + t + 1];
  }

  /// After a cycle's loop, with every item's seconds so far: every kEvery cycles the runs are
  /// cut by the seconds since the last cut.
  void update(const std::vector<double>& item_seconds) {
    if (seconds_at_cut_.size() != item_seconds.size()) {
      seconds_at_cut_ = item_seconds;
      cycles_ = 0;
      return;
    }
    if (++cycles_ < kEvery)
      return;
    window_.resize(item_seconds.size());
    for (std::size_t i = 0; i < window_.size(); ++i)
      window_[i] = std::max(0.0, item_seconds[i] - seconds_at_cut_[i]);
    cut(window_.data());
    seconds_at_cut_ = item_seconds;
    cycles_ = 0;
  }

 private:
  void cut(const double* cost) {
    for (std::size_t p = 0; p + 1 < offset_.size(); ++p)
      balanced_cuts(cost + offset_[p], offset_[p + 1] - offset_[p], threads_,
                    &cuts_[p * (threads_ + 1)]);
  }

  std::vector<std::size_t> offset_;
  std::size_t threads_ = 0;
  std::vector<std::size_t> cuts_;  // per phase, threads_ + 1 cut points
  std::vector<double> seconds_at_cut_, window_;
  long cycles_ = 0;
};

}  // namespace plyform::engine
