#pragma once

#include <array>
#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// What a pressure load names: one segment by its nodes (*LOAD_SEGMENT), a *SET_SEGMENT
/// (*LOAD_SEGMENT_SET), one shell element (*LOAD_SHELL_ELEMENT) or a *SET_SHELL
/// (*LOAD_SHELL_SET).
enum class PressureTarget { kSegment, kSegmentSet, kShell, kShellSet };

/// One card of *LOAD_SEGMENT, *LOAD_SEGMENT_SET, *LOAD_SHELL_ELEMENT or *LOAD_SHELL_SET
/// (_ID): a pressure of a curve against time on the current area of each segment, along its
/// current normal (a follower load); positive pressure pushes against the normal of
/// N1 -> N2 -> N3 (the right-hand rule).
struct LoadPressureDesc {
  PressureTarget target = PressureTarget::kSegment;
  int target_id = 0;           ///< SSID, EID or ESID (0 for kSegment)
  std::array<int, 4> nodes{};  ///< kSegment: N1..N4 (N4 = N3 or 0 for a triangle)
  int id = 0;                  ///< ID of the _ID option (0 without it)
  std::string heading;         ///< HEADING of the _ID option
  int curve_id = 0;            ///< LCID: the curve of the pressure against time
  double scale = 1.0;          ///< SF: ordinate scale factor of the curve
  double arrival = 0.0;        ///< AT: the pressure is 0 before this time
  std::string keyword;         ///< as written ("*LOAD_SEGMENT_SET"), for messages
  SourceLocation where;        ///< the card line
};

}  // namespace plyform::model
