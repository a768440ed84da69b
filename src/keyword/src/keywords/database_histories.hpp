#pragma once
// What the element history outputs need once the whole deck is read: *DATABASE_ELOUT and the
// *DATABASE_HISTORY_SHELL / _SOLID elements come in either order (and from includes), so only
// then is it known whether one asks for a file the other does not let plyform write.

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::keyword {

/// Warns (by keyword and line) about *DATABASE_ELOUT without any history element ("nothing to
/// write") and about history elements without *DATABASE_ELOUT (kept, but no elout.csv).
void warn_unpaired_element_histories(const model::ModelDesc& model,
                                     std::vector<Diagnostic>& warnings);

}  // namespace plyform::keyword
