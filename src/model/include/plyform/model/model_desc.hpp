#pragma once

#include <string>
#include <vector>

#include "plyform/model/curve_desc.hpp"
#include "plyform/model/user_interface_friction_desc.hpp"

namespace plyform::model {

/// The whole deck as plain data keyed by deck ids, in the order the keywords were read.
/// Each supported keyword adds one vector of its *Desc struct here.
struct ModelDesc {
  std::string title;            ///< *TITLE (the last one read)
  std::string keyword_options;  ///< text after *KEYWORD on its line (memory size, ...), if any
  std::vector<CurveDesc> curves;
  std::vector<UserInterfaceFrictionDesc> user_interface_frictions;
  std::vector<std::string> files_read;  ///< the main deck first, then each include as opened
};

}  // namespace plyform::model
