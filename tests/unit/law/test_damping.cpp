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
  const double dt = 1e-5, g_new = -2e-3;
  const Response r = law.update(moving(g_new, dt), h);
  const double rate = (g_new - (-1e-3)) / dt;
  const double c_force = 0.2 * 2.0 * std::sqrt(1000.0 * 0.25 * 2e-6);  // on the node
  const double expected = 1000.0 * 2e-3 - c_force * rate / 0.25;
  EXPECT_NEAR(r.pressure, expected, 1e-12);
  EXPECT_NEAR(h.e_damping - before, c_force * rate * rate * dt, 1e-12 * before);
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
