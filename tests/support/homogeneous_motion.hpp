#pragma once
// Homogeneous in-plane motions prescribed at every node of a model built in code (the
// material-point tests of shells: picture frame, rigid rotation).

#include <cmath>
#include <functional>
#include <utility>

#include "plyform/core/model.hpp"
#include "solid_models.hpp"

namespace plyform::test {

// Every node (or those `driven` picks) follows x = F(s) X, s from 0 to 1 over `end` in k steps
// of the tabulated motion; every node keeps z and its rotations.
template <class F>
inline void prescribe_homogeneous(core::Model& m, double end, int k, F&& deformation,
                                  const std::function<bool(std::size_t)>& driven = {}) {
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const auto node = static_cast<core::Index>(i);
    if (driven && !driven(i)) {
      m.fixed.push_back({node, core::dof_z | core::dof_rx | core::dof_ry | core::dof_rz});
      continue;
    }
    std::vector<double> t, ux, uy;
    for (int s = 0; s <= k; ++s) {
      double f[2][2];
      deformation(static_cast<double>(s) / k, f);
      t.push_back(end * s / k);
      ux.push_back(f[0][0] * m.x0[i] + f[0][1] * m.y0[i] - m.x0[i]);
      uy.push_back(f[1][0] * m.x0[i] + f[1][1] * m.y0[i] - m.y0[i]);
    }
    prescribe(m, {node}, 0, core::MotionKind::displacement, add_curve(m, t, ux));
    prescribe(m, {node}, 1, core::MotionKind::displacement, add_curve(m, t, uy));
    m.fixed.push_back({node, core::dof_z | core::dof_rx | core::dof_ry | core::dof_rz});
  }
}

// The picture frame: the families along the frame's edges turn towards each other, each edge
// keeping its length: F = [[cos g/2, sin g/2], [sin g/2, cos g/2]], the angle between the
// families 90 degrees - g.
inline void picture_frame(double gamma, double f[2][2]) {
  f[0][0] = f[1][1] = std::cos(0.5 * gamma);
  f[0][1] = f[1][0] = std::sin(0.5 * gamma);
}

// The work per initial area of an isotropic hypoelastic plane-stress matrix (E, nu) of
// thickness t in the picture frame to `gamma`: F = [[c, s], [s, c]] stretches along the
// diagonals by c + s and c - s without rotating, so the matrix is elastic in the log strains
// e1 = ln(c + s), e2 = ln(c - s), with the thickness strain -nu/(1 - nu)(e1 + e2); the work is
// integral J (s1 de1 + s2 de2), by the midpoint rule.
inline double picture_frame_matrix_work(double young, double nu, double gamma, double t) {
  const double c11 = young / (1 - nu * nu);
  const auto strains = [](double g) {
    return std::pair{std::log(std::cos(g / 2) + std::sin(g / 2)),
                     std::log(std::cos(g / 2) - std::sin(g / 2))};
  };
  double work = 0.0;
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    const auto [a1, a2] = strains(gamma * i / steps);
    const auto [b1, b2] = strains(gamma * (i + 1) / steps);
    const double m1 = 0.5 * (a1 + b1), m2 = 0.5 * (a2 + b2);
    const double jac = std::exp((m1 + m2) * (1.0 - nu / (1.0 - nu)));
    work += t * jac * (c11 * (m1 + nu * m2) * (b1 - a1) + c11 * (m2 + nu * m1) * (b2 - a2));
  }
  return work;
}

}  // namespace plyform::test
