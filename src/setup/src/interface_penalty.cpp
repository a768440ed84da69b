// `plyform check`: a layer interface whose penalty the press's pressure pushes through. A
// rigid tool loaded by a force (the blank holder) puts that force through every layer of the
// stack it presses; each layer interface then carries the mean pressure p = F / A and, with
// its penalty k per area in compression, lets the layers sink p / k into each other. A share
// of the thinner layer's thickness beyond kPenetrationShare is no longer a thin contact
// layer: the layers' offsets overlap, and a cohesive interface reads that compression as
// contact instead of bond.
//
// The area: the contact area cannot exceed the tool's area projected on the plane across the
// force, nor either layer's projected area, so F / min(those) is the least mean pressure the
// force can put through (a lower bound: the warning never overstates it). Both areas come
// from the meshes as they are, which is robust where the contact patch is not known before
// the run.
//
// The penalty in compression: the contact's SOFT = 0 stiffness per area (setup::side_penalty,
// chosen by PENOPT as the contact chooses it); for an interface whose cohesive law bonds the
// nodes at t = 0 (BOND_TOL > 0), the law's max(k, C_N beta0^2). A contact with SOFT = 1 is
// left alone: its penalty follows the nodal masses and the step, the stiffest the step
// allows, which is this warning's remedy.

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "plyform/setup/contact_penalty.hpp"
#include "plyform/setup/contact_sides.hpp"
#include "plyform/setup/interface_warnings.hpp"

namespace plyform::setup {
namespace {

constexpr const char* kAxis[] = {"x", "y", "z"};

// The largest |scale * curve(t)| over the run (0 to the end time; the whole curve without one).
double peak(const core::Model& m, core::Index curve, double scale) {
  const core::LoadCurve& c = m.curves[static_cast<std::size_t>(curve)];
  const double end = m.controls.end_time;
  double v = std::max(std::abs(c(0.0)), end > 0.0 ? std::abs(c(end)) : 0.0);
  for (std::size_t i = 0; i < c.x.size(); ++i)
    if (end <= 0.0 || (c.x[i] >= 0.0 && c.x[i] <= end))
      v = std::max(v, std::abs(c.y[i]));
  return std::abs(scale) * v;
}

// Area of the block's elements projected on the plane across axis d.
double projected_area(const core::Model& m, const core::ShellBlock& b, int d) {
  double area = 0.0;
  const auto p = [&](core::Index n) {
    const auto i = static_cast<std::size_t>(n);
    return std::array<double, 3>{m.x0[i], m.y0[i], m.z0[i]};
  };
  for (std::size_t e = 0; e < b.size(); ++e) {
    const core::Index* c = &b.connectivity[4 * e];
    // Half the diagonals' cross product (a triangle repeats N3: its area all the same).
    const auto a = p(c[0]), q = p(c[1]), r = p(c[2]), s = p(c[3]);
    const double d1[3] = {r[0] - a[0], r[1] - a[1], r[2] - a[2]};
    const double d2[3] = {s[0] - q[0], s[1] - q[1], s[2] - q[2]};
    const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                         d1[0] * d2[1] - d1[1] * d2[0]};
    area += 0.5 * std::abs(n[d]);
  }
  return area;
}

double mean_thickness(const core::ShellBlock& b) {
  double sum = 0.0;
  for (double t : b.thickness)
    sum += t;
  return b.thickness.empty() ? 0.0 : sum / static_cast<double>(b.thickness.size());
}

// The contact's own penalty per area (SOFT = 0, chosen by PENOPT); 0 when it has none.
double contact_penalty(const core::Model& m, const core::ContactInterface& c) {
  double k = 0.0;
  for (const core::ContactPass& p : c.passes) {
    const SidePenalty s = side_penalty(m, p);
    // PENOPT 0, a layer interface's rule: the stiffer side (the run holds it below
    // m* / (4 dt0^2), which needs the masses and the step: this is its upper bound).
    const double kp = c.penopt == 2   ? s.master
                      : c.penopt == 3 ? s.slave
                      : c.penopt == 0 ? std::max(s.slave, s.master)
                                      : std::min(s.slave, s.master);
    k = std::max(k, kp);  // a two-way contact: the stiffer pass holds the layers apart
  }
  return k;
}

// The interface's penalty per area in compression (see above): a cohesive law that bonds the
// nodes at t = 0 holds them with at least C_N beta0^2.
double compression_penalty(const core::Model& m, const core::ContactInterface& c) {
  double k = contact_penalty(m, c);
  if (c.cohesive && c.law.bond_tol > 0.0)
    k = std::max(k, c.law.cn * c.law.beta0 * c.law.beta0);
  return k;
}

// A force-driven tool: a rigid part and the force along one axis that loads it.
struct Press {
  core::Index part = 0;
  int axis = 0;
  double force = 0.0;
};

std::vector<Press> presses(const core::Model& m) {
  std::map<std::pair<core::Index, int>, double> force;
  for (const core::RigidLoad& l : m.rigid_loads)
    if (l.dof <= 2)
      force[{l.part, l.dof}] += peak(m, l.curve, l.scale);
  // Nodal loads on a rigid part's nodes load the body the same way.
  std::vector<core::Index> rigid_part(m.node_count(), -1);
  for (const core::ShellBlock& b : m.shell_blocks)
    if (is_rigid(m, b))
      for (core::Index n : b.connectivity)
        rigid_part[static_cast<std::size_t>(n)] = b.part;
  for (const core::NodalLoad& l : m.loads) {
    const core::Index part = rigid_part[static_cast<std::size_t>(l.node)];
    if (part >= 0 && l.direction >= 0 && l.direction <= 2)
      force[{part, l.direction}] += peak(m, l.curve, l.scale);
  }
  std::vector<Press> out;
  for (const auto& [key, f] : force)
    if (f > 0.0)
      out.push_back({key.first, key.second, f});
  return out;
}

}  // namespace

std::vector<InterfaceWarning> penalty_pressure_warnings(const core::Model& model) {
  std::vector<InterfaceWarning> out;
  // No force-driven tool: no pressure is known before the run, nothing is derived.
  const std::vector<Press> tools = presses(model);
  if (tools.empty())
    return out;
  const std::size_t nc = model.contacts.size();
  std::vector<ContactSides> sides(nc);
  std::vector<char> layer(nc, 0);
  for (std::size_t i = 0; i < nc; ++i) {
    sides[i] = contact_sides(model, model.contacts[i]);
    layer[i] = is_layer_interface(model, model.contacts[i], sides[i]) ? 1 : 0;
  }
  const auto deformable = [&](std::size_t b) { return !is_rigid(model, model.shell_blocks[b]); };
  for (const Press& tool : tools) {
    const auto on_tool = [&](std::size_t b) { return model.shell_blocks[b].part == tool.part; };
    // The stack the tool presses: the deformable shells a contact puts against the tool, and
    // every layer joined to them through layer interfaces.
    std::vector<char> in_stack(model.shell_blocks.size(), 0);
    for (std::size_t i = 0; i < nc; ++i) {
      const auto& s = sides[i];
      const bool slave_tool = std::any_of(s.slave_shells.begin(), s.slave_shells.end(), on_tool);
      const bool master_tool = std::any_of(s.master_shells.begin(), s.master_shells.end(), on_tool);
      if (master_tool)
        for (std::size_t b : s.slave_shells)
          in_stack[b] = in_stack[b] || deformable(b);
      if (slave_tool)
        for (std::size_t b : s.master_shells)
          in_stack[b] = in_stack[b] || deformable(b);
    }
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t i = 0; i < nc; ++i) {
        if (!layer[i])
          continue;
        const auto& s = sides[i];
        const auto any_in = [&](const std::vector<std::size_t>& l) {
          return std::any_of(l.begin(), l.end(), [&](std::size_t b) { return in_stack[b] != 0; });
        };
        if (!any_in(s.slave_shells) && !any_in(s.master_shells))
          continue;
        for (const auto* l : {&s.slave_shells, &s.master_shells})
          for (std::size_t b : *l)
            if (!in_stack[b])
              in_stack[b] = 1, grew = true;
      }
    }
    double tool_area = 0.0;
    for (std::size_t b = 0; b < model.shell_blocks.size(); ++b)
      if (on_tool(b))
        tool_area += projected_area(model, model.shell_blocks[b], tool.axis);
    for (std::size_t i = 0; i < nc; ++i) {
      const core::ContactInterface& c = model.contacts[i];
      if (!layer[i] || !in_stack[sides[i].slave_shells.front()] ||
          c.penalty == core::PenaltyKind::mass)
        continue;
      double slave_area = 0.0, master_area = 0.0, thinnest = 1e300;
      for (std::size_t b : sides[i].slave_shells) {
        slave_area += projected_area(model, model.shell_blocks[b], tool.axis);
        thinnest = std::min(thinnest, mean_thickness(model.shell_blocks[b]));
      }
      for (std::size_t b : sides[i].master_shells) {
        master_area += projected_area(model, model.shell_blocks[b], tool.axis);
        thinnest = std::min(thinnest, mean_thickness(model.shell_blocks[b]));
      }
      const double area = std::min({tool_area, slave_area, master_area});
      const double k = compression_penalty(model, c);
      if (!(area > 0.0) || !(k > 0.0) || !(thinnest > 0.0))
        continue;
      const double pressure = tool.force / area;
      const double depth = pressure / k;
      const double share = depth / thinnest;
      if (share <= kPenetrationShare)
        continue;
      const char* area_of = area == tool_area    ? "the tool's"
                            : area == slave_area ? "the slave layer's"
                                                 : "the master layer's";
      // The remedy: a penalty per area that keeps the penetration at the share, against the
      // contact's own penalty (SFS and SFM scale it; C_N of a bonded law is not theirs).
      const double needed = pressure / (kPenetrationShare * thinnest);
      const double own = contact_penalty(model, c);
      InterfaceWarning w;
      w.contact = c.id;
      w.value = share;
      w.message = fmt::format(
          "{}, between layers, gives way under the tool pressure: the force on {} ({:.4g} "
          "along {}) over {} projected area ({:.4g}) presses the layers with at least {:.4g} "
          "(stress); the interface's penalty in compression, {:.4g} (stress/length{}), lets them "
          "sink {:.3g} into each other, {:.3g} % of the thinner layer's thickness {:.4g} (more "
          "than {:g} %: the layers overlap); set SOFT = 1 on this contact (the penalty from the "
          "nodal mass and the step, LS-DYNA's SOFT = 1 reasoning), or raise SFS and SFM to a "
          "penalty of at least {:.4g} per area{}",
          contact_name(model, c), part_name(model, tool.part), tool.force, kAxis[tool.axis],
          area_of, area, pressure, k,
          k > own ? ", C_N of the law that bonds the layers at t = 0" : "", depth, 100.0 * share,
          thinnest, 100.0 * kPenetrationShare, needed,
          own > 0.0 ? fmt::format(" ({:.3g} times the contact's {:.4g})", needed / own, own)
                    : std::string());
      out.push_back(std::move(w));
    }
  }
  return out;
}

}  // namespace plyform::setup
