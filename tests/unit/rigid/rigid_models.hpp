#pragma once
// Rigid-body test models: hex boxes (tests/support/solid_models.hpp) and shell plates.

#include <array>
#include <cmath>

#include "plyform/core/model.hpp"
#include "solid_models.hpp"

namespace plyform::test {

inline core::RigidMaterial rigid_material(double rho, int cmo = 0, int con1 = 0, int con2 = 0) {
  core::RigidMaterial m;
  m.density = rho;
  m.young = 2.1e11;
  m.poisson = 0.3;
  m.cmo = cmo;
  m.con1 = con1;
  m.con2 = con2;
  return m;
}

/// A plate [0, a] x [0, b] in the plane z = 0 of nx * ny shells, thickness t(x, y) at the nodes.
template <typename T>
core::Model plate(double a, double b, int nx, int ny, T&& thickness, core::Material material) {
  core::Model m;
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.node_id.push_back(id(i, j) + 1);
      m.x0.push_back(a * i / nx);
      m.y0.push_back(b * j / ny);
      m.z0.push_back(0.0);
    }
  core::ShellBlock s;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      s.element_id.push_back(static_cast<core::GlobalId>(s.element_id.size() + 1));
      const int c[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      for (int n : c) {
        s.connectivity.push_back(n);
        const auto k = static_cast<std::size_t>(n);
        s.thickness.push_back(thickness(m.x0[k], m.y0[k]));
      }
    }
  m.materials.push_back(material);
  m.parts.push_back(core::Part{1, "plate", 0});
  m.shell_blocks.push_back(std::move(s));
  return m;
}

/// Moves every node x -> c + Q x (Q a rotation matrix, row-major).
inline void place(core::Model& m, const std::array<double, 9>& q, const std::array<double, 3>& c) {
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const double x = m.x0[i], y = m.y0[i], z = m.z0[i];
    m.x0[i] = c[0] + q[0] * x + q[1] * y + q[2] * z;
    m.y0[i] = c[1] + q[3] * x + q[4] * y + q[5] * z;
    m.z0[i] = c[2] + q[6] * x + q[7] * y + q[8] * z;
  }
}

/// Rotation by angle about the unit axis n (Rodrigues), row-major.
inline std::array<double, 9> axis_rotation(std::array<double, 3> n, double angle) {
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& c : n)
    c /= len;
  const double c = std::cos(angle), s = std::sin(angle), k = 1.0 - c;
  return {c + k * n[0] * n[0],        k * n[0] * n[1] - s * n[2], k * n[0] * n[2] + s * n[1],
          k * n[1] * n[0] + s * n[2], c + k * n[1] * n[1],        k * n[1] * n[2] - s * n[0],
          k * n[2] * n[0] - s * n[1], k * n[2] * n[1] + s * n[0], c + k * n[2] * n[2]};
}

}  // namespace plyform::test
