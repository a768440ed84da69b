// Tangential laws: Coulomb return mapping, static-dynamic decay, RCCM coupling, film shear.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

constexpr double kPenalty = 1000.0;  // MPa/mm
constexpr double kStick = 500.0;     // MPa/mm

Increment pressed(double gap, double slip_x, double slip_y, double dt = 1e-3) {
  Increment in;
  in.gap = gap;
  in.slip[0] = slip_x;
  in.slip[1] = slip_y;
  in.dt = dt;
  in.temperature = 300.0;
  in.k_normal = kPenalty;
  in.k_tangent = kStick;
  return in;
}

Parameters coulomb(double mu) {
  Parameters p = test::probe_parameters();
  p.mu = {mu, mu, -1};
  return p;
}

TEST(Coulomb, SticksBelowMuP) {
  const Law law(coulomb(0.3));
  NodeHistory h = law.initial_history(0.0);
  // P = 1000 * 1e-3 = 1 MPa: limit 0.3 MPa. A slip of 2e-4 mm gives a trial 0.1 MPa.
  const Response r = law.update(pressed(-1e-3, 2e-4, 0.0), h);
  EXPECT_DOUBLE_EQ(r.pressure, 1.0);
  EXPECT_DOUBLE_EQ(r.tau[0], -kStick * 2e-4);
  EXPECT_DOUBLE_EQ(r.tau[1], 0.0);
  EXPECT_DOUBLE_EQ(h.e_friction, 0.0);
}

TEST(Coulomb, SlipsAtMuPAgainstTheSlipDirection) {
  const Law law(coulomb(0.3));
  NodeHistory h = law.initial_history(0.0);
  const double sx = 3e-3, sy = -4e-3;  // |s| = 5e-3, trial 2.5 MPa >> 0.3
  const Response r = law.update(pressed(-1e-3, sx, sy), h);
  const double norm = std::hypot(r.tau[0], r.tau[1]);
  EXPECT_NEAR(norm, 0.3 * r.pressure, 1e-14);
  EXPECT_NEAR(r.tau[0] / norm, -0.6, 1e-14);
  EXPECT_NEAR(r.tau[1] / norm, 0.8, 1e-14);
  // Dissipation: the step's mean traction along the inelastic slip |s| - |tau|/k_t; from rest
  // (no traction at the step's start) that is half the limit.
  EXPECT_NEAR(h.e_friction, 0.5 * 0.3 * (5e-3 - 0.3 / kStick), 1e-15);
  // Continued sliding keeps the traction on the cone, and dissipates the limit times the slip.
  const double before = h.e_friction;
  const Response r2 = law.update(pressed(-1e-3, sx, sy), h);
  EXPECT_NEAR(std::hypot(r2.tau[0], r2.tau[1]), 0.3, 1e-14);
  EXPECT_NEAR(h.e_friction - before, 0.3 * 5e-3, 1e-15);
}

// The tangential books of every step against the trapezoid of the tractions, the rule by which
// the contact measures the work it does (docs/contact.md): W_t = sum (tau_n + tau_{n+1})/2 . ds
// equals what the stick spring holds plus what friction dissipated, to round-off, on a path
// that sticks, slides, turns, touches down sliding at a rising pressure, lets the pressure
// fall, lifts off mid-slide and lands again. (The backward rule, the limit times the
// inelastic slip, books twice the work on a touch-down step and misses the stick spring's
// energy at lift-off.)
TEST(Coulomb, EveryStepsTangentialBooksCloseOnTheTrapezoidOfTheTractions) {
  Parameters p = coulomb(0.3);
  p.beta0 = 0.0;  // no adhesion: contact and friction only
  p.bond_tol = 0.0;
  const Law law(p);
  NodeHistory h = law.initial_history(1e-3);
  double work = 0.0, tau_old[2] = {0.0, 0.0}, most = 0.0;
  for (int n = 0; n < 400; ++n) {
    const double t = 0.05 * n;
    const double gap = n % 97 < 6 ? 2e-4 : -1e-3 * (1.2 + std::sin(0.7 * t));
    const double sx = 4e-4 * std::cos(0.3 * t), sy = 3e-4 * std::sin(0.45 * t) + 1e-4;
    const Response r = law.update(pressed(gap, sx, sy), h);
    work -= 0.5 * (tau_old[0] + r.tau[0]) * sx + 0.5 * (tau_old[1] + r.tau[1]) * sy;
    tau_old[0] = r.tau[0];
    tau_old[1] = r.tau[1];
    const double normal = gap <= 0.0 ? 0.5 * kPenalty * gap * gap : 0.0;  // area 1
    const double books = r.stored - normal + h.e_friction;
    most = std::max(most, std::abs(work));
    ASSERT_NEAR(books, work, 1e-12 * most) << "step " << n;
  }
  EXPECT_GT(h.e_friction, 0.1 * most);  // it slid
}

TEST(Coulomb, NoFrictionInTension) {
  Parameters p = coulomb(0.5);
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);  // bonded
  const Response r = law.update(pressed(+2e-3, 1e-3, 0.0), h);
  EXPECT_EQ(h.state, NodeState::separating);
  EXPECT_LT(r.pressure, 0.0);
  EXPECT_EQ(r.tau[0], 0.0);
  EXPECT_EQ(r.tau[1], 0.0);
}

TEST(Coulomb, StaticDynamicDecayFollowsTheExponentialLaw) {
  Parameters p = coulomb(0.4);  // FS
  p.decay_dc = 2.0;             // s/mm
  p.dynamic_ratio = 0.5;        // FD = 0.2
  const Law law(p);
  for (double v : {0.0, 0.1, 1.0, 10.0}) {
    NodeHistory h = law.initial_history(0.0);
    const double dt = 1e-3;
    const Response r = law.update(pressed(-1e-3, v * dt + 1e-2, 0.0, dt), h);
    const double speed = (v * dt + 1e-2) / dt;
    const double mu = 0.2 + (0.4 - 0.2) * std::exp(-2.0 * speed);
    EXPECT_NEAR(-r.tau[0], mu * r.pressure, 1e-13) << "v = " << speed;
  }
}

TEST(Coulomb, RccmCouplingScalesWithOneMinusBeta) {
  Parameters p = coulomb(0.4);
  p.coupling = FrictionCoupling::rccm;
  p.beta0 = 0.25;
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);
  const Response r = law.update(pressed(-1e-3, 1e-2, 0.0), h);
  // No healing (zeta = 0): beta stays 0.25, mu_eff = 0.4 * 0.75.
  EXPECT_NEAR(-r.tau[0], 0.3 * r.pressure, 1e-14);

  p.beta0 = 1.0;
  const Law bonded(p);
  NodeHistory hb = bonded.initial_history(0.0);
  const Response rb = bonded.update(pressed(-1e-3, 1e-2, 0.0), hb);
  EXPECT_EQ(rb.tau[0], 0.0);  // fully bonded: no friction
}

TEST(Hydrodynamic, ShearIsViscosityTimesRateOverFilm) {
  Parameters p = test::probe_parameters();
  p.friction = FrictionModel::hydrodynamic;
  p.film_viscosity = {200.0, 200.0, -1};  // MPa s
  p.film_thickness = 0.05;                // mm
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);
  const double dt = 1e-4, vx = 2.0, vy = -1.0;  // mm/s
  const Response r = law.update(pressed(-1e-3, vx * dt, vy * dt, dt), h);
  EXPECT_NEAR(r.tau[0], -200.0 * vx / 0.05, 1e-9);
  EXPECT_NEAR(r.tau[1], -200.0 * vy / 0.05, 1e-9);
  EXPECT_NEAR(h.e_friction, 200.0 / 0.05 * (vx * vx + vy * vy) * dt, 1e-12);
  // It also acts in the cohesive zone while bonded...
  const Response open = law.update(pressed(+1e-3, vx * dt, 0.0, dt), h);
  EXPECT_EQ(h.state, NodeState::separating);
  EXPECT_NEAR(open.tau[0], -200.0 * vx / 0.05, 1e-9);
}

TEST(Hydrodynamic, NoShearOnADetachedNode) {
  Parameters p = test::probe_parameters();
  p.friction = FrictionModel::hydrodynamic;
  p.film_viscosity = {200.0, 200.0, -1};
  p.film_thickness = 0.05;
  p.beta0 = 0.0;
  const Law law(p);
  NodeHistory h = law.initial_history(0.0);
  const Response r = law.update(pressed(+1e-3, 1e-3, 0.0), h);
  EXPECT_EQ(h.state, NodeState::detached);
  EXPECT_EQ(r.tau[0], 0.0);
}

TEST(Hydrodynamic, ViscosityFollowsTemperature) {
  Parameters p = test::probe_parameters();
  p.friction = FrictionModel::hydrodynamic;
  p.film_viscosity = {1000.0, 10.0, -1};
  p.film_thickness = 0.1;
  const Law law(p);
  for (double t : {300.0, 400.0, 500.0}) {
    NodeHistory h = law.initial_history(0.0);
    Increment in = pressed(-1e-3, 1e-4, 0.0, 1e-4);
    in.temperature = t;
    const Response r = law.update(in, h);
    EXPECT_NEAR(r.tau[0], -evaluate(p.film_viscosity, p, t) * 1.0 / 0.1, 1e-9);
  }
}

}  // namespace
}  // namespace plyform::law
