#pragma once
// The stable-step vote of each contact interface at t = 0, for `plyform check`: the run's own
// contact pass (contact::ContactSet, whose search computes the vote TSSFAC sqrt(2 m* / k)) set
// up on the masses and the elements' first step the run starts with, so that the step check
// announces is the one the run will take and the formula lives in one place.

#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::engine {

/// Per interface of model.contacts (in order): its vote at t = 0, TSSFAC included (what
/// ContactSet::stable_step gives the run after its first search); infinity where no slave
/// node is near a segment. Empty when the model's rigid bodies cannot be set up (the run
/// reports that) or it has no contact.
std::vector<double> initial_contact_steps(const core::Model& model);

}  // namespace plyform::engine
