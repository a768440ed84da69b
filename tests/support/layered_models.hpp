#pragma once
// Multi-layer blanks built in code: flat layers stacked along z, each its own mesh (the middle
// layer's shifted by a third of an element, as separately meshed layers are), joined by one-way
// contacts (each outer layer the slave of the middle one), with a rigid tool plate above. For the
// decomposition's tests and its scale study (bench/decomposition_scale.cpp).

#include <array>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::test {

struct LayeredBlankOptions {
  int nx = 24, ny = 24;  ///< elements per layer along x and y
  double size = 1.5;     ///< element size
  std::array<double, 3> thickness{0.25, 1.0, 0.25};
  core::ShellFormulation formulation = core::ShellFormulation::belytschko_tsay;
  int nip = 5;
  bool tool = true;  ///< a rigid plate over the blank, the top layer its slave
};

/// Adds a flat nx x ny quad mesh at height z, shifted by (dx, dy), to block `b`; returns the
/// index of its first node.
inline core::Index add_layer_mesh(core::Model& m, core::ShellBlock& b, int nx, int ny, double h,
                                  double z, double dx, double dy, double t) {
  const auto first = static_cast<core::Index>(m.node_count());
  const auto id = [&](int i, int j) { return first + j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.node_id.push_back(static_cast<core::GlobalId>(m.node_count() + 1));
      m.x0.push_back(dx + h * i);
      m.y0.push_back(dy + h * j);
      m.z0.push_back(z);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      b.element_id.push_back(static_cast<core::GlobalId>(b.element_id.size() + 1));
      for (core::Index n : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) {
        b.connectivity.push_back(n);
        b.thickness.push_back(t);
      }
    }
  return first;
}

/// A one-way contact pass: the nodes [slave_first, slave_first + slave_count) against the faces
/// of block `master` (a flat mesh: its elements are the segments).
inline core::ContactPass layer_pass(core::Index slave_first, std::size_t slave_count,
                                    double slave_offset, const core::ShellBlock& master,
                                    double master_offset) {
  core::ContactPass p;
  for (std::size_t k = 0; k < slave_count; ++k) {
    p.slave_nodes.push_back(slave_first + static_cast<core::Index>(k));
    p.slave_offset.push_back(slave_offset);
    p.slave_area.push_back(1.0);
    p.slave_stiffness.push_back(1.0);
  }
  p.segments = master.connectivity;
  p.segment_offset.assign(master.size(), master_offset);
  p.segment_one_sided.assign(master.size(), 0);
  p.segment_depth.assign(master.size(), 0.0);
  p.segment_stiffness.assign(master.size(), 1.0);
  return p;
}

/// The three-layer blank (bottom skin, core, top skin: shell blocks 0, 1, 2, parts 1-3) with its
/// two interfaces and, when asked, the rigid tool (block 3, part 4) in contact with the top skin.
inline core::Model layered_blank(const LayeredBlankOptions& o) {
  core::Model m;
  m.materials.push_back(core::PiecewiseLinearPlasticity{});
  m.materials.push_back(core::ElasticMaterial{});
  m.materials.push_back(core::RigidMaterial{});
  const double z[3] = {0.0, 0.5 * (o.thickness[0] + o.thickness[1]),
                       0.5 * o.thickness[0] + o.thickness[1] + 0.5 * o.thickness[2]};
  std::array<core::Index, 4> first{};
  for (int layer = 0; layer < 3; ++layer) {
    core::ShellBlock b;
    b.formulation = o.formulation;
    b.nip = o.nip;
    b.part = layer;
    b.material = layer == 1 ? 1 : 0;
    // The core is meshed on its own: shifted by a third of an element, one element fewer each way.
    const bool core_layer = layer == 1;
    first[static_cast<std::size_t>(layer)] =
        add_layer_mesh(m, b, core_layer ? o.nx - 1 : o.nx, core_layer ? o.ny - 1 : o.ny, o.size,
                       z[layer], core_layer ? o.size / 3.0 : 0.0, core_layer ? o.size / 3.0 : 0.0,
                       o.thickness[static_cast<std::size_t>(layer)]);
    m.parts.push_back(core::Part{layer + 1, "layer", b.material});
    m.shell_blocks.push_back(std::move(b));
  }
  const std::size_t skin_nodes = static_cast<std::size_t>((o.nx + 1) * (o.ny + 1));
  for (int skin : {0, 2}) {
    core::ContactInterface c;
    c.id = skin == 0 ? 1 : 2;
    c.keyword = "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE";
    c.cohesive = true;
    c.passes.push_back(layer_pass(first[static_cast<std::size_t>(skin)], skin_nodes,
                                  0.5 * o.thickness[static_cast<std::size_t>(skin)],
                                  m.shell_blocks[1], 0.5 * o.thickness[1]));
    m.contacts.push_back(std::move(c));
  }
  if (o.tool) {
    core::ShellBlock b;
    b.part = 3;
    b.material = 2;
    const double top = z[2] + 0.5 * o.thickness[2] + 0.5;
    first[3] = add_layer_mesh(m, b, o.nx / 2, o.ny / 2, 2.0 * o.size, top, 0.0, 0.0, 1.0);
    m.parts.push_back(core::Part{4, "tool", 2});
    m.shell_blocks.push_back(std::move(b));
    core::ContactInterface c;
    c.id = 3;
    c.keyword = "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE";
    c.kind = core::ContactKind::forming;
    c.passes.push_back(
        layer_pass(first[2], skin_nodes, 0.5 * o.thickness[2], m.shell_blocks[3], 0.5));
    m.contacts.push_back(std::move(c));
  }
  m.controls.tssfac = 0.9;
  return m;
}

}  // namespace plyform::test
