#pragma once
// What the shell kernels and the element queries share (Belytschko-Tsay, shell_bt.cpp; fully
// integrated, shell_full.cpp): the co-rotational frame and flat local geometry of one
// quadrilateral (the frame the outputs and set-up ask for; the kernels compute the same frame
// lane-wise over a chunk, shell_stages.hpp), the shell length of the stable step, the
// plane-stress moduli of the wave speed.

#include <algorithm>
#include <cmath>

#include "plyform/core/model.hpp"
#include "plyform/material/constitutive.hpp"
#include "plyform/material/law_registry.hpp"

namespace plyform::element::shell_detail {

constexpr int kMaxNip = 10;

// Plane-stress moduli of an isotropic law: E and nu from its small-strain K and G.
struct PlaneStress {
  double e, nu, g;
};
inline PlaneStress plane_stress(const core::Material& m) {
  const double k = material::bulk_modulus(m), g = material::shear_modulus(m);
  const double e = 9.0 * k * g / (3.0 * k + g);
  const double nu = (3.0 * k - 2.0 * g) / (2.0 * (3.0 * k + g));
  return {e, nu, g};
}

// Plate wave speed sqrt(E / (rho (1 - nu^2))) for the shell's stable step.
inline double plate_wave_speed(const core::Material& m) {
  const PlaneStress p = plane_stress(m);
  return std::sqrt(p.e / (material::density(m) * (1.0 - p.nu * p.nu)));
}

// The law of a material's parameters (material/law_registry.hpp): the kernel reads its traits
// only, never which law it is.
template <class M>
using LawOf = material::LawOf<M>;

struct Geometry {
  double e1[3], e2[3], e3[3];  // co-rotational frame
  double xl[4], yl[4];         // local in-plane coordinates about the centroid
  double b1[4], b2[4];         // dN/dx, dN/dy at the centre
  double area;
};

inline bool geometry(const double x[4][3], Geometry& g) {
  const double r31[3] = {x[2][0] - x[0][0], x[2][1] - x[0][1], x[2][2] - x[0][2]};
  const double r42[3] = {x[3][0] - x[1][0], x[3][1] - x[1][1], x[3][2] - x[1][2]};
  double n[3] = {r31[1] * r42[2] - r31[2] * r42[1], r31[2] * r42[0] - r31[0] * r42[2],
                 r31[0] * r42[1] - r31[1] * r42[0]};
  const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(nl > 0.0))
    return false;
  for (double& c : n)
    c /= nl;
  // e1 along the mid-side vector from edge 4-1 to edge 2-3, projected on the plane.
  double s1[3];
  for (int d = 0; d < 3; ++d)
    s1[d] = 0.5 * (x[1][d] + x[2][d] - x[0][d] - x[3][d]);
  const double sn = s1[0] * n[0] + s1[1] * n[1] + s1[2] * n[2];
  for (int d = 0; d < 3; ++d)
    s1[d] -= sn * n[d];
  const double sl = std::sqrt(s1[0] * s1[0] + s1[1] * s1[1] + s1[2] * s1[2]);
  if (!(sl > 0.0))
    return false;
  for (int d = 0; d < 3; ++d) {
    g.e1[d] = s1[d] / sl;
    g.e3[d] = n[d];
  }
  g.e2[0] = n[1] * g.e1[2] - n[2] * g.e1[1];
  g.e2[1] = n[2] * g.e1[0] - n[0] * g.e1[2];
  g.e2[2] = n[0] * g.e1[1] - n[1] * g.e1[0];
  double c[3] = {0, 0, 0};
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d)
      c[d] += 0.25 * x[i][d];
  for (int i = 0; i < 4; ++i) {
    const double r[3] = {x[i][0] - c[0], x[i][1] - c[1], x[i][2] - c[2]};
    g.xl[i] = r[0] * g.e1[0] + r[1] * g.e1[1] + r[2] * g.e1[2];
    g.yl[i] = r[0] * g.e2[0] + r[1] * g.e2[1] + r[2] * g.e2[2];
  }
  g.area =
      0.5 * ((g.xl[2] - g.xl[0]) * (g.yl[3] - g.yl[1]) + (g.xl[1] - g.xl[3]) * (g.yl[2] - g.yl[0]));
  if (!(g.area > 0.0))
    return false;
  const double inv = 1.0 / (2.0 * g.area);
  g.b1[0] = (g.yl[1] - g.yl[3]) * inv;
  g.b1[1] = (g.yl[2] - g.yl[0]) * inv;
  g.b1[2] = (g.yl[3] - g.yl[1]) * inv;
  g.b1[3] = (g.yl[0] - g.yl[2]) * inv;
  g.b2[0] = (g.xl[3] - g.xl[1]) * inv;
  g.b2[1] = (g.xl[0] - g.xl[2]) * inv;
  g.b2[2] = (g.xl[1] - g.xl[3]) * inv;
  g.b2[3] = (g.xl[2] - g.xl[0]) * inv;
  return true;
}

// LS-DYNA's shell length: the area over the longest side (triangles: twice the area).
inline double characteristic_length(const double x[4][3], double area, bool triangle) {
  double lmax = 0.0;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
    lmax = std::max(lmax, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
  }
  return lmax > 0.0 ? (triangle ? 2.0 : 1.0) * area / lmax : 0.0;
}

}  // namespace plyform::element::shell_detail
