#include "build_rigid_walls.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>

#include "id_table.hpp"
#include "node_roles.hpp"

namespace plyform::setup {

using core::Index;
using detail::cat;

namespace {

using Vec = std::array<double, 3>;

Vec unit(const Vec& a) {
  const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / l, a[1] / l, a[2] / l};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

void build_rigid_walls(const model::ModelDesc& desc, core::Model& m,
                       std::vector<keyword::Diagnostic>& warnings) {
  if (desc.rigid_walls.empty())
    return;
  const std::size_t n = m.node_count();
  std::unordered_map<int, Index> index;
  for (std::size_t i = 0; i < n; ++i)
    index.emplace(static_cast<int>(m.node_id[i]), static_cast<Index>(i));
  std::unordered_map<int, const model::SetListDesc*> node_sets;
  for (const model::SetListDesc& s : desc.node_sets)
    node_sets.emplace(s.id, &s);
  std::vector<unsigned char> why = node_roles(m);
  for (const core::TiedInterface& t : m.tied)  // a tie moves its slaves
    for (Index i : t.slaves)
      if (why[static_cast<std::size_t>(i)] == kFreeNode)
        why[static_cast<std::size_t>(i)] = kHeldNode;
  // A node lies behind a wall when it is further than this below it (round-off of the
  // coordinates: a node written on the wall is in front of it).
  double size = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    size = std::max({size, std::abs(m.x0[i]), std::abs(m.y0[i]), std::abs(m.z0[i])});
  const double tolerance = 1e-9 * std::max(size, 1e-300);

  std::size_t place = 0;
  for (const model::RigidWallDesc& d : desc.rigid_walls) {
    ++place;
    core::RigidWall w;
    w.id = d.id > 0 ? d.id : static_cast<core::GlobalId>(place);
    w.heading = d.heading;
    w.origin = d.tail;
    w.normal = unit({d.head[0] - d.tail[0], d.head[1] - d.tail[1], d.head[2] - d.tail[2]});
    w.finite = d.finite;
    if (d.finite) {
      Vec l{d.edge[0] - d.tail[0], d.edge[1] - d.tail[1], d.edge[2] - d.tail[2]};
      const double along = dot(l, w.normal);
      for (std::size_t k = 0; k < 3; ++k)
        l[k] -= along * w.normal[k];
      w.edge_l = unit(l);
      w.edge_m = cross(w.normal, w.edge_l);
      w.length_l = d.length_l;
      w.length_m = d.length_m;
    }
    w.friction = d.fric;
    w.mass = d.moving ? d.mass : 0.0;
    w.velocity0 = d.moving ? d.v0 : 0.0;
    w.birth = d.birth;
    w.death = d.death;
    for (int id : d.display)
      if (id != 0)
        w.display_nodes.push_back(index.at(id));

    std::vector<unsigned char> pick(n, d.nsid == 0 ? 1 : 0);
    if (d.nsid != 0)
      for (int id : node_sets.at(d.nsid)->ids)
        pick[static_cast<std::size_t>(index.at(id))] = 1;
    if (d.nsidex != 0)
      for (int id : node_sets.at(d.nsidex)->ids)
        pick[static_cast<std::size_t>(index.at(id))] = 0;
    for (Index i : w.display_nodes)
      pick[static_cast<std::size_t>(i)] = 0;
    std::array<std::size_t, 4> left{};  // by NodeRole
    std::size_t behind = 0, far = 0;
    core::GlobalId first_behind = 0, first_held = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!pick[i])
        continue;
      if (why[i] != kFreeNode) {
        ++left[why[i]];
        if (why[i] == kHeldNode && first_held == 0)
          first_held = m.node_id[i];
        continue;
      }
      const Vec r{m.x0[i] - w.origin[0], m.y0[i] - w.origin[1], m.z0[i] - w.origin[2]};
      const double gap = dot(r, w.normal);
      if (w.finite) {
        const double a = dot(r, w.edge_l), b = dot(r, w.edge_m);
        const bool over = a >= 0.0 && a <= w.length_l && b >= 0.0 && b <= w.length_m;
        if (over && gap < -tolerance) {
          ++behind;
          if (first_behind == 0)
            first_behind = m.node_id[i];
          continue;
        }
      } else if (gap < -tolerance) {
        ++behind;
        if (first_behind == 0)
          first_behind = m.node_id[i];
        continue;
      }
      if (d.offset > 0.0 && std::abs(gap) > d.offset) {
        ++far;
        continue;
      }
      w.nodes.push_back(static_cast<Index>(i));
    }
    const std::string name = cat("rigid wall ", w.id);
    if (behind > 0) {
      warnings.push_back(
          {d.where, d.keyword, "",
           cat(name, ": ", behind, " slave nodes lie behind the wall at t = 0 (the first is node ",
               first_behind,
               "); they are left out: a wall never pushes a node through itself. Check the "
               "normal's direction (from XT, YT, ZT to XH, YH, ZH, towards the nodes)")});
    }
    if (left[kHeldNode] > 0) {
      warnings.push_back(
          {d.where, d.keyword, "",
           cat(name, ": ", left[kHeldNode],
               " slave nodes are held by a constraint, a prescribed motion or a tie (the first is "
               "node ",
               first_held, "); the wall does not act on them")});
    }
    if (w.nodes.empty()) {
      warnings.push_back({d.where, d.keyword, "",
                          cat(name, " has no slave node: it acts on nothing (", left[kRigidNode],
                              " rigid-body nodes, ", left[kNoElement], " nodes of no element, ",
                              far, " beyond OFFSET left out)")});
    }
    m.rigid_walls.push_back(std::move(w));
  }
}

}  // namespace plyform::setup
