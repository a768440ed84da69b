// The run's verdict on its energy books (books_verdict.hpp), driven with series of books against
// the rules of docs/energy.md: the ratio's scale is the most energy that entered; the ratio
// counts against the results only when out of 1 +- 0.1 at two judgements in a row (or at the
// last); hourglass energy above 10 % of the largest internal energy and a contact that gave
// more than 1 % of the energy that entered count against them, unless the whole run outgrew
// them; the stop band counts the checks in a row outside it.
#include <gtest/gtest.h>

#include <vector>

#include "books_verdict.hpp"

namespace plyform::engine {
namespace {

Energies books(double time, double kinetic, double internal, double hourglass = 0.0,
               double contact = 0.0) {
  Energies e;
  e.time = time;
  e.kinetic = kinetic;
  e.internal = internal;
  e.hourglass = hourglass;
  e.contact = contact;
  e.total = kinetic + internal + hourglass + contact;
  return e;
}

bool has_reason(const RunResult& r, const std::string& start) {
  for (const Distrust& d : r.distrust)
    if (d.reason.rfind(start, 0) == 0)
      return true;
  return false;
}

TEST(BooksVerdict, TheRatioIsMeasuredAgainstTheMostEnergyThatEntered) {
  BooksVerdict v;
  v.start(0.0, false);
  // 10 entered and is held; then it is taken back out and 1e-3 is left over.
  Energies e = books(1.0, 4.0, 6.0);
  v.measure(e, 10.0);
  EXPECT_DOUBLE_EQ(e.ratio, 1.0);
  e = books(2.0, 0.0, 1e-3);
  v.measure(e, 0.0);
  EXPECT_DOUBLE_EQ(e.ratio, 1.0 + 1e-4) << "the error over the 10 that entered, not over 0";
}

TEST(BooksVerdict, OneJudgementOutOfBalanceIsAJumpTwoInARowBreakTheBooks) {
  BooksVerdict v;
  v.start(1.0, false);
  RunResult r;
  Energies e = books(1.0, 1.3, 0.0);
  v.measure(e, 1.0);
  v.judge(e, 1.0, {}, {}, false, r);
  EXPECT_TRUE(r.distrust.empty());
  e = books(2.0, 1.0, 0.0);
  v.measure(e, 1.0);
  v.judge(e, 1.0, {}, {}, false, r);
  EXPECT_TRUE(r.distrust.empty()) << "back in the band";
  for (const double t : {3.0, 4.0}) {
    e = books(t, 1.2, 0.0);
    v.measure(e, 1.0);
    v.judge(e, 1.0, {}, {}, false, r);
  }
  ASSERT_EQ(r.distrust.size(), 1u);
  EXPECT_TRUE(has_reason(r, "energy ratio 1.2"));
  EXPECT_DOUBLE_EQ(r.distrust[0].time, 3.0) << "from the first of the two";
  // At the end of a run one judgement suffices.
  BooksVerdict end;
  end.start(1.0, false);
  RunResult r_end;
  e = books(1.0, 0.85, 0.0);
  end.measure(e, 1.0);
  end.judge(e, 1.0, {}, {}, true, r_end);
  EXPECT_EQ(r_end.distrust.size(), 1u);
}

TEST(BooksVerdict, HourglassEnergyIsJudgedAgainstTheWholeRunsLargestInternalEnergy) {
  const HourglassLeader leader{.part = 7, .hourglass = 0.3, .internal = 1.0};
  // Early, 0.3 of hourglass against an internal energy of 1: warned, naming part 7.
  BooksVerdict v;
  v.start(0.0, false);
  RunResult r;
  Energies e = books(1.0, 0.0, 1.0, 0.3);
  v.measure(e, 1.3);
  v.judge(e, 0.0, leader, {}, false, r);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("most in part 7"), std::string::npos) << r.warnings[0];
  EXPECT_TRUE(has_reason(r, "hourglass energy"));
  // The run goes on to an internal energy of 10: the early share was outgrown.
  e = books(2.0, 0.0, 10.0, 0.3);
  v.measure(e, 10.3);
  v.judge(e, 0.0, leader, {}, true, r);
  v.settle(r);
  EXPECT_FALSE(has_reason(r, "hourglass energy"));
  EXPECT_EQ(r.warnings.size(), 2u) << "the warning stays, and the settlement says why";
  // Had the hourglass energy kept up, it stays against the results.
  BooksVerdict kept;
  kept.start(0.0, false);
  RunResult r_kept;
  e = books(1.0, 0.0, 10.0, 3.0);
  kept.measure(e, 13.0);
  kept.judge(e, 0.0, leader, {}, true, r_kept);
  kept.settle(r_kept);
  EXPECT_TRUE(has_reason(r_kept, "hourglass energy"));
}

TEST(BooksVerdict, AContactThatGivesEnergyIsWarnedAtATenthOfAPercentDistrustedAtOne) {
  std::vector<contact::InterfaceReport> iface(1);
  iface[0].id = 4;
  BooksVerdict v;
  v.start(100.0, false);
  RunResult r;
  iface[0].work = -0.5;  // 0.5 % of the 100 that entered
  Energies e = books(1.0, 100.5, 0.0, 0.0, -0.5);
  v.measure(e, 100.0);
  v.judge(e, 100.0, {}, iface, false, r);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("contact 4 energy"), std::string::npos) << r.warnings[0];
  EXPECT_TRUE(r.distrust.empty());
  iface[0].work = -2.0;
  e = books(2.0, 102.0, 0.0, 0.0, -2.0);
  v.measure(e, 100.0);
  v.judge(e, 100.0, {}, iface, false, r);
  EXPECT_TRUE(has_reason(r, "contact 4 energy"));
  // 2 of 100 is not outgrown even if 150 entered in all: 1.3 % of the run's most.
  e = books(3.0, 152.0, 0.0, 0.0, -2.0);
  v.measure(e, 150.0);
  v.judge(e, 100.0, {}, iface, true, r);
  v.settle(r);
  EXPECT_TRUE(has_reason(r, "contact 4 energy"));
  // Once 1000 has entered, -2 is 0.2 % of it: the early distrust is settled.
  e = books(4.0, 1002.0, 0.0, 0.0, -2.0);
  v.measure(e, 1000.0);
  v.settle(r);
  EXPECT_FALSE(has_reason(r, "contact 4 energy"));
}

TEST(BooksVerdict, TheStopBandCountsTheChecksInARowOutsideIt) {
  BooksVerdict v;
  EXPECT_EQ(v.stop_check(1.2, 0.5), 0);
  EXPECT_EQ(v.stop_check(1.7, 0.5), 1);
  EXPECT_EQ(v.stop_check(1.4, 0.5), 0);
  EXPECT_EQ(v.stop_check(0.4, 0.5), 1);
  EXPECT_EQ(v.stop_check(2.0, 0.5), 2);
}

}  // namespace
}  // namespace plyform::engine
