#pragma once
// The geometry of the offset surfaces that several jobs of a pass read: a segment's normal, a
// master corner's offset vector, the relative velocity of a slave's surface point and the
// segment's point below it. Inline: they run per slave node and cycle.

#include <cmath>

#include "pass_runtime.hpp"
#include "plyform/core/invariant.hpp"

namespace plyform::contact {

// Unit normal of a segment's mid-surface (N1 N2 N3 right hand), from its corner positions:
// the cross product of the diagonals (of the two edges at N1 for a triangle). Always inlined:
// surface_normals.cpp compiles it without fused multiply-adds, and a call there must not reach
// another file's copy.
[[gnu::always_inline]] inline void segment_normal(const core::Index* q, const double* packed,
                                                  double n[3]) {
  const double *c0 = at(packed, q[0]), *c1 = at(packed, q[1]), *c2 = at(packed, q[2]);
  double a[3], b[3];
  if (q[2] == q[3]) {
    for (int d = 0; d < 3; ++d)
      a[d] = c1[d] - c0[d], b[d] = c2[d] - c0[d];
  } else {
    const double* c3 = at(packed, q[3]);
    for (int d = 0; d < 3; ++d)
      a[d] = c2[d] - c0[d], b[d] = c3[d] - c1[d];
  }
  n[0] = a[1] * b[2] - a[2] * b[1];
  n[1] = a[2] * b[0] - a[0] * b[2];
  n[2] = a[0] * b[1] - a[1] * b[0];
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double inv = len > 0.0 ? 1.0 / len : 0.0;
  n[0] *= inv, n[1] *= inv, n[2] *= inv;
}

// Offset vector of corner j of segment s for a slave on `side`: along the corner's nodal
// normal by the node's offset, turned to the slave's side (the normal's sign relative to the
// segment, fixed at t = 0). Every segment around a node puts its corner at the same point, so
// the offset surface has no step where the layer's thickness changes from element to element
// (with each segment's own offset, a node crossing from one to the next saw its gap jump by
// the difference of their half-thicknesses: 22 um at a 35 degree kink of the frictionless
// square cup, and a weak bond damaged by the sudden opening).
inline void corner_offset(const PassRuntime& pr, std::size_t s, int j, int side, double r[3]) {
  const auto c = 4 * s + static_cast<std::size_t>(j);
  const auto m = static_cast<std::size_t>(pr.corner[c]);
  const double o = side * pr.st.node_offset[m] * pr.corner_sign[c];
  const double* d = &pr.st.master_normal[3 * m];
  PLYFORM_INVARIANT(std::isfinite(d[0] + d[1] + d[2]),
                    "a master node's normal computed this cycle (surface_reads.hpp)");
  r[0] = o * d[0], r[1] = o * d[1], r[2] = o * d[2];
}

// Each master node's offset: the mean of the offsets of the segments around it (after the
// segments' offsets changed: the set-up, and each cycle where they follow the thickness).
inline void update_node_offsets(PassRuntime& pr) {
  const std::size_t nm = pr.master_nodes.size();
  pr.st.node_offset.resize(nm);
  for (std::size_t m = 0; m < nm; ++m) {
    const std::size_t b = pr.node_seg_start[m], e = pr.node_seg_start[m + 1];
    double sum = 0.0;
    for (std::size_t i = b; i < e; ++i)
      sum += pr.st.seg_offset[static_cast<std::size_t>(pr.node_seg[i])];
    pr.st.node_offset[m] = e > b ? sum / static_cast<double>(e - b) : 0.0;
  }
}

// Segment s's unit normal at this cycle's positions: the one update_master_normals() computed
// (the same numbers), or computed here when the pass keeps none.
inline const double* current_segment_normal(const PassRuntime& pr, core::Index s,
                                            const double* packed, double* scratch) {
  const auto su = static_cast<std::size_t>(s);
  if (pr.st.seg_normal_current) {
    PLYFORM_INVARIANT(std::isfinite(pr.st.seg_normal[3 * su] + pr.st.seg_normal[3 * su + 1] +
                                    pr.st.seg_normal[3 * su + 2]),
                      "a segment's normal computed this cycle (surface_reads.hpp)");
    return &pr.st.seg_normal[3 * su];
  }
  segment_normal(&pr.pass->segments[4 * su], packed, scratch);
  return scratch;
}

// Velocity of slave k's surface point relative to the surface point of segment s below it:
// v_s - sum N_j v_j, plus the tangential part (normal to `n`, the contact normal) of the
// rotations' share w_s x r_s - sum N_j w_j x r_j, with r the offset vectors (the master's along
// its nodal normals, turned to the slave's side). The rotations move the surface points along
// the surface (the layers' faces slide past each other as they bend, which adhesion and
// friction resist); the gap is geometry. Forces then put F on the nodes and the couples of the
// tangential part of F on their rotations (apply()), and F . du is exactly their power.
inline void relative_velocity(const PassRuntime& pr, std::size_t k, core::Index s,
                              const double* shape, const double* rs, int side, const double* n,
                              const double* packed, const Rotations& rot, double du[3]) {
  const core::ContactPass& cp = *pr.pass;
  const auto sn = static_cast<std::size_t>(cp.slave_nodes[k]);
  const double* p = at(packed, cp.slave_nodes[k]);
  // Summed in locals (not through du, which the compiler must assume may alias the inputs).
  double u0 = p[3], u1 = p[4], u2 = p[5];
  double r0 = 0.0, r1 = 0.0, r2 = 0.0;  // the rotations' share
  const bool spin = rot.inertia != nullptr;
  if (spin && rot.inertia[sn] > 0.0) {
    const double w0 = rot.wx[sn], w1 = rot.wy[sn], w2 = rot.wz[sn];
    r0 += w1 * rs[2] - w2 * rs[1];
    r1 += w2 * rs[0] - w0 * rs[2];
    r2 += w0 * rs[1] - w1 * rs[0];
  }
  const auto su = static_cast<std::size_t>(s);
  const core::Index* q = &cp.segments[4 * su];
  const bool offset_spin = spin && pr.st.seg_offset[su] > 0.0;
  for (int j = 0; j < 4; ++j) {
    const double nj = shape[j];
    if (nj == 0.0)
      continue;
    const double* v = at(packed, q[j]);
    u0 -= nj * v[3];
    u1 -= nj * v[4];
    u2 -= nj * v[5];
    const auto m = static_cast<std::size_t>(q[j]);
    if (offset_spin && rot.inertia[m] > 0.0) {
      double r[3];
      corner_offset(pr, su, j, side, r);
      const double w0 = rot.wx[m], w1 = rot.wy[m], w2 = rot.wz[m];
      r0 -= nj * (w1 * r[2] - w2 * r[1]);
      r1 -= nj * (w2 * r[0] - w0 * r[2]);
      r2 -= nj * (w0 * r[1] - w1 * r[0]);
    }
  }
  const double rn = r0 * n[0] + r1 * n[1] + r2 * n[2];
  du[0] = u0 + r0 - rn * n[0], du[1] = u1 + r1 - rn * n[1], du[2] = u2 + r2 - rn * n[2];
}

}  // namespace plyform::contact
