#include "plyform/setup/validate.hpp"

#include <string>
#include <unordered_map>

#include "plyform/setup/cohesive_law.hpp"
#include "plyform/setup/validate_contact.hpp"
#include "plyform/setup/validate_mesh.hpp"

namespace plyform::setup {

namespace {

std::string at(const model::SourceLocation& w) {
  return w.file + ":" + std::to_string(w.line);
}

}  // namespace

std::vector<keyword::Diagnostic> validate(const model::ModelDesc& model) {
  std::vector<keyword::Diagnostic> errors = validate_mesh(model);
  for (keyword::Diagnostic& d : validate_contact(model)) {
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
  return errors;
}

}  // namespace plyform::setup
