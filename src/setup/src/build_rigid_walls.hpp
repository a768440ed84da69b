#pragma once
// The build step of the planar rigid walls (*RIGIDWALL_PLANAR): the wall's frame, and its slave
// nodes (NSID, less NSIDEX, within OFFSET; less the nodes a constraint, a prescribed motion or a
// rigid body moves, the nodes of no element and those behind the wall at t = 0, each counted in
// a warning).

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

/// Fills model.rigid_walls. The nodes, element blocks, constraints and prescribed motions must
/// be built; the deck validated (validate_rigid_walls).
void build_rigid_walls(const model::ModelDesc& desc, core::Model& model,
                       std::vector<keyword::Diagnostic>& warnings);

}  // namespace plyform::setup
