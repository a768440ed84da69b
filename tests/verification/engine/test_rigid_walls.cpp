// Planar rigid walls (*RIGIDWALL_PLANAR) against closed forms and conservation laws:
// - an elastic bar (nu = 0) dropped on a fixed wall: the impact sends a stress wave up the bar
//   and back; the wall pushes with rho c A v0 for 2 L / c (c = sqrt(E / rho)) and the bar leaves
//   at -v0: the wall's impulse is 2 m v0, and it is the bar's momentum change to round-off;
// - a moving wall of mass M strikes a free bar at rest: the momentum along the normal of the wall
//   and the bar together is conserved to round-off, and the model's books close with the
//   wall's work booked as external work;
// - a block pushed onto the wall and sliding along it decelerates at mu N / m (Coulomb) and
//   stops at v0 m / (mu N); FRIC 1 stops its sliding at once;
// - a finite wall stops a block over its rectangle and lets one beside it fall past.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../contact/contact_decks.hpp"

namespace plyform::test {
namespace {

constexpr double kE = 210000.0, kRho = 7.85e-9;  // steel: MPa, t/mm^3 (mm, s, N)

/// A bar of n hexahedra along z, a x a across, from z0 to z0 + length, part 1 (nu = 0: the
/// 1-D wave speed sqrt(E / rho)). Without bulk viscosity unless `bulk`: it smears the impact's
/// front over a few elements (the bar released early, 1.8 % of the rebound's impulse at 50
/// elements), which is its job, not the wall's.
void bar(DeckWriter& w, double a, double z0, double length, int n, bool bulk = false) {
  if (!bulk)
    w.kw("*CONTROL_BULK_VISCOSITY").card(0.0, 0.0);
  w.kw("*PART").card("bar").card(1, 1, 1);
  w.kw("*SECTION_SOLID").card(1, 1);
  w.kw("*MAT_ELASTIC").card(1, kRho, kE, 0.0);
  w.block(1, 1, 1, 0.0, a, 0.0, a, z0, z0 + length, 1, 1, n);
}

struct BarMotion {
  double momentum = 0.0, mass = 0.0;
};

BarMotion bar_motion(const engine::Snapshot& s) {
  BarMotion b;
  for (std::size_t i = 0; i < s.model->node_count(); ++i) {
    // The half-step velocities: they hold every impulse so far (v_n holds half the last).
    b.momentum += s.nodes->mass[i] * s.nodes->vz[i];
    b.mass += s.nodes->mass[i];
  }
  return b;
}

TEST(RigidWalls, AnElasticBarReboundsWithTheClosedFormImpulse) {
  const double a = 10.0, length = 100.0, v0 = 1000.0, gap = 0.002;
  const double c = std::sqrt(kE / kRho), contact = 2.0 * length / c, t_hit = gap / v0;
  const double t_end = t_hit + 1.5 * contact;
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(t_end);
  w.kw("*DATABASE_GLSTAT").card(t_end / 50);
  w.kw("*DATABASE_RWFORC").card(contact / 100);
  w.kw("*DATABASE_BINARY_D3PLOT").card(t_end / 30);
  bar(w, a, gap, length, 50);
  w.kw("*INITIAL_VELOCITY_GENERATION").card(1, 2, 0.0, 0.0, 0.0, -v0).card(0, 0, 0, 0, 0, 0);
  w.kw("*RIGIDWALL_PLANAR_ID").card(5, "floor").card(0).card(0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
  BarMotion last;
  double mass = 0.0;
  DeckRun run;
  run.sink.on_state = [&](const engine::Snapshot& s) { last = bar_motion(s); };
  run_deck(w.text(), run);
  mass = last.mass;
  ASSERT_FALSE(run.sink.walls.empty());
  const auto& reports = run.sink.walls;
  const double impulse = reports.back().second.at(0).impulse;
  EXPECT_EQ(reports.back().second.at(0).id, 5);
  // The wall is the only force: its impulse is the bar's momentum change, to round-off.
  EXPECT_NEAR(impulse, last.momentum + mass * v0, 1e-9 * mass * v0);
  // The elastic rebound: 2 m v0 within 1 %.
  EXPECT_NEAR(impulse / (2.0 * mass * v0), 1.0, 0.01);
  // The force while the wave runs: rho c A v0, from the impulse over the middle of the contact.
  const auto impulse_at = [&](double t) {
    for (const auto& [time, r] : reports)
      if (time >= t)
        return std::pair{time, r.at(0).impulse};
    return std::pair{0.0, 0.0};
  };
  const auto [t1, j1] = impulse_at(t_hit + 0.2 * contact);
  const auto [t2, j2] = impulse_at(t_hit + 0.8 * contact);
  const double force = kRho * c * a * a * v0;
  EXPECT_NEAR((j2 - j1) / (t2 - t1) / force, 1.0, 0.02);
  // Contact lasts 2 L / c: the last report with held nodes.
  double released = 0.0;
  for (const auto& [time, r] : reports)
    if (r.at(0).held > 0)
      released = time;
  EXPECT_NEAR((released - t_hit) / contact, 1.0, 0.03);
  for (const engine::Energies& e : run.sink.energies)
    EXPECT_NEAR(e.ratio, 1.0, 0.01) << "at t = " << e.time;
}

TEST(RigidWalls, AMovingWallExchangesMomentumExactly) {
  // A wall of the bar's mass at 2 m/s strikes the bar's lower end (the normal +z: the wall
  // moves up, into the bar).
  const double a = 10.0, length = 100.0, v_wall = 2000.0, gap = 0.004;
  const double c = std::sqrt(kE / kRho), t_end = gap / v_wall + 3.0 * length / c;
  const double mass = kRho * a * a * length;
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(t_end);
  w.kw("*DATABASE_GLSTAT").card(t_end / 50);
  w.kw("*DATABASE_RWFORC").card(t_end / 50);
  w.kw("*DATABASE_BINARY_D3PLOT").card(t_end / 50);
  bar(w, a, gap, length, 40, true);  // LS-DYNA's default bulk viscosity
  w.kw("*NODE").card(9999, 0.0, 0.0, -50.0);
  w.kw("*RIGIDWALL_PLANAR_MOVING_FORCES")
      .card(0)
      .card(0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
      .card(mass, v_wall)
      .card(0, 0, 9999);
  std::vector<std::pair<double, double>> bar_momentum;  // (time, p)
  double shown_z = 0.0;
  DeckRun run;
  run.sink.on_state = [&](const engine::Snapshot& s) {
    bar_momentum.emplace_back(s.time, bar_motion(s).momentum);
    shown_z = s.nodes->uz[s.model->node_count() - 1];
  };
  run_deck(w.text(), run);
  ASSERT_EQ(run.sink.walls.size(), bar_momentum.size());
  double struck = 0.0;
  for (std::size_t k = 0; k < bar_momentum.size(); ++k) {
    const auto& r = run.sink.walls[k].second.at(0);
    ASSERT_NEAR(run.sink.walls[k].first, bar_momentum[k].first, 1e-15);
    // The bar's momentum at t_n against the wall's: the wall's velocity is that of the step
    // after t_n, and the bar's v_n the mean of its two half steps, so the sum holds to the
    // last step's impulse; the wall's cumulative impulse matches the bar exactly.
    EXPECT_NEAR(bar_momentum[k].second, r.impulse, 1e-9 * mass * v_wall);
    struck = std::max(struck, r.impulse);
  }
  const auto& last = run.sink.walls.back().second.at(0);
  EXPECT_NEAR(mass * last.velocity + last.impulse, mass * v_wall, 1e-9 * mass * v_wall)
      << "momentum along the normal: the wall's loss is the bar's gain";
  EXPECT_GT(struck, 0.3 * mass * v_wall);
  // The node that shows the wall moved with it.
  EXPECT_NEAR(shown_z, last.displacement, 1e-9 * length);
  // The books at every output, through the impact and the bulk viscosity's shortened steps: its
  // pressure and the stresses booked on dt_avg / 2 each side of their time (docs/energy.md; on
  // the new pressure alone and the steps' halves, 1.053 over the first cycles). What is left is
  // the viscous hourglass forces', booked on the step's rate.
  double worst = 0.0;
  for (const engine::Energies& e : run.sink.energies)
    worst = std::max(worst, std::abs(e.ratio - 1.0));
  EXPECT_LT(worst, 5e-4);
  std::printf("moving wall striking a bar, default bulk viscosity: ratio within %.2e of 1\n",
              worst);
  // The wall's loss of kinetic energy covers what the model gained (the impacts dissipate).
  const engine::Energies& e = run.sink.energies.back();
  const double wall_loss = 0.5 * mass * v_wall * v_wall - last.kinetic;
  EXPECT_GE(wall_loss, e.kinetic + e.internal);
  EXPECT_GT(e.kinetic + e.internal, 0.9 * wall_loss);
}

// A 10 mm steel cube pushed onto the wall z = 0 by a force F on each of its 8 nodes, sliding
// along x at v0 from t = 0: at each state time, the mean x velocity and the largest x
// displacement of the bottom nodes (on the wall).
struct Slide {
  double t = 0.0, vx = 0.0, bottom_ux = 0.0;
};
std::vector<Slide> sliding_cube(double fric, double force, double v0, double t_end) {
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(t_end);
  w.kw("*DATABASE_GLSTAT").card(t_end / 40);
  w.kw("*DATABASE_BINARY_D3PLOT").card(t_end / 40);
  w.kw("*PART").card("cube").card(1, 1, 1);
  w.kw("*SECTION_SOLID").card(1, 1);
  w.kw("*MAT_ELASTIC").card(1, kRho, kE, 0.3);
  w.block(1, 1, 1, 0.0, 10.0, 0.0, 10.0, 0.0, 10.0, 1, 1, 1);
  w.kw("*SET_NODE_LIST").card(1).ids({1, 2, 3, 4, 5, 6, 7, 8});
  w.kw("*DEFINE_CURVE").card(1).card(0.0, 1.0).card(1.0, 1.0);
  w.kw("*LOAD_NODE_SET").card(1, 3, 1, -force);
  w.kw("*INITIAL_VELOCITY_GENERATION").card(1, 2, 0.0, v0, 0.0, 0.0).card(0, 0, 0, 0, 0, 0);
  w.kw("*RIGIDWALL_PLANAR").card(0).card(0.0, 0.0, 0.0, 0.0, 0.0, 1.0, fric);
  std::vector<Slide> slide;
  DeckRun run;
  run.sink.on_state = [&](const engine::Snapshot& s) {
    Slide now{.t = s.time};
    double p = 0.0, m = 0.0;
    for (std::size_t i = 0; i < s.model->node_count(); ++i) {
      p += s.nodes->mass[i] * s.nodes->vnx[i];
      m += s.nodes->mass[i];
      if (s.model->z0[i] == 0.0)
        now.bottom_ux = std::max(now.bottom_ux, std::abs(s.nodes->ux[i]));
    }
    now.vx = p / m;
    slide.push_back(now);
  };
  run_deck(w.text(), run);
  return slide;
}

TEST(RigidWalls, CoulombFrictionStopsASlidingBlockAtMuN) {
  const double mu = 0.3, force = 100.0, v0 = 5000.0;  // N per node, mm/s
  const double mass = kRho * 1000.0, decel = mu * 8.0 * force / mass;
  const double t_stop = v0 / decel;
  // While it slides, its mean velocity falls at mu N / m (the block's shear vibration, excited
  // by the friction at its base, rides on it with a few per mille of v0).
  for (const Slide& s : sliding_cube(mu, force, v0, 1.5 * t_stop)) {
    if (s.t < 0.95 * t_stop) {
      EXPECT_NEAR(s.vx, v0 - decel * s.t, 0.01 * v0) << "at t = " << s.t << " of " << t_stop;
    } else if (s.t > 1.05 * t_stop) {
      EXPECT_LT(std::abs(s.vx), 0.03 * v0) << "stopped, vibrating, at t = " << s.t;
    }
  }
  // FRIC 1: the base does not slide (one cycle's motion at most); the rest of the block swings
  // over it, slowly enough (20 mm/s) not to lift its trailing edge off the wall.
  const double slow = 20.0;
  const std::vector<Slide> stuck = sliding_cube(1.0, force, slow, 0.2 * t_stop);
  EXPECT_LT(stuck.back().bottom_ux, 1e-2 * slow * 0.2 * t_stop);
}

TEST(RigidWalls, AFiniteWallStopsOnlyWhatFallsOnIt) {
  // Two cubes falling at 1 m/s, one over the rectangle [0, 20] x [0, 20] of the wall z = 0,
  // the other beside it.
  const double v0 = 1000.0, t_end = 2e-5;
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(t_end);
  w.kw("*DATABASE_BINARY_D3PLOT").card(t_end / 4);
  w.kw("*PART").card("cubes").card(1, 1, 1);
  w.kw("*SECTION_SOLID").card(1, 1);
  w.kw("*MAT_ELASTIC").card(1, kRho, kE, 0.3);
  w.block(1, 1, 1, 5.0, 10.0, 5.0, 10.0, 0.001, 5.001, 1, 1, 1);
  w.block(1, 101, 101, 25.0, 30.0, 5.0, 10.0, 0.001, 5.001, 1, 1, 1);
  w.kw("*INITIAL_VELOCITY_GENERATION").card(1, 2, 0.0, 0.0, 0.0, -v0).card(0, 0, 0, 0, 0, 0);
  w.kw("*RIGIDWALL_PLANAR_FINITE")
      .card(0)
      .card(0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
      .card(1.0, 0.0, 0.0, 20.0, 20.0);
  double lowest_on = 1e9, lowest_beside = 1e9;
  DeckRun run;
  run.sink.on_state = [&](const engine::Snapshot& s) {
    lowest_on = lowest_beside = 1e9;
    for (std::size_t i = 0; i < s.model->node_count(); ++i) {
      double& low = s.model->node_id[i] > 100 ? lowest_beside : lowest_on;
      low = std::min(low, s.model->z0[i] + s.nodes->uz[i]);
    }
  };
  run_deck(w.text(), run);
  EXPECT_GE(lowest_on, -1e-9) << "stopped on the wall";
  EXPECT_NEAR(lowest_beside, 0.001 - v0 * t_end, 1e-6) << "fell freely past it";
}

}  // namespace
}  // namespace plyform::test
