#pragma once
// Mass, centre of mass and inertia tensor of a set of elements, integrated from the element
// geometry and the density.
//
// Hexahedra (8 nodes, trilinear map x(xi)): m = int rho dV, S = int rho x dV and
// Q = int rho (x - c)(x - c)^T dV with 3x3x3 Gauss points over the parent cube. The Jacobian
// determinant of a trilinear map has degree <= 2 in each parent coordinate, so the integrand of
// Q has degree <= 4: the 3-point rule (exact to degree 5) integrates all three exactly for any
// hexahedron (2x2x2, exact to degree 3, is exact for m and S only, or for parallelepipeds).
//
// Shells (4 nodes, triangles as N3 = N4), mid-surface x(xi, eta) bilinear, thickness
// t = sum N_a t_a: the material is a thin plate along the unit normal n, so
// m = int rho t dA, S = int rho t x dA, Q = int rho (t (x - c)(x - c)^T + t^3/12 n n^T) dA,
// with dA = |x_xi x x_eta| dxi deta, 3x3 Gauss (exact for flat quadrilaterals).
//
// The inertia tensor about the centre is I = tr(Q) 1 - Q (I_xx = int rho (y^2 + z^2) dV, ...,
// I_xy = -int rho x y dV): for a box a x b x c, I_xx = m (b^2 + c^2) / 12.

#include <array>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::rigid {

struct MassProperties {
  double mass = 0.0;                ///< [mass]
  std::array<double, 3> centre{};   ///< centre of mass [length]
  std::array<double, 9> inertia{};  ///< about the centre, global axes, row-major [kg m^2]
  std::vector<core::Index> nodes;   ///< nodes of the elements, ascending
  std::vector<double> nodal_mass;   ///< consistent row sums rho int N_a dV, per entry of nodes
};

/// Mass properties of the solid and shell elements of model part `part` (index into
/// Model::parts) with density `rho` [kg/m^3]; mass 0 and no nodes when it has none. Throws
/// std::invalid_argument naming the part and element when an element has a non-positive Jacobian at
/// a Gauss point.
[[nodiscard]] MassProperties part_mass_properties(const core::Model& model, core::Index part,
                                                  double rho);

}  // namespace plyform::rigid
