// The thread governor's decision on a shared machine (thread_governor.hpp), window by window:
// a team that gets its CPU keeps its threads; one that gets about half of it for two windows
// running drops to one thread, probes its full count after the backoff, and backs off twice as
// long each time the sharing persists (up to the cap), and half as long once it is gone.
#include <gtest/gtest.h>

#include "plyform/engine/thread_governor.hpp"

namespace plyform::engine {
namespace {

constexpr double kWindow = 0.25;

TEST(ThreadPolicy, KeepsItsThreadsWhenAlone) {
  ThreadPolicy p(2);
  for (int i = 1; i <= 100; ++i)
    EXPECT_EQ(p.on_window(0.97, i * kWindow), 2);
  EXPECT_EQ(p.reductions(), 0);
}

TEST(ThreadPolicy, OneSlowWindowIsNotSharing) {
  ThreadPolicy p(2);
  for (int i = 1; i <= 40; ++i)  // an output write every fourth window
    EXPECT_EQ(p.on_window(i % 4 == 0 ? 0.3 : 0.95, i * kWindow), 2);
}

TEST(ThreadPolicy, DropsToOneThreadAndProbesWithBackoff) {
  ThreadPolicy p(2);
  double t = 0.0;
  EXPECT_EQ(p.on_window(0.5, t += kWindow), 2);
  EXPECT_EQ(p.on_window(0.5, t += kWindow), 1);  // two windows: shared
  const double dropped = t;
  while (t + kWindow < dropped + ThreadPolicy::kFirstBackoff - 1e-9)
    EXPECT_EQ(p.on_window(1.0, t += kWindow), 1) << t;
  EXPECT_EQ(p.on_window(1.0, t += kWindow), 2);  // the probe
  EXPECT_EQ(p.on_window(0.5, t += kWindow), 2);
  EXPECT_EQ(p.on_window(0.5, t += kWindow), 1);  // still shared: twice the backoff
  const double again = t;
  while (t + kWindow < again + 2.0 * ThreadPolicy::kFirstBackoff - 1e-9)
    EXPECT_EQ(p.on_window(1.0, t += kWindow), 1) << t;
  EXPECT_EQ(p.on_window(1.0, t += kWindow), 2);
  EXPECT_EQ(p.reductions(), 2);
  // Alone again: it keeps its threads.
  for (int i = 0; i < 20; ++i)
    EXPECT_EQ(p.on_window(0.95, t += kWindow), 2);
}

TEST(ThreadPolicy, BackoffIsCapped) {
  ThreadPolicy p(2);
  double t = 0.0, longest = 0.0;
  for (int k = 0; k < 12; ++k) {
    p.on_window(0.5, t += kWindow);
    ASSERT_EQ(p.on_window(0.5, t += kWindow), 1);
    const double dropped = t;
    while (p.on_window(1.0, t += kWindow) == 1) {
    }
    longest = std::max(longest, t - dropped);
  }
  EXPECT_LE(longest, ThreadPolicy::kMaxBackoff + kWindow);
  EXPECT_GE(longest, ThreadPolicy::kMaxBackoff);
}

TEST(ThreadPolicy, OneRequestedThreadIsLeftAlone) {
  ThreadPolicy p(1);
  for (int i = 1; i <= 10; ++i)
    EXPECT_EQ(p.on_window(0.2, i * kWindow), 1);
}

}  // namespace
}  // namespace plyform::engine
