#pragma once

#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *SET_NODE_LIST or *SET_PART_LIST: a list of node or part ids (ModelDesc keeps the two
/// kinds apart: node_sets, part_sets).
struct SetListDesc {
  int id = 0;         ///< SID
  std::string title;  ///< from the _TITLE option; empty otherwise
  double da1 = 0.0;   ///< DA1..DA4: attributes, as written
  double da2 = 0.0;
  double da3 = 0.0;
  double da4 = 0.0;
  std::string solver;                     ///< SOLVER ("MECH" when blank)
  std::vector<int> ids;                   ///< the node or part ids, in deck order
  std::vector<SourceLocation> ids_where;  ///< the card line of each id
  SourceLocation where;                   ///< the line of card 1 (SID ...)
};

}  // namespace plyform::model
