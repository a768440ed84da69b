// When a run writes its outputs (output_clocks.hpp), against the rule of docs/outputs.md: every
// output at t = 0, then at each multiple of its interval (within the end time's tolerance), and
// at the end once more unless it was written at that very time; the states with no interval at
// the start and the end only. A checkpoint holds the clocks and what was written at the last
// output time.
#include <gtest/gtest.h>

#include "output_clocks.hpp"

namespace plyform::engine {
namespace {

constexpr double kEps = 1e-12;

TEST(OutputClocks, EveryOutputIsDueAtTheStartThenAtItsInterval) {
  OutputClocks c;
  EXPECT_TRUE(c.due(Output::glstat, 0.0, kEps, false));
  EXPECT_TRUE(c.due(Output::elout, 0.0, kEps, false));
  c.wrote(Output::glstat, 0.0, kEps, 0.1, 1.0);
  EXPECT_FALSE(c.due(Output::glstat, 0.05, kEps, false));
  EXPECT_FALSE(c.due(Output::glstat, 0.1 - 1e-9, kEps, false));
  EXPECT_TRUE(c.due(Output::glstat, 0.1 - 0.5 * kEps, kEps, false)) << "within the tolerance";
  // A step that overshoots two intervals moves the clock past both.
  c.wrote(Output::glstat, 0.25, kEps, 0.1, 1.0);
  EXPECT_FALSE(c.due(Output::glstat, 0.29, kEps, false));
  EXPECT_TRUE(c.due(Output::glstat, 0.3, kEps, false));
}

TEST(OutputClocks, TheEndWritesWhatWasNotWrittenAtThatTime) {
  // glstat every 0.4, nodout every 0.5, written as a run does up to t = 0.8.
  OutputClocks c;
  c.wrote(Output::glstat, 0.0, kEps, 0.4, 1.0);
  c.wrote(Output::nodout, 0.0, kEps, 0.5, 1.0);
  c.wrote(Output::glstat, 0.4, kEps, 0.4, 1.0);
  c.wrote(Output::nodout, 0.5, kEps, 0.5, 1.0);
  c.wrote(Output::glstat, 0.8, kEps, 0.4, 1.0);
  // The end falls on glstat's interval (0.8): written on its clock, not a second time by the
  // end's pass; nodout is written by the end's pass.
  EXPECT_TRUE(c.written_now(Output::glstat, 0.8));
  EXPECT_FALSE(c.due(Output::glstat, 0.8, kEps, true));
  EXPECT_FALSE(c.written_now(Output::nodout, 0.8));
  EXPECT_TRUE(c.due(Output::nodout, 0.8, kEps, true));
  // An end at 0.9, between both intervals: neither is due on its clock, the end writes both.
  EXPECT_FALSE(c.due(Output::glstat, 0.9, kEps, false));
  EXPECT_FALSE(c.due(Output::nodout, 0.9, kEps, false));
  EXPECT_TRUE(c.due(Output::glstat, 0.9, kEps, true));
  EXPECT_TRUE(c.due(Output::nodout, 0.9, kEps, true));
  EXPECT_FALSE(c.written_now(Output::glstat, 0.9));
}

TEST(OutputClocks, StatesWithoutAnIntervalAtTheStartAndTheEndOnly) {
  OutputClocks c;
  const double end = 2.0;
  EXPECT_TRUE(c.due(Output::state, 0.0, kEps, false));
  c.wrote(Output::state, 0.0, kEps, 0.0, end);
  EXPECT_FALSE(c.due(Output::state, 1.0, kEps, false));
  EXPECT_TRUE(c.due(Output::state, end, kEps, false));
}

TEST(OutputClocks, ACheckpointHoldsTheClocksAndWhatWasWritten) {
  OutputClocks c;
  c.wrote(Output::rcforc, 0.0, kEps, 0.25, 1.0);
  c.wrote(Output::matsum, 0.5, kEps, 0.5, 1.0);
  auto saving = core::StateArchive::for_saving();
  c.visit_state(saving);
  const core::StateArchive::Records records = saving.take_records();
  OutputClocks back;
  auto loading = core::StateArchive::for_loading(records);
  back.visit_state(loading);
  for (const double t : {0.1, 0.25, 0.5, 0.75, 1.0})
    for (const bool last : {false, true})
      for (const Output o : {Output::rcforc, Output::matsum, Output::glstat})
        EXPECT_EQ(back.due(o, t, kEps, last), c.due(o, t, kEps, last)) << t;
  EXPECT_TRUE(back.written_now(Output::matsum, 0.5));
  EXPECT_FALSE(back.written_now(Output::rcforc, 0.5));
}

}  // namespace
}  // namespace plyform::engine
