// Rigid-body motion against closed forms, through a driver loop that does what the engine does
// each cycle: x_{n+1} = x_n + v dt (displacements), forces at t_{n+1}, RigidBodies::advance.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "plyform/rigid/rigid_bodies.hpp"
#include "rigid_models.hpp"

namespace plyform {
namespace {

using Vec = std::array<double, 3>;

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

struct Driver {
  explicit Driver(const core::Model& model) : m(model), rb(model) {
    const std::size_t n = m.node_count();
    for (auto* a : {&ux, &uy, &uz, &vx, &vy, &vz, &wx, &wy, &wz, &fx, &fy, &fz, &ex, &ey, &ez})
      a->assign(n, 0.0);
  }
  rigid::NodalArrays arrays() {
    return {fx.data(), fy.data(), fz.data(), ex.data(), ey.data(), ez.data(), ux.data(), uy.data(),
            uz.data(), vx.data(), vy.data(), vz.data(), wx.data(), wy.data(), wz.data()};
  }
  /// t = 0: forces at t_0, velocities for the first step.
  void start(double dt) {
    loads(0.0);
    rb.advance({0.0, 0.0, dt, 0.5 * dt}, arrays());
    dt_ = dt;
  }
  /// One cycle: positions with the current step, forces at the new time, next step dt_next.
  void step(double dt_next) {
    for (core::Index i : rb.rigid_nodes()) {
      const auto k = static_cast<std::size_t>(i);
      ux[k] += vx[k] * dt_;
      uy[k] += vy[k] * dt_;
      uz[k] += vz[k] * dt_;
    }
    t += dt_;
    loads(t);
    rb.advance({t, dt_, dt_next, 0.5 * (dt_ + dt_next)}, arrays());
    dt_ = dt_next;
  }
  Vec position(std::size_t i) const { return {m.x0[i] + ux[i], m.y0[i] + uy[i], m.z0[i] + uz[i]}; }

  const core::Model& m;
  rigid::RigidBodies rb;
  std::vector<double> ux, uy, uz, vx, vy, vz, wx, wy, wz, fx, fy, fz, ex, ey, ez;
  std::function<void(double)> loads = [](double) {};
  double t = 0.0;
  double dt_ = 0.0;
};

Vec rotate(const std::array<double, 9>& q, const Vec& r) {
  return {q[0] * r[0] + q[1] * r[1] + q[2] * r[2], q[3] * r[0] + q[4] * r[1] + q[5] * r[2],
          q[6] * r[0] + q[7] * r[1] + q[8] * r[2]};
}

/// Largest distance of a node from c + Q (X - c).
double rigid_error(const Driver& d, const Vec& c, const Vec& shift,
                   const std::array<double, 9>& q) {
  double err = 0.0;
  for (std::size_t i = 0; i < d.m.node_count(); ++i) {
    const Vec r = rotate(q, {d.m.x0[i] - c[0], d.m.y0[i] - c[1], d.m.z0[i] - c[2]});
    const Vec x = d.position(i);
    for (std::size_t k = 0; k < 3; ++k)
      err = std::max(err, std::abs(x[k] - (c[k] + shift[k] + r[k])));
  }
  return err;
}

/// Largest change of the distances from node 0 to the other nodes: 0 for a rigid motion.
double shape_error(const Driver& d) {
  const Vec x0 = d.position(0);
  double err = 0.0;
  for (std::size_t i = 1; i < d.m.node_count(); ++i) {
    const Vec x = d.position(i);
    const double a = std::hypot(x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]);
    const double b =
        std::hypot(d.m.x0[i] - d.m.x0[0], d.m.y0[i] - d.m.y0[0], d.m.z0[i] - d.m.z0[0]);
    err = std::max(err, std::abs(a - b));
  }
  return err;
}

core::Index add_curve(core::Model& m, std::vector<double> x, std::vector<double> y) {
  m.curves.push_back(core::LoadCurve{std::move(x), std::move(y)});
  return static_cast<core::Index>(m.curves.size() - 1);
}

void add_motion(core::Model& m, int dof, core::MotionKind kind, core::Index curve,
                double scale = 1.0) {
  core::RigidMotion r;
  r.part = 0;
  r.dof = dof;
  r.kind = kind;
  r.curve = curve;
  r.scale = scale;
  m.rigid_motions.push_back(r);
}

// A box offset from the origin turns about the global z axis through its centre at a constant
// prescribed angular velocity: after 10^4 steps (10 rad), every node is on its circle at the
// prescribed angle to round-off.
TEST(RigidMotion, PrescribedAngularVelocityTurnsNodesOnCircles) {
  core::Model m = test::box(0.4, 0.2, 0.1, 4, 2, 2, test::rigid_material(7850.0, 1, 7, 7));
  test::place(m, test::axis_rotation({1, 0, 0}, 0.0), {3.0, -2.0, 1.0});
  const double omega = 5.0;
  add_motion(m, 5, core::MotionKind::velocity, add_curve(m, {0.0, 10.0}, {omega, omega}));
  Driver d(m);
  const double dt = 2e-4;
  d.start(dt);
  const Vec c = d.rb.mass_properties(0).centre;
  const int steps = 10000;
  for (int s = 0; s < steps; ++s)
    d.step(dt);
  const double angle = omega * steps * dt;
  const double err = rigid_error(d, c, {0, 0, 0}, test::axis_rotation({0, 0, 1}, angle));
  EXPECT_LT(err, 1e-12);
  const auto r = d.rb.report();
  EXPECT_NEAR(r[0].omega[2], omega, 1e-12);
  EXPECT_NEAR(r[0].centre[0], c[0], 1e-13);
  EXPECT_NEAR(r[0].centre[1], c[1], 1e-13);
  for (std::size_t i = 0; i < m.node_count(); ++i)
    EXPECT_DOUBLE_EQ(d.wz[i], omega);
  RecordProperty("max_node_error_m", sci(err));
}

// Angle prescribed by a curve about the global x axis, with a varying step: the nodes are at
// the curve's angle at every step.
TEST(RigidMotion, PrescribedAngleWithVaryingStep) {
  core::Model m = test::box(0.3, 0.5, 0.2, 3, 5, 2, test::rigid_material(2700.0));
  test::place(m, test::axis_rotation({0.2, 1.0, 0.1}, 0.4), {-1.0, 0.5, 2.0});
  const core::Index c = add_curve(m, {0.0, 0.5, 1.0, 3.0}, {0.0, 1.0, -2.0, 4.0});
  add_motion(m, 3, core::MotionKind::displacement, c);
  add_motion(m, 4, core::MotionKind::velocity, add_curve(m, {0.0, 1.0}, {0.0, 0.0}));
  add_motion(m, 5, core::MotionKind::velocity, add_curve(m, {0.0, 1.0}, {0.0, 0.0}));
  Driver d(m);
  const Vec centre = d.rb.mass_properties(0).centre;
  double dt = 1e-4;
  d.start(dt);
  double worst = 0.0;
  for (int s = 0; s < 20000; ++s) {
    const double dt_next = 1e-4 * (1.0 + 0.5 * std::sin(0.01 * s));
    d.step(dt_next);
    if (s % 997 == 0) {
      const double angle = m.curves[0](d.t);
      worst =
          std::max(worst, rigid_error(d, centre, {0, 0, 0}, test::axis_rotation({1, 0, 0}, angle)));
    }
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(d.t, 1.5);
  RecordProperty("max_node_error_m", sci(worst));
}

// A free body spinning about a principal axis keeps its spin, angular momentum and energy.
TEST(RigidMotion, FreeSpinAboutAPrincipalAxisIsSteady) {
  core::Model m = test::box(0.6, 0.4, 0.2, 3, 2, 2, test::rigid_material(1000.0));
  const auto q = test::axis_rotation({1.0, -0.5, 2.0}, 0.9);
  test::place(m, q, {1.0, 1.0, 1.0});
  const rigid::MassProperties p = rigid::RigidBodies(m).mass_properties(0);
  // Initial velocities: spin omega about the body's third axis q e_3, plus a drift V0.
  const Vec axis = {q[2], q[5], q[8]};
  const double omega = 20.0;
  const Vec v0 = {0.1, -0.2, 0.3};
  m.v0x.resize(m.node_count());
  m.v0y.resize(m.node_count());
  m.v0z.resize(m.node_count());
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const Vec r = {m.x0[i] - p.centre[0], m.y0[i] - p.centre[1], m.z0[i] - p.centre[2]};
    m.v0x[i] = v0[0] + omega * (axis[1] * r[2] - axis[2] * r[1]);
    m.v0y[i] = v0[1] + omega * (axis[2] * r[0] - axis[0] * r[2]);
    m.v0z[i] = v0[2] + omega * (axis[0] * r[1] - axis[1] * r[0]);
  }
  Driver d(m);
  const double izz = p.mass * (0.6 * 0.6 + 0.4 * 0.4) / 12.0;
  const double ke0 = 0.5 * p.mass * (0.01 + 0.04 + 0.09) + 0.5 * izz * omega * omega;
  EXPECT_NEAR(d.rb.kinetic_energy(), ke0, 1e-12 * ke0);
  const double dt = 1e-4;
  d.start(dt);
  const int steps = 10000;
  for (int s = 0; s < steps; ++s)
    d.step(dt);
  const double t = steps * dt;
  const auto r = d.rb.report();
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(r[0].omega[k], omega * axis[k], 1e-11);
    EXPECT_NEAR(r[0].velocity[k], v0[k], 1e-13);
  }
  EXPECT_NEAR(d.rb.kinetic_energy(), ke0, 1e-12 * ke0);
  const double err = rigid_error(d, p.centre, {v0[0] * t, v0[1] * t, v0[2] * t},
                                 test::axis_rotation(axis, omega * t));
  // Against the closed form, the orientation carries the round-off of Omega summed over
  // 10^4 steps (2e-12 rad here); the shape itself stays rigid to round-off.
  EXPECT_LT(err, 1e-11);
  EXPECT_LT(shape_error(d), 1e-14);
  RecordProperty("max_node_error_m", sci(err));
  RecordProperty("shape_error_m", sci(shape_error(d)));
}

// A free body spinning about a general axis precesses: angular momentum stays to round-off,
// the kinetic energy to the scheme's O((omega dt)^2).
TEST(RigidMotion, FreeSpinAboutAGeneralAxisConservesMomentumAndEnergy) {
  core::Model m = test::box(0.6, 0.4, 0.2, 3, 2, 1, test::rigid_material(1000.0));
  const rigid::MassProperties p = rigid::RigidBodies(m).mass_properties(0);
  const Vec w0 = {3.0, 10.0, -6.0};
  m.v0x.resize(m.node_count());
  m.v0y.resize(m.node_count());
  m.v0z.resize(m.node_count());
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const Vec r = {m.x0[i] - p.centre[0], m.y0[i] - p.centre[1], m.z0[i] - p.centre[2]};
    m.v0x[i] = w0[1] * r[2] - w0[2] * r[1];
    m.v0y[i] = w0[2] * r[0] - w0[0] * r[2];
    m.v0z[i] = w0[0] * r[1] - w0[1] * r[0];
  }
  Driver d(m);
  const Vec l0 = {p.inertia[0] * w0[0], p.inertia[4] * w0[1], p.inertia[8] * w0[2]};
  const double ke0 = 0.5 * (w0[0] * l0[0] + w0[1] * l0[1] + w0[2] * l0[2]);
  EXPECT_NEAR(d.rb.kinetic_energy(), ke0, 1e-12 * ke0);
  const double dt = 1e-4;
  d.start(dt);
  double ke_err = 0.0, l_err = 0.0, w_change = 0.0;
  const double lnorm = std::sqrt(l0[0] * l0[0] + l0[1] * l0[1] + l0[2] * l0[2]);
  for (int s = 0; s < 20000; ++s) {
    d.step(dt);
    ke_err = std::max(ke_err, std::abs(d.rb.kinetic_energy() - ke0) / ke0);
    const auto r = d.rb.report();
    for (std::size_t k = 0; k < 3; ++k) {
      l_err = std::max(l_err, std::abs(r[0].angular_momentum[k] - l0[k]) / lnorm);
      w_change = std::max(w_change, std::abs(r[0].omega[k] - w0[k]));
    }
  }
  EXPECT_LT(l_err, 1e-13);
  EXPECT_LT(ke_err, 1e-6);
  EXPECT_GT(w_change, 1.0);  // it does precess: Omega is far from constant
  EXPECT_LT(shape_error(d), 1e-14);
  const auto r = d.rb.report();
  EXPECT_NEAR(r[0].centre[0], p.centre[0], 1e-13);
  RecordProperty("kinetic_energy_drift", sci(ke_err));
  RecordProperty("angular_momentum_drift", sci(l_err));
}

// Spin about the intermediate principal axis with a small perturbation is unstable: the body
// turns over (its intermediate axis reverses with respect to the angular momentum), while
// the energy stays.
TEST(RigidMotion, IntermediateAxisSpinTurnsOver) {
  // Box 0.1 x 0.2 x 0.3: I_xx > I_yy > I_zz; y is the intermediate axis.
  core::Model m = test::box(0.1, 0.2, 0.3, 1, 2, 3, test::rigid_material(1000.0));
  const rigid::MassProperties p = rigid::RigidBodies(m).mass_properties(0);
  const Vec w0 = {0.01, 10.0, 0.01};
  m.v0x.resize(m.node_count());
  m.v0y.resize(m.node_count());
  m.v0z.resize(m.node_count());
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const Vec r = {m.x0[i] - p.centre[0], m.y0[i] - p.centre[1], m.z0[i] - p.centre[2]};
    m.v0x[i] = w0[1] * r[2] - w0[2] * r[1];
    m.v0y[i] = w0[2] * r[0] - w0[0] * r[2];
    m.v0z[i] = w0[0] * r[1] - w0[1] * r[0];
  }
  Driver d(m);
  const double ke0 = d.rb.kinetic_energy();
  // Two nodes along the body's y axis.
  std::size_t a = 0, b = 0;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    if (m.x0[i] == 0.0 && m.z0[i] == 0.0 && m.y0[i] == 0.0)
      a = i;
    if (m.x0[i] == 0.0 && m.z0[i] == 0.0 && std::abs(m.y0[i] - 0.2) < 1e-12)
      b = i;
  }
  const double dt = 1e-4;
  d.start(dt);
  double min_cos = 1.0;
  for (int s = 0; s < 30000; ++s) {
    d.step(dt);
    const Vec xa = d.position(a), xb = d.position(b);
    // L is along global y (initially, and conserved): the body's y axis against it.
    const double dy = xb[1] - xa[1];
    min_cos = std::min(min_cos, dy / 0.2);
  }
  EXPECT_LT(min_cos, -0.9);  // turned over
  EXPECT_LT(shape_error(d), 1e-14);
  EXPECT_LT(std::abs(d.rb.kinetic_energy() - ke0) / ke0, 1e-4);
  RecordProperty("min_cos", sci(min_cos));
}

// Constant nodal forces on a free body: the centre moves F t^2 / (2 m) (exact for central
// differences with a constant step). CON1 = 1 (x fixed) removes the x motion, and the reaction
// balances F_x.
TEST(RigidMotion, ConstantForceAndCon1) {
  for (const int con1 : {0, 1}) {
    core::Model m = test::box(0.2, 0.2, 0.2, 2, 2, 2, test::rigid_material(1000.0, 1, con1, 0));
    Driver d(m);
    const double mass = d.rb.mass_properties(0).mass;
    const Vec f = {3.0, -2.0, 1.0};
    const double n = static_cast<double>(m.node_count());
    d.loads = [&](double) {
      std::fill(d.ex.begin(), d.ex.end(), f[0] / n);
      std::fill(d.ey.begin(), d.ey.end(), f[1] / n);
      std::fill(d.ez.begin(), d.ez.end(), f[2] / n);
    };
    const double dt = 1e-3;
    d.start(dt);
    for (int s = 0; s < 1000; ++s)
      d.step(dt);
    const double t = d.t;
    const auto r = d.rb.report();
    for (std::size_t k = 0; k < 3; ++k) {
      const double want = (con1 == 1 && k == 0) ? 0.0 : f[k] * t * t / (2.0 * mass);
      EXPECT_NEAR(r[0].centre[k] - 0.1, want, 1e-13) << "con1 " << con1 << " dir " << k;
      const double u = k == 0 ? d.ux[5] : (k == 1 ? d.uy[5] : d.uz[5]);  // any node
      EXPECT_NEAR(u, want, 1e-13);
      EXPECT_NEAR(r[0].force[k], f[k], 1e-13);
      EXPECT_NEAR(r[0].reaction[k], (con1 == 1 && k == 0) ? -f[0] : 0.0, 1e-12);
    }
  }
}

// *LOAD_RIGID_BODY: a force on the centre and a moment about z; omega_z = M t / I_zz.
TEST(RigidMotion, RigidBodyLoads) {
  core::Model m = test::box(0.4, 0.2, 0.1, 2, 1, 1, test::rigid_material(1000.0));
  const core::Index one = add_curve(m, {0.0, 1.0}, {1.0, 1.0});
  m.rigid_loads.push_back(core::RigidLoad{0, 1, one, 5.0});
  m.rigid_loads.push_back(core::RigidLoad{0, 5, one, 0.2});
  Driver d(m);
  const rigid::MassProperties& p = d.rb.mass_properties(0);
  const double dt = 1e-3;
  d.start(dt);
  for (int s = 0; s < 500; ++s)
    d.step(dt);
  const auto r = d.rb.report();
  const double t = d.t;
  EXPECT_NEAR(r[0].centre[1] - p.centre[1], 5.0 * t * t / (2.0 * p.mass), 1e-13);
  EXPECT_NEAR(r[0].omega[2], 0.2 * t / p.inertia[8], 1e-10);
  EXPECT_NEAR(r[0].load_force[1], 5.0, 0.0);
  EXPECT_NEAR(r[0].load_moment[2], 0.2, 0.0);
}

// Prescribed translations: a velocity curve with kinks between the steps is followed exactly
// (the centre is at the curve's integral at every step), an acceleration curve, and a
// displacement curve reached exactly.
TEST(RigidMotion, PrescribedTranslations) {
  core::Model m = test::box(0.1, 0.1, 0.1, 1, 1, 1, test::rigid_material(1000.0));
  const core::Index vel = add_curve(m, {0.0, 0.0123, 0.0377, 0.1}, {0.0, 2.0, -1.0, 0.5});
  const core::Index acc = add_curve(m, {0.0, 0.1}, {10.0, 10.0});
  const core::Index dis = add_curve(m, {0.0, 0.05, 0.1}, {0.0, 0.01, -0.02});
  add_motion(m, 0, core::MotionKind::velocity, vel, 2.0);
  add_motion(m, 1, core::MotionKind::acceleration, acc);
  add_motion(m, 2, core::MotionKind::displacement, dis);
  Driver d(m);
  const Vec c0 = d.rb.mass_properties(0).centre;
  double dt = 1e-4;
  d.start(dt);
  double ex = 0.0, ez = 0.0;
  while (d.t < 0.09) {
    const double dt_next = 1e-4 * (1.0 + 0.3 * std::cos(1e3 * d.t));
    d.step(dt_next);
    ex = std::max(ex, std::abs(d.ux[0] - 2.0 * m.curves[0].integral(d.t)));
    ez = std::max(ez, std::abs(d.uz[0] - m.curves[2](d.t)));
  }
  EXPECT_LT(ex, 1e-14);
  EXPECT_LT(ez, 1e-14);
  RecordProperty("velocity_curve_error_m", sci(ex));
  // Acceleration: v = a t, y = a t^2 / 2 to the central-difference error with a varying step.
  const auto r = d.rb.report();
  EXPECT_NEAR(r[0].centre[1] - c0[1], 5.0 * d.t * d.t, 1e-6);
  EXPECT_NEAR(r[0].velocity[1], 10.0 * d.t, 1e-9 + 1e-3 * 10.0 * 1e-4);
}

// Equilibrium: the report's force and moment are the resultants of the nodal forces applied
// (f_ext - f_int), and the body's momentum changes by them.
TEST(RigidMotion, ReportIsTheResultantOfTheNodalForces) {
  core::Model m = test::box(0.3, 0.2, 0.1, 3, 2, 1, test::rigid_material(500.0));
  test::place(m, test::axis_rotation({0, 1, 1}, 0.3), {2.0, 0.0, -1.0});
  Driver d(m);
  const rigid::MassProperties& p = d.rb.mass_properties(0);
  d.loads = [&](double t) {
    for (std::size_t i = 0; i < m.node_count(); ++i) {
      const double s = static_cast<double>(i);
      d.ex[i] = std::sin(1.3 * s + t);
      d.ey[i] = std::cos(0.7 * s);
      d.ez[i] = 0.1 * s;
      d.fx[i] = 0.5 * std::cos(s);
      d.fy[i] = -0.2;
      d.fz[i] = std::sin(2.1 * s);
    }
  };
  const double dt = 1e-3;
  d.start(dt);
  for (int s = 0; s < 10; ++s)
    d.step(dt);
  const auto r = d.rb.report();
  Vec f{}, mo{};
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const Vec g = {d.ex[i] - d.fx[i], d.ey[i] - d.fy[i], d.ez[i] - d.fz[i]};
    // Position at t: the displacement before the last step's velocities are applied.
    const Vec x = d.position(i);
    const Vec rr = {x[0] - r[0].centre[0], x[1] - r[0].centre[1], x[2] - r[0].centre[2]};
    f = {f[0] + g[0], f[1] + g[1], f[2] + g[2]};
    mo = {mo[0] + rr[1] * g[2] - rr[2] * g[1], mo[1] + rr[2] * g[0] - rr[0] * g[2],
          mo[2] + rr[0] * g[1] - rr[1] * g[0]};
  }
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(r[0].force[k], f[k], 1e-12);
    EXPECT_NEAR(r[0].moment[k], mo[k], 1e-12);
    EXPECT_NEAR(r[0].reaction[k], 0.0, 1e-12);
    EXPECT_NEAR(r[0].reaction_moment[k], 0.0, 1e-9);
  }
  (void)p;
}

}  // namespace
}  // namespace plyform
