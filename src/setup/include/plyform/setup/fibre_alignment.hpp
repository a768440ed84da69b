#pragma once
// Is a woven ply meshed along its fibres? (`plyform check`'s advice; docs/materials.md has the
// bias-extension study behind it.) A family that crosses an element's edges obliquely must stay
// inextensible along a line that joins no nodes: the element then cannot shear as the fabric
// does (intra-ply shear locking), and the shear gathers where the mesh lets it.

#include <string>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::setup {

/// A family lies along an element when it is within this angle of one of its edges.
inline constexpr double kFibreEdgeToleranceDegrees = 10.0;
/// A part is advised when more than this share of its elements has a family along no edge.
inline constexpr double kFibreOffShare = 0.1;

struct FibreAlignmentAdvice {
  core::GlobalId part = 0;     ///< the woven ply's shell part (its id)
  std::size_t elements = 0;    ///< the part's elements
  std::size_t off_fibres = 0;  ///< of them, those with a family along none of their edges
  double worst_degrees = 0.0;  ///< the largest angle of a family to its element's nearest edge
  std::string message;         ///< one line for `plyform check`
};

/// One advice per *MAT_REINFORCED_THERMOPLASTIC shell part meshed mostly across its fibres:
/// the families' initial directions (AOPT 0, 2, 3, MANGL or the element's BETA, ALPHi, as the
/// shell kernels set them at the first step) against each element's edges.
std::vector<FibreAlignmentAdvice> fibre_alignment_advice(const core::Model& model);

/// The angle in degrees, in [0, 90], between a family at `fibre` radians and the nearest of the
/// element's edges in its plane (directions in one in-plane basis; a line, not a vector).
double fibre_edge_angle(double fibre, const double* edge_angles, int edges);

}  // namespace plyform::setup
