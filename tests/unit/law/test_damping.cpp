// Normal damping: c = (VDC/100) 2 sqrt(k m), only for nodes in contact or bonded.
#include <gtest/gtest.h>

#include <cmath>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

Increment moving(double gap, double dt) {
  Increment in;
  in.gap = gap;
  in.dt = dt;
  in.temperature = 300.0;
  in.k_normal = 1000.0;
  in.k_tangent = 1000.0;
  in.area = 0.25;
  in.mass = 2e-6;
  return in;
}

Parameters damped() {
  Parameters p = test::probe_parameters();
  p.vdc = 20.0;
  p.bond_tol = 0.0;  // nodes start APPROACHING
  return p;
}

TEST(Damping, NeverActsOnAnApproachingNode) {
  const Law law(damped());
  NodeHistory h = law.initial_history(0.5);
  ASSERT_EQ(h.state, NodeState::approaching);
  // Closing fast, still apart: no force at all.
  const Response r = law.update(moving(0.1, 1e-4), h);
  EXPECT_EQ(h.state, NodeState::approaching);
  EXPECT_EQ(r.pressure, 0.0);
  EXPECT_EQ(h.e_damping, 0.0);
}

TEST(Damping, NeverActsOnADetachedNode) {
  Parameters p = damped();
  p.beta0 = 0.0;
  const Law law(p);
  NodeHistory h = law.initial_history(0.5);
  law.update(moving(-1e-4, 1e-4), h);  // touch (no healing: zeta = 0)
  const Response r = law.update(moving(0.2, 1e-4), h);
  EXPECT_EQ(h.state, NodeState::detached);
  EXPECT_EQ(r.pressure, 0.0);
}

TEST(Damping, ActsInContactWithTheCriticalFraction) {
  const Law law(damped());
  NodeHistory h = law.initial_history(0.5);
  law.update(moving(-1e-3, 1e-4), h);  // first touch
  const double before = h.e_damping;
  const double touch = h.damping;  // the traction of the touch's own gap rate
  const double dt = 1e-5, g_new = -2e-3;
  const Response r = law.update(moving(g_new, dt), h);
  const double rate = (g_new - (-1e-3)) / dt;
  const double c_force = 0.2 * 2.0 * std::sqrt(1000.0 * 0.25 * 2e-6);  // on the node
  const double expected = 1000.0 * 2e-3 - c_force * rate / 0.25;
  EXPECT_NEAR(r.pressure, expected, 1e-12);
  // The second half of the touch's traction and the first half of this one's, each on half of
  // this step's gap change.
  const double booked = 0.5 * touch * (g_new - (-1e-3)) * 0.25 + 0.5 * c_force * rate * rate * dt;
  EXPECT_NEAR(h.e_damping - before, booked, 1e-12 * before);
  EXPECT_NEAR(h.damping, c_force * rate / 0.25, 1e-9);
}

// The damper's work is booked as the host books the contact's work: each traction on half the
// step before and half the step after its time, sum of (d_{n-1} + d_n) / 2 (g_n - g_{n-1}) A.
// - A node held in contact and moved sinusoidally, g = g0 + a sin(omega t), 1000 steps a
//   period: one period dissipates pi c omega a^2 (the viscous damper's loop).
// - A gap alternating every step (the rate changing sign each step, a mode at the step's
//   limit): the tractions alternate, their trapezoid does no work, and nothing is booked; the
//   law booked c rate^2 dt each step before.
TEST(Damping, BookedAsTheHostBooksTheContactsWork) {
  Parameters p = damped();
  p.beta0 = 0.0;  // no adhesion: k_node = k_normal
  const Law law(p);
  const double k = 1000.0, area = 0.25, mass = 2e-6;
  const double c_force = 0.2 * 2.0 * std::sqrt(k * area * mass);  // on the node
  const double a = 1e-4, g0 = -1e-3, omega = 2.0 * M_PI / 1e-3;
  const int steps = 1000;
  const double dt = 1e-3 / steps;
  NodeHistory h = law.initial_history(g0);
  law.update(moving(g0, dt), h);  // in contact, at rest
  ASSERT_EQ(h.state, NodeState::contact);
  const double before = h.e_damping;
  double d_last = 0.0, g_last = g0, trapezoid = 0.0;
  for (int n = 1; n <= steps; ++n) {
    const double g = g0 + a * std::sin(omega * n * dt);
    const Response r = law.update(moving(g, dt), h);
    const double d = -k * g - r.pressure;  // the damping traction
    trapezoid += 0.5 * (d_last + d) * (g - g_last) * area;
    d_last = d;
    g_last = g;
  }
  EXPECT_NEAR(h.e_damping - before, trapezoid, 1e-12 * trapezoid);
  // Against the loop of a continuous damper, to the backward gap rate's error, O(omega dt).
  const double loop = M_PI * c_force * omega * a * a;
  EXPECT_NEAR(h.e_damping - before, loop, omega * dt * loop);

  NodeHistory chatter = law.initial_history(g0);
  law.update(moving(g0, dt), chatter);
  const double start = chatter.e_damping;
  for (int n = 1; n <= 100; ++n)
    law.update(moving(g0 + (n % 2 == 1 ? a : 0.0), dt), chatter);
  // The first step's half traction (from rest) and the last one's: nothing in between.
  EXPECT_NEAR(chatter.e_damping - start, 0.5 * c_force * (a / dt) * a, 1e-9 * c_force * a * a / dt);
}

TEST(Damping, ActsOnABondedNodeWithItsCohesiveStiffness) {
  Parameters p = damped();
  p.bond_tol = 1e-6;
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);
  const double dt = 1e-5, g = 1e-3;  // below g_c = 0.01: no damage, beta = 1
  const Response r = law.update(moving(g, dt), h);
  const double c_force = 0.2 * 2.0 * std::sqrt(p.cn * 0.25 * 2e-6);
  EXPECT_NEAR(r.pressure, -p.cn * g - c_force * (g / dt) / 0.25, 1e-12);
}

}  // namespace
}  // namespace plyform::law
