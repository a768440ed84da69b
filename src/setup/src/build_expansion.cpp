#include "build_expansion.hpp"

#include <algorithm>
#include <string>
#include <variant>

namespace plyform::setup {

namespace {

// The *MAT_004 table's ALPHA as a curve against temperature; empty when every ALPHA is 0.
core::LoadCurve law_expansion(const core::Material& law) {
  core::LoadCurve c;
  const auto* m = std::get_if<core::ElasticPlasticThermal>(&law);
  if (m == nullptr ||
      std::all_of(m->alpha.begin(), m->alpha.end(), [](double a) { return a == 0.0; }))
    return c;
  c.x = m->temperature;
  c.y = m->alpha;
  return c;
}

}  // namespace

void build_thermal_expansion(const model::ModelDesc& d, core::Model& m,
                             std::vector<keyword::Diagnostic>& errors,
                             std::vector<keyword::Diagnostic>& warnings) {
  // Per part: the curve of *MAT_ADD_THERMAL_EXPANSION, else the law's own.
  std::vector<core::LoadCurve> per_part(m.parts.size());
  std::vector<const model::MatAddThermalExpansionDesc*> added(m.parts.size(), nullptr);
  for (std::size_t p = 0; p < m.parts.size(); ++p)
    per_part[p] = law_expansion(m.materials[static_cast<std::size_t>(m.parts[p].material)]);
  for (const model::MatAddThermalExpansionDesc& x : d.thermal_expansions) {
    const auto part = std::find_if(m.parts.begin(), m.parts.end(),
                                   [&](const core::Part& p) { return p.id == x.pid; });
    if (part == m.parts.end()) {
      errors.push_back({x.where, "*MAT_ADD_THERMAL_EXPANSION", "PID",
                        "part " + std::to_string(x.pid) + " is not defined"});
      continue;
    }
    const auto p = static_cast<std::size_t>(part - m.parts.begin());
    const core::Material& law = m.materials[static_cast<std::size_t>(part->material)];
    if (added[p] != nullptr) {
      errors.push_back({x.where, "*MAT_ADD_THERMAL_EXPANSION", "PID",
                        "part " + std::to_string(x.pid) +
                            " already has a *MAT_ADD_THERMAL_EXPANSION (line " +
                            std::to_string(added[p]->where.line) + ")"});
      continue;
    }
    added[p] = &x;
    if (!per_part[p].x.empty()) {
      errors.push_back({x.where, "*MAT_ADD_THERMAL_EXPANSION", "PID",
                        "part " + std::to_string(x.pid) +
                            ": its *MAT_ELASTIC_PLASTIC_THERMAL has its own ALPHA; adding an "
                            "expansion would count it twice (set the ALPHAs to 0, or remove "
                            "this keyword)"});
      continue;
    }
    if (std::holds_alternative<core::RigidMaterial>(law)) {
      warnings.push_back(
          {x.where, "*MAT_ADD_THERMAL_EXPANSION", "PID",
           "part " + std::to_string(x.pid) + " is rigid: its thermal expansion has no effect"});
      continue;
    }
    core::LoadCurve c;
    if (x.lcid == 0) {
      c.x = {0.0};
      c.y = {x.mult};
    } else {
      const auto it = std::find_if(d.curves.begin(), d.curves.end(),
                                   [&](const model::CurveDesc& k) { return k.id == x.lcid; });
      if (it == d.curves.end()) {
        errors.push_back({x.where, "*MAT_ADD_THERMAL_EXPANSION", "LCID",
                          "curve " + std::to_string(x.lcid) + " is not defined"});
        continue;
      }
      c = m.curves[static_cast<std::size_t>(it - d.curves.begin())];
      for (double& y : c.y)
        y *= x.mult;
    }
    per_part[p] = std::move(c);
  }
  for (core::SolidBlock& b : m.solid_blocks)
    b.expansion = per_part[static_cast<std::size_t>(b.part)];
  for (core::ShellBlock& b : m.shell_blocks)
    b.expansion = per_part[static_cast<std::size_t>(b.part)];
}

}  // namespace plyform::setup
