#include "boundary_conditions.hpp"

#include <algorithm>

namespace plyform::engine {
namespace {

double* component(std::vector<double>& x, std::vector<double>& y, std::vector<double>& z, int d) {
  return d == 0 ? x.data() : (d == 1 ? y.data() : z.data());
}

}  // namespace

BoundaryConditions::BoundaryConditions(const core::Model& model)
    : model_(model), constrained_(3 * model.node_count(), 0) {
  for (const core::FixedDofs& f : model.fixed) {
    for (int d = 0; d < 3; ++d) {
      if (f.dofs & (1u << d))
        constrained_[3 * static_cast<std::size_t>(f.node) + d] = 1;
    }
  }
  for (const core::PrescribedMotion& m : model.motions) {
    constrained_[3 * static_cast<std::size_t>(m.node) + static_cast<std::size_t>(m.direction)] = 1;
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

void BoundaryConditions::constrain(double t, double dt, double dt_avg, const double* const old[3],
                                   NodalState& s) const {
  for (const core::FixedDofs& f : model_.fixed) {
    const auto n = static_cast<std::size_t>(f.node);
    if (f.dofs & core::dof_x)
      s.vx[n] = 0.0;
    if (f.dofs & core::dof_y)
      s.vy[n] = 0.0;
    if (f.dofs & core::dof_z)
      s.vz[n] = 0.0;
  }
  const double t_mid = t + 0.5 * dt;
  for (const core::PrescribedMotion& m : model_.motions) {
    if (t_mid < m.birth || t_mid > m.death)
      continue;
    const core::LoadCurve& c = model_.curves[static_cast<std::size_t>(m.curve)];
    double* v = component(s.vx, s.vy, s.vz, m.direction);
    const double* u =
        m.direction == 0 ? s.ux.data() : (m.direction == 1 ? s.uy.data() : s.uz.data());
    switch (m.kind) {
      case core::MotionKind::velocity:
        v[m.node] = m.scale * c(t_mid);
        break;
      case core::MotionKind::displacement:
        // Reach the prescribed displacement exactly at the end of the step.
        v[m.node] = (m.scale * c(t + dt) - u[m.node]) / dt;
        break;
      case core::MotionKind::acceleration:
        v[m.node] = old[m.direction][m.node] + m.scale * c(t) * dt_avg;
        break;
    }
  }
}

}  // namespace plyform::engine
