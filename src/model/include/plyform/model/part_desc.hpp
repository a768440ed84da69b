#pragma once

#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *PART: a part ties elements to a section, a material and optionally an hourglass control.
struct PartDesc {
  int id = 0;                   ///< PID
  std::string title;            ///< HEADING (the title card, always present)
  int section_id = 0;           ///< SECID
  int material_id = 0;          ///< MID
  int eos_id = 0;               ///< EOSID (must be 0: equations of state are not supported)
  int hourglass_id = 0;         ///< HGID (0: *CONTROL_HOURGLASS defaults)
  int grav = 0;                 ///< GRAV, as written
  int adpopt = 0;               ///< ADPOPT (must be 0: adaptivity is not supported)
  int thermal_material_id = 0;  ///< TMID (*MAT_THERMAL_...; 0: no heat conduction in the part)
  SourceLocation where;         ///< the line of card 1 (PID SECID MID ...)
};

}  // namespace plyform::model
