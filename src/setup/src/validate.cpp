#include "plyform/setup/validate.hpp"

#include <string>
#include <unordered_map>

#include "plyform/setup/cohesive_law.hpp"
#include "plyform/setup/validate_contact.hpp"
#include "plyform/setup/validate_mesh.hpp"
#include "validate_pressure_loads.hpp"
#include "validate_rigid_walls.hpp"
#include "validate_woven_ply.hpp"

namespace plyform::setup {

namespace {

std::string at(const model::SourceLocation& w) {
  return w.file + ":" + std::to_string(w.line);
}

// One mistake often repeats on every card it touches (the elements of a part that is not
// defined, the nodes of a set from a missing include): the first kMaxAlike errors of the same
// text on the same keyword, field and file are kept, and the rest are counted in one more
// that names the last line, so the deck's other errors are not lost in the flood.
std::vector<keyword::Diagnostic> condensed(std::vector<keyword::Diagnostic> errors) {
  constexpr int kMaxAlike = 3;
  struct Group {
    int count = 0;
    std::size_t summary = 0;  // index of the summary diagnostic in `out`
    int first_line = 0;       // the line of the first error the summary stands for
  };
  std::unordered_map<std::string, Group> groups;
  std::vector<keyword::Diagnostic> out;
  for (keyword::Diagnostic& d : errors) {
    const std::string key = d.where.file + '\n' + d.keyword + '\n' + d.field + '\n' + d.message;
    Group& g = groups[key];
    ++g.count;
    if (g.count <= kMaxAlike) {
      out.push_back(std::move(d));
    } else if (g.count == kMaxAlike + 1) {
      g.summary = out.size();
      g.first_line = d.where.line;
      out.push_back(std::move(d));
    } else {
      out[g.summary].where.line = d.where.line;  // the last one
    }
  }
  for (auto& [key, g] : groups) {
    if (g.count > kMaxAlike) {
      keyword::Diagnostic& d = out[g.summary];
      d.message += " (the same on " + std::to_string(g.count - kMaxAlike) + " more lines, " +
                   std::to_string(g.first_line) + " to " + std::to_string(d.where.line) + ")";
    }
  }
  return out;
}

}  // namespace

std::vector<keyword::Diagnostic> validate(const model::ModelDesc& model) {
  std::vector<keyword::Diagnostic> errors = validate_mesh(model);
  for (keyword::Diagnostic& d : validate_contact(model)) {
    errors.push_back(std::move(d));
  }
  for (keyword::Diagnostic& d : validate_woven_plies(model)) {
    errors.push_back(std::move(d));
  }
  for (keyword::Diagnostic& d : validate_pressure_loads(model)) {
    errors.push_back(std::move(d));
  }
  for (keyword::Diagnostic& d : validate_rigid_walls(model)) {
    errors.push_back(std::move(d));
  }

  std::unordered_map<int, const model::CurveDesc*> curves;
  for (const model::CurveDesc& c : model.curves) {
    const auto [it, inserted] = curves.emplace(c.id, &c);
    if (!inserted) {
      errors.push_back(
          {c.where, "*DEFINE_CURVE", "LCID",
           "curve id " + std::to_string(c.id) + " is already defined at " + at(it->second->where)});
    }
  }

  // Tables: ids apart from the curves' and each other's, a curve for every value (the curves
  // that follow the table), the LCID column (where written) naming that curve.
  std::unordered_map<int, const model::DefineTableDesc*> tables;
  for (const model::DefineTableDesc& t : model.tables) {
    if (const auto c = curves.find(t.id); c != curves.end()) {
      errors.push_back({t.where, "*DEFINE_TABLE", "TBID",
                        "table id " + std::to_string(t.id) + " is the id of the curve at " +
                            at(c->second->where) + ": tables and curves share one id space"});
    }
    const auto [it, inserted] = tables.emplace(t.id, &t);
    if (!inserted) {
      errors.push_back(
          {t.where, "*DEFINE_TABLE", "TBID",
           "table id " + std::to_string(t.id) + " is already defined at " + at(it->second->where)});
    }
    const std::vector<int> ids = model::table_curve_ids(model, t);
    if (ids.size() < t.values.size()) {
      errors.push_back({t.where, "*DEFINE_TABLE", "VALUE",
                        "table " + std::to_string(t.id) + " has " +
                            std::to_string(t.values.size()) + " values but only " +
                            std::to_string(ids.size()) +
                            " *DEFINE_CURVE keywords follow it (one curve per value, in order, "
                            "after the table)"});
    }
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (t.lcid_written[i] != 0 && t.lcid_written[i] != ids[i]) {
        errors.push_back({t.value_where[i], "*DEFINE_TABLE", "LCID",
                          "table " + std::to_string(t.id) + ": value card " +
                              std::to_string(i + 1) + " names curve " +
                              std::to_string(t.lcid_written[i]) + " but the curve that follows " +
                              "the table in that place is " + std::to_string(ids[i]) +
                              " (the curves of a table are the ones that follow it, in order)"});
      }
    }
  }

  std::unordered_map<int, const model::UserInterfaceFrictionDesc*> interfaces;
  for (const model::UserInterfaceFrictionDesc& u : model.user_interface_frictions) {
    const auto [it, inserted] = interfaces.emplace(u.contact_id, &u);
    if (!inserted) {
      errors.push_back({u.where, "*USER_INTERFACE_FRICTION", "NOSID",
                        "contact " + std::to_string(u.contact_id) +
                            " already has a *USER_INTERFACE_FRICTION at " + at(it->second->where)});
    }
    for (keyword::Diagnostic& d : build_cohesive_law(model, u).errors) {
      errors.push_back(std::move(d));
    }
  }
  return condensed(std::move(errors));
}

}  // namespace plyform::setup
