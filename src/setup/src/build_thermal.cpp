#include "build_thermal.hpp"

#include <string>
#include <unordered_map>

#include "plyform/material/law_registry.hpp"

namespace plyform::setup {
namespace {

using core::Index;
using Diagnostics = std::vector<keyword::Diagnostic>;

model::SourceLocation first_thermal_contact(const model::ModelDesc& d) {
  for (const model::ContactDesc& c : d.contacts)
    if (c.thermal)
      return c.where;
  return {};
}

bool any_thermal_keyword(const model::ModelDesc& d) {
  for (const model::ContactDesc& c : d.contacts)
    if (c.thermal)
      return true;
  return d.thermal_solver || d.thermal_timestep || !d.thermal_materials.empty() ||
         !d.heat_boundaries.empty() || d.tprint;
}

const char* boundary_keyword(model::HeatBoundaryKind k) {
  switch (k) {
    case model::HeatBoundaryKind::kConvection:
      return "*BOUNDARY_CONVECTION_SET";
    case model::HeatBoundaryKind::kFlux:
      return "*BOUNDARY_FLUX_SET";
    case model::HeatBoundaryKind::kRadiation:
      return "*BOUNDARY_RADIATION_SET";
  }
  return "";
}

}  // namespace

void build_thermal(const model::ModelDesc& d, core::Model& m, Diagnostics& errors,
                   Diagnostics& warnings) {
  const int soln = d.control_solution ? d.control_solution->soln : 0;
  if (soln == 0) {
    if (any_thermal_keyword(d)) {
      const model::SourceLocation where =
          d.thermal_solver               ? d.thermal_solver->where
          : d.thermal_timestep           ? d.thermal_timestep->where
          : !d.thermal_materials.empty() ? d.thermal_materials.front().where
          : !d.heat_boundaries.empty()   ? d.heat_boundaries.front().where
          : d.tprint                     ? d.tprint->where
                                         : first_thermal_contact(d);
      warnings.push_back({where, "*CONTROL_SOLUTION", "SOLN",
                          "the deck has thermal keywords but no *CONTROL_SOLUTION with SOLN 1 "
                          "or 2: temperatures are not computed (they stay as prescribed)"});
    }
    return;
  }
  core::ThermalControls& c = m.thermal;
  c.enabled = true;
  c.thermal_only = soln == 1;
  const model::SourceLocation& solution_where = d.control_solution->where;
  c.thick_shells = d.control_shell && d.control_shell->thshel == 1;
  if (d.thermal_solver) {
    const model::ControlThermalSolverDesc& s = *d.thermal_solver;
    c.steady = s.atype == 0;
    c.solver = s.solver;
    c.one_point = s.gpt == 1;
    c.max_iterations = s.maxitr > 0 ? s.maxitr : 500;
    c.abs_tol = s.abstol > 0.0 ? s.abstol : 1e-10;
    c.rel_tol = s.reltol > 0.0 ? s.reltol : 1e-6;
    c.reassemble_every = s.ncycl > 0 ? s.ncycl : 1;
    c.fwork = s.fwork;
    c.eqheat = s.eqheat;
    if (s.tsf < 0.0) {
      const int id = static_cast<int>(-s.tsf);
      c.tsf_curve = -1;
      for (std::size_t i = 0; i < d.curves.size(); ++i)
        if (d.curves[i].id == id)
          c.tsf_curve = static_cast<Index>(i);
      if (c.tsf_curve < 0)
        errors.push_back({s.where, "*CONTROL_THERMAL_SOLVER", "TSF",
                          "TSF = " + std::to_string(s.tsf) + ": curve " + std::to_string(id) +
                              " does not exist"});
    } else {
      c.tsf = s.tsf > 0.0 ? s.tsf : 1.0;
    }
  } else {
    c.steady = false;  // without the solver card: a transient analysis (ATYPE 1)
  }
  if (d.thermal_timestep) {
    const model::ControlThermalTimestepDesc& t = *d.thermal_timestep;
    c.variable_step = t.ts == 1;
    c.theta = t.tip > 0.0 ? t.tip : 0.5;
    c.dt_initial = t.its;
    c.dt_min = t.tmin;
    c.dt_max = t.tmax;
    c.dtemp = t.dtemp > 0.0 ? t.dtemp : 1.0;
    c.tscp = t.tscp > 0.0 ? t.tscp : 0.5;
  }
  if (!(c.dt_initial > 0.0)) {
    errors.push_back({d.thermal_timestep ? d.thermal_timestep->where : solution_where,
                      "*CONTROL_THERMAL_TIMESTEP", "ITS",
                      "the thermal solution needs its step: give ITS > 0 in "
                      "*CONTROL_THERMAL_TIMESTEP"});
  }

  // Thermal materials, and the parts that conduct.
  std::unordered_map<int, Index> tmat;
  for (const model::MatThermalDesc& t : d.thermal_materials) {
    if (tmat.count(t.id) != 0) {
      errors.push_back({t.where,
                        t.orthotropic ? "*MAT_THERMAL_ORTHOTROPIC" : "*MAT_THERMAL_ISOTROPIC",
                        "TMID", "thermal material " + std::to_string(t.id) + " is defined twice"});
      continue;
    }
    core::ThermalMaterial tm;
    tm.id = t.id;
    tm.density = t.density;
    tm.heat_capacity = t.heat_capacity;
    tm.conductivity = t.conductivity;
    tm.orthotropic = t.orthotropic;
    tm.aopt = t.aopt;
    tm.a = t.a;
    tm.d = t.d;
    tm.generation = t.tgmult;
    if (t.tgrlc > 0) {
      for (std::size_t i = 0; i < d.curves.size(); ++i)
        if (d.curves[i].id == t.tgrlc)
          tm.generation_curve = static_cast<Index>(i);
      if (tm.generation_curve < 0)
        errors.push_back({t.where, "*MAT_THERMAL", "TGRLC",
                          "curve " + std::to_string(t.tgrlc) + " does not exist"});
    }
    tmat.emplace(t.id, static_cast<Index>(m.thermal_materials.size()));
    m.thermal_materials.push_back(tm);
  }
  bool any = false;
  for (const model::PartDesc& p : d.parts) {
    if (p.thermal_material_id == 0)
      continue;
    const auto it = tmat.find(p.thermal_material_id);
    if (it == tmat.end()) {
      errors.push_back({p.where, "*PART", "TMID",
                        "part " + std::to_string(p.id) + ": thermal material " +
                            std::to_string(p.thermal_material_id) +
                            " is not defined (*MAT_THERMAL_ISOTROPIC or _ORTHOTROPIC)"});
      continue;
    }
    for (core::Part& part : m.parts) {
      if (part.id != p.id)
        continue;
      part.thermal_material = it->second;
      core::ThermalMaterial& tm = m.thermal_materials[static_cast<std::size_t>(it->second)];
      if (tm.density == 0.0)  // TRO = 0: the structural density
        tm.density = material::density(m.materials[static_cast<std::size_t>(part.material)]);
      any = true;
    }
  }
  if (!any) {
    errors.push_back({solution_where, "*CONTROL_SOLUTION", "SOLN",
                      "SOLN = " + std::to_string(soln) +
                          " computes temperatures, but no *PART has a thermal material (TMID)"});
  }

  // Heat boundaries: the faces of their segment sets.
  std::unordered_map<std::int64_t, Index> node;
  for (std::size_t i = 0; i < m.node_id.size(); ++i)
    node.emplace(m.node_id[i], static_cast<Index>(i));
  const auto curve_index = [&](int id, const model::HeatBoundaryDesc& b, const char* field) {
    if (id == 0)
      return Index{-1};
    for (std::size_t i = 0; i < d.curves.size(); ++i)
      if (d.curves[i].id == id)
        return static_cast<Index>(i);
    errors.push_back({b.where, boundary_keyword(b.kind), field,
                      "curve " + std::to_string(id) + " does not exist"});
    return Index{-1};
  };
  for (const model::HeatBoundaryDesc& b : d.heat_boundaries) {
    const char* kw = boundary_keyword(b.kind);
    core::HeatBoundary hb;
    hb.kind = static_cast<core::HeatBoundaryKind>(static_cast<int>(b.kind));
    hb.set_id = b.segment_set_id;
    const bool radiation = b.kind == model::HeatBoundaryKind::kRadiation;
    const bool flux = b.kind == model::HeatBoundaryKind::kFlux;
    hb.curve = curve_index(b.curve_id, b, flux ? "LCID" : radiation ? "RFLCID" : "HLCID");
    hb.mult = flux ? 1.0 : b.mult;
    hb.node_mult = b.node_mult;
    hb.ambient_curve =
        flux ? -1 : curve_index(b.ambient_curve_id, b, radiation ? "TILCID" : "TLCID");
    hb.ambient_mult = b.ambient_mult;
    hb.loc = b.loc;
    if (b.loc != 0 && !c.thick_shells) {
      warnings.push_back({b.where, kw, "LOC",
                          "LOC " + std::to_string(b.loc) +
                              " names a face of thick thermal shells, but *CONTROL_SHELL "
                              "THSHEL is not 1: the boundary acts on the shells' one temperature"});
    }
    const model::SetSegmentDesc* set = nullptr;
    for (const model::SetSegmentDesc& s : d.segment_sets)
      if (s.id == b.segment_set_id)
        set = &s;
    if (set == nullptr) {
      errors.push_back({b.where, kw, "SSID",
                        "segment set " + std::to_string(b.segment_set_id) + " does not exist"});
      continue;
    }
    for (std::size_t k = 0; k < set->segments.size(); ++k) {
      std::array<int, 4> ids = set->segments[k];
      if (ids[3] == 0)
        ids[3] = ids[2];  // a triangle
      bool ok = true;
      for (int id : ids) {
        const auto it = node.find(id);
        if (it == node.end()) {
          errors.push_back({set->segments_where[k], "*SET_SEGMENT", "N1",
                            "node " + std::to_string(id) + " does not exist"});
          ok = false;
          break;
        }
      }
      if (!ok)
        continue;
      for (int id : ids)
        hb.faces.push_back(node.at(id));
    }
    m.heat_boundaries.push_back(std::move(hb));
  }
  if (d.tprint)
    m.output.tprint_dt = d.tprint->dt;
}

}  // namespace plyform::setup
