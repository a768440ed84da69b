#pragma once

#include "plyform/model/boundary_desc.hpp"
#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One card of *INITIAL_TEMPERATURE_NODE / _SET: the temperature of a node, of every node of a
/// set, or (_SET with NSID 0) of every node of the model at t = 0.
struct InitialTemperatureDesc {
  NodeTarget target = NodeTarget::kNode;
  int target_id = 0;         ///< NID or NSID (NSID 0: every node)
  double temperature = 0.0;  ///< TEMP
  int loc = 0;               ///< LOC: shell surface (thermal shells); must be 0
  SourceLocation where;      ///< the card line
};

/// One card of *BOUNDARY_TEMPERATURE_NODE / _SET: a prescribed temperature history
/// T(t) = CMULT * curve(t) between TBIRTH and TDEATH (before TBIRTH the initial temperature).
struct BoundaryTemperatureDesc {
  NodeTarget target = NodeTarget::kSet;
  int target_id = 0;     ///< NID or NSID
  int curve_id = 0;      ///< LCID: temperature against time (0: constant CMULT)
  double cmult = 1.0;    ///< CMULT: curve multiplier
  int loc = 0;           ///< LOC: thick thermal shells' face: -1 bottom, 0 middle, 1 top
  double death = 1e20;   ///< TDEATH (a written 0 is 1e20)
  double birth = 0.0;    ///< TBIRTH
  SourceLocation where;  ///< the card line
};

}  // namespace plyform::model
