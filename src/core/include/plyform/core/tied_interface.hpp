#pragma once

#include <array>
#include <string>
#include <vector>

#include "plyform/core/types.hpp"

namespace plyform::core {

/// A tied contact (*CONTACT_TIED_NODES_TO_SURFACE, *CONTACT_TIED_SHELL_EDGE_TO_SURFACE): each
/// tied slave node follows the point of a master segment it projected to at t = 0, at its
/// distance from it (docs/contact.md, "Tied contacts").
struct TiedInterface {
  GlobalId id = 0;      ///< CID (0: none)
  std::string keyword;  ///< as written, for messages
  /// The slave shell nodes' rotations turn with the segment, and an offset slave node moves
  /// as a point rigidly linked to it (the tie carries moments).
  bool rotations = false;
  std::vector<Index> slaves;                  ///< tied slave nodes, ascending
  std::vector<std::array<Index, 4>> segment;  ///< each slave's master segment (N4 = N3: a triangle)
  std::vector<std::array<double, 4>> weight;  ///< the segment's shape functions at the point
};

}  // namespace plyform::core
