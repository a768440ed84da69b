#include "plyform/keyword/parameter_table.hpp"

#include <utility>

namespace plyform::keyword {

void ParameterTable::enter_file() {
  locals_.emplace_back();
}

void ParameterTable::leave_file() {
  if (!locals_.empty()) {
    locals_.pop_back();
  }
}

const Parameter* ParameterTable::define(std::string name, Parameter value, bool local) {
  Scope& scope = (local && !locals_.empty()) ? locals_.back() : global_;
  const auto [it, inserted] = scope.try_emplace(std::move(name), std::move(value));
  return inserted ? nullptr : &it->second;
}

const Parameter* ParameterTable::find(std::string_view name) const {
  for (auto scope = locals_.rbegin(); scope != locals_.rend(); ++scope) {
    if (const auto it = scope->find(name); it != scope->end()) {
      return &it->second;
    }
  }
  if (const auto it = global_.find(name); it != global_.end()) {
    return &it->second;
  }
  return nullptr;
}

}  // namespace plyform::keyword
