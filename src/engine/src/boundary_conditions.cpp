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
}

void BoundaryConditions::loads(double t, NodalState& s) const {
  // External forces are non-zero only at loaded nodes: reset those, then add every load.
  for (const core::NodalLoad& l : model_.loads)
    component(s.ex, s.ey, s.ez, l.direction)[l.node] = 0.0;
  for (const core::NodalLoad& l : model_.loads) {
    const double f = l.scale * model_.curves[static_cast<std::size_t>(l.curve)](t);
    component(s.ex, s.ey, s.ez, l.direction)[l.node] += f;
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
