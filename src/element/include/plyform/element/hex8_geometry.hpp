#pragma once
// Geometry of the trilinear 8-node hexahedron (LS-DYNA node order: 1-4 the face at zeta = -1,
// 5-8 the face at zeta = +1, counter-clockwise seen from outside... as in *ELEMENT_SOLID).

#include <array>

namespace plyform::element {

/// Natural coordinates of the 8 nodes.
inline constexpr double kHexNodeXi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

/// Coordinates of 8 nodes, one array per direction.
struct HexCoords {
  double x[8], y[8], z[8];
};

/// Uniform gradient of Flanagan and Belytschko (1981): b_I = (1/V) dV/dx_I, the exact volume
/// average of grad N_I over the trilinear element, and V the exact volume. Computed from a
/// constant table of the volume form, V = sum C_IJK x_I y_J z_K, as
/// grad_I V = sum_{J<K} C_IJK (r_J x r_K). Exact for any distorted hexahedron, which is what
/// makes a one-point element pass the patch test (interior nodal forces cancel).
struct UniformGradient {
  double bx[8], by[8], bz[8];
  double volume;
};

/// Returns false (and leaves `out` with the raw volume) when the volume is not positive.
bool uniform_gradient(const HexCoords& c, UniformGradient& out);

/// The four hourglass base vectors of Flanagan-Belytschko: eta zeta, zeta xi, xi eta and
/// xi eta zeta at the nodes.
inline constexpr double kHourglass[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                            {1, -1, -1, 1, -1, 1, 1, -1},
                                            {1, -1, 1, -1, 1, -1, 1, -1},
                                            {-1, 1, -1, 1, 1, -1, 1, -1}};

/// Characteristic length for the stable time step, dt = L / c: the bound of Flanagan and
/// Belytschko on the largest eigenfrequency of the uniform-strain hexahedron,
/// omega_max^2 <= 8 c^2 sum_I |b_I|^2, so L = 1 / sqrt(2 sum_I |b_I|^2). It equals the thickness
/// of a thin element and 0.58 of the side of a cube, whose exact critical step is 0.73 L / c:
/// LS-DYNA's volume over largest face area (1.0 for the cube) is above that limit, and a free
/// cube integrated with it diverges (tests/verification/solid/test_energy.cpp).
double characteristic_length(const UniformGradient& g);

/// Shape-function gradients at the 2x2x2 Gauss points: for point q, dN_I/dx (3 x 8) and
/// det J times the weight. Returns false on a non-positive Jacobian.
struct GaussGradients {
  double bx[8][8], by[8][8], bz[8][8];  ///< [q][I]
  double weight_det[8];                 ///< w_q det J_q (the point's volume share)
};
bool gauss_gradients(const HexCoords& c, GaussGradients& out);

}  // namespace plyform::element
