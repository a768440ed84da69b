#pragma once

#include <array>
#include <optional>
#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// A local coordinate system fixed in space, by id: *DEFINE_COORDINATE_SYSTEM (an origin, a
/// point on the local x axis, a point in the local x-y plane) or *DEFINE_COORDINATE_VECTOR
/// (a vector along local x and one in the local x-y plane, origin at 0). Kept as written; the
/// axes come from coordinate_axes().
struct CoordinateSystemDesc {
  int id = 0;                      ///< CID
  std::string title;               ///< from the _TITLE option; empty otherwise
  std::array<double, 3> origin{};  ///< XO YO ZO (0 for _VECTOR)
  std::array<double, 3> on_x{};    ///< XL YL ZL, or the origin + (XX YX ZX)
  std::array<double, 3> in_xy{};   ///< XP YP ZP, or the origin + (XV YV ZV)
  bool from_vectors = false;       ///< true: *DEFINE_COORDINATE_VECTOR
  SourceLocation where;            ///< card 1
};

/// The local unit axes (rows: local x, y, z in global components) of a right-handed system:
/// x along on_x - origin, z along x cross (in_xy - origin), y = z cross x. nullopt when the
/// x axis has no length or the x-y point lies on the x axis (relative to the system's size).
std::optional<std::array<std::array<double, 3>, 3>> coordinate_axes(
    const CoordinateSystemDesc& system);

}  // namespace plyform::model
