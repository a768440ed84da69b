#pragma once

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One node of *NODE. Coordinates in length units of the deck.
struct NodeDesc {
  int id = 0;            ///< NID
  double x = 0.0;        ///< X, in length units
  double y = 0.0;        ///< Y, in length units
  double z = 0.0;        ///< Z, in length units
  int tc = 0;            ///< TC: translational constraint code 0..7, as written
  int rc = 0;            ///< RC: rotational constraint code 0..7, as written
  SourceLocation where;  ///< the node's card line
};

}  // namespace plyform::model
