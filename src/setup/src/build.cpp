#include "plyform/setup/build.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

namespace plyform::setup {
namespace {

using core::Index;

struct Builder {
  const model::ModelDesc& d;
  BuildResult out;
  core::Model m;
  std::unordered_map<int, Index> node, curve, part;
  std::unordered_map<int, const model::SetListDesc*> node_set, part_set;

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
      if (nd.tc > 0 && nd.tc < 8) {
        m.fixed.push_back({static_cast<Index>(m.node_id.size()), kTc[nd.tc]});
      }
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
  }

  void parts_and_elements() {
    std::unordered_map<int, const model::SectionSolidDesc*> sections;
    for (const auto& s : d.solid_sections)
      sections.emplace(s.id, &s);
    std::unordered_map<int, const model::HourglassDesc*> hourglasses;
    for (const auto& h : d.hourglasses)
      hourglasses.emplace(h.id, &h);
    std::unordered_map<int, Index> material;  // material id -> index in m.materials
    const auto material_of = [&](int id) -> Index {
      if (auto it = material.find(id); it != material.end())
        return it->second;
      for (const auto& e : d.elastic_materials) {
        if (e.id == id)
          m.materials.push_back(
              core::ElasticMaterial{e.density, e.youngs_modulus, e.poisson_ratio});
      }
      for (const auto& r : d.mooney_rivlin_materials) {
        if (r.id == id) {
          m.materials.push_back(core::MooneyRivlinMaterial{r.density, r.poisson_ratio, r.a, r.b});
        }
      }
      if (m.materials.size() == material.size())
        return -1;  // not a solid material
      const auto index = static_cast<Index>(m.materials.size() - 1);
      material.emplace(id, index);
      return index;
    };

    std::unordered_map<int, std::size_t> block_of_part;
    for (const model::PartDesc& p : d.parts) {
      const auto sec = sections.find(p.section_id);
      if (sec == sections.end())
        continue;  // not a solid part; reported by validation
      part.emplace(p.id, static_cast<Index>(m.parts.size()));
      const Index mat = material_of(p.material_id);
      if (mat < 0) {
        error(p.where, "*PART", "MID",
              "part " + std::to_string(p.id) + ": material " + std::to_string(p.material_id) +
                  " is not a solid material (*MAT_ELASTIC or *MAT_MOONEY-RIVLIN_RUBBER)");
        continue;
      }
      m.parts.push_back(core::Part{p.id, p.title, mat});
      core::SolidBlock b;
      b.formulation = sec->second->elform == 2 ? core::SolidFormulation::selective_reduced
                                               : core::SolidFormulation::one_point;
      b.part = static_cast<Index>(m.parts.size() - 1);
      b.material = mat;
      // Hourglass: the part's *HOURGLASS, else *CONTROL_HOURGLASS, else IHQ 1, QM 0.1.
      if (d.control_hourglass) {
        b.hourglass.ihq = d.control_hourglass->ihq;
        b.hourglass.qm = d.control_hourglass->qh;
      }
      if (p.hourglass_id != 0) {
        const model::HourglassDesc& h = *hourglasses.at(p.hourglass_id);
        if (h.ihq != 0)
          b.hourglass.ihq = h.ihq;
        b.hourglass.qm = h.qm;
      }
      if (b.hourglass.ihq < 1 || b.hourglass.ihq > 5) {
        error(p.hourglass_id != 0 ? hourglasses.at(p.hourglass_id)->where : p.where, "*HOURGLASS",
              "IHQ",
              "hourglass type " + std::to_string(b.hourglass.ihq) +
                  " is not supported for solids: use 1-3 (viscous) or 4-5 (stiffness)");
      }
      block_of_part.emplace(p.id, m.solid_blocks.size());
      m.solid_blocks.push_back(std::move(b));
    }
    for (const model::ElementSolidDesc& e : d.solids) {
      const auto it = block_of_part.find(e.part_id);
      if (it == block_of_part.end()) {
        error(e.where, "*ELEMENT_SOLID", "PID",
              "element " + std::to_string(e.id) + ": part " + std::to_string(e.part_id) +
                  " has no *SECTION_SOLID");
        continue;
      }
      core::SolidBlock& b = m.solid_blocks[it->second];
      b.element_id.push_back(e.id);
      for (int n : e.nodes)
        b.connectivity.push_back(node.at(n));
    }
  }

  void boundary_conditions() {
    for (const model::BoundarySpcDesc& s : d.spcs) {
      unsigned dofs = 0;
      for (int k = 0; k < 3; ++k) {
        if (s.fixed[static_cast<std::size_t>(k)])
          dofs |= 1u << k;
      }
      if (dofs == 0)
        continue;  // rotations only: solids carry no rotational freedom
      for (Index n : targets(s.target, s.target_id))
        m.fixed.push_back({n, dofs});
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
        pm.direction = p.dof - 1;
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
  }

  void initial_velocities() {
    if (d.initial_velocities.empty())
      return;
    const std::size_t n = m.node_count();
    m.v0x.assign(n, 0.0);
    m.v0y.assign(n, 0.0);
    m.v0z.assign(n, 0.0);
    for (const model::InitialVelocityGenerationDesc& v : d.initial_velocities) {
      std::vector<char> pick(n, 0);
      const auto mark_part = [&](int part_id) {
        const auto it = part.find(part_id);
        if (it == part.end())
          return;
        const core::SolidBlock& b = m.solid_blocks[static_cast<std::size_t>(it->second)];
        for (Index c : b.connectivity)
          pick[static_cast<std::size_t>(c)] = 1;
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
  }

  void controls_and_output() {
    if (d.termination) {
      m.controls.end_time = d.termination->end_time;
      m.controls.end_cycle = d.termination->end_cycle;
      m.controls.dt_min_ratio = d.termination->dtmin;
    } else {
      error({d.files_read.empty() ? std::string() : d.files_read.front(), 0},
            "*CONTROL_TERMINATION", "ENDTIM",
            "the deck has no *CONTROL_TERMINATION: the run would never end");
    }
    if (d.timestep) {
      m.controls.tssfac = d.timestep->tssfac;
      m.controls.dt2ms = d.timestep->dt2ms;
      m.controls.dt_init = d.timestep->dtinit;
    }
    if (d.d3plot) {
      m.output.d3plot_dt =
          d.d3plot->npltc > 0 ? m.controls.end_time / d.d3plot->npltc : d.d3plot->dt;
    }
    for (const model::DatabaseAsciiDesc& a : d.ascii_outputs) {
      if (a.name == "GLSTAT")
        m.output.glstat_dt = a.dt;
      if (a.name == "NODOUT")
        m.output.nodout_dt = a.dt;
    }
    for (const model::DatabaseHistoryNodeDesc& h : d.history_nodes) {
      for (int id : h.node_ids)
        m.output.history_nodes.push_back(node.at(id));
    }
  }
};

}  // namespace

BuildResult build(const model::ModelDesc& desc) {
  Builder b{desc, {}, {}, {}, {}, {}, {}, {}};
  b.m.title = desc.title;
  b.nodes();
  b.curves();
  b.parts_and_elements();
  b.boundary_conditions();
  b.initial_velocities();
  b.controls_and_output();
  if (!core::colour_element_blocks(b.m)) {
    b.error({desc.files_read.empty() ? std::string() : desc.files_read.front(), 0},
            "*ELEMENT_SOLID", "",
            "a node is shared by more solid elements than the element colouring supports (128)");
  }
  if (b.out.errors.empty())
    b.out.model = std::move(b.m);
  return std::move(b.out);
}

}  // namespace plyform::setup
