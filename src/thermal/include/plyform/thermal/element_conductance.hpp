#pragma once
// The element matrices of heat conduction: the conductance of an 8-node hexahedron (2x2x2
// Gauss points, or one at the centre), of a thin shell quadrilateral or triangle (one
// temperature through the thickness, conduction in its plane), their volumes and areas, and
// the conductivity tensor of a thermal material in the element's axes.

#include <array>

#include "plyform/core/thermal.hpp"

namespace plyform::thermal {

using Vec3 = std::array<double, 3>;
using Tensor3 = std::array<std::array<double, 3>, 3>;  ///< symmetric, global axes

/// The conductivity tensor of `m` in global axes, for an element whose first, second and
/// fourth nodes are x1, x2, x4 (AOPT 0: a along 1-2, d along 1-4) or from the vectors a and d
/// (AOPT 2); isotropic materials ignore the nodes. Times `scale` (the thermal speed-up).
[[nodiscard]] Tensor3 conductivity_tensor(const core::ThermalMaterial& m, const Vec3& x1,
                                          const Vec3& x2, const Vec3& x4, double scale);

/// Conductance K (8 x 8, symmetric, rows summing to 0) of a hexahedron with nodes x in
/// LS-DYNA order; `one_point` integrates at the centre only (GPT 1). Returns the volume
/// (the sum of the Gauss weights times det J), <= 0 for an inverted element.
double hex8_conductance(const std::array<Vec3, 8>& x, const Tensor3& k, bool one_point,
                        double (&K)[8][8]);

/// Conductance (4 x 4) of a thin shell of thickness t: the bilinear quadrilateral in the
/// plane through its centre (2x2 Gauss points), or the linear triangle when node 4 repeats
/// node 3 (its fourth row and column are then 0). Returns the area.
double shell_conductance(const std::array<Vec3, 4>& x, bool triangle, const Tensor3& k, double t,
                         double (&K)[4][4]);

/// Conductance (12 x 12) of a thick thermal shell of thickness t with a quadratic temperature
/// profile through it: unknowns in the order (middle of nodes 1-4, bottom of nodes 1-4, top of
/// nodes 1-4), bottom and top along -/+ the face normal (face_normal). In-plane conduction as
/// the thin shell's, shared by the three levels with Simpson's weights t (1/6, 2/3, 1/6);
/// through the thickness the quadratic element with k_n = n . k n, lumped on the corners. A
/// triangle's fourth rows and columns are 0. Returns the area.
double thick_shell_conductance(const std::array<Vec3, 4>& x, bool triangle, const Tensor3& k,
                               double t, double (&K)[12][12]);

/// The unit normal of a face (x2 - x0) x (x3 - x1), a triangle's (x1 - x0) x (x2 - x0): the
/// shell's top side.
[[nodiscard]] Vec3 face_normal(const std::array<Vec3, 4>& x, bool triangle);

/// The volume of a hexahedron (2x2x2 Gauss points).
[[nodiscard]] double hex8_volume(const std::array<Vec3, 8>& x);

/// The area of a face with nodes x (a triangle when `triangle`: x[3] is not used).
[[nodiscard]] double face_area(const std::array<Vec3, 4>& x, bool triangle);

}  // namespace plyform::thermal
