#pragma once

#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::keyword {

/// One located problem found while reading a deck.
struct Diagnostic {
  model::SourceLocation where;  ///< file and 1-based line (0: the file as a whole)
  std::string keyword;          ///< as "*DEFINE_CURVE_TITLE"; empty outside any keyword
  std::string field;            ///< card field such as "SFA"; empty when none applies
  std::string message;

  /// "deck.k:12: *DEFINE_CURVE: field SFA: expected a real number, got 'abc'"
  std::string to_string() const;
};

}  // namespace plyform::keyword
