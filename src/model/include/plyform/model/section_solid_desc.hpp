#pragma once

#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *SECTION_SOLID: the formulation of solid elements.
struct SectionSolidDesc {
  int id = 0;         ///< SECID
  std::string title;  ///< from the _TITLE option; empty otherwise
  /// ELFORM as LS-DYNA uses it: 1 constant stress (one point, hourglass control),
  /// 2 fully integrated selectively reduced. A written 0 (or blank) is stored as 1.
  int elform = 1;
  int aet = 0;           ///< AET, as written (0 for the supported formulations)
  SourceLocation where;  ///< the line of the card holding SECID
};

}  // namespace plyform::model
