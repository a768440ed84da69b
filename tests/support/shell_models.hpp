#pragma once
// Shell plates built in code for the shell verification tests.

#include <cmath>

#include "plyform/core/model.hpp"

namespace plyform::test {

/// A flat plate [0, lx] x [0, ly] in the z = 0 plane, nx * ny Belytschko-Tsay quads of
/// thickness t, one block, ids from 1, nodes x fastest.
inline core::Model plate(double lx, double ly, int nx, int ny, double t, core::Material material,
                         int nip = 5) {
  core::Model m;
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.node_id.push_back(id(i, j) + 1);
      m.x0.push_back(lx * i / nx);
      m.y0.push_back(ly * j / ny);
      m.z0.push_back(0.0);
    }
  core::ShellBlock b;
  b.nip = nip;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      b.element_id.push_back(static_cast<core::GlobalId>(b.element_id.size() + 1));
      for (int n : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) {
        b.connectivity.push_back(n);
        b.thickness.push_back(t);
      }
    }
  m.materials.push_back(material);
  m.parts.push_back(core::Part{1, "plate", 0});
  m.shell_blocks.push_back(std::move(b));
  m.controls.tssfac = 0.9;
  core::colour_element_blocks(m);
  return m;
}

}  // namespace plyform::test
