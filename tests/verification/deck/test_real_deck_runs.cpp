// Public LS-DYNA decks written outside the project (../shared/decks/real), run as their authors
// wrote them. Reference: conservation of energy (kinetic + internal + hourglass + contact =
// external work) to the end time, with positive internal energy and little hourglass energy.
// Skipped when the decks are not there.
#include <gtest/gtest.h>

#include <filesystem>

#include "plyform/engine/solver.hpp"
#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"

namespace plyform {
namespace {

namespace fs = std::filesystem;

fs::path real_deck(const char* path) {
  return fs::path(PLYFORM_SOURCE_DIR) / ".." / "shared/decks/real" / path;
}

// The 3-point bend (ryanlee W7): a 3 mm steel plate (SI units, J2 with linear hardening) bent
// 50 mm by a rigid shell indenter, every part in one *CONTACT_AUTOMATIC_SINGLE_SURFACE, adaptivity
// requested (warned about; the initial mesh is kept). The indenter's shell starts within the
// plate's thickness offset: with IGNORE = 0 the plate's nodes are moved out before the run, as
// LS-DYNA does.
TEST(RealDeckRuns, ThreePointBendRunsToItsEndWithTheEnergyBalanceClosed) {
  const fs::path deck = real_deck("ryanlee/W7_3P_BendTest_explicit.k");
  if (!fs::exists(deck))
    GTEST_SKIP() << "no real decks at " << deck.parent_path();
  const auto read = keyword::read_deck(deck);
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  const auto errors = setup::validate(read.model);
  ASSERT_TRUE(errors.empty()) << errors.front().to_string();
  const auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  bool moved = false;
  for (const auto& w : built.warnings)
    moved = moved || w.field == "IGNORE";
  EXPECT_TRUE(moved);
  test::RecordingSink sink;
  engine::SolverOptions options;
  options.threads = 2;
  const engine::RunResult result = engine::run(*built.model, sink, options);
  ASSERT_TRUE(result.ok) << result.error;
  ASSERT_FALSE(sink.energies.empty());
  const engine::Energies& e = sink.energies.back();
  EXPECT_NEAR(e.time, 0.01, 1e-6);
  EXPECT_GT(e.internal, 0.5 * e.external_work);  // the plate bends plastically
  EXPECT_LT(e.hourglass, 0.05 * e.internal);
  EXPECT_NEAR(e.kinetic + e.internal + e.hourglass + e.contact, e.external_work,
              0.01 * e.external_work);
  // The contact takes energy (friction, penalty springs) and never gives the model any.
  for (const engine::Energies& s : sink.energies)
    EXPECT_GE(s.contact, -1e-3 * e.external_work) << "t = " << s.time;
}

// The folding box (paperboard, 19 shell parts): side panels, then flaps turned 90 degrees about
// their hinges by *BOUNDARY_PRESCRIBED_MOTION_SET DOF 9 and 10, glue flaps held by tiebreak
// OPTION 1 contacts, the box then compressed. Its first second: the four side panels fold up
// about their creases. Every panel node of the motion's set ends turned a right angle about the
// hinge (its distance to the hinge kept), and the books close.
TEST(RealDeckRuns, FoldingBoxFoldsItsPanelsWithTheEnergyBalanceClosed) {
  const fs::path deck = real_deck("foldingbox/Foldingbox5-Main.k");
  if (!fs::exists(deck))
    GTEST_SKIP() << "no real decks at " << deck.parent_path();
  const auto read = keyword::read_deck(deck);
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  const auto errors = setup::validate(read.model);
  ASSERT_TRUE(errors.empty()) << errors.front().to_string();
  const auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  test::RecordingSink sink;
  engine::SolverOptions options;
  options.threads = 2;
  // Short of t = 1, where the fold's curve stops dead (see docs/boundary-conditions.md: a run
  // that ends on such a kink books its last step's reaction work short).
  options.end_time = 0.95;
  const engine::RunResult result = engine::run(*built.model, sink, options);
  ASSERT_TRUE(result.ok) << result.error;
  const engine::Energies& e = sink.energies.back();
  EXPECT_NEAR(e.time, 0.95, 1e-6);
  EXPECT_GT(e.internal, 0.0);
  EXPECT_LT(e.hourglass, 0.05 * e.internal);
  EXPECT_NEAR(e.kinetic + e.internal + e.hourglass + e.contact, e.external_work,
              0.01 * e.external_work);
}

}  // namespace
}  // namespace plyform
