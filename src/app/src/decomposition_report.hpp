#pragma once
// What `plyform check --ranks N` prints of a model's split over N ranks (domain/decomposition.hpp).

#include <ostream>

#include "plyform/core/model.hpp"
#include "plyform/domain/decomposition.hpp"

namespace plyform::app {

/// Each domain's elements, nodes, shared nodes, neighbours, contact slave nodes, ghost segments
/// and share of the cost (a row per domain up to 16 domains), their least, mean and largest, the
/// imbalance and the interface edges the split cuts.
void print_decomposition(const core::Model& model, const domain::Decomposition& d,
                         std::ostream& out);

}  // namespace plyform::app
