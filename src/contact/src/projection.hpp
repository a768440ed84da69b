#pragma once
// Which segment a slave node is on, and where: the projection of the node's surface point on
// the master's offset surface, the side, and the choice among candidates (MAXPAR, the faces the
// node's surface faces, valleys).

#include <algorithm>
#include <cmath>

#include "pass_runtime.hpp"
#include "plyform/contact/segment_projection.hpp"
#include "plyform/core/invariant.hpp"
#include "surface_geometry.hpp"
#include "surface_normals.hpp"

namespace plyform::contact {

/// A slave node against one segment: the projection of its surface point on the segment's
/// offset surface, the side it is on, and where that surface point lies.
struct Located {
  SegmentPoint sp;  // on the offset surface: distance = signed gap along the segment normal
  signed char side = 0;
  double rs[3] = {0, 0, 0};  // slave surface point minus the slave node
};

// Projects slave k, on `side` of segment s, on the segment's offset surface. The slave's
// surface point is the node moved by its offset o_s towards the master along its nodal normal
// (geometry, like the master's), so that the point lies on the layer's face: a node going
// round a faceted tool's kink then sees the gap of its face, not of a point o_s above it. A
// node without faces is moved along the contact normal (the gap is its distance minus o_s).
// `towards`: about the contact normal (last cycle's), or null to take the segment's.
inline void project_surface(const PassRuntime& pr, std::size_t k, core::Index s,
                            const double* packed, const double* guess, const double* towards,
                            Located& L) {
  const core::ContactPass& cp = *pr.pass;
  const auto su = static_cast<std::size_t>(s);
  const core::Index* q = &cp.segments[4 * su];
  const double* p = at(packed, cp.slave_nodes[k]);
  const double om = pr.st.seg_offset[su];
  const double os = pr.st.slave_offset[k];
  const double* dir = &pr.st.slave_normal[3 * k];
  PLYFORM_INVARIANT(std::isfinite(dir[0] + dir[1] + dir[2]),
                    "a slave node's normal computed this cycle (surface_reads.hpp)");
  const bool along_normal = os > 0.0 && (dir[0] != 0.0 || dir[1] != 0.0 || dir[2] != 0.0);
  if (along_normal) {
    // Towards the master: against the contact normal (side times the segment's normal).
    double nc[3];
    if (towards != nullptr) {
      nc[0] = towards[0], nc[1] = towards[1], nc[2] = towards[2];
    } else {
      double scratch[3];
      const double* ns = current_segment_normal(pr, s, packed, scratch);
      nc[0] = L.side * ns[0], nc[1] = L.side * ns[1], nc[2] = L.side * ns[2];
    }
    const double sg = dir[0] * nc[0] + dir[1] * nc[1] + dir[2] * nc[2] < 0.0 ? os : -os;
    L.rs[0] = sg * dir[0], L.rs[1] = sg * dir[1], L.rs[2] = sg * dir[2];
  }
  const double xs[3] = {p[0] + (along_normal ? L.rs[0] : 0.0),
                        p[1] + (along_normal ? L.rs[1] : 0.0),
                        p[2] + (along_normal ? L.rs[2] : 0.0)};
  double c[4][3];
  for (int j = 0; j < 4; ++j) {
    const double* x = at(packed, q[j]);
    c[j][0] = x[0], c[j][1] = x[1], c[j][2] = x[2];
    if (om > 0.0) {
      double r[3];
      corner_offset(pr, su, j, L.side, r);
      c[j][0] += r[0], c[j][1] += r[1], c[j][2] += r[2];
    }
  }
  if (q[2] == q[3]) {
    L.sp = project_triangle(xs, c[0], c[1], c[2]);
  } else {
    const double* cc[4] = {c[0], c[1], c[2], c[3]};
    if (guess == nullptr) {
      L.sp = project_quad(xs, cc);
    } else {
      // xi = N1 + N2 - N0 - N3, eta = N2 + N3 - N0 - N1 for the bilinear shape functions.
      L.sp = project_quad(xs, cc, guess[1] + guess[2] - guess[0] - guess[3],
                          guess[2] + guess[3] - guess[0] - guess[1]);
    }
  }
  if (!along_normal) {
    const double so = L.side * os;
    L.sp.distance -= so;
    L.rs[0] = -so * L.sp.normal[0], L.rs[1] = -so * L.sp.normal[1], L.rs[2] = -so * L.sp.normal[2];
  }
}

// Projects slave k on segment s. The side: the node's own while it is in contact or bonded;
// a free node (approaching, detached) takes the side its mid-surface is on once it is clear of
// both surfaces, or when it had no segment last cycle (it cannot have come through). `guess`:
// shape functions of an earlier projection on the same segment (warm start), or null.
inline Located project_on(const PassRuntime& pr, std::size_t k, core::Index s, bool free,
                          bool was_located, const double* packed, const double* guess) {
  const core::ContactPass& cp = *pr.pass;
  const core::Index* q = &cp.segments[4 * static_cast<std::size_t>(s)];
  const double offsets = pr.st.slave_offset[k] + pr.st.seg_offset[static_cast<std::size_t>(s)];
  Located L;
  if (!cp.segment_one_sided.empty() && cp.segment_one_sided[static_cast<std::size_t>(s)]) {
    // A solid's face: the node is outside, on the outward normal's side, whatever its motion.
    L.side = 1;
    project_surface(pr, k, s, packed, guess, nullptr, L);
    return L;
  }
  L.side = pr.st.side[k];
  if (L.side != 0 && was_located) {
    // The side is relative to a segment's normal, and a surface's segments need not be
    // oriented alike (a tool mesh from several patches): on another segment than last cycle's,
    // the side is the one last cycle's contact normal is on.
    if (s != pr.st.seg[k]) {
      double scratch[3];
      const double* ns = current_segment_normal(pr, s, packed, scratch);
      const double* fr = &pr.st.frame[9 * k];
      L.side = fr[0] * ns[0] + fr[1] * ns[1] + fr[2] * ns[2] < 0.0 ? -1 : 1;
    }
    project_surface(pr, k, s, packed, guess, &pr.st.frame[9 * k], L);
    // A free node whose mid-surface is beyond the master's on the other side (its gap on this
    // side below minus twice the offsets) changes side. Between surfaces of no thickness (a
    // solid's face against a tool mesh, which is not offset) twice the offsets is 0: every
    // approaching node that pressed in at all turned to the other side before the law could
    // push it back, and a rigid cylinder went through a rubber block untouched. There a node
    // changes side only once it is deeper than half the search margin.
    // A node that takes another segment is as much behind it only if it is on its other side:
    // the side that last cycle's contact normal gave it (a segment of another part, met while
    // the node lay in the plane of a first one) would read as a penetration of the whole
    // distance between them, and the penalty would fire it through (the crush box deck's
    // coplanar flanges: 14 mm deep in one cycle, 9 kJ in the next).
    const double through = offsets > 0.0 ? 2.0 * offsets : 0.5 * pr.margin;
    if (!((free || s != pr.st.seg[k]) && L.side * L.sp.distance < -through))
      return L;
    L.side = static_cast<signed char>(-L.side);
    project_surface(pr, k, s, packed, guess, nullptr, L);
    return L;
  }
  // No segment last cycle: the side of the mid plane (through the centroid) the node is on.
  double scratch[3];
  const double* ns = current_segment_normal(pr, s, packed, scratch);
  const double* p = at(packed, cp.slave_nodes[k]);
  double dm = 0.0;
  const int nn = q[2] == q[3] ? 3 : 4;
  for (int d = 0; d < 3; ++d) {
    double c = 0.0;
    for (int j = 0; j < nn; ++j)
      c += at(packed, q[j])[d];
    dm += (p[d] - c / nn) * ns[d];
  }
  if (L.side == 0 || free)
    L.side = dm >= 0.0 ? 1 : -1;
  project_surface(pr, k, s, packed, guess, nullptr, L);
  return L;
}

// How squarely a segment faces slave k's own surface: the node's outward normal (its faces'
// mean) against the segment's normal turned to the node's side; -1 face to face, 0 at a right
// angle. A shell node's normal has no outward sense (both faces touch): the alignment counts
// either way. Without faces (a node set), 0.
inline double facing(const PassRuntime& pr, std::size_t k, const Located& L) {
  const double* own = &pr.st.slave_normal[3 * k];
  PLYFORM_INVARIANT(std::isfinite(own[0] + own[1] + own[2]),
                    "a slave node's normal computed this cycle (surface_reads.hpp)");
  const double f =
      L.side * (own[0] * L.sp.normal[0] + own[1] * L.sp.normal[1] + own[2] * L.sp.normal[2]);
  return pr.st.slave_offset[k] > 0.0 ? -std::fabs(f) : f;
}

// A node more than half its element's depth behind a solid's face is on the body's far side,
// not through the face: no candidate (a thin block's far face is within the search's reach).
inline bool behind(const PassRuntime& pr, core::Index s, const Located& L) {
  const core::ContactPass& cp = *pr.pass;
  const auto su = static_cast<std::size_t>(s);
  return !cp.segment_one_sided.empty() && cp.segment_one_sided[su] &&
         L.sp.distance < -0.5 * cp.segment_depth[su];
}

// A segment the node's surface faces (within about 78 degrees of face to face).
constexpr double kFaces = -0.2;

// Whether point p is surely out of segment s's reach, told without the projection (a Newton
// solve): the quad as the parallelogram c + xi a + eta b through its centroid, the point's
// (xi, eta) in it by least squares, and the point's distance along a x b. A point of a convex
// quad has |xi|, |eta| <= 2 in that parallelogram (a corner of a trapezoid's long edge reads
// 2 l / (l + s) < 2), so beyond 2.1 plus MAXPAR's tolerance, or beyond the segment's search
// radius along the normal, it cannot project inside. Triangles are always projected.
inline bool out_of_reach(const PassRuntime& pr, core::Index s, const double* p, double tol,
                         const double* packed) {
  const auto su = static_cast<std::size_t>(s);
  const core::Index* q = &pr.pass->segments[4 * su];
  if (q[2] == q[3])
    return false;
  const double* x0 = at(packed, q[0]);
  const double* x1 = at(packed, q[1]);
  const double* x2 = at(packed, q[2]);
  const double* x3 = at(packed, q[3]);
  double a[3], b[3], d[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = 0.25 * (-x0[i] + x1[i] + x2[i] - x3[i]);
    b[i] = 0.25 * (-x0[i] - x1[i] + x2[i] + x3[i]);
    d[i] = p[i] - 0.25 * (x0[i] + x1[i] + x2[i] + x3[i]);
  }
  const double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
  const double bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
  const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double det = aa * bb - ab * ab;
  if (!(det > 1e-12 * aa * bb))
    return false;
  const double ad = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
  const double bd = b[0] * d[0] + b[1] * d[1] + b[2] * d[2];
  const double xi = (bb * ad - ab * bd) / det, eta = (aa * bd - ab * ad) / det;
  const double reach = 2.1 + tol;
  if (std::fabs(xi) > reach || std::fabs(eta) > reach)
    return true;
  const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                       a[0] * b[1] - a[1] * b[0]};
  const double along = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
  const double r = pr.st.seg_radius[su];
  return along * along > 1.1 * r * r * det;  // |n|^2 = det
}

// Within this share of a segment's edge (the smallest shape function of the projection) a
// pressed node looks for a deeper neighbour across a concave junction (deeper_across_valley).
constexpr double kEdgeBand = 0.05;

// Whether segment s rises towards the slave's side of the plane of L (a valley between them,
// seen from the slave): its centroid lies on that side.
inline bool rises_towards(const PassRuntime& pr, core::Index s, const Located& L) {
  const double* c = &pr.fold_centroid[3 * static_cast<std::size_t>(s)];  // this cycle's
  PLYFORM_INVARIANT(std::isfinite(c[0] + c[1] + c[2]),
                    "a segment's centroid computed this cycle (surface_reads.hpp)");
  const double* n = L.sp.normal;
  const double above =
      (c[0] - L.sp.x[0]) * n[0] + (c[1] - L.sp.x[1]) * n[1] + (c[2] - L.sp.x[2]) * n[2];
  return L.side * above > 1e-9 * pr.margin;
}

// A node near the edge of its segment `cur` (within about half a segment of it), where the
// master surface folds towards it (a valley: the inside of a bend, a die's corner), may be
// nearer to, or deeper in, the neighbouring segment than `cur`. It takes the one of smallest
// gap: its gap is then the smaller of the two, which is continuous where they are equal,
// instead of jumping when its projection leaves `cur`
// (a spring whose length jumps while it holds energy gives the model energy; the square cup's
// upper skin at the punch corner gave 1.6 J that way, hunting between two core segments).
// Across a ridge the nearer segment stays (a node must leave the way its surface faces).
inline core::Index deeper_across_valley(const PassRuntime& pr, std::size_t k, core::Index cur,
                                        bool free, bool was_located, const double* packed,
                                        double tol, Located& best) {
  const auto cu = static_cast<std::size_t>(cur);
  PLYFORM_INVARIANT(pr.folded[cu] != kUnlistedFold,
                    "a segment's fold tested this cycle (surface_reads.hpp)");
  if (!pr.folded[cu])
    return cur;
  const core::Index* qc = &pr.pass->segments[4 * cu];
  const int corners = qc[2] == qc[3] ? 3 : 4;
  double smallest = 1.0;
  for (int j = 0; j < corners; ++j)
    smallest = std::min(smallest, best.sp.shape[j]);
  const double g = best.side * best.sp.distance;
  if (!(g < pr.margin) || smallest > kEdgeBand)
    return cur;
  const double* p = at(packed, pr.pass->slave_nodes[k]);
  const double tie = 1e-6 * pr.margin;
  core::Index found = cur;
  double deepest = g;
  const Located on_cur = best;
  for (std::size_t j = pr.nb_start[cu]; j < pr.nb_start[cu + 1]; ++j) {
    const core::Index s = pr.nb[j];
    if (!rises_towards(pr, s, on_cur) || out_of_reach(pr, s, p, tol, packed))
      continue;
    const Located L = project_on(pr, k, s, free, was_located, packed, nullptr);
    if (L.sp.degenerate || L.sp.outside > tol ||
        std::fabs(L.sp.distance) > pr.st.seg_radius[static_cast<std::size_t>(s)] ||
        behind(pr, s, L) || !(facing(pr, k, L) <= kFaces || pr.slave_face_normals_absent))
      continue;
    const double gs = L.side * L.sp.distance;
    if (gs < deepest - tie) {
      deepest = gs;
      best = L;
      found = s;
    }
  }
  return found;
}

// Within this share of the offsets' band, a node's gap on the neighbour across an edge counts
// as its gap on its own segment's extension (across_edge).
constexpr double kAgreeBand = 1e-3;

// A node whose projection has left its segment `cur` past an edge, where a neighbour of `cur`
// holds it (or holds it less far outside), takes that neighbour once its gap there and on
// `cur`'s extension part by more than kAgreeBand of the offsets (or of half a segment without
// offsets). Over a ridge the offset surfaces of the two meet at the edge, so the gaps agree
// there and part as the node rides on: kept on `cur` to MAXPAR's tolerance, its gap would jump
// by the tolerance's overshoot times the sine of the kink when it finally changed (a bonded
// node at a 35 degree kink of 1.5 mm segments: 11 um, past the cohesive law's peak opening).
// Where the two faces are nearly flat (a bending layer's matching mesh, its nodes on the
// master's corners) the gaps agree all the way, and the tolerance keeps the node from hunting
// between the segments around a corner, which rang a stiff bonded ligament (the DCB). MAXPAR's
// tolerance also stays for edges without a neighbour (a layer's free edge), and for free nodes
// (approaching, detached): no traction acts across their gap, so its jump costs nothing (and
// the hot draw's kinematics 1-4 % dearer instead of 5-16 %).
// The corners of segment `cur` that projection L has passed: of a quad, those of the edge it
// crossed, or the one corner it passed diagonally (xi = N1 + N2 - N0 - N3, eta = N2 + N3 - N0 -
// N1); only a neighbour holding them all lies across. A triangle's: all (any neighbour).
inline void passed_corners(const PassRuntime& pr, core::Index cur, const Located& L,
                           bool passed[4]) {
  const core::Index* q = &pr.pass->segments[4 * static_cast<std::size_t>(cur)];
  for (int c = 0; c < 4; ++c)
    passed[c] = true;
  if (q[2] == q[3])
    return;
  const double* sh = L.sp.shape;
  const double xi = sh[1] + sh[2] - sh[0] - sh[3], eta = sh[2] + sh[3] - sh[0] - sh[1];
  const bool xp = xi > 1.0, ep = eta > 1.0;
  const bool xm = xi < -1.0, em = eta < -1.0;
  constexpr int cx[4] = {-1, 1, 1, -1}, cy[4] = {-1, -1, 1, 1};
  for (int c = 0; c < 4; ++c)
    passed[c] =
        (!xp || cx[c] > 0) && (!xm || cx[c] < 0) && (!ep || cy[c] > 0) && (!em || cy[c] < 0);
}

// Whether neighbour s of segment `cur` holds every corner in `passed`.
inline bool holds_passed(const PassRuntime& pr, core::Index cur, core::Index s,
                         const bool passed[4]) {
  const core::Index* q = &pr.pass->segments[4 * static_cast<std::size_t>(cur)];
  const core::Index* qs = &pr.pass->segments[4 * static_cast<std::size_t>(s)];
  bool holds = true;
  for (int c = 0; c < 4 && holds; ++c)
    holds = !passed[c] || qs[0] == q[c] || qs[1] == q[c] || qs[2] == q[c] || qs[3] == q[c];
  return holds;
}

inline core::Index across_edge(const PassRuntime& pr, std::size_t k, core::Index cur, bool free,
                               bool was_located, const double* packed, double tol, Located& best) {
  const auto cu = static_cast<std::size_t>(cur);
  const double* p = at(packed, pr.pass->slave_nodes[k]);
  const double tie = 1e-9;
  // Only a neighbour holding the passed corners lies across (a node riding a flat junction
  // inside MAXPAR's tolerance tries these each cycle, not all eight neighbours).
  bool passed[4];
  passed_corners(pr, cur, best, passed);
  core::Index found = cur;
  Located across;
  for (std::size_t j = pr.nb_start[cu]; j < pr.nb_start[cu + 1]; ++j) {
    const core::Index s = pr.nb[j];
    if (!holds_passed(pr, cur, s, passed) || out_of_reach(pr, s, p, tol, packed))
      continue;
    const Located L = project_on(pr, k, s, free, was_located, packed, nullptr);
    const double least = found == cur ? best.sp.outside : across.sp.outside;
    if (L.sp.degenerate || !(L.sp.outside < least - tie) ||
        std::fabs(L.sp.distance) > pr.st.seg_radius[static_cast<std::size_t>(s)] ||
        behind(pr, s, L) || !(facing(pr, k, L) <= kFaces || pr.slave_face_normals_absent))
      continue;
    across = L;
    found = s;
  }
  if (found == cur)
    return cur;
  const double band = pr.st.slave_offset[k] + pr.st.seg_offset[cu];
  const double agree = kAgreeBand * (band > 0.0 ? band : pr.margin);
  if (!(std::fabs(across.side * across.sp.distance - best.side * best.sp.distance) > agree))
    return cur;
  best = across;
  return found;
}

// How far outside (parametric) a pressed or bonded node may be of its segment in the gap of a
// valley (in_valley_gap).
constexpr double kValleyGap = 0.25;

// A pressed or bonded node that has sunk into the master at a valley (a concave junction seen
// from the slave: the inside of a bend) lies in the gap between the two faces' offset
// surfaces, outside both by about the depth times the tangent of half the kink: on a coarse
// core at the punch's corner (5.6 mm segments, about 35 degrees) a node 0.18 mm deep was
// outside its segment by 0.028, past MAXPAR's tolerance, and outside its neighbour too. It
// lost its segment, found one again 0.75 mm deep the next cycle, was let in as an arrival and
// went through the core. There the nearest point of the master's surface is the crease (the
// passed edge of the offset surface, or the passed corner): the node presses against it, its
// gap minus the distance to it, its normal towards it (continuous with each face's at the
// boundary of its gap). Either face's extension instead understates the depth and pushes
// sideways (the node kept on its segment: the contact gave the model 41 J). Returns -1 where
// the node is not inside the master by `cur` and by a neighbour holding the passed edge while
// outside both (a layer's free edge, a convex edge: the node leaves, as before). `Lc`: the
// node's projection on `cur`.
inline core::Index in_valley_gap(const PassRuntime& pr, std::size_t k, core::Index cur,
                                 const Located& Lc, bool was_located, const double* packed,
                                 Located& best) {
  const auto cu = static_cast<std::size_t>(cur);
  const core::Index* q = &pr.pass->segments[4 * cu];
  if (q[2] == q[3])
    return -1;
  if (Lc.sp.degenerate || !(Lc.sp.outside > 0.0) || Lc.sp.outside > kValleyGap ||
      std::fabs(Lc.sp.distance) > pr.st.seg_radius[cu] || behind(pr, cur, Lc) ||
      !(Lc.side * Lc.sp.distance < 0.0))
    return -1;
  // A valley's gap: inside the master by a neighbour holding the passed corners too, and
  // outside it (beyond a convex edge, a block's top face over its side, the node is in front of
  // the side face: it has left the master, as before).
  bool passed[4];
  passed_corners(pr, cur, Lc, passed);
  bool valley = false;
  for (std::size_t j = pr.nb_start[cu]; j < pr.nb_start[cu + 1] && !valley; ++j) {
    const core::Index s = pr.nb[j];
    if (!holds_passed(pr, cur, s, passed))
      continue;
    // It rises towards the slave's side of cur's plane (a kink of a degree at least: a flat
    // junction, or a master's free edge passed at a corner, is no valley).
    const core::Index* qs = &pr.pass->segments[4 * static_cast<std::size_t>(s)];
    const int ns = qs[2] == qs[3] ? 3 : 4;
    double rise = 0.0, reach2 = 0.0;
    for (int d = 0; d < 3; ++d) {
      double c = 0.0;
      for (int i = 0; i < ns; ++i)
        c += at(packed, qs[i])[d];
      const double v = c / ns - Lc.sp.x[d];
      rise += v * Lc.sp.normal[d];
      reach2 += v * v;
    }
    if (!(Lc.side * rise > 0.02 * std::sqrt(reach2)))
      continue;
    const Located L = project_on(pr, k, s, false, was_located, packed, nullptr);
    valley = !L.sp.degenerate && L.side * L.sp.distance < 0.0 && L.sp.outside > 0.0 &&
             L.sp.outside <= kValleyGap;
  }
  if (!valley)
    return -1;
  // The crease on the offset surface: the passed corners moved by their offsets.
  int c0 = -1, c1 = -1;
  for (int c = 0; c < 4; ++c) {
    if (!passed[c])
      continue;
    (c0 < 0 ? c0 : c1) = c;
  }
  if (c1 < 0)
    c1 = c0;
  double e0[3], e1[3];
  for (int i = 0; i < 2; ++i) {
    const int c = i == 0 ? c0 : c1;
    double r[3] = {0.0, 0.0, 0.0};
    if (pr.master_offsets)
      corner_offset(pr, cu, c, Lc.side, r);
    const double* xc = at(packed, q[c]);
    double* e = i == 0 ? e0 : e1;
    for (int d = 0; d < 3; ++d)
      e[d] = xc[d] + r[d];
  }
  const double* node = at(packed, pr.pass->slave_nodes[k]);
  double ps[3], de[3], to[3];
  for (int d = 0; d < 3; ++d) {
    ps[d] = node[d] + Lc.rs[d];
    de[d] = e1[d] - e0[d];
  }
  const double len2 = de[0] * de[0] + de[1] * de[1] + de[2] * de[2];
  double t = 0.0;
  if (len2 > 0.0)
    t = std::clamp(
        ((ps[0] - e0[0]) * de[0] + (ps[1] - e0[1]) * de[1] + (ps[2] - e0[2]) * de[2]) / len2, 0.0,
        1.0);
  for (int d = 0; d < 3; ++d)
    to[d] = e0[d] + t * de[d] - ps[d];
  const double dist = std::sqrt(to[0] * to[0] + to[1] * to[1] + to[2] * to[2]);
  // The crease must lie out of the master from the node, along the face's outward normal.
  const double out =
      Lc.side * (to[0] * Lc.sp.normal[0] + to[1] * Lc.sp.normal[1] + to[2] * Lc.sp.normal[2]);
  if (!(dist > 0.0) || !(out > 0.0))
    return -1;
  best = Lc;
  for (int c = 0; c < 4; ++c)
    best.sp.shape[c] = 0.0;
  best.sp.shape[c0] += 1.0 - t;
  best.sp.shape[c1] += t;
  for (int d = 0; d < 3; ++d) {
    best.sp.x[d] = ps[d] + to[d];
    best.sp.normal[d] = Lc.side * to[d] / dist;
  }
  best.sp.distance = -Lc.side * dist;
  return cur;
}

// The segment of slave k: its current one while the projection stays within MAXPAR - 1 of it
// (parametric measure) and the node's surface faces it, else the nearest candidate within that
// tolerance, the candidates the node's surface faces first. A node on an edge of the master (a
// slice's bottom corner on the edge between the top and the side faces of the slice below) is
// as near to the side face whose plane it lies in as to the top face it presses into, nearer
// once it has pressed in; it must take the top face, which its own surface faces (as LS-DYNA
// does), or it falls through. Returns -1 when no candidate is within reach.
inline core::Index locate(const PassRuntime& pr, std::size_t k, bool free, bool was_located,
                          const double* packed, Located& best) {
  const core::Index cur = pr.st.seg[k];
  const double tol = pr.iface->maxpar - 1.0;
  if (cur >= 0) {
    // prev_shape holds last cycle's projection on `cur` (apply() swaps the arrays).
    const Located L = project_on(pr, k, cur, free, was_located, packed, &pr.st.prev_shape[4 * k]);
    if (!L.sp.degenerate && L.sp.outside <= tol &&
        std::fabs(L.sp.distance) <= pr.st.seg_radius[static_cast<std::size_t>(cur)] &&
        !behind(pr, cur, L) && (facing(pr, k, L) <= kFaces || pr.slave_face_normals_absent)) {
      best = L;
      // In a valley's gap from the moment the projection leaves `cur` (so that the gap is
      // continuous where the node's foot reaches the crease).
      if (!free && L.sp.outside > 0.0 &&
          in_valley_gap(pr, k, cur, L, was_located, packed, best) >= 0)
        return cur;
      const core::Index s = deeper_across_valley(pr, k, cur, free, was_located, packed, tol, best);
      if (s != cur || free || !(best.sp.outside > 0.0))
        return s;
      return across_edge(pr, k, cur, free, was_located, packed, tol, best);
    }
  }
  // A node that has touched the master takes a new segment only within half the tolerance by
  // which it keeps one (a node that never touched it, within all of it, as LS-DYNA's MAXPAR):
  // at a master's edge (a solid's corner, a layer's free edge) a node that just left its
  // segment there would otherwise take it back the next cycle, hunting between it and the side
  // face (or nothing) beyond: free, it sinks under its load; back on the segment, it is pushed
  // out of a depth it sank to with no force on it, and the spring gives the model that energy.
  const bool touched = static_cast<law::NodeState>(pr.hist.state[k]) != law::NodeState::approaching;
  const double acquire = touched ? 0.5 * tol : tol;
  double best_score = kInf, best_facing = kInf;
  bool best_faces = false;
  core::Index found = -1;
  const double tie = 1e-6 * pr.margin;
  const double* p = at(packed, pr.pass->slave_nodes[k]);
  for (std::size_t c = pr.st.cand_start[k]; c < pr.st.cand_start[k + 1]; ++c) {
    const core::Index s = pr.st.cand[c];
    // A candidate out of reach is passed over before the projection (a Newton solve): a
    // point that projects inside the segment (to MAXPAR) lies within its corners' distance
    // from its centroid, scaled by MAXPAR, in the plane, and within its radius along the
    // normal. Nodes with no segment (a layer's nodes beyond the other layer's edge) try their
    // candidates every cycle, and most are out of reach.
    if (out_of_reach(pr, s, p, tol, packed))
      continue;
    const Located L = project_on(pr, k, s, free, was_located, packed, nullptr);
    if (L.sp.degenerate || L.sp.outside > acquire ||
        std::fabs(L.sp.distance) > pr.st.seg_radius[static_cast<std::size_t>(s)] ||
        behind(pr, s, L))
      continue;
    // About the true distance to the segment: the normal distance and, outside the segment,
    // the parametric overshoot times half the segment size.
    // (sqrt, not hypot: neither term comes near overflow, and it runs per candidate.)
    const double over = L.sp.outside * pr.margin;
    const double score = std::sqrt(L.sp.distance * L.sp.distance + over * over);
    const double f = facing(pr, k, L);
    const bool faces = f <= kFaces;
    const bool better = faces != best_faces        ? faces
                        : score < best_score - tie ? true
                                                   : score <= best_score + tie && f < best_facing;
    if (found < 0 || better) {
      best_score = score;
      best_facing = f;
      best_faces = faces;
      best = L;
      found = s;
    }
  }
  if (found < 0 && cur >= 0 && !free) {
    const Located Lc = project_on(pr, k, cur, false, was_located, packed, &pr.st.prev_shape[4 * k]);
    return in_valley_gap(pr, k, cur, Lc, was_located, packed, best);
  }
  return found;
}

}  // namespace plyform::contact
