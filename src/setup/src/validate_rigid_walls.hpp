#pragma once
// Cross-keyword checks of the planar rigid walls (*RIGIDWALL_PLANAR): the node sets and the
// display nodes exist, the normal and a finite wall's edge are well defined, ids are unique.

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

[[nodiscard]] std::vector<keyword::Diagnostic> validate_rigid_walls(const model::ModelDesc& model);

}  // namespace plyform::setup
