#pragma once
// The true strains at a shell's outer surfaces for the formability outputs (the forming-limit
// diagram reads the skins, where a sheet cracks first): the mid-surface's logarithmic membrane
// strain plus the bending part, the change of curvature times the distance from the
// mid-surface,
//
//   eps(z) = eps_m + z kappa,   z = -h/2 (bottom), 0 (middle), +h/2 (top),
//
// and its in-plane principal values (major >= minor). Like element_strain.hpp this is not a
// quantity the solver integrates: it is computed from the reference and current node positions
// whenever a state is written. A Belytschko-Tsay element is flat at its centre and carries no
// director, so its curvature comes from its neighbours: the gradient of the unit normal at its
// centre, fitted by least squares to the normals of the elements across its edges (docs/outputs.md,
// "Formability").

namespace plyform::element {

/// A shell at its centre: the centre (the mean of its distinct nodes), the bilinear map's
/// tangents dx/dxi, dx/deta there, and the unit normal t1 x t2 (the side the kernel's top,
/// zeta = +1, faces). Coordinates per node, [node][direction]; node 3 = node 4 is a triangle.
struct ShellCentre {
  double centre[3];
  double t1[3], t2[3];
  double normal[3];
};

/// False for a collapsed element (no normal).
bool shell_centre(const double nodes[4][3], ShellCentre& out);

/// The covariant curvature b_ab = t_a . grad(n) . t_b (11, 22, 12) at the centre of `self`:
/// grad(n), the surface gradient of the unit normal, is fitted by least squares to
/// n_k - n = grad(n) (c_k - c) over the `count` neighbours (their centres and their normals,
/// turned to `self`'s side), both sides projected on `self`'s tangent plane and grad(n) taken
/// symmetric. What the neighbours leave undetermined (a strip one element wide has no
/// neighbour across it) is zero. With no neighbour the curvature is zero.
void fit_curvature(const ShellCentre& self, int count, const double (*centres)[3],
                   const double (*normals)[3], double b[3]);

/// In-plane principal true strains (major >= minor) at the bottom (z = -h/2), the middle and
/// the top (z = +h/2) of a shell of current thickness h.
struct SurfaceStrains {
  double major[3], minor[3];  ///< [0] bottom, [1] middle, [2] top
};

/// The strains of a shell from its reference and current centres and covariant curvatures:
/// eps_m = 1/2 ln(B) with B the in-plane left Cauchy-Green tensor of the centre's tangents,
/// kappa = b - b0 turned from the covariant basis to the current tangent plane's orthonormal
/// axes (the Koiter bending strain). False (and NaN) for a collapsed element.
bool shell_surface_strains(const ShellCentre& reference, const double b_reference[3],
                           const ShellCentre& current, const double b_current[3], double thickness,
                           SurfaceStrains& out);

/// The same strains as tensors in global axes at the bottom and top surfaces (xx yy zz xy yz
/// zx, tensor shears): the in-plane tensor eps_m + z kappa on the current tangent plane's axes,
/// plus `thickness_strain` (ln(h/h0)) along the normal, as element_strain.hpp adds it to the
/// mid-surface's strain. For LS-DYNA's *INITIAL_STRAIN_SHELL (the dynain file). False for a
/// collapsed element.
bool shell_surface_strain_tensors(const ShellCentre& reference, const double b_reference[3],
                                  const ShellCentre& current, const double b_current[3],
                                  double thickness, double thickness_strain, double bottom[6],
                                  double top[6]);

}  // namespace plyform::element
