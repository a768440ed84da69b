#include "validate_woven_ply.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

namespace plyform::setup {

namespace {

constexpr const char* kKeyword = "*MAT_REINFORCED_THERMOPLASTIC";

template <class... T>
std::string cat(const T&... parts) {
  std::string s;
  ((s +=
    [&] {
      if constexpr (std::is_arithmetic_v<T>)
        return std::to_string(parts);
      else
        return std::string(parts);
    }()),
   ...);
  return s;
}

}  // namespace

std::vector<keyword::Diagnostic> validate_woven_plies(const model::ModelDesc& model) {
  std::vector<keyword::Diagnostic> errors;
  if (model.reinforced_thermoplastic_materials.empty())
    return errors;
  std::unordered_map<int, const model::CurveDesc*> curves;
  for (const model::CurveDesc& c : model.curves)
    curves.emplace(c.id, &c);
  std::unordered_map<int, const model::DefineTableDesc*> tables;
  for (const model::DefineTableDesc& t : model.tables)
    tables.emplace(t.id, &t);
  // Temperatures the law can read: initial or prescribed ones, or computed ones.
  const bool temperatures = !model.initial_temperatures.empty() ||
                            !model.temperature_histories.empty() ||
                            (model.control_solution && model.control_solution->soln != 0);

  for (const model::MatReinforcedThermoplasticDesc& m : model.reinforced_thermoplastic_materials) {
    bool reads_temperature = false;
    const auto curve = [&](int id, const model::SourceLocation& where, const char* field) {
      if (id == 0)
        return;
      if (!curves.contains(id))
        errors.push_back({where, kKeyword, field,
                          cat("material ", m.id, ": curve ", id,
                              " is not defined (no *DEFINE_CURVE with this id)")});
      reads_temperature = true;
    };
    const auto curve_or_table = [&](int id, const model::SourceLocation& where, const char* field) {
      if (id == 0)
        return;
      if (tables.contains(id)) {
        reads_temperature = true;
        return;
      }
      if (!curves.contains(id))
        errors.push_back(
            {where, kKeyword, field,
             cat("material ", m.id, ": ", id,
                 " is neither a curve nor a table (no *DEFINE_CURVE or *DEFINE_TABLE with this "
                 "id)")});
    };
    curve(m.lcem, m.where, "LCEM");
    curve(m.lcprm, m.where, "LCPRM");
    curve_or_table(m.lcsigy, m.where, "LCSIGY");
    for (std::size_t i = 0; i < m.fibres.size(); ++i) {
      const std::string field = cat("LCEF", i + 1);
      curve_or_table(m.fibres[i].lcef, m.fibres[i].where, field.c_str());
    }
    for (std::size_t k = 0; k < m.shears.size(); ++k) {
      const model::FibreShearDesc& s = m.shears[k];
      const std::string pair = k == 0 ? "12" : "23";
      const std::string field = "LCG" + pair;
      curve_or_table(s.lcg, s.where, field.c_str());
      // METH 3: the loading curve's slope must stay below the elastic slope G (the curve is
      // then reached by the return; a steeper curve has no elasto-plastic reading).
      if (s.meth == 3 && s.lcg != 0) {
        std::vector<const model::CurveDesc*> of;
        if (const auto t = tables.find(s.lcg); t != tables.end()) {
          for (int id : model::table_curve_ids(model, *t->second)) {
            if (const auto c = curves.find(id); c != curves.end())
              of.push_back(c->second);
          }
        } else if (const auto c = curves.find(s.lcg); c != curves.end()) {
          of.push_back(c->second);
        }
        double steepest = 0.0;
        for (const model::CurveDesc* c : of) {
          const std::vector<model::CurvePoint> pts = model::effective_points(*c);
          for (std::size_t i = 1; i < pts.size(); ++i)
            steepest = std::max(steepest, (pts[i].y - pts[i - 1].y) / (pts[i].x - pts[i - 1].x));
        }
        if (steepest > s.g)
          errors.push_back(
              {s.where, kKeyword, "G" + pair,
               cat("material ", m.id, ": METH", pair, " = 3 unloads with slope G", pair, " = ", s.g,
                   ", below the steepest slope ", steepest, " of its curve LCG", pair, ": give G",
                   pair, " at least that slope (the elastic shear modulus)")});
      }
    }
    if (reads_temperature && !temperatures) {
      errors.push_back({m.where, kKeyword, m.lcem != 0 ? "LCEM" : (m.lcprm != 0 ? "LCPRM" : "MID"),
                        cat("material ", m.id,
                            " has properties against temperature but the deck has no temperatures "
                            "(*INITIAL_TEMPERATURE, *BOUNDARY_TEMPERATURE or a thermal solution, "
                            "*CONTROL_SOLUTION SOLN 1 or 2)")});
    }
  }
  return errors;
}

}  // namespace plyform::setup
