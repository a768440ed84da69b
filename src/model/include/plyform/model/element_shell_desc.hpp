#pragma once

#include <array>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One shell element of *ELEMENT_SHELL (_THICKNESS). Triangles are written as in LS-DYNA with
/// N4 = N3; setup::validate_mesh documents which repeats are accepted.
struct ElementShellDesc {
  int id = 0;                  ///< EID
  int part_id = 0;             ///< PID
  std::array<int, 4> nodes{};  ///< N1..N4 (node ids; N4 = N3 for a triangle)
  /// True when the element has the thickness card of the _THICKNESS option.
  bool has_thickness_card = false;
  /// THIC1..THIC4: shell thickness at N1..N4, length, as written (all 0 without the _THICKNESS
  /// card; a 0 leaves the section's thickness to the build step, as in LS-DYNA).
  std::array<double, 4> thickness{};
  double beta = 0.0;     ///< BETA: material angle of the element, degrees (0 without the card)
  SourceLocation where;  ///< the card line holding EID PID N1..N4
};

}  // namespace plyform::model
