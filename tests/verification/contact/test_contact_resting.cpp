// Resting slave nodes (src/contact/src/resting_nodes.hpp): a node clear of the master is passed
// over until the motion since it came to rest could have spent its clearance. A node that woke
// late would meet the tool already inside it and be pushed out by a spring that no work loaded,
// or touch late. References: the free flight's closed form (the first touch at gap / speed) and
// the conservation of energy (no damping, no friction, elastic sheet and rigid tool).
#include <gtest/gtest.h>

#include <cmath>

#include "contact_decks.hpp"

namespace plyform {
namespace {

constexpr double kSheetZ = 3.0;      // the sheet's mid-surface above the tool's face (z = 0)
constexpr double kHalfThick = 0.25;  // the sheet's offset: half its 0.5 mm
constexpr double kOut = 2e-6;        // the contact forces' output interval (about 6 cycles)

struct Flight {
  double first_touch = -1.0;  // the first output time with a contact force
  double energy_error = 0.0;  // |total - (initial kinetic + external work)| / initial kinetic
  double rested = 0.0;        // the share of the slave node-cycles at rest
};

// An elastic steel sheet (10 x 10 mm, 5 x 5 Belytschko-Tsay shells) over a rigid plate of
// 4 x 4 shells spanning [x0, x1] x [0, 10]: the sheet flies at (vx, 0, -vz) onto the fixed
// plate, or the plate moves up at vz onto the sheet at rest (`tool_moves`).
Flight fly(double vx, double vz, bool tool_moves, double x1, double end) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 50);
  d.kw("*DATABASE_RCFORC").card(kOut);
  d.kw("*PART").kw("sheet").card(1, 1, 1);
  d.kw("*PART").kw("tool").card(2, 1, 2);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 3).card(0.5, 0.5, 0.5, 0.5);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 2.1e5, 0.3);
  d.kw("*MAT_RIGID").card(2, 7.85e-9, 2.1e5, 0.3).card(1.0, tool_moves ? 4 : 7, 7);
  d.plate(1, 1, 1, 0.0, 10.0, 0.0, 10.0, 5, 5, kSheetZ);
  d.plate(2, 1001, 1001, -5.0, x1, -5.0, 15.0, 8, 4, 0.0);
  if (tool_moves) {
    d.kw("*DEFINE_CURVE").card(1).card(0.0, 1.0).card(end, 1.0);
    d.kw("*BOUNDARY_PRESCRIBED_MOTION_RIGID").card(2, 3, 0, 1, vz);
  } else {
    d.kw("*INITIAL_VELOCITY_GENERATION").card(1, 2, 0.0, vx, 0.0, -vz).card(0, 0, 0, 0, 0, 0);
  }
  d.kw("*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID").card(5, "sheet on the tool");
  d.card(1, 2, 3, 3).card(0.0, 0.0, 0.0, 0.0, 0.0).card(1, 1);
  test::DeckRun r;
  run_deck(d.text(), r);
  Flight f;
  for (const auto& [time, reports] : r.sink.contact) {
    if (std::abs(reports.at(0).force[2]) > 0.0) {
      f.first_touch = time;
      break;
    }
  }
  const double m = 7.85e-9 * 10.0 * 10.0 * 0.5;
  const double kinetic0 = tool_moves ? 0.5 * m * vz * vz : 0.5 * m * (vx * vx + vz * vz);
  const engine::Energies& e = r.sink.energies.back();
  f.energy_error =
      std::abs(e.total - (r.sink.energies.front().kinetic + e.external_work)) / kinetic0;
  f.rested = r.result.contact_rested_share;
  return f;
}

TEST(ContactResting, ASheetFlyingOntoAFixedToolTouchesWhenItsFlightSaysSo) {
  const double v = 1000.0;  // mm/s
  const double touch = (kSheetZ - kHalfThick) / v;
  const Flight f = fly(0.0, v, false, 15.0, touch + 0.3e-3);
  EXPECT_GT(f.rested, 0.5);  // most of the flight at rest
  EXPECT_GE(f.first_touch, touch);
  EXPECT_LE(f.first_touch, touch + 2.0 * kOut);
  EXPECT_LT(f.energy_error, 1e-3);
}

TEST(ContactResting, AToolMovingOntoASheetAtRestTouchesWhenItsTravelSaysSo) {
  const double v = 1000.0;
  const double touch = (kSheetZ - kHalfThick) / v;
  const Flight f = fly(0.0, v, true, 15.0, touch + 0.3e-3);
  EXPECT_GT(f.rested, 0.5);
  EXPECT_GE(f.first_touch, touch);
  EXPECT_LE(f.first_touch, touch + 2.0 * kOut);
  EXPECT_LT(f.energy_error, 1e-3);
}

// Sliding fast along the tool while closing slowly: the nodes' own motion, mostly along the
// face, wakes them again and again (the margin counts every direction).
TEST(ContactResting, ASheetSlidingOntoAToolWhileClosingSlowlyTouchesOnTime) {
  const double vx = 20000.0, vz = 500.0;
  const double touch = (kSheetZ - kHalfThick) / vz;
  const Flight f = fly(vx, vz, false, 5.0 + 1.2 * vx * touch, touch + 0.3e-3);
  EXPECT_GT(f.rested, 0.2);
  EXPECT_GE(f.first_touch, touch);
  EXPECT_LE(f.first_touch, touch + 2.0 * kOut);
  EXPECT_LT(f.energy_error, 1e-3);
}

}  // namespace
}  // namespace plyform
