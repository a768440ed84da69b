#pragma once
// The build step of heat transfer: *CONTROL_SOLUTION and the thermal controls, the thermal
// materials of the parts (*PART TMID), the heat boundaries on segment sets, *DATABASE_TPRINT.

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

/// Fills model.thermal, model.thermal_materials, the parts' thermal_material, and
/// model.heat_boundaries. The nodes, curves, parts and materials must be built.
void build_thermal(const model::ModelDesc& desc, core::Model& model,
                   std::vector<keyword::Diagnostic>& errors,
                   std::vector<keyword::Diagnostic>& warnings);

}  // namespace plyform::setup
