// The per-node state machine, initial bonding, and the identity of the two entry points.
#include <gtest/gtest.h>

#include <random>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

Increment at(double gap, double dt = 1e-3) {
  Increment in;
  in.gap = gap;
  in.dt = dt;
  in.temperature = 300.0;
  in.k_normal = 1000.0;
  in.k_tangent = 1000.0;
  return in;
}

TEST(StateMachine, ApproachContactSeparateDetachAndTouchAgain) {
  Parameters p = test::probe_parameters();
  p.bond_tol = 0.0;
  p.eta = 1e-9;  // quasi-static
  const Law law(p);
  NodeHistory h = law.initial_history(0.1);
  EXPECT_EQ(h.state, NodeState::approaching);
  EXPECT_EQ(h.beta, 1.0);
  law.update(at(0.05), h);
  EXPECT_EQ(h.state, NodeState::approaching);
  law.update(at(-1e-4), h);
  EXPECT_EQ(h.state, NodeState::contact);
  const Response r = law.update(at(0.005), h);
  EXPECT_EQ(h.state, NodeState::separating);
  EXPECT_DOUBLE_EQ(r.pressure, -p.cn * 0.005);  // below g_c: intact
  law.update(at(1.0), h);                       // 100 g_c: beta = 1e-4 < BETA_MIN
  EXPECT_EQ(h.state, NodeState::detached);
  EXPECT_EQ(h.beta, 0.0);
  EXPECT_EQ(law.update(at(0.5), h).pressure, 0.0);
  law.update(at(-1e-4), h);
  EXPECT_EQ(h.state, NodeState::contact);
  law.update(at(0.001), h);
  EXPECT_EQ(h.state, NodeState::detached);  // no healing: zeta = 0
}

TEST(StateMachine, InitialBondingWithinTolerance) {
  Parameters p = test::probe_parameters();
  p.bond_tol = 0.01;
  p.beta0 = 0.8;
  const Law law(p);
  EXPECT_EQ(law.initial_history(0.005).state, NodeState::separating);
  EXPECT_EQ(law.initial_history(0.005).beta, 0.8);
  EXPECT_EQ(law.initial_history(-0.005).state, NodeState::contact);
  EXPECT_EQ(law.initial_history(0.02).state, NodeState::approaching);
  // A bonded node resists opening at once.
  NodeHistory h = law.initial_history(0.0);
  EXPECT_LT(law.update(at(0.002), h).pressure, 0.0);
}

TEST(StateMachine, ReleaseGapDetachesABondedNode) {
  Parameters p = test::probe_parameters();
  p.release_gap = 0.005;
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);
  law.update(at(0.004), h);
  EXPECT_EQ(h.state, NodeState::separating);
  const Response r = law.update(at(0.006), h);
  EXPECT_EQ(h.state, NodeState::detached);
  EXPECT_EQ(r.pressure, 0.0);
  // The held elastic energy and the adhesion energy are booked as released.
  EXPECT_NEAR(h.e_damage, test::omega(p) + 0.5 * p.cn * 0.006 * 0.006, 1e-15);
}

// Random mixed histories through both entry points must agree bit for bit.
TEST(EntryPoints, BatchedAndSingleNodeUpdatesAreIdentical) {
  Parameters p = test::probe_parameters(1e-4);
  p.zeta = {5.0, 1.0, -1};
  p.mu = {0.3, 0.1, -1};
  p.vdc = 10.0;
  p.ct = 10.0;
  const Law law(p);
  const std::size_t n = 257;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> gap(-0.002, 0.03), slip(-1e-3, 1e-3), temp(250.0, 550.0);

  HistoryStore store(n);
  std::vector<NodeHistory> single(n);
  std::vector<double> g0(n);
  for (auto& g : g0)
    g = gap(rng) * 0.1;
  law.initialize_batch(n, g0.data(), store.view());
  for (std::size_t i = 0; i < n; ++i)
    single[i] = law.initial_history(g0[i]);

  std::vector<double> g(n), sx(n), sy(n), t(n), kn(n, 800.0), kt(n, 400.0), area(n, 0.5),
      mass(n, 1e-6), pr(n), tx(n), ty(n), st(n);
  for (int cycle = 0; cycle < 50; ++cycle) {
    for (std::size_t i = 0; i < n; ++i) {
      g[i] = gap(rng);
      sx[i] = slip(rng);
      sy[i] = slip(rng);
      t[i] = temp(rng);
    }
    const BatchInput in{n,         g.data(),  sx.data(),   sy.data(),   t.data(),
                        kn.data(), kt.data(), area.data(), mass.data(), 1e-4};
    law.update_batch(in, store.view(), BatchOutput{pr.data(), tx.data(), ty.data(), st.data()});
    for (std::size_t i = 0; i < n; ++i) {
      Increment inc;
      inc.gap = g[i];
      inc.slip[0] = sx[i];
      inc.slip[1] = sy[i];
      inc.dt = 1e-4;
      inc.temperature = t[i];
      inc.k_normal = kn[i];
      inc.k_tangent = kt[i];
      inc.area = area[i];
      inc.mass = mass[i];
      const Response r = law.update(inc, single[i]);
      ASSERT_EQ(r.pressure, pr[i]);
      ASSERT_EQ(r.tau[0], tx[i]);
      ASSERT_EQ(r.tau[1], ty[i]);
      ASSERT_EQ(r.stored, st[i]);
      const NodeHistory b = store.get(i);
      ASSERT_EQ(b.state, single[i].state);
      ASSERT_EQ(b.beta, single[i].beta);
      ASSERT_EQ(b.e_damage, single[i].e_damage);
      ASSERT_EQ(b.e_healing, single[i].e_healing);
      ASSERT_EQ(b.e_friction, single[i].e_friction);
      ASSERT_EQ(b.opening_t[0], single[i].opening_t[0]);
    }
  }
  // The mix really covered every state.
  int seen[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < n; ++i)
    seen[static_cast<int>(single[i].state)]++;
  EXPECT_GT(seen[1] + seen[2] + seen[3], 0);
}

}  // namespace
}  // namespace plyform::law
