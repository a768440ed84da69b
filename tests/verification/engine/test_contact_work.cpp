// The contact's work in the energy books where the time step changes, against a conservation
// law: an elastic plate thrown tumbling onto a clamped one through a frictionless, undamped
// penalty contact lands edge first, slaps down and bounces off. Nothing else works on the two,
// so kinetic + internal + hourglass + contact energy stays the thrown plate's kinetic energy of
// t = 0 at every output. (The contact's own energy need not return to zero: a penalty spring
// that lets go between two cycles gives or takes a little, which the books must show.) The
// central differences move the nodes with the contact force of t_n over dt_avg = (dt_{n-1/2} +
// dt_{n+1/2}) / 2; booked on the steps' own halves (the trapezoid), the force's work misses
// (dt_{n+1/2} - dt_{n-1/2}) / 4 times its change of power at t_n each cycle.
// *CONTROL_TIMESTEP LCTM (the largest step against time) makes the step jump between two
// values through the bounce.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "../contact/contact_decks.hpp"

namespace plyform {
namespace contact_work {

constexpr double kRho = 7.85e-9, kE = 2.1e5, kSpeed = 2000.0;  // t/mm^3, MPa, mm/s

struct Bounce {
  double worst = 0.0;        // the largest |total - initial| over the initial kinetic energy
  double kinetic_end = 0.0;  // the kinetic energy at the end, over the same
  double internal_peak = 0.0;
  double contact_peak = 0.0;
  double dt_min = 1e300, dt_max = 0.0;
};

// `dt_low`, `dt_high` > 0: the step capped at dt_low and dt_high alternately, every
// `period` of time.
Bounce bounce(double end, double dt_low = 0.0, double dt_high = 0.0, double period = 0.0) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  if (dt_low > 0.0) {
    d.kw("*CONTROL_TIMESTEP").card(0.0, 0.9, 0, 0.0, 0.0, 9);
    d.kw("*DEFINE_CURVE").card(9);
    for (int i = 0; i * period < 1.5 * end; ++i) {
      const double v = i % 2 == 0 ? dt_high : dt_low;
      d.card(i * period, v).card((i + 1) * period * (1.0 - 1e-9), v);
    }
  }
  d.kw("*DATABASE_GLSTAT").card(end / 200);
  d.kw("*PART").kw("clamped plate").card(1, 1, 1);
  d.kw("*PART").kw("thrown plate").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, kRho, kE, 0.3);
  const std::vector<int> master = d.plate(1, 1, 1, 0.0, 8.0, 0.0, 8.0, 4, 4, 0.0);
  // The thrown plate touches the clamped one (the two half thicknesses) at t = 0, its edge
  // x = 6 falling three times as fast as its edge x = 2.
  const std::vector<int> slave = d.plate(2, 1001, 1001, 2.0, 6.0, 2.0, 6.0, 4, 4, 1.0);
  d.kw("*SET_NODE_LIST").card(1).ids(master);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*INITIAL_VELOCITY_NODE");
  for (std::size_t i = 0; i < slave.size(); ++i)
    d.card(slave[i], 0.0, 0.0, -kSpeed * (0.5 + 0.25 * static_cast<double>(i % 5)));
  d.kw("*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID").card(7, "bounce");
  d.card(2, 1, 3, 3).kw("0,0,0,0,0").kw("1,1");
  test::DeckRun r;
  run_deck(d.text(), r);
  Bounce b;
  const double k0 = r.sink.energies.front().kinetic;  // 1/2 m v^2 of t = 0
  for (const auto& e : r.sink.energies) {
    const double total = e.kinetic + e.internal + e.hourglass + e.contact - e.external_work;
    b.worst = std::max(b.worst, std::abs(total - k0) / k0);
    b.internal_peak = std::max(b.internal_peak, e.internal / k0);
    b.contact_peak = std::max(b.contact_peak, e.contact / k0);
    if (e.time > 0.0) {
      b.dt_min = std::min(b.dt_min, e.dt);
      b.dt_max = std::max(b.dt_max, e.dt);
    }
  }
  b.kinetic_end = r.sink.energies.back().kinetic / k0;
  return b;
}

TEST(ContactWork, ABounceWhileTheStepJumpsKeepsTheBooks) {
  const double end = 2e-5;
  const Bounce steady = bounce(end);
  // The contact took a good share of the energy, some of it rang on in the plates, and the
  // thrown plate flies off with most of it.
  EXPECT_GT(steady.contact_peak, 0.3);
  EXPECT_GT(steady.internal_peak, 0.01);
  EXPECT_GT(steady.kinetic_end, 0.5);
  EXPECT_LT(steady.worst, 1e-7);
  // The step capped at 0.3 and 0.7 of the steady one, alternately every 1.3 steps.
  const double dt = steady.dt_max;
  const Bounce jumping = bounce(end, 0.3 * dt, 0.7 * dt, 1.3 * dt);
  EXPECT_LT(jumping.dt_min, 0.31 * dt);
  EXPECT_GT(jumping.dt_max, 0.69 * dt);
  EXPECT_GT(jumping.contact_peak, 0.3);
  EXPECT_GT(jumping.kinetic_end, 0.5);
  EXPECT_LT(jumping.worst, 1e-7) << "the books' error over the initial kinetic energy";
  std::printf("bounce: books within %.2g with the step jumping (steady step %.3g s: %.2g)\n",
              jumping.worst, dt, steady.worst);
}

}  // namespace contact_work
}  // namespace plyform
