#pragma once
// Index types: deck ids (global, as written) are kept apart from array indices (local).

#include <cstdint>

namespace plyform::core {

/// A position in a local array (node, element, part ...). Local to one process/partition.
using Index = std::int32_t;
/// An id as written in the deck (node id, element id, part id ...).
using GlobalId = std::int64_t;

}  // namespace plyform::core
