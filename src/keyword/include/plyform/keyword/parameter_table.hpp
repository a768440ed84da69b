#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::keyword {

/// A *PARAMETER value. type is 'R' (real), 'I' (integer) or 'C' (character).
struct Parameter {
  char type = 'R';
  double number = 0.0;  ///< R and I parameters
  std::string text{};   ///< C parameters
  model::SourceLocation where{};
};

/// The parameters visible while reading: global ones (*PARAMETER) and, per file being read,
/// local ones (*PARAMETER_LOCAL) that the file and the files it includes see. Names are case
/// sensitive, as in LS-DYNA.
class ParameterTable {
 public:
  /// Opens the local scope of a file; leave_file() closes it.
  void enter_file();
  void leave_file();

  /// Defines a parameter. If the name is already defined in that scope, the first definition
  /// is kept (LS-DYNA's default) and the earlier one is returned; otherwise nullptr.
  const Parameter* define(std::string name, Parameter value, bool local);

  /// The innermost visible definition, or nullptr.
  const Parameter* find(std::string_view name) const;

 private:
  using Scope = std::map<std::string, Parameter, std::less<>>;
  Scope global_;
  std::vector<Scope> locals_;  ///< one per file being read, innermost last
};

}  // namespace plyform::keyword
