#pragma once
// Cross-keyword checks of the pressure loads (*LOAD_SEGMENT, *LOAD_SEGMENT_SET,
// *LOAD_SHELL_ELEMENT, *LOAD_SHELL_SET) and of the shell sets they name: every node, segment
// set, shell, shell set and curve exists, and a segment's corners are distinct.

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

[[nodiscard]] std::vector<keyword::Diagnostic> validate_pressure_loads(
    const model::ModelDesc& model);

}  // namespace plyform::setup
