#pragma once
// Is a plastic hinge that a rigid tool forces into a shell part resolved by the part's mesh?
// (`plyform check`'s advice; docs/shells.md has the study behind the criterion.)

#include <array>
#include <string>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::setup {

/// Elements a quarter turn of the tool's radius needs: the part's elements are too coarse for
/// the hinge when their median length across the tool's axis exceeds
/// pi R / (2 * kHingeElementsPerQuarterTurn).
inline constexpr double kHingeElementsPerQuarterTurn = 4.0;

struct HingeAdvice {
  core::GlobalId shell_part = 0;  ///< the deformable, plastic shell part (its id)
  core::GlobalId tool_part = 0;   ///< the rigid part it meets in a contact (its id)
  double tool_radius = 0.0;       ///< the tool's smallest radius of curvature, from its mesh
  double element_length = 0.0;    ///< the part's median element length across the axis
  std::string message;            ///< one line for `plyform check`
};

/// One advice per (plastic shell part, rigid shell tool) pair that a contact brings together
/// and whose tool radius is smaller than the part's elements can follow.
std::vector<HingeAdvice> hinge_resolution_advice(const core::Model& model);

struct ToolCurvature {
  double radius = 0.0;           ///< 0: no meshed radius
  std::array<double, 3> axis{};  ///< unit direction of the shared edge (the bend's axis)
};

/// The smallest radius of curvature of a rigid part's shell mesh: over the edges two of its
/// elements share, the distance between their centres over the angle between their normals;
/// flat edges (under 1 degree) and sharp ones (over 60 degrees, a corner rather than a meshed
/// radius) are not radii. The axis is that edge's direction.
ToolCurvature tool_curvature(const core::Model& model, const core::ShellBlock& block);

}  // namespace plyform::setup
