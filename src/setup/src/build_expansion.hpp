#pragma once
// The build step of thermal expansion: each deformable block's coefficient alpha(T), from
// *MAT_ADD_THERMAL_EXPANSION on its part or from its law's own table (*MAT_004 ALPHA).

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

/// Sets core::SolidBlock::expansion and core::ShellBlock::expansion. Parts, blocks and curves
/// must be built.
void build_thermal_expansion(const model::ModelDesc& desc, core::Model& model,
                             std::vector<keyword::Diagnostic>& errors,
                             std::vector<keyword::Diagnostic>& warnings);

}  // namespace plyform::setup
