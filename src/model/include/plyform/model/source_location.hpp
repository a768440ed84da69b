#pragma once

#include <string>

namespace plyform::model {

/// Where a piece of the deck was written: the file as it was opened and the 1-based line.
/// line = 0 means "the file as a whole" (e.g. a file that cannot be opened).
struct SourceLocation {
  std::string file;
  int line = 0;
};

}  // namespace plyform::model
