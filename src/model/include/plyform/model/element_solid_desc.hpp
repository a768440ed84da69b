#pragma once

#include <array>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One 8-node solid element of *ELEMENT_SOLID. Degenerate shapes are written with repeated
/// nodes as in LS-DYNA (tetrahedron N1 N2 N3 N4 N4 N4 N4 N4, pentahedron N1..N5 N5 N6 N6);
/// setup::validate_mesh documents which repeats are accepted.
struct ElementSolidDesc {
  int id = 0;                  ///< EID
  int part_id = 0;             ///< PID
  std::array<int, 8> nodes{};  ///< N1..N8 (node ids)
  SourceLocation where;        ///< the card line holding the nodes' first card (EID PID)
};

}  // namespace plyform::model
