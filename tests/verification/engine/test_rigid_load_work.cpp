// The work of a *LOAD_RIGID_BODY (a blank holder's force) in the energy books, against the
// closed form: a free rigid plate of mass M pushed by a force ramped from 0, F = a t, moves
// with v = a t^2 / (2 M), and the force's work up to t is a^2 t^4 / (8 M). The body's load is
// booked as the nodes' loads are, each half step on the velocities of that half step; booked
// whole on the velocity at t_n it ran half a step ahead of the motion, and a holder's ramped
// force read an energy ratio of 0.56 at the third cycle (the restart tests' square cup).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../contact/contact_decks.hpp"

namespace plyform {
namespace {

TEST(RigidLoadWork, RampedForceOnAFreeBodyBooksItsClosedFormWork) {
  const double end = 1e-4, dt = end / 200, rho = 7.85e-9, side = 10.0, thick = 1.0, peak = 100.0;
  const double mass = rho * side * side * thick;
  const double a = peak / end;  // the force's rate [force / time]
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*CONTROL_TIMESTEP").card(dt, 0.9);  // DTINIT: nothing deformable sets the step
  d.kw("*DATABASE_GLSTAT").card(end / 50);
  d.kw("*PART").kw("plate").card(1, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(thick, thick, thick, thick);
  d.kw("*MAT_RIGID").card(1, rho, 2.0e5, 0.3).card(0.0, 0, 0);
  (void)d.plate(1, 1, 1, 0.0, side, 0.0, side, 4, 4, 0.0);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end, 1.0);
  d.kw("*LOAD_RIGID_BODY").card(1, 3, 1, -peak);
  test::DeckRun r;
  run_deck(d.text(), r);
  ASSERT_GT(r.sink.energies.size(), 40u);
  double worst_ke = 0.0, worst_scaled = 0.0;
  for (const auto& e : r.sink.energies) {
    if (e.time <= 0.0)
      continue;
    const double exact = a * a * std::pow(e.time, 4) / (8.0 * mass);
    const double n = e.time / dt;  // the steps taken
    // The motion: the central differences integrate the ramp exactly.
    worst_ke = std::max(worst_ke, std::abs(e.kinetic - exact) / exact);
    // The work: second order, within 1/n^2 of the closed form after n steps (from the half
    // step the first output books without its last half). Booked whole on the velocity at
    // t_n it ran ahead by about 2/n: 56 % at the first output, 1 % at the end.
    worst_scaled = std::max(worst_scaled, std::abs(e.external_work - exact) / exact * n * n);
  }
  EXPECT_LT(worst_ke, 1e-9);
  EXPECT_LT(worst_scaled, 1.0 + 1e-6);
  std::printf(
      "ramped rigid-body load: kinetic energy within %.2e of a^2 t^4 / (8 M), the work "
      "within %.4f / n^2 after n steps\n",
      worst_ke, worst_scaled);
}

}  // namespace
}  // namespace plyform
