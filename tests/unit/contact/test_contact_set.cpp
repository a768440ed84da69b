// ContactSet on a hand-built model: one master quad (a rectangle in a tilted plane) and one
// slave node. Penalty-only law (no adhesion): one cycle must put k * penetration along the
// segment normal on the slave node and the opposite force on the master nodes, split by the
// bilinear shape functions at the projection point; Coulomb friction opposes the relative
// sliding (stick spring or mu times the normal force). All values in closed form.
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <vector>

#include "plyform/contact/contact_set.hpp"
#include "plyform/core/model.hpp"

namespace test_contact_set {

using namespace plyform;
using V3 = std::array<double, 3>;

constexpr double kTheta = 0.5;                          // tilt of the master plane about y [rad]
const V3 kU{std::cos(kTheta), 0.0, std::sin(kTheta)};   // xi direction
const V3 kW{0.0, 1.0, 0.0};                             // eta direction
const V3 kN{-std::sin(kTheta), 0.0, std::cos(kTheta)};  // kU x kW: the segment normal
const V3 kCentre{0.3, -0.2, 0.5};
constexpr double kA = 1.0, kB = 0.6;  // half-sizes of the rectangle along kU, kW
constexpr double kSlaveOffset = 0.04, kSegmentOffset = 0.06;
constexpr double kSlaveArea = 0.3;
constexpr double kDt = 1e-3;

V3 on_segment(double xi, double eta) {
  V3 x{};
  for (std::size_t k = 0; k < 3; ++k)
    x[k] = kCentre[k] + kA * xi * kU[k] + kB * eta * kW[k];
  return x;
}

std::array<double, 4> shape(double xi, double eta) {
  return {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta), 0.25 * (1 + xi) * (1 + eta),
          0.25 * (1 - xi) * (1 + eta)};
}

law::Parameters penalty_law(double mu) {
  law::Parameters p;
  p.cn = 1.0;
  p.sigma_max = {1.0, 1.0, -1};
  p.eta = 1.0;
  p.beta0 = 0.0;
  p.mu = {mu, mu, -1};
  return p;
}

// Nodes 0-3: the master quad; node 4: the slave node at (xi, eta) of the segment, `depth`
// into the offset surfaces (negative: a gap).
struct Scene {
  core::Model model;
  std::vector<double> mass;
  std::vector<double> packed;
  std::vector<double> fx, fy, fz;

  Scene(double xi, double eta, double depth, double ks, double km, int penopt, double mu) {
    const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    std::vector<V3> x;
    for (const auto& c : corners)
      x.push_back(on_segment(c[0], c[1]));
    const V3 s = on_segment(xi, eta);
    const double h = kSlaveOffset + kSegmentOffset - depth;
    x.push_back({s[0] + h * kN[0], s[1] + h * kN[1], s[2] + h * kN[2]});
    for (std::size_t i = 0; i < x.size(); ++i) {
      model.node_id.push_back(static_cast<core::GlobalId>(101 + i));
      model.x0.push_back(x[i][0]);
      model.y0.push_back(x[i][1]);
      model.z0.push_back(x[i][2]);
      packed.insert(packed.end(), {x[i][0], x[i][1], x[i][2], 0.0, 0.0, 0.0});
    }
    core::ContactInterface ci;
    ci.id = 7;
    ci.keyword = "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE";
    ci.penopt = penopt;
    ci.law = penalty_law(mu);
    core::ContactPass p;
    p.slave_nodes = {4};
    p.slave_offset = {kSlaveOffset};
    p.slave_area = {kSlaveArea};
    p.slave_stiffness = {ks};
    p.segments = {0, 1, 2, 3};
    p.segment_offset = {kSegmentOffset};
    p.segment_stiffness = {km};
    ci.passes.push_back(p);
    model.contacts.push_back(ci);
    mass.assign(x.size(), 2.0);
    fx.assign(x.size(), 0.0);
    fy.assign(x.size(), 0.0);
    fz.assign(x.size(), 0.0);
  }

  void set_velocity(std::size_t node, const V3& v) {
    for (std::size_t k = 0; k < 3; ++k)
      packed[6 * node + 3 + k] = v[k];
  }

  // The contact force on node i (the arrays hold internal forces: a = (f_ext - f) / m).
  [[nodiscard]] V3 force(std::size_t i) const { return {-fx[i], -fy[i], -fz[i]}; }
};

// start() at t = 0, then one cycle. One thread: a single slave node gains nothing from more,
// and the passes' parallel regions would only wait on a busy machine.
contact::InterfaceReport one_cycle(Scene& s) {
  const int threads0 = omp_get_max_threads();
  omp_set_num_threads(1);
  contact::ContactSet cs(s.model, s.mass, nullptr, 1e-4, 0.9);
  EXPECT_FALSE(cs.empty());
  EXPECT_EQ(cs.slave_count(), 1u);
  cs.start(s.packed.data());
  cs.apply(kDt, kDt, s.packed.data(), nullptr, s.fx.data(), s.fy.data(), s.fz.data());
  const auto reports = cs.report();
  omp_set_num_threads(threads0);
  EXPECT_EQ(reports.size(), 1u);
  return reports.empty() ? contact::InterfaceReport{} : reports.front();
}

void expect_near(const V3& a, const V3& b, double tol, const char* what) {
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(a[k], b[k], tol) << what << " component " << k;
}

// The expected split of a slave force F: F on the slave, -N_j F on master node j.
void check_split(const Scene& s, double xi, double eta, const V3& f_slave,
                 const contact::InterfaceReport& r) {
  const double tol =
      1e-12 * (1.0 + std::fabs(f_slave[0]) + std::fabs(f_slave[1]) + std::fabs(f_slave[2]));
  expect_near(s.force(4), f_slave, tol, "slave");
  const auto n = shape(xi, eta);
  for (std::size_t j = 0; j < 4; ++j) {
    const V3 expect{-n[j] * f_slave[0], -n[j] * f_slave[1], -n[j] * f_slave[2]};
    expect_near(s.force(j), expect, tol, "master");
  }
  expect_near(V3{r.force[0], r.force[1], r.force[2]}, f_slave, tol, "report");
  EXPECT_EQ(r.id, 7);
}

TEST(ContactSet, PenaltyForceSplitByShapeFunctions) {
  const double ks = 800.0, km = 500.0, depth = 2e-3;
  struct Pos {
    double xi, eta;
  };
  // In-segment points, and one within the MAXPAR tolerance (1.025) beyond an edge, where the
  // shape functions extrapolate.
  for (const Pos p : {Pos{0.0, 0.0}, Pos{0.5, -0.3}, Pos{-0.9, 0.8}, Pos{0.99, 0.99},
                      Pos{-0.2, -1.0}, Pos{1.015, 0.2}}) {
    SCOPED_TRACE(testing::Message() << "xi " << p.xi << " eta " << p.eta);
    Scene s(p.xi, p.eta, depth, ks, km, 1, 0.2);
    const contact::InterfaceReport r = one_cycle(s);
    const double fn = std::min(ks, km) * depth;  // PENOPT 1: the smaller stiffness
    check_split(s, p.xi, p.eta, V3{fn * kN[0], fn * kN[1], fn * kN[2]}, r);
    EXPECT_EQ(r.in_contact, 1u);
  }
}

TEST(ContactSet, PenaltyOptionPicksTheStiffness) {
  const double ks = 800.0, km = 500.0, depth = 1e-3, xi = 0.25, eta = 0.4;
  for (const auto& [penopt, k] : {std::pair{1, km}, std::pair{2, km}, std::pair{3, ks}}) {
    Scene s(xi, eta, depth, ks, km, penopt, 0.0);
    const contact::InterfaceReport r = one_cycle(s);
    const double fn = k * depth;
    check_split(s, xi, eta, V3{fn * kN[0], fn * kN[1], fn * kN[2]}, r);
  }
  // PENOPT 1 with the slave side softer.
  Scene s(xi, eta, depth, 300.0, km, 1, 0.0);
  const contact::InterfaceReport r = one_cycle(s);
  const double fn = 300.0 * depth;
  check_split(s, xi, eta, V3{fn * kN[0], fn * kN[1], fn * kN[2]}, r);
}

TEST(ContactSet, NodeBeyondMaxparOrClearGetsNothing) {
  struct Case {
    double xi, eta, depth;
  };
  for (const Case c : {Case{1.04, 0.0, 2e-3}, Case{0.0, -1.1, 2e-3}, Case{1.2, 1.2, 2e-3},
                       Case{-1.5, 0.3, 2e-3}, Case{0.1, 0.2, -1e-3}}) {
    SCOPED_TRACE(testing::Message() << "xi " << c.xi << " eta " << c.eta << " depth " << c.depth);
    Scene s(c.xi, c.eta, c.depth, 800.0, 500.0, 1, 0.2);
    const contact::InterfaceReport r = one_cycle(s);
    for (std::size_t i = 0; i < 5; ++i)
      expect_near(s.force(i), V3{0, 0, 0}, 0.0, "node");
    expect_near(V3{r.force[0], r.force[1], r.force[2]}, V3{0, 0, 0}, 0.0, "report");
    EXPECT_EQ(r.in_contact, 0u);
  }
}

TEST(ContactSet, CoulombFrictionOpposesSliding) {
  // The slave node slides along kU relative to the segment (slave moving, or the master nodes
  // moving the other way): a stick spring k * slip for a small slip, mu * Fn once the slip
  // exceeds mu * depth.
  const double ks = 800.0, km = 500.0, depth = 2e-3, mu = 0.2, xi = 0.3, eta = -0.45;
  const double k = std::min(ks, km), fn = k * depth;
  for (const bool master_moves : {false, true}) {
    for (const double speed : {0.1, 0.3, 5.0}) {  // slip dt * v: 1e-4, 3e-4 (stick), 5e-3 (slide)
      SCOPED_TRACE(testing::Message() << "speed " << speed << " master moves " << master_moves);
      Scene s(xi, eta, depth, ks, km, 1, mu);
      if (master_moves) {
        for (std::size_t j = 0; j < 4; ++j)
          s.set_velocity(j, V3{-speed * kU[0], -speed * kU[1], -speed * kU[2]});
      } else {
        s.set_velocity(4, V3{speed * kU[0], speed * kU[1], speed * kU[2]});
      }
      const contact::InterfaceReport r = one_cycle(s);
      const double slip = kDt * speed;
      const double ft = slip < mu * depth ? k * slip : mu * fn;
      const V3 f{fn * kN[0] - ft * kU[0], fn * kN[1] - ft * kU[1], fn * kN[2] - ft * kU[2]};
      check_split(s, xi, eta, f, r);
    }
  }
}

// The stick slip stays on the surface when the surface turns. One cycle of sticking slip along
// kU, then the whole scene (master and slave) turned rigidly by 1 rad about y through the
// segment's centre, nothing moving relative to anything: the friction force must be the same
// stick force turned with the scene, k slip along -R kU. The turn takes the normal to within
// 4 degrees of -x, where the node's tangent axes switch from the x-based to the y-based pair;
// the stored slip written in the old axes would then act along kW, a quarter turn off.
TEST(ContactSet, StickSlipTurnsWithTheSurface) {
  const double ks = 800.0, km = 500.0, depth = 2e-3, mu = 0.2, xi = 0.3, eta = -0.45;
  const double k = std::min(ks, km), fn = k * depth, speed = 0.1, slip = kDt * speed;
  Scene s(xi, eta, depth, ks, km, 1, mu);
  s.set_velocity(4, V3{speed * kU[0], speed * kU[1], speed * kU[2]});
  const int threads0 = omp_get_max_threads();
  omp_set_num_threads(1);
  contact::ContactSet cs(s.model, s.mass, nullptr, 1e-4, 0.9);
  cs.start(s.packed.data());
  cs.apply(kDt, kDt, s.packed.data(), nullptr, s.fx.data(), s.fy.data(), s.fz.data());
  const V3 f1{fn * kN[0] - k * slip * kU[0], fn * kN[1] - k * slip * kU[1],
              fn * kN[2] - k * slip * kU[2]};
  expect_near(s.force(4), f1, 1e-12, "first cycle");
  // The turn: x' = c + R (x - c), R about y by `turn` (taking kN towards -x).
  const double turn = -1.0, co = std::cos(turn), si = std::sin(turn);
  const auto rotate = [&](const V3& v) {
    return V3{co * v[0] + si * v[2], v[1], -si * v[0] + co * v[2]};
  };
  for (std::size_t i = 0; i < 5; ++i) {
    double* p = &s.packed[6 * i];
    const V3 r = rotate(V3{p[0] - kCentre[0], p[1] - kCentre[1], p[2] - kCentre[2]});
    for (std::size_t d = 0; d < 3; ++d) {
      p[d] = kCentre[d] + r[d];
      p[3 + d] = 0.0;
    }
    s.fx[i] = s.fy[i] = s.fz[i] = 0.0;
  }
  const V3 n2 = rotate(kN), u2 = rotate(kU);
  ASSERT_GT(std::fabs(n2[0]), 0.995);  // past the switch of the tangent axes
  cs.apply(2.0 * kDt, kDt, s.packed.data(), nullptr, s.fx.data(), s.fy.data(), s.fz.data());
  omp_set_num_threads(threads0);
  const V3 f2{fn * n2[0] - k * slip * u2[0], fn * n2[1] - k * slip * u2[1],
              fn * n2[2] - k * slip * u2[2]};
  expect_near(s.force(4), f2, 1e-9, "after the turn");
}

// An interface past its death time (or before its birth) sets no step: its vote was kept from
// its last active cycle and went on limiting the run's step.
TEST(ContactSet, AnInterfaceOutsideItsBirthAndDeathVotesNoStep) {
  Scene s(0.0, 0.0, 2e-3, 800.0, 500.0, 1, 0.2);
  s.model.contacts.front().death = 1.5 * kDt;
  const int threads0 = omp_get_max_threads();
  omp_set_num_threads(1);
  contact::ContactSet cs(s.model, s.mass, nullptr, 1e-4, 0.9);
  cs.start(s.packed.data());
  cs.apply(kDt, kDt, s.packed.data(), nullptr, s.fx.data(), s.fy.data(), s.fz.data());
  const double alive = cs.stable_step();
  EXPECT_TRUE(std::isfinite(alive));
  EXPECT_GT(alive, 0.0);
  cs.apply(2.0 * kDt, kDt, s.packed.data(), nullptr, s.fx.data(), s.fy.data(), s.fz.data());
  EXPECT_TRUE(std::isinf(cs.stable_step())) << cs.stable_step();
  omp_set_num_threads(threads0);
}

}  // namespace test_contact_set
