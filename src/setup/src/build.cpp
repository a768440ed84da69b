#include "plyform/setup/build.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <variant>

#include "build_contact.hpp"
#include "build_expansion.hpp"
#include "build_initial_state.hpp"
#include "build_rigid_walls.hpp"
#include "build_tables.hpp"
#include "build_thermal.hpp"
#include "plyform/element/shell_kernels.hpp"
#include "plyform/element/solid_kernels.hpp"
#include "plyform/material/law_registry.hpp"

namespace plyform::setup {
namespace {

using core::Index;

struct Builder {
  const model::ModelDesc& d;
  BuildResult out;
  core::Model m;
  std::unordered_map<int, Index> node, curve, part;
  std::unordered_map<int, const model::SetListDesc*> node_set, part_set;
  std::unordered_map<int, core::CurveTable> table;  // *DEFINE_TABLE by id

  void error(const model::SourceLocation& where, std::string keyword, std::string field,
             std::string message) {
    out.errors.push_back({where, std::move(keyword), std::move(field), std::move(message)});
  }

  // Node indices of a node or a node set target (validated ids).
  std::vector<Index> targets(model::NodeTarget t, int id) {
    if (t == model::NodeTarget::kNode)
      return {node.at(id)};
    std::vector<Index> v;
    for (int n : node_set.at(id)->ids)
      v.push_back(node.at(n));
    return v;
  }

  void nodes() {
    const std::size_t n = d.nodes.size();
    m.node_id.reserve(n);
    m.x0.reserve(n), m.y0.reserve(n), m.z0.reserve(n);
    for (const model::NodeDesc& nd : d.nodes) {
      node.emplace(nd.id, static_cast<Index>(m.node_id.size()));
      // TC: 1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all.
      static constexpr unsigned kTc[8] = {0, 1, 2, 4, 3, 6, 5, 7};
      // RC: the same codes for the rotations (shell nodes).
      const unsigned dofs = (nd.tc > 0 && nd.tc < 8 ? kTc[nd.tc] : 0u) |
                            (nd.rc > 0 && nd.rc < 8 ? kTc[nd.rc] << 3 : 0u);
      if (dofs != 0)
        m.fixed.push_back({static_cast<Index>(m.node_id.size()), dofs});
      m.node_id.push_back(nd.id);
      m.x0.push_back(nd.x);
      m.y0.push_back(nd.y);
      m.z0.push_back(nd.z);
    }
    for (const auto& s : d.node_sets)
      node_set.emplace(s.id, &s);
    for (const auto& s : d.part_sets)
      part_set.emplace(s.id, &s);
  }

  void curves() {
    for (const model::CurveDesc& c : d.curves) {
      core::LoadCurve lc;
      for (const model::CurvePoint& p : model::effective_points(c)) {
        lc.x.push_back(p.x);
        lc.y.push_back(p.y);
      }
      curve.emplace(c.id, static_cast<Index>(m.curves.size()));
      m.curves.push_back(std::move(lc));
    }
    table = build_tables(d);
  }

  // The runtime material of a deck material id (any law), created once.
  std::unordered_map<int, Index> material_index;
  Index material_of(int id) {
    if (auto it = material_index.find(id); it != material_index.end())
      return it->second;
    // Each law reads its own cards (material/laws/, the registry's from_card).
    std::optional<core::Material> law = material::material_from_deck(
        d, id,
        [&](int curve_id) -> const core::LoadCurve& {
          return m.curves[static_cast<std::size_t>(curve.at(curve_id))];
        },
        [&](int table_id) -> const core::CurveTable* {
          const auto it = table.find(table_id);
          return it == table.end() ? nullptr : &it->second;
        });
    if (!law)
      return -1;
    m.materials.push_back(std::move(*law));
    const auto index = static_cast<Index>(m.materials.size() - 1);
    material_index.emplace(id, index);
    return index;
  }

  // The part's hourglass control: its *HOURGLASS, else *CONTROL_HOURGLASS, else IHQ 1, QM 0.1.
  core::HourglassControl hourglass_of(const model::PartDesc& p, int max_ihq, const char* kind) {
    core::HourglassControl hg;
    if (d.control_hourglass) {
      hg.ihq = d.control_hourglass->ihq;
      hg.qm = d.control_hourglass->qh;
    }
    const model::HourglassDesc* h = nullptr;
    for (const auto& x : d.hourglasses) {
      if (x.id == p.hourglass_id)
        h = &x;
    }
    if (p.hourglass_id != 0 && h != nullptr) {
      if (h->ihq != 0)
        hg.ihq = h->ihq;
      hg.qm = h->qm;
    }
    if (hg.ihq < 1 || hg.ihq > max_ihq) {
      error(h != nullptr ? h->where : p.where, "*HOURGLASS", "IHQ",
            "hourglass type " + std::to_string(hg.ihq) + " is not supported for " + kind +
                (max_ihq == 5 ? ": use 1-3 (viscous) or 4-5 (stiffness)" : ": use 1-3 (viscous)"));
    }
    return hg;
  }

  // The part's bulk viscosity: its *HOURGLASS Q1 and Q2, else *CONTROL_BULK_VISCOSITY's,
  // else LS-DYNA's defaults 1.5 and 0.06.
  core::BulkViscosity bulk_viscosity_of(const model::PartDesc& p) {
    core::BulkViscosity bv;
    if (d.bulk_viscosity) {
      bv.q1 = d.bulk_viscosity->q1;
      bv.q2 = d.bulk_viscosity->q2;
    }
    for (const auto& x : d.hourglasses) {
      if (p.hourglass_id != 0 && x.id == p.hourglass_id) {
        bv.q1 = x.q1;
        bv.q2 = x.q2;
      }
    }
    return bv;
  }

  void parts_and_elements() {
    std::unordered_map<int, const model::SectionSolidDesc*> solid_sections;
    for (const auto& s : d.solid_sections)
      solid_sections.emplace(s.id, &s);
    std::unordered_map<int, const model::SectionShellDesc*> shell_sections;
    for (const auto& s : d.shell_sections)
      shell_sections.emplace(s.id, &s);

    std::unordered_map<int, std::size_t> solid_block_of_part, shell_block_of_part;
    for (const model::PartDesc& p : d.parts) {
      const auto solid = solid_sections.find(p.section_id);
      const auto shell = shell_sections.find(p.section_id);
      if (solid == solid_sections.end() && shell == shell_sections.end())
        continue;  // validation
      const Index mat = material_of(p.material_id);
      if (mat < 0) {
        error(p.where, "*PART", "MID",
              "part " + std::to_string(p.id) + ": material " + std::to_string(p.material_id) +
                  " is not defined by a supported *MAT_ keyword");
        continue;
      }
      const core::Material& law = m.materials[static_cast<std::size_t>(mat)];
      const bool rigid = std::holds_alternative<core::RigidMaterial>(law);
      part.emplace(p.id, static_cast<Index>(m.parts.size()));
      m.parts.push_back(core::Part{p.id, p.title, mat});
      const auto part_index = static_cast<Index>(m.parts.size() - 1);
      if (solid != solid_sections.end()) {
        if (!rigid && !element::supports_solids(law)) {
          error(p.where, "*PART", "MID",
                "part " + std::to_string(p.id) + ": material " + std::to_string(p.material_id) +
                    " is not a law for solid elements (use " + material::law_keywords(true) + ")");
          continue;
        }
        core::SolidBlock b;
        b.formulation = solid->second->elform == 2 ? core::SolidFormulation::selective_reduced
                                                   : core::SolidFormulation::one_point;
        b.part = part_index;
        b.material = mat;
        b.hourglass = hourglass_of(p, 5, "solids");
        b.bulk_viscosity = bulk_viscosity_of(p);
        solid_block_of_part.emplace(p.id, m.solid_blocks.size());
        m.solid_blocks.push_back(std::move(b));
      } else {
        const model::SectionShellDesc& sec = *shell->second;
        if (sec.elform != 2 && sec.elform != 16) {
          error(sec.where, "*SECTION_SHELL", "ELFORM",
                "ELFORM " + std::to_string(sec.elform) +
                    " is not supported yet: plyform has the Belytschko-Tsay shell, ELFORM 2, "
                    "and the fully integrated shell, ELFORM 16");
          continue;
        }
        const bool fully_integrated = sec.elform == 16;
        if (!rigid && !element::supports_shells(law)) {
          error(p.where, "*PART", "MID",
                "part " + std::to_string(p.id) + ": material " + std::to_string(p.material_id) +
                    " is not a law for shells (use " + material::law_keywords(false) + ")");
          continue;
        }
        if (sec.nip < 1 || sec.nip > 5) {
          error(sec.where, "*SECTION_SHELL", "NIP",
                "NIP " + std::to_string(sec.nip) + " is not supported: use 1 to 5");
          continue;
        }
        core::ShellBlock b;
        b.part = part_index;
        b.material = mat;
        b.nip = sec.nip;
        b.shear_factor = sec.shear_factor;
        b.hourglass = hourglass_of(p, 5, "shells");
        if (fully_integrated) {
          // 2 x 2 Gauss points leave no hourglass modes: like LS-DYNA, ELFORM 16 ignores
          // hourglass control (and the bulk viscosity of the shells, not in its kernel yet).
          b.formulation = core::ShellFormulation::fully_integrated;
          if (p.hourglass_id != 0)
            out.warnings.push_back(
                {p.where, "*PART", "HGID",
                 "part " + std::to_string(p.id) +
                     ": *HOURGLASS is ignored for the fully integrated shell (ELFORM 16), "
                     "which has no hourglass modes"});
          b.hourglass = core::HourglassControl{};
          b.hourglass.qm = 0.0;
        }
        if (!fully_integrated && std::holds_alternative<core::ReinforcedThermoplastic>(law) &&
            b.hourglass.ihq < 4) {
          // The one-point element holds the fibres inextensible at its centre only: a viscous
          // hourglass force does not resist the edges (the fibres of a fibre-aligned mesh)
          // stretching while their mean stays, and a bias-extension specimen then shears up to
          // 3.5 degrees off the kinematic formula; with IHQ 4 it follows it within 0.1 degree
          // (docs/materials.md).
          out.warnings.push_back(
              {p.where, "*PART", "HGID",
               "part " + std::to_string(p.id) + ": *MAT_REINFORCED_THERMOPLASTIC with viscous " +
                   "hourglass control (IHQ " + std::to_string(b.hourglass.ihq) +
                   ") lets the fibres stretch through the elements' hourglass modes; use " +
                   "stiffness control, IHQ 4 (*HOURGLASS or *CONTROL_HOURGLASS)"});
        }
        if (d.control_shell && d.control_shell->intgrd == 1) {
          if (sec.nip < 2) {
            error(sec.where, "*SECTION_SHELL", "NIP",
                  "Lobatto integration (*CONTROL_SHELL INTGRD = 1) needs NIP >= 2");
            continue;
          }
          b.rule = core::ThicknessRule::lobatto;
        }
        // *CONTROL_BULK_VISCOSITY TYPE -1 or -2 puts the bulk viscosity in the shells too.
        b.bulk_viscosity_on = d.bulk_viscosity && d.bulk_viscosity->type < 0;
        b.bulk_viscosity = bulk_viscosity_of(p);
        shell_block_of_part.emplace(p.id, m.shell_blocks.size());
        m.shell_blocks.push_back(std::move(b));
      }
    }
    for (const model::ElementSolidDesc& e : d.solids) {
      const auto it = solid_block_of_part.find(e.part_id);
      if (it == solid_block_of_part.end())
        continue;  // reported with its part
      core::SolidBlock& b = m.solid_blocks[it->second];
      b.element_id.push_back(e.id);
      for (int n : e.nodes)
        b.connectivity.push_back(node.at(n));
    }
    for (const model::ElementShellDesc& e : d.shells) {
      const auto it = shell_block_of_part.find(e.part_id);
      if (it == shell_block_of_part.end())
        continue;
      core::ShellBlock& b = m.shell_blocks[it->second];
      // Thickness: the element's THIC card where given, else the section's T1..T4.
      const model::SectionShellDesc* sec = nullptr;
      for (const auto& p : d.parts) {
        if (p.id == e.part_id) {
          for (const auto& s : d.shell_sections) {
            if (s.id == p.section_id)
              sec = &s;
          }
        }
      }
      b.element_id.push_back(e.id);
      if (e.beta != 0.0 && b.material_angle.empty())
        b.material_angle.assign(b.element_id.size() - 1, 0.0);
      if (!b.material_angle.empty())
        b.material_angle.push_back(e.beta * std::numbers::pi / 180.0);
      for (int k = 0; k < 4; ++k) {
        b.connectivity.push_back(node.at(e.nodes[static_cast<std::size_t>(k)]));
        double t = e.has_thickness_card ? e.thickness[static_cast<std::size_t>(k)] : 0.0;
        if (!(t > 0.0) && sec != nullptr)
          t = sec->thickness[static_cast<std::size_t>(k)];
        if (!(t > 0.0) && sec != nullptr)
          t = sec->thickness[0];
        b.thickness.push_back(t);
      }
    }
  }

  void boundary_conditions() {
    std::unordered_map<int, const model::CoordinateSystemDesc*> systems;
    for (const model::CoordinateSystemDesc& c : d.coordinate_systems)
      systems.emplace(c.id, &c);
    for (const model::BoundarySpcDesc& s : d.spcs) {
      unsigned dofs = 0;
      for (int k = 0; k < 6; ++k) {
        if (s.fixed[static_cast<std::size_t>(k)])
          dofs |= 1u << k;
      }
      if (dofs == 0)
        continue;
      core::FixedDofs fixed{.dofs = dofs};
      if (s.cid != 0) {
        // The reader checks the axes and validate the id; a local system whose axes are the
        // global ones still takes the projection path (same result, no special case).
        const auto system = systems.find(s.cid);
        const auto axes =
            system == systems.end() ? std::nullopt : model::coordinate_axes(*system->second);
        if (!axes) {
          error(s.where,
                s.target == model::NodeTarget::kNode ? "*BOUNDARY_SPC_NODE" : "*BOUNDARY_SPC_SET",
                "CID", "coordinate system " + std::to_string(s.cid) + " has no valid axes");
          continue;
        }
        fixed.local = true;
        fixed.axes = *axes;
      }
      for (Index n : targets(s.target, s.target_id)) {
        fixed.node = n;
        m.fixed.push_back(fixed);
      }
    }
    for (const model::PrescribedMotionDesc& p : d.prescribed_motions) {
      if (p.vad < 0 || p.vad > 2) {
        error(p.where, "*BOUNDARY_PRESCRIBED_MOTION", "VAD",
              "VAD " + std::to_string(p.vad) + " is not supported: use 0, 1 or 2");
        continue;
      }
      for (Index n : targets(p.target, p.target_id)) {
        core::PrescribedMotion pm;
        pm.node = n;
        // DOF 1-3 translations, 9-11 turning about an offset axis (directions 3-5).
        pm.direction = p.dof <= 3 ? p.dof - 1 : p.dof - 6;
        pm.axis = {p.offset1, p.offset2};
        pm.kind = p.vad == 0   ? core::MotionKind::velocity
                  : p.vad == 1 ? core::MotionKind::acceleration
                               : core::MotionKind::displacement;
        pm.curve = curve.at(p.curve_id);
        pm.scale = p.scale;
        pm.birth = p.birth;
        pm.death = p.death;
        m.motions.push_back(pm);
      }
    }
    for (const model::LoadNodeDesc& l : d.nodal_loads) {
      for (Index n : targets(l.target, l.target_id)) {
        m.loads.push_back(core::NodalLoad{n, l.dof - 1, curve.at(l.curve_id), l.scale});
      }
    }
    pressure_loads();
  }

  // Each pressure load's segments, in the order of its set, as local node indices.
  void pressure_loads() {
    if (d.pressure_loads.empty())
      return;
    std::unordered_map<int, const model::SetSegmentDesc*> segment_sets;
    for (const model::SetSegmentDesc& s : d.segment_sets)
      segment_sets.emplace(s.id, &s);
    std::unordered_map<int, const model::SetListDesc*> shell_sets;
    for (const model::SetListDesc& s : d.shell_sets)
      shell_sets.emplace(s.id, &s);
    std::unordered_map<int, const model::ElementShellDesc*> shells;
    for (const model::ElementShellDesc& e : d.shells)
      shells.emplace(e.id, &e);
    const auto add = [&](const std::array<int, 4>& ids) {
      m.pressure_segments.push_back({node.at(ids[0]), node.at(ids[1]), node.at(ids[2]),
                                     node.at(ids[3] == 0 ? ids[2] : ids[3])});
    };
    for (const model::LoadPressureDesc& l : d.pressure_loads) {
      core::PressureLoad p{.curve = curve.at(l.curve_id),
                           .scale = l.scale,
                           .arrival = l.arrival,
                           .first = m.pressure_segments.size()};
      switch (l.target) {
        case model::PressureTarget::kSegment:
          add(l.nodes);
          break;
        case model::PressureTarget::kSegmentSet:
          for (const std::array<int, 4>& seg : segment_sets.at(l.target_id)->segments)
            add(seg);
          break;
        case model::PressureTarget::kShell:
          add(shells.at(l.target_id)->nodes);
          break;
        case model::PressureTarget::kShellSet:
          for (int eid : shell_sets.at(l.target_id)->ids)
            add(shells.at(eid)->nodes);
          break;
      }
      p.count = m.pressure_segments.size() - p.first;
      m.pressure_loads.push_back(p);
    }
  }

  void rigid_bodies() {
    for (const model::PrescribedMotionRigidDesc& r : d.rigid_motions) {
      core::RigidMotion rm;
      rm.part = part.at(r.part_id);
      rm.dof = r.dof <= 3 ? r.dof - 1 : r.dof - 2;  // 1-3 translations, 5-7 rotations
      rm.kind = r.vad == 0   ? core::MotionKind::velocity
                : r.vad == 1 ? core::MotionKind::acceleration
                             : core::MotionKind::displacement;
      rm.curve = curve.at(r.curve_id);
      rm.scale = r.scale;
      rm.birth = r.birth;
      rm.death = r.death;
      m.rigid_motions.push_back(rm);
    }
    for (const model::LoadRigidBodyDesc& l : d.rigid_body_loads) {
      m.rigid_loads.push_back(core::RigidLoad{
          part.at(l.part_id), l.dof <= 3 ? l.dof - 1 : l.dof - 2, curve.at(l.curve_id), l.scale});
    }
  }

  void initial_velocities() {
    if (d.initial_velocities.empty() && d.initial_node_velocities.empty())
      return;
    const std::size_t n = m.node_count();
    m.v0x.assign(n, 0.0);
    m.v0y.assign(n, 0.0);
    m.v0z.assign(n, 0.0);
    for (const model::InitialVelocityGenerationDesc& v : d.initial_velocities) {
      std::vector<char> pick(n, 0);
      // The nodes of every element block of the part, solid or shell (a rigid part's blocks
      // too: the rigid body takes its velocity from its nodes').
      const auto mark_part = [&](int part_id) {
        const auto it = part.find(part_id);
        if (it == part.end())
          return;
        const auto mark = [&](const auto& blocks) {
          for (const auto& b : blocks)
            if (b.part == it->second)
              for (Index c : b.connectivity)
                pick[static_cast<std::size_t>(c)] = 1;
        };
        mark(m.solid_blocks);
        mark(m.shell_blocks);
      };
      if (v.target_id == 0) {
        std::fill(pick.begin(), pick.end(), 1);
      } else if (v.styp == 1) {
        for (int p : part_set.at(v.target_id)->ids)
          mark_part(p);
      } else if (v.styp == 2) {
        mark_part(v.target_id);
      } else {
        for (Index i : targets(model::NodeTarget::kSet, v.target_id)) {
          pick[static_cast<std::size_t>(i)] = 1;
        }
      }
      // v = v_t + omega n x (x - x_c), n the unit axis.
      double ax = v.nx, ay = v.ny, az = v.nz;
      const double len = std::sqrt(ax * ax + ay * ay + az * az);
      if (v.omega != 0.0 && len == 0.0) {
        error(v.where, "*INITIAL_VELOCITY_GENERATION", "NX",
              "OMEGA is not zero but the rotation axis (NX, NY, NZ) is zero");
        continue;
      }
      if (len > 0.0)
        ax /= len, ay /= len, az /= len;
      for (std::size_t i = 0; i < n; ++i) {
        if (!pick[i])
          continue;
        const double rx = m.x0[i] - v.xc, ry = m.y0[i] - v.yc, rz = m.z0[i] - v.zc;
        m.v0x[i] = v.vx + v.omega * (ay * rz - az * ry);
        m.v0y[i] = v.vy + v.omega * (az * rx - ax * rz);
        m.v0z[i] = v.vz + v.omega * (ax * ry - ay * rx);
      }
    }
    // *INITIAL_VELOCITY_NODE last: it replaces a generated velocity. Angular velocities go to
    // the nodes of shells (the only nodes with rotations).
    std::vector<char> has_rotation;
    for (const model::InitialVelocityNodeDesc& v : d.initial_node_velocities) {
      const auto i = static_cast<std::size_t>(node.at(v.node_id));
      m.v0x[i] = v.vx;
      m.v0y[i] = v.vy;
      m.v0z[i] = v.vz;
      if (v.vxr == 0.0 && v.vyr == 0.0 && v.vzr == 0.0)
        continue;
      if (has_rotation.empty()) {
        has_rotation.assign(n, 0);
        for (const auto& b : m.shell_blocks)
          for (Index c : b.connectivity)
            has_rotation[static_cast<std::size_t>(c)] = 1;
      }
      if (!has_rotation[i]) {
        error(v.where, "*INITIAL_VELOCITY_NODE", "VXR",
              "node " + std::to_string(v.node_id) +
                  " has an angular velocity but no rotations (it belongs to no shell)");
        continue;
      }
      if (m.w0x.empty()) {
        m.w0x.assign(n, 0.0);
        m.w0y.assign(n, 0.0);
        m.w0z.assign(n, 0.0);
      }
      m.w0x[i] = v.vxr;
      m.w0y[i] = v.vyr;
      m.w0z[i] = v.vzr;
    }
  }

  void controls_and_output() {
    if (d.termination) {
      m.controls.end_time = d.termination->end_time;
      m.controls.end_cycle = d.termination->end_cycle;
      m.controls.dt_min_ratio = d.termination->dtmin;
      m.controls.energy_change_limit = 0.01 * std::max(0.0, d.termination->endeng);  // percent
    } else {
      error({d.files_read.empty() ? std::string() : d.files_read.front(), 0},
            "*CONTROL_TERMINATION", "ENDTIM",
            "the deck has no *CONTROL_TERMINATION: the run would never end");
    }
    if (d.timestep) {
      m.controls.tssfac = d.timestep->tssfac;
      m.controls.dt2ms = d.timestep->dt2ms;
      m.controls.dt_init = d.timestep->dtinit;
      if (d.timestep->lctm != 0)
        m.controls.max_step_curve = curve.at(d.timestep->lctm);
    }
    if (d.d3plot) {
      m.output.d3plot_dt =
          d.d3plot->npltc > 0 ? m.controls.end_time / d.d3plot->npltc : d.d3plot->dt;
    }
    if (d.d3dump)
      m.output.d3dump_cycles = d.d3dump->cycles;
    if (d.extent_binary) {
      // LS-DYNA's flags: 1 (or blank) writes, 2 writes neither, 3 writes the solids' only.
      const model::DatabaseExtentBinaryDesc& x = *d.extent_binary;
      core::OutputRequests::StateFields& f = m.output.state_fields;
      f.shell_stress = x.sigflg <= 1;
      f.solid_stress = x.sigflg != 2;
      f.shell_plastic_strain = x.epsflg <= 1;
      f.solid_plastic_strain = x.epsflg != 2;
      f.thickness = x.engflg != 2;
      f.strain = x.strflg % 10 == 1;
    }
    for (const model::DatabaseAsciiDesc& a : d.ascii_outputs) {
      if (a.name == "GLSTAT")
        m.output.glstat_dt = a.dt;
      if (a.name == "NODOUT")
        m.output.nodout_dt = a.dt;
      if (a.name == "RCFORC")
        m.output.rcforc_dt = a.dt;
      if (a.name == "BNDOUT")
        m.output.bndout_dt = a.dt;
      if (a.name == "SPCFORC")
        m.output.spcforc_dt = a.dt;
      if (a.name == "SLEOUT")
        m.output.sleout_dt = a.dt;
      if (a.name == "RWFORC")
        m.output.rwforc_dt = a.dt;
      if (a.name == "MATSUM")
        m.output.matsum_dt = a.dt;
    }
    for (const model::DatabaseHistoryNodeDesc& h : d.history_nodes) {
      for (int id : h.node_ids)
        m.output.history_nodes.push_back(node.at(id));
      for (int sid : h.set_ids) {
        for (Index i : targets(model::NodeTarget::kSet, sid))
          m.output.history_nodes.push_back(i);
      }
    }
  }
};

/// The *DATABASE_HISTORY_SHELL / _SOLID elements as block elements, once the blocks are coloured
/// (colouring reorders a block's elements). An element named twice is written once; an element
/// of a rigid part has no stresses to write (warned about). Without *DATABASE_ELOUT (or with
/// DT 0) nothing is kept: the reader has warned about it.
void element_histories(const model::ModelDesc& d, core::Model& m,
                       std::vector<keyword::Diagnostic>& warnings) {
  if (!d.elout || d.elout->dt <= 0.0)
    return;
  std::unordered_map<core::GlobalId, core::BlockElement> solid_at, shell_at;
  for (std::size_t b = 0; b < m.solid_blocks.size(); ++b) {
    const core::SolidBlock& blk = m.solid_blocks[b];
    for (std::size_t e = 0; e < blk.size(); ++e)
      solid_at.emplace(blk.element_id[e],
                       core::BlockElement{static_cast<Index>(b), static_cast<Index>(e)});
  }
  for (std::size_t b = 0; b < m.shell_blocks.size(); ++b) {
    const core::ShellBlock& blk = m.shell_blocks[b];
    for (std::size_t e = 0; e < blk.size(); ++e)
      shell_at.emplace(blk.element_id[e],
                       core::BlockElement{static_cast<Index>(b), static_cast<Index>(e)});
  }
  std::unordered_set<core::GlobalId> seen_solid, seen_shell;
  for (const model::DatabaseHistoryElementDesc& h : d.history_elements) {
    auto& at = h.shell ? shell_at : solid_at;
    auto& seen = h.shell ? seen_shell : seen_solid;
    auto& list = h.shell ? m.output.history_shells : m.output.history_solids;
    for (std::size_t i = 0; i < h.element_ids.size(); ++i) {
      const auto it = at.find(h.element_ids[i]);
      if (it == at.end() || !seen.insert(h.element_ids[i]).second)
        continue;  // undefined: validate reported it
      const Index part = h.shell ? m.shell_blocks[static_cast<std::size_t>(it->second.block)].part
                                 : m.solid_blocks[static_cast<std::size_t>(it->second.block)].part;
      const core::Part& p = m.parts[static_cast<std::size_t>(part)];
      if (std::holds_alternative<core::RigidMaterial>(
              m.materials[static_cast<std::size_t>(p.material)])) {
        warnings.push_back(
            {h.ids_where[i], h.shell ? "*DATABASE_HISTORY_SHELL" : "*DATABASE_HISTORY_SOLID", "",
             "element " + std::to_string(h.element_ids[i]) + " is in rigid part " +
                 std::to_string(p.id) + ": it has no stresses, so it is not in elout.csv"});
        continue;
      }
      list.push_back(it->second);
    }
  }
  if (!m.output.history_shells.empty() || !m.output.history_solids.empty())
    m.output.elout_dt = d.elout->dt;
}

}  // namespace

BuildResult build(const model::ModelDesc& desc) {
  Builder b{desc, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  b.m.title = desc.title;
  b.nodes();
  b.curves();
  b.parts_and_elements();
  b.boundary_conditions();
  b.rigid_bodies();
  b.initial_velocities();
  b.controls_and_output();
  if (!core::colour_element_blocks(b.m)) {
    b.error({desc.files_read.empty() ? std::string() : desc.files_read.front(), 0},
            "*ELEMENT_SOLID", "",
            "a node is shared by more solid elements than the element colouring supports (128)");
  }
  element_histories(desc, b.m, b.out.warnings);
  build_initial_state(desc, b.m, b.out.errors, b.out.warnings);
  // Contacts last: they read the final (coloured) element blocks.
  build_contacts(desc, b.m, b.out.errors, b.out.warnings);
  build_temperatures(desc, b.m, b.out.errors);
  build_thermal(desc, b.m, b.out.errors, b.out.warnings);
  build_thermal_expansion(desc, b.m, b.out.errors, b.out.warnings);
  build_rigid_walls(desc, b.m, b.out.warnings);
  if (b.out.errors.empty())
    b.out.model = std::move(b.m);
  return std::move(b.out);
}

}  // namespace plyform::setup
