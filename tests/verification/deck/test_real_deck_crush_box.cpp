// The crush box of ../shared/decks/real (ryanlee W8, LS-PrePost training deck, mm ms kg kN): a
// steel box of three shell parts (BT, Cowper-Symonds *MAT_PIECEWISE_LINEAR_PLASTICITY with
// C 40 P 5), its flanges joined by four *CONTACT_TIED_NODES_TO_SURFACE, every part in one
// *CONTACT_AUTOMATIC_SINGLE_SURFACE (coplanar overlapping flanges among them), its far end
// clamped, crushed for 25 ms by an 800 kg *RIGIDWALL_PLANAR_MOVING_FORCES at 9 m/s (32.4 kJ).
// References: the energy balance (the acceptance: ratio within 1 +- 0.02), the wall's
// momentum (its loss is the impulse it gave the nodes, to round-off) and energy (its loss of
// kinetic energy covers the work it did on the box). A minute on two cores: the long tier.
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

TEST(RealDeckRuns, CrushBoxIsCrushedByItsMovingWallWithTheBooksClosed) {
  const fs::path deck =
      fs::path(PLYFORM_SOURCE_DIR) / ".." / "shared/decks/real/ryanlee/W8_SETUP_CrushBox.k";
  if (!fs::exists(deck))
    GTEST_SKIP() << "no real decks at " << deck.parent_path();
  const auto read = keyword::read_deck(deck);
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  const auto errors = setup::validate(read.model);
  ASSERT_TRUE(errors.empty()) << errors.front().to_string();
  const auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  const core::Model& m = *built.model;
  ASSERT_EQ(m.tied.size(), 4u);
  ASSERT_EQ(m.rigid_walls.size(), 1u);
  test::RecordingSink sink;
  engine::SolverOptions options;
  options.threads = 2;
  const engine::RunResult result = engine::run(m, sink, options);
  ASSERT_TRUE(result.ok) << result.error;
  EXPECT_TRUE(result.distrust.empty()) << result.distrust.front().reason;
  ASSERT_FALSE(sink.energies.empty());
  const engine::Energies& e = sink.energies.back();
  EXPECT_NEAR(e.time, 25.0, 1e-6);
  for (const engine::Energies& s : sink.energies)
    EXPECT_NEAR(s.ratio, 1.0, 0.02) << "t = " << s.time;
  EXPECT_GT(e.internal, 0.5 * e.external_work);  // the box folds plastically
  EXPECT_LT(e.hourglass, 0.1 * e.internal);
  // The wall: 800 kg at 9 mm/ms along its normal.
  ASSERT_FALSE(sink.walls.empty());
  const rigid::RigidWalls::Report& w = sink.walls.back().second.at(0);
  const double mass = 800.0, v0 = 9.0;
  EXPECT_NEAR(mass * (v0 - w.velocity), w.impulse, 1e-9 * mass * v0);
  EXPECT_GT(w.impulse, 0.1 * mass * v0);  // it was slowed
  EXPECT_GE(0.5 * mass * v0 * v0 - w.kinetic, e.external_work * (1.0 - 1e-6));
}

}  // namespace
}  // namespace plyform
