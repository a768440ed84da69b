#pragma once
// Closest-point projection of a point on a contact segment: a bilinear quadrilateral
// (Gauss-Newton on its parametric coordinates) or a flat triangle (exact). The contact pass
// calls these for every slave node and candidate segment, so they are inline and allocate
// nothing.

#include <algorithm>
#include <cmath>

namespace plyform::contact {

struct SegmentPoint {
  double shape[4] = {0, 0, 0, 0};  ///< shape functions of the 4 segment nodes at the point
  double x[3] = {0, 0, 0};         ///< the point on the segment
  double normal[3] = {0, 0, 1};    ///< unit normal, right hand N1 -> N2 -> N3
  double distance = 0.0;           ///< (p - x) . normal, signed
  double outside = 0.0;            ///< how far outside the segment in parametric measure (0 inside)
  bool degenerate = false;         ///< zero area: no normal
};

namespace detail {
inline double dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline void finish(const double* p, const double* tx, const double* ty, SegmentPoint& s) {
  double n[3] = {tx[1] * ty[2] - tx[2] * ty[1], tx[2] * ty[0] - tx[0] * ty[2],
                 tx[0] * ty[1] - tx[1] * ty[0]};
  const double len = std::sqrt(dot3(n, n));
  if (!(len > 0.0)) {
    s.degenerate = true;
    return;
  }
  for (int k = 0; k < 3; ++k)
    s.normal[k] = n[k] / len;
  const double r[3] = {p[0] - s.x[0], p[1] - s.x[1], p[2] - s.x[2]};
  s.distance = dot3(r, s.normal);
}
}  // namespace detail

/// Flat triangle c0 c1 c2 (shape[3] = 0).
inline SegmentPoint project_triangle(const double* p, const double* c0, const double* c1,
                                     const double* c2) {
  SegmentPoint s;
  const double a[3] = {c1[0] - c0[0], c1[1] - c0[1], c1[2] - c0[2]};
  const double b[3] = {c2[0] - c0[0], c2[1] - c0[1], c2[2] - c0[2]};
  const double r[3] = {p[0] - c0[0], p[1] - c0[1], p[2] - c0[2]};
  const double aa = detail::dot3(a, a), ab = detail::dot3(a, b), bb = detail::dot3(b, b);
  const double ar = detail::dot3(a, r), br = detail::dot3(b, r);
  const double det = aa * bb - ab * ab;
  if (!(det > 0.0)) {
    s.degenerate = true;
    return s;
  }
  const double xi = (bb * ar - ab * br) / det;
  const double eta = (aa * br - ab * ar) / det;
  s.shape[0] = 1.0 - xi - eta;
  s.shape[1] = xi;
  s.shape[2] = eta;
  for (int k = 0; k < 3; ++k)
    s.x[k] = c0[k] + xi * a[k] + eta * b[k];
  double out = 0.0;
  for (double w : {s.shape[0], s.shape[1], s.shape[2]})
    out = std::max(out, -w);
  // Scaled like the quadrilateral's measure (its parametric range is twice as wide).
  s.outside = 2.0 * out;
  detail::finish(p, a, b, s);
  return s;
}

/// Bilinear quadrilateral c0..c3 (parametric square [-1, 1]^2); `xi0`, `eta0` start the
/// iteration (the last projection, or 0). Newton on the squared distance with the bilinear
/// map's twist X_{,xi eta} (its only second derivative): quadratic convergence on warped
/// segments; Gauss-Newton where that Hessian is not positive (far from a strongly warped one).
/// Stops once a step is below 1e-10 in parametric measure, keeping the point it evaluated.
inline SegmentPoint project_quad(const double* p, const double* const c[4], double xi0 = 0.0,
                                 double eta0 = 0.0) {
  SegmentPoint s;
  // X(xi, eta) = a0 + a1 xi + a2 eta + a3 xi eta: the bilinear map in its monomial form, so an
  // iteration costs a few multiply-adds (a3 is the twist X_{,xi eta}).
  double a0[3], a1[3], a2[3], a3[3];
  for (int k = 0; k < 3; ++k) {
    a0[k] = 0.25 * (c[0][k] + c[1][k] + c[2][k] + c[3][k]);
    a1[k] = 0.25 * (-c[0][k] + c[1][k] + c[2][k] - c[3][k]);
    a2[k] = 0.25 * (-c[0][k] - c[1][k] + c[2][k] + c[3][k]);
    a3[k] = 0.25 * (c[0][k] - c[1][k] + c[2][k] - c[3][k]);
  }
  double xi = xi0, eta = eta0;
  double tx[3] = {0, 0, 0}, ty[3] = {0, 0, 0};
  for (int iter = 0; iter < 16; ++iter) {
    double r[3];
    for (int k = 0; k < 3; ++k) {
      tx[k] = a1[k] + a3[k] * eta;
      ty[k] = a2[k] + a3[k] * xi;
      s.x[k] = a0[k] + a1[k] * xi + ty[k] * eta;
      r[k] = p[k] - s.x[k];
    }
    const double a = detail::dot3(tx, tx), d = detail::dot3(ty, ty);
    double b = detail::dot3(tx, ty);
    const double gn = a * d - b * b;  // Gauss-Newton determinant: zero for a degenerate map
    if (!(gn > 0.0)) {
      s.degenerate = true;
      return s;
    }
    const double bt = b - detail::dot3(r, a3);
    double det = a * d - bt * bt;
    if (det > 1e-3 * gn) {
      b = bt;
    } else {
      det = gn;
    }
    const double inv = 1.0 / det;
    const double gx = detail::dot3(tx, r), gy = detail::dot3(ty, r);
    const double dx = (d * gx - b * gy) * inv;
    const double dy = (a * gy - b * gx) * inv;
    if (std::fabs(dx) + std::fabs(dy) < 1e-10)
      break;  // converged: keep the evaluated point
    // Far outside the segment the bilinear map folds: keep the iterate in a sane range.
    xi = std::clamp(xi + dx, -3.0, 3.0);
    eta = std::clamp(eta + dy, -3.0, 3.0);
  }
  s.shape[0] = 0.25 * (1 - xi) * (1 - eta);
  s.shape[1] = 0.25 * (1 + xi) * (1 - eta);
  s.shape[2] = 0.25 * (1 + xi) * (1 + eta);
  s.shape[3] = 0.25 * (1 - xi) * (1 + eta);
  s.outside = std::max(0.0, std::max(std::fabs(xi), std::fabs(eta)) - 1.0);
  detail::finish(p, tx, ty, s);
  return s;
}

}  // namespace plyform::contact
