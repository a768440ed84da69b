#pragma once
// The total strain of an element for output (*DATABASE_EXTENT_BINARY STRFLG): the logarithmic
// (Hencky) strain 1/2 ln(F F^T) of the element's mean deformation gradient F, in global axes.
// It is what the element's stretches are (ln(l / l0) along each principal direction), is zero
// for any rigid motion, and is not a quantity the solver integrates: it is computed afresh
// from the reference and current node positions whenever a state is written.

#include "plyform/element/hex8_geometry.hpp"

namespace plyform::element {

/// Components xx, yy, zz, xy, yz, zx (tensor shear, not engineering).
using StrainTensor = double[6];

/// 1/2 ln(F F^T) of a deformation gradient (row-major, F[i][j] = dx_i / dX_j). Returns false
/// when det F <= 0 (an inverted element has no logarithmic strain; `out` is then NaN).
bool log_strain(const double F[3][3], StrainTensor out);

/// A hexahedron's volume-averaged F = sum_I x_I (x) b_I, with b_I the uniform gradient of the
/// reference configuration. Returns false for a reference of non-positive volume or an
/// inverted F.
bool hex8_log_strain(const HexCoords& reference, const HexCoords& current, StrainTensor out);

/// A shell's mid-surface strain at its centre: F maps the reference tangents (dX/dxi, dX/deta)
/// onto the current ones and the reference normal onto the current normal stretched by
/// `thickness_ratio` (h / h0). Degenerate quads (node 3 = node 4, triangles) are exact.
/// Coordinates per node, [node][direction]. Returns false for a collapsed element.
bool shell_log_strain(const double reference[4][3], const double current[4][3],
                      double thickness_ratio, StrainTensor out);

}  // namespace plyform::element
