#include "plyform/keyword/diagnostic.hpp"

#include <fmt/format.h>

namespace plyform::keyword {

std::string Diagnostic::to_string() const {
  std::string out = where.file;
  if (where.line > 0) {
    out += fmt::format(":{}", where.line);
  }
  out += ": ";
  if (!keyword.empty()) {
    out += keyword + ": ";
  }
  if (!field.empty()) {
    out += "field " + field + ": ";
  }
  out += message;
  return out;
}

}  // namespace plyform::keyword
