#include "boundary_conditions.hpp"

#include <algorithm>
#include <cmath>

namespace plyform::engine {
namespace {

double* component(std::vector<double>& x, std::vector<double>& y, std::vector<double>& z, int d) {
  return d == 0 ? x.data() : (d == 1 ? y.data() : z.data());
}

/// The two global axes across axis k, in cyclic order (a, b, k right-handed): a positive
/// turn about k takes a towards b.
constexpr std::array<int, 2> across(int k) {
  return {(k + 1) % 3, (k + 2) % 3};
}

/// Velocity over a step of length dt that turns the relative position r = (r_a, r_b) by the
/// angle `turn`: ((R(turn) - I) r) / dt. cos - 1 is written -2 sin^2(turn/2), which keeps its
/// digits for the small angles of one step.
std::array<double, 2> chord_velocity(double ra, double rb, double turn, double dt) {
  const double s = std::sin(turn);
  const double h = std::sin(0.5 * turn);
  const double c1 = -2.0 * h * h;  // cos(turn) - 1
  return {(c1 * ra - s * rb) / dt, (s * ra + c1 * rb) / dt};
}

}  // namespace

BoundaryConditions::BoundaryConditions(const core::Model& model)
    : model_(model), constrained_(3 * model.node_count(), 0) {
  for (const core::FixedDofs& f : model.fixed) {
    for (int d = 0; d < 3; ++d) {
      // A local constraint acts on every global component (its reaction is the velocity change
      // the projection makes, m (v - v_free) / dt, along the fixed local axes).
      const bool fixed = f.local ? (f.dofs & 7u) != 0 : (f.dofs & (1u << d)) != 0;
      if (fixed)
        constrained_[3 * static_cast<std::size_t>(f.node) + static_cast<std::size_t>(d)] = 1;
    }
  }
  for (const core::PrescribedMotion& m : model.motions) {
    const std::size_t base = 3 * static_cast<std::size_t>(m.node);
    if (m.direction < 3) {
      constrained_[base + static_cast<std::size_t>(m.direction)] = 1;
    } else {
      for (int d : across(m.direction - 3))
        constrained_[base + static_cast<std::size_t>(d)] = 1;
    }
  }
  for (std::size_t i = 0; i < model.node_count(); ++i) {
    if (constrained_[3 * i] || constrained_[3 * i + 1] || constrained_[3 * i + 2]) {
      constrained_nodes_.push_back(static_cast<core::Index>(i));
    }
  }
  std::vector<unsigned char> pressed(model.node_count(), 0);
  for (const std::array<core::Index, 4>& seg : model.pressure_segments) {
    for (core::Index i : seg)
      pressed[static_cast<std::size_t>(i)] = 1;
  }
  for (std::size_t i = 0; i < pressed.size(); ++i) {
    if (pressed[i])
      pressure_nodes_.push_back(static_cast<core::Index>(i));
  }
}

void BoundaryConditions::loads(double t, NodalState& s) const {
  // External forces are non-zero only at loaded nodes: reset those, then add every load.
  for (const core::NodalLoad& l : model_.loads)
    component(s.ex, s.ey, s.ez, l.direction)[l.node] = 0.0;
  for (core::Index i : pressure_nodes_)
    s.ex[i] = s.ey[i] = s.ez[i] = 0.0;
  for (const core::NodalLoad& l : model_.loads) {
    const double f = l.scale * model_.curves[static_cast<std::size_t>(l.curve)](t);
    component(s.ex, s.ey, s.ez, l.direction)[l.node] += f;
  }
  for (const core::PressureLoad& load : model_.pressure_loads) {
    if (t < load.arrival)
      continue;
    const double p = load.scale * model_.curves[static_cast<std::size_t>(load.curve)](t);
    if (p == 0.0)
      continue;
    for (std::size_t k = load.first; k < load.first + load.count; ++k)
      press_segment(model_.pressure_segments[k], p, s);
  }
}

// The nodal forces of pressure p on one segment at its current position: f_a = -p times the
// integral of N_a (x,xi x x,eta) over the bilinear surface. With x = a0 + a1 xi + a2 eta +
// a3 xi eta, the area vector x,xi x x,eta = c0 + xi c1 + eta c2 is linear (c0 = a1 x a2,
// c1 = a1 x a3, c2 = a3 x a2: a3 x a3 vanishes), so the integral is exact in closed form,
// f_a = -p (c0 + (xi_a c1 + eta_a c2) / 3): on a warped segment too, the forces' power is
// -p times the rate of the volume the surface sweeps (the external work is p dV). They sum
// to -p times the segment's area vector. A triangle: -p A / 3 on each corner.
void BoundaryConditions::press_segment(const std::array<core::Index, 4>& seg, double p,
                                       NodalState& s) const {
  double x[4][3];
  for (int a = 0; a < 4; ++a) {
    const auto i = static_cast<std::size_t>(seg[static_cast<std::size_t>(a)]);
    x[a][0] = model_.x0[i] + s.ux[i];
    x[a][1] = model_.y0[i] + s.uy[i];
    x[a][2] = model_.z0[i] + s.uz[i];
  }
  const auto cross = [](const double* u, const double* v, double* w) {
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
  };
  double f[4][3];
  int corners = 4;
  if (seg[2] == seg[3]) {
    corners = 3;
    double e1[3], e2[3], area[3];
    for (int d = 0; d < 3; ++d) {
      e1[d] = x[1][d] - x[0][d];
      e2[d] = x[2][d] - x[0][d];
    }
    cross(e1, e2, area);  // twice the area vector
    for (int a = 0; a < 3; ++a)
      for (int d = 0; d < 3; ++d)
        f[a][d] = -p * area[d] / 6.0;
  } else {
    double a1[3], a2[3], a3[3];
    for (int d = 0; d < 3; ++d) {
      a1[d] = 0.25 * (-x[0][d] + x[1][d] + x[2][d] - x[3][d]);
      a2[d] = 0.25 * (-x[0][d] - x[1][d] + x[2][d] + x[3][d]);
      a3[d] = 0.25 * (x[0][d] - x[1][d] + x[2][d] - x[3][d]);
    }
    double c0[3], c1[3], c2[3];
    cross(a1, a2, c0);
    cross(a1, a3, c1);
    cross(a3, a2, c2);
    constexpr double xi[4] = {-1.0, 1.0, 1.0, -1.0};
    constexpr double eta[4] = {-1.0, -1.0, 1.0, 1.0};
    for (int a = 0; a < 4; ++a)
      for (int d = 0; d < 3; ++d)
        f[a][d] = -p * (c0[d] + (xi[a] * c1[d] + eta[a] * c2[d]) / 3.0);
  }
  for (int a = 0; a < corners; ++a) {
    const auto i = static_cast<std::size_t>(seg[static_cast<std::size_t>(a)]);
    s.ex[i] += f[a][0];
    s.ey[i] += f[a][1];
    s.ez[i] += f[a][2];
  }
}

void BoundaryConditions::constrain(const StepTimes& step, const double* const old[3],
                                   NodalState& s) const {
  const double t = step.t, dt = step.dt, dt_avg = step.dt_avg;
  for (const core::FixedDofs& f : model_.fixed) {
    const auto n = static_cast<std::size_t>(f.node);
    if (f.local) {
      // Remove the velocity along each fixed local axis (the axes are orthonormal, so one
      // projection after the other leaves each removed component at 0).
      for (std::size_t k = 0; k < 3; ++k) {
        if (!(f.dofs & (1u << k)))
          continue;
        const std::array<double, 3>& e = f.axes[k];
        const double along = s.vx[n] * e[0] + s.vy[n] * e[1] + s.vz[n] * e[2];
        s.vx[n] -= along * e[0];
        s.vy[n] -= along * e[1];
        s.vz[n] -= along * e[2];
      }
      continue;
    }
    if (f.dofs & core::dof_x)
      s.vx[n] = 0.0;
    if (f.dofs & core::dof_y)
      s.vy[n] = 0.0;
    if (f.dofs & core::dof_z)
      s.vz[n] = 0.0;
  }
  const double t_mid = t + 0.5 * dt;
  const double* const x0[3] = {model_.x0.data(), model_.y0.data(), model_.z0.data()};
  double* const u[3] = {s.ux.data(), s.uy.data(), s.uz.data()};
  double* const v[3] = {s.vx.data(), s.vy.data(), s.vz.data()};
  for (const core::PrescribedMotion& m : model_.motions) {
    if (t_mid < m.birth || t_mid > m.death)
      continue;
    const core::LoadCurve& c = model_.curves[static_cast<std::size_t>(m.curve)];
    const auto n = static_cast<std::size_t>(m.node);
    if (step.hold) {
      // The end of the run: the velocity at the end time is the last step's, not one read
      // from the curve beyond the end (a displacement that stops there would stop its node in
      // a step that is never taken, and its kinetic energy would vanish from the final books).
      if (m.direction < 3) {
        const auto d = static_cast<std::size_t>(m.direction);
        v[d][n] = old[d][n];
      } else {
        for (int k : across(m.direction - 3))
          v[static_cast<std::size_t>(k)][n] = old[static_cast<std::size_t>(k)][n];
      }
      continue;
    }
    if (m.direction < 3) {
      const auto d = static_cast<std::size_t>(m.direction);
      switch (m.kind) {
        case core::MotionKind::velocity:
          v[d][n] = m.scale * c(t_mid);
          break;
        case core::MotionKind::displacement:
          if (m.birth > 0.0) {
            // Born later: the curve is read from BIRTH and moves the node on from where it is
            // then (the step's share of f(t - BIRTH) - f(0)).
            v[d][n] = m.scale * (c(t + dt - m.birth) - c(std::max(t - m.birth, 0.0))) / dt;
          } else {
            // Reach the prescribed displacement exactly at the end of the step.
            v[d][n] = (m.scale * c(t + dt) - u[d][n]) / dt;
          }
          break;
        case core::MotionKind::acceleration:
          v[d][n] = old[d][n] + m.scale * c(t) * dt_avg;
          break;
      }
      continue;
    }
    // Turning about the axis through (axis[0], axis[1]) across the two axes a, b.
    const auto [ia, ib] = across(m.direction - 3);
    const auto a = static_cast<std::size_t>(ia), b = static_cast<std::size_t>(ib);
    std::array<double, 2> w{};
    if (m.kind == core::MotionKind::displacement && m.birth > 0.0) {
      // Born later: the curve's angle is read from BIRTH and turns the node on from where it is
      // then (a folding flap carried along by the panel it hangs on): each step turns the
      // present position by the step's share of f(t - BIRTH) - f(0).
      const double ra = x0[a][n] + u[a][n] - m.axis[0];
      const double rb = x0[b][n] + u[b][n] - m.axis[1];
      const double turn = m.scale * (c(t + dt - m.birth) - c(std::max(t - m.birth, 0.0)));
      w = chord_velocity(ra, rb, turn, dt);
    } else if (m.kind == core::MotionKind::displacement) {
      // The angle at the end of the step turns the initial position about the axis; the step's
      // velocity lands the node there exactly (as for a prescribed displacement), so the node
      // stays on its circle to round-off whatever the step.
      const double ra0 = x0[a][n] - m.axis[0], rb0 = x0[b][n] - m.axis[1];
      const std::array<double, 2> target = chord_velocity(ra0, rb0, m.scale * c(t + dt), 1.0);
      w = {(target[0] - u[a][n]) / dt, (target[1] - u[b][n]) / dt};
    } else {
      // Velocity and acceleration turn the node's present position by the step's angle: a turn
      // (not the tangent velocity w x r) keeps the radius, and the angle advances by the
      // midpoint rule's integral of the angular velocity.
      const double ra = x0[a][n] + u[a][n] - m.axis[0];
      const double rb = x0[b][n] + u[b][n] - m.axis[1];
      double omega = 0.0;
      if (m.kind == core::MotionKind::velocity) {
        omega = m.scale * c(t_mid);
      } else {
        // The angular velocity of the step just taken: the angle between the position before
        // it and now (exact for the chord velocities set here), or at t = 0 the initial
        // velocity's; plus the angular acceleration over the interval between the half steps.
        const double r2 = ra * ra + rb * rb;
        double previous = 0.0;
        if (step.dt_prev > 0.0) {
          const double pa = ra - old[a][n] * step.dt_prev, pb = rb - old[b][n] * step.dt_prev;
          previous = std::atan2(pa * rb - pb * ra, pa * ra + pb * rb) / step.dt_prev;
        } else if (r2 > 0.0) {
          previous = (ra * old[b][n] - rb * old[a][n]) / r2;
        }
        omega = previous + m.scale * c(t) * dt_avg;
      }
      w = chord_velocity(ra, rb, omega * dt, dt);
    }
    v[a][n] = w[0];
    v[b][n] = w[1];
  }
}

}  // namespace plyform::engine
