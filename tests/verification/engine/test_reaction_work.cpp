// The work of a nodal constraint's reaction (a prescribed motion) in the energy books, against
// the closed form: a free plate carried at speed V by a velocity prescribed on all its nodes and
// stopped at once holds 1/2 M V^2 of kinetic energy, all of it the reactions' work, and nothing
// once stopped. The stop is an impulse at t_n; it changes the nodes' kinetic energy by exactly
// its impulse times the mean of the velocities before and after, booked over dt_avg / 2 each side
// of t_n. Booked on the steps' own halves, a stop between steps of different length (here while
// the step still doubles from DTINIT, 2 dt then 4 dt) books dt_prev / (dt_prev + dt_next) of it:
// 1/6 M V^2 left in the books of a plate at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../contact/contact_decks.hpp"

namespace plyform {
namespace {

TEST(ReactionWork, APrescribedStopBetweenStepsOfDifferentLengthTakesTheKineticEnergyOut) {
  const double rho = 7.85e-9, side = 10.0, thick = 1.0, speed = 1000.0;  // mm, t, s
  const double mass = rho * side * side * thick;
  const double dt0 = 1e-8, stop = 3e-8, end = 4e-7;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*CONTROL_TIMESTEP").card(dt0, 0.9);
  d.kw("*DATABASE_GLSTAT").card(dt0);
  d.kw("*PART").kw("plate").card(1, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(thick, thick, thick, thick);
  d.kw("*MAT_ELASTIC").card(1, rho, 2.1e5, 0.3);
  const std::vector<int> nodes = d.plate(1, 1, 1, 0.0, side, 0.0, side, 4, 4, 0.0);
  d.kw("*SET_NODE_LIST").card(1).ids(nodes);
  d.kw("*DEFINE_CURVE")
      .card(1)
      .card(0.0, speed)
      .card(stop, speed)
      .card(stop * (1 + 1e-6), 0.0)
      .card(1.0, 0.0);
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(1, 1, 0, 1, 1.0);
  test::DeckRun r;
  run_deck(d.text(), r);
  const double moving = 0.5 * mass * speed * speed;
  double worst_before = 0.0, after = 0.0;
  std::size_t outputs_after = 0;
  for (const auto& e : r.sink.energies) {
    if (e.time <= 0.0)
      continue;
    if (e.time < stop * (1 - 1e-9)) {
      // Carried at V: all the work is the kinetic energy (the plate does not deform).
      worst_before = std::max(worst_before, std::abs(e.external_work - e.kinetic) / moving);
      EXPECT_NEAR(e.kinetic, moving, 1e-9 * moving) << "t = " << e.time;
    } else if (e.time > stop * (1 + 1e-6)) {
      // At rest: no kinetic energy, and the reactions took out what they put in.
      ++outputs_after;
      EXPECT_NEAR(e.kinetic, 0.0, 1e-12 * moving) << "t = " << e.time;
      after = std::max(after, std::abs(e.external_work) / moving);
    }
  }
  ASSERT_GT(outputs_after, 3u);
  EXPECT_LT(worst_before, 1e-9);
  EXPECT_LT(after, 1e-9) << "the work left in the books of the stopped plate, over 1/2 M V^2";
  std::printf("prescribed stop: work left at rest %.3g of 1/2 M V^2 (on the steps' halves: 1/3)\n",
              after);
}

}  // namespace
}  // namespace plyform
