#pragma once
// Cross-keyword checks of *MAT_REINFORCED_THERMOPLASTIC (249): its curves and tables exist, its
// temperature-dependent input has temperatures to read, its elasto-plastic shear is well posed.

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

[[nodiscard]] std::vector<keyword::Diagnostic> validate_woven_plies(const model::ModelDesc& model);

}  // namespace plyform::setup
