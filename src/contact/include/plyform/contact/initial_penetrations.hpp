#pragma once
// LS-DYNA's IGNORE = 0 (its default) at t = 0: slave nodes that penetrate the other side's
// surface are moved out of it in the model definition, before anything is computed, so a run
// starts without the jolt a penalty would give them (that energy would come from nowhere).

#include <vector>

#include "plyform/contact/contact_set.hpp"
#include "plyform/core/model.hpp"

namespace plyform::contact {

/// Every deformable slave node of the model's interfaces with IGNORE = 0 (no cohesive law) that
/// penetrates its master segment at the model's coordinates, with the move that clears it (the
/// deepest, when several passes find it).
[[nodiscard]] std::vector<InitialPenetration> initial_penetrations(const core::Model& model);

}  // namespace plyform::contact
