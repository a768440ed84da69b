#pragma once
// Runtime models built in code for the solver's verification tests: structured hexahedral
// boxes, with helpers to find nodes by position and to constrain them.

#include <cmath>
#include <functional>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::test {

/// A box [0, lx] x [0, ly] x [0, lz] of nx * ny * nz hexahedra (one block, one part, one
/// material), nodes numbered x fastest, ids from 1.
inline core::Model box(double lx, double ly, double lz, int nx, int ny, int nz,
                       core::Material material,
                       core::SolidFormulation formulation = core::SolidFormulation::one_point) {
  core::Model m;
  const auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        m.node_id.push_back(id(i, j, k) + 1);
        m.x0.push_back(lx * i / nx);
        m.y0.push_back(ly * j / ny);
        m.z0.push_back(lz * k / nz);
      }
  core::SolidBlock b;
  b.formulation = formulation;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        b.element_id.push_back(static_cast<core::GlobalId>(b.element_id.size() + 1));
        const int c[8] = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        for (int n : c)
          b.connectivity.push_back(n);
      }
  m.materials.push_back(material);
  m.parts.push_back(core::Part{1, "box", 0});
  m.solid_blocks.push_back(std::move(b));
  m.controls.tssfac = 0.9;
  core::colour_element_blocks(m);
  return m;
}

/// Indices of the nodes for which pred(x, y, z) holds.
inline std::vector<core::Index> nodes_where(
    const core::Model& m, const std::function<bool(double, double, double)>& pred) {
  std::vector<core::Index> out;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    if (pred(m.x0[i], m.y0[i], m.z0[i]))
      out.push_back(static_cast<core::Index>(i));
  }
  return out;
}

inline void fix(core::Model& m, const std::vector<core::Index>& nodes, unsigned dofs) {
  for (core::Index n : nodes)
    m.fixed.push_back(core::FixedDofs{n, dofs});
}

/// Adds a curve and returns its index.
inline core::Index add_curve(core::Model& m, std::vector<double> x, std::vector<double> y) {
  m.curves.push_back(core::LoadCurve{std::move(x), std::move(y)});
  return static_cast<core::Index>(m.curves.size() - 1);
}

inline void prescribe(core::Model& m, const std::vector<core::Index>& nodes, int direction,
                      core::MotionKind kind, core::Index curve, double scale = 1.0) {
  for (core::Index n : nodes) {
    core::PrescribedMotion pm;
    pm.node = n;
    pm.direction = direction;
    pm.kind = kind;
    pm.curve = curve;
    pm.scale = scale;
    m.motions.push_back(pm);
  }
}

inline bool near(double a, double b) {
  return std::abs(a - b) < 1e-9;
}

}  // namespace plyform::test
