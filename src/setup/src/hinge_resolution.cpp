// `plyform check`'s advice on plastic hinges a rigid tool forces into a shell part: a tool
// radius R asks for elements no longer than pi R / 8 (four along a quarter turn). The air bend
// of docs/shells.md (scripts/hinge_study.py, R = 5 mm) puts the bending work within 1 % of the
// converged one from four elements per quarter turn on (3.5 % off at 1.6; below one the run
// stops); the public 3-point bend (R = 40 mm over 10 mm elements, 6.3 per quarter turn,
// converged within 0.2 %) lies on the safe side and is not advised.

#include "plyform/setup/hinge_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <variant>

namespace plyform::setup {
namespace {

using Vec = std::array<double, 3>;

Vec node(const core::Model& m, core::Index n) {
  const auto i = static_cast<std::size_t>(n);
  return {m.x0[i], m.y0[i], m.z0[i]};
}

Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

double norm(const Vec& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// Centre and unit normal of shell e (a triangle repeats N3).
std::pair<Vec, Vec> centre_normal(const core::Model& m, const core::ShellBlock& b, std::size_t e) {
  const core::Index* c = &b.connectivity[4 * e];
  const bool tri = c[2] == c[3];
  Vec p[4];
  for (int i = 0; i < 4; ++i)
    p[i] = node(m, c[i]);
  Vec centre{};
  const int count = tri ? 3 : 4;
  for (int i = 0; i < count; ++i)
    for (int d = 0; d < 3; ++d)
      centre[static_cast<std::size_t>(d)] += p[i][static_cast<std::size_t>(d)] / count;
  // The diagonals' cross product (a triangle: two edges'); the sense does not matter here.
  const Vec u = tri ? sub(p[1], p[0]) : sub(p[2], p[0]);
  const Vec v = tri ? sub(p[2], p[0]) : sub(p[3], p[1]);
  Vec n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double l = norm(n);
  if (l > 0.0)
    n = {n[0] / l, n[1] / l, n[2] / l};
  return {centre, n};
}

bool is_plastic(const core::Material& m) {
  return std::holds_alternative<core::PiecewiseLinearPlasticity>(m) ||
         std::holds_alternative<core::PowerLawPlasticity>(m) ||
         std::holds_alternative<core::PlasticKinematic>(m) ||
         std::holds_alternative<core::ElasticPlasticThermal>(m) ||
         std::holds_alternative<core::TransverselyAnisotropicPlastic>(m) ||
         std::holds_alternative<core::Barlat89Plastic>(m) ||
         std::holds_alternative<core::Hill3RPlastic>(m);
}

// The median over the part's elements of their extent across the hinge line: along the
// in-plane direction normal to the tool's axis (the direction the sheet bends in). An element
// whose normal is near the axis has no such direction and is left out.
double median_length_across(const core::Model& m, const core::ShellBlock& b, const Vec& axis) {
  std::vector<double> lengths;
  lengths.reserve(b.size());
  for (std::size_t e = 0; e < b.size(); ++e) {
    const Vec n = centre_normal(m, b, e).second;
    Vec across{n[1] * axis[2] - n[2] * axis[1], n[2] * axis[0] - n[0] * axis[2],
               n[0] * axis[1] - n[1] * axis[0]};
    const double l = norm(across);
    if (l < 0.5)
      continue;  // the axis within 30 degrees of the element's normal
    double lo = 1e300, hi = -1e300;
    for (int i = 0; i < 4; ++i) {
      const Vec p = node(m, b.connectivity[4 * e + static_cast<std::size_t>(i)]);
      const double s = (p[0] * across[0] + p[1] * across[1] + p[2] * across[2]) / l;
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
    lengths.push_back(hi - lo);
  }
  if (lengths.empty())
    return 0.0;
  auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

// Whether a contact pass brings the nodes of blocks a and b together (one on each side).
bool in_contact(const core::Model& m, const core::ShellBlock& a, const core::ShellBlock& b) {
  const std::size_t n = m.node_count();
  std::vector<char> in_a(n, 0), in_b(n, 0);
  for (core::Index k : a.connectivity)
    in_a[static_cast<std::size_t>(k)] = 1;
  for (core::Index k : b.connectivity)
    in_b[static_cast<std::size_t>(k)] = 1;
  for (const core::ContactInterface& c : m.contacts) {
    for (const core::ContactPass& p : c.passes) {
      bool slave_a = false, slave_b = false, master_a = false, master_b = false;
      for (core::Index k : p.slave_nodes) {
        slave_a = slave_a || in_a[static_cast<std::size_t>(k)];
        slave_b = slave_b || in_b[static_cast<std::size_t>(k)];
      }
      for (core::Index k : p.segments) {
        master_a = master_a || in_a[static_cast<std::size_t>(k)];
        master_b = master_b || in_b[static_cast<std::size_t>(k)];
      }
      if ((slave_a && master_b) || (slave_b && master_a))
        return true;
    }
  }
  return false;
}

}  // namespace

ToolCurvature tool_curvature(const core::Model& model, const core::ShellBlock& block) {
  // Elements by shared edge (the two nodes, smaller first).
  std::map<std::pair<core::Index, core::Index>, std::vector<std::size_t>> by_edge;
  for (std::size_t e = 0; e < block.size(); ++e) {
    const core::Index* c = &block.connectivity[4 * e];
    for (int i = 0; i < 4; ++i) {
      const core::Index a = c[i], z = c[(i + 1) % 4];
      if (a != z)
        by_edge[{std::min(a, z), std::max(a, z)}].push_back(e);
    }
  }
  constexpr double kFlat = std::numbers::pi / 180.0, kSharp = std::numbers::pi / 3.0;
  ToolCurvature smallest;
  for (const auto& [edge, elements] : by_edge) {
    if (elements.size() != 2)
      continue;
    const auto [c1, n1] = centre_normal(model, block, elements[0]);
    const auto [c2, n2] = centre_normal(model, block, elements[1]);
    const double cosine = std::clamp(n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2], -1.0, 1.0);
    // Neighbours may be numbered in opposite senses: the angle between the surfaces.
    const double angle = std::acos(std::abs(cosine));
    if (angle < kFlat || angle > kSharp)
      continue;
    const double radius = norm(sub(c2, c1)) / angle;
    if (smallest.radius == 0.0 || radius < smallest.radius) {
      const Vec t = sub(node(model, edge.second), node(model, edge.first));
      const double lt = norm(t);
      smallest = {radius, {t[0] / lt, t[1] / lt, t[2] / lt}};
    }
  }
  return smallest;
}

std::vector<HingeAdvice> hinge_resolution_advice(const core::Model& model) {
  std::vector<HingeAdvice> out;
  if (model.contacts.empty())
    return out;
  for (const core::ShellBlock& tool : model.shell_blocks) {
    if (!std::holds_alternative<core::RigidMaterial>(
            model.materials[static_cast<std::size_t>(tool.material)]))
      continue;
    const ToolCurvature curvature = tool_curvature(model, tool);
    const double radius = curvature.radius;
    if (radius <= 0.0)
      continue;
    for (const core::ShellBlock& part : model.shell_blocks) {
      if (!is_plastic(model.materials[static_cast<std::size_t>(part.material)]))
        continue;
      const double h = median_length_across(model, part, curvature.axis);
      const double limit = std::numbers::pi * radius / (2.0 * kHingeElementsPerQuarterTurn);
      if (h <= limit || !in_contact(model, part, tool))
        continue;
      HingeAdvice a;
      a.shell_part = model.parts[static_cast<std::size_t>(part.part)].id;
      a.tool_part = model.parts[static_cast<std::size_t>(tool.part)].id;
      a.tool_radius = radius;
      a.element_length = h;
      a.message = fmt::format(
          "part {}: its elements (median length {:.4g} across the tool's axis) are coarser than "
          "the plastic hinge that "
          "rigid part {} (smallest radius {:.4g}) bends into it can carry: a quarter turn of that "
          "radius spans {:.2g} elements, the hinge wants at least {:g} (edges up to {:.3g}); "
          "refine the part where it meets the tool, or the bending work is off by the mesh "
          "(docs/shells.md)",
          a.shell_part, h, a.tool_part, radius, std::numbers::pi * radius / (2.0 * h),
          kHingeElementsPerQuarterTurn, limit);
      out.push_back(std::move(a));
    }
  }
  return out;
}

}  // namespace plyform::setup
