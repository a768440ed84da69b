#include "surface_normals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "plyform/core/invariant.hpp"
#include "surface_geometry.hpp"

namespace plyform::contact {

namespace {

// Mean of the normals of `count` faces (4 node indices each, listed by `index`), each turned to
// agree with the first, normalised; zero when there are none. The normals are summed in a fixed
// (sorted) order, so the result does not depend on how a side lists its faces.
template <class FaceOf>
void mean_normal(std::size_t count, FaceOf&& face, const double* packed, double out[3]) {
  out[0] = out[1] = out[2] = 0.0;
  std::vector<std::array<double, 3>> normals(count);
  for (std::size_t f = 0; f < count; ++f)
    segment_normal(face(f), packed, normals[f].data());
  std::sort(normals.begin(), normals.end());
  for (const auto& n : normals) {
    const double* first = normals.front().data();
    const double sg = n[0] * first[0] + n[1] * first[1] + n[2] * first[2] < 0.0 ? -1.0 : 1.0;
    out[0] += sg * n[0], out[1] += sg * n[1], out[2] += sg * n[2];
  }
  const double len = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
  if (len > 0.0)
    out[0] /= len, out[1] /= len, out[2] /= len;
}

// Each face's and node's normal, each segment's centroid and fold, the same numbers whichever
// loop asks for them, over a whole surface or over a list of its parts (surface_reads.hpp),
// which differs from rank to rank: this file is compiled without fused multiply-adds
// (-ffp-contract=off, src/contact/CMakeLists.txt), so that a vectorised loop body, its scalar
// remainder and a loop over a list round every item alike (each operation is IEEE's, and
// nothing here sums across items).
// In the builds that check invariants (core/invariant.hpp), what a list leaves out is made
// unreadable before the listed parts are computed: a kinematics that read it would trip the
// invariants of its readers (projection.hpp, surface_geometry.hpp) in every test of the suite.
void poison_unlisted(std::vector<double>& v) {
  if constexpr (core::kCheckInvariants)
    std::fill(v.begin(), v.end(), std::numeric_limits<double>::quiet_NaN());
}

inline void face_normal(const core::Index* q, const double* packed, double* out) {
  segment_normal(q, packed, out);
}

inline void node_normal(std::size_t i, const std::size_t* start, const core::Index* index,
                        const signed char* sign, const double* face_normal, double* out) {
  double n0 = 0.0, n1 = 0.0, n2 = 0.0;
  for (std::size_t e = start[i]; e < start[i + 1]; ++e) {
    const double* nf = &face_normal[3 * static_cast<std::size_t>(index[e])];
    const double sg = sign[e];
    n0 += sg * nf[0], n1 += sg * nf[1], n2 += sg * nf[2];
  }
  const double len = std::sqrt(n0 * n0 + n1 * n1 + n2 * n2);
  const double inv = len > 0.0 ? 1.0 / len : 0.0;
  out[0] = n0 * inv, out[1] = n1 * inv, out[2] = n2 * inv;
}

inline void centroid(const core::Index* q, const double* packed, double* c) {
  const double *x0 = at(packed, q[0]), *x1 = at(packed, q[1]), *x2 = at(packed, q[2]),
               *x3 = at(packed, q[3]);
  for (int i = 0; i < 3; ++i)
    c[i] = 0.25 * (x0[i] + x1[i] + x2[i] + x3[i]);
}

}  // namespace

// Which segments have a neighbour out of their plane this cycle (its centroid off the plane by
// more than sin 0.5 degree of the distance between the centroids): only a node on such a
// segment looks across to its neighbours (deeper_across_valley), so flat and gently bent
// surfaces (a DCB's arms) pay one load per node. Below that fold a gap's jump at a segment
// change is under a hundredth of the overshoot MAXPAR allows.
constexpr double kFoldSin2 = 7.6e-5;  // sin^2(0.5 degree)

namespace {

// Whether a neighbour of segment sg lies out of its plane (centroids c, normals n).
inline unsigned char folds_at(const PassRuntime& pr, std::size_t sg, const double* c,
                              const double* n) {
  unsigned char f = 0;
  const double* cs = &c[3 * sg];
  const double* ns = &n[3 * sg];
  for (std::size_t j = pr.nb_start[sg]; j < pr.nb_start[sg + 1] && !f; ++j) {
    const double* co = &c[3 * static_cast<std::size_t>(pr.nb[j])];
    const double d[3] = {co[0] - cs[0], co[1] - cs[1], co[2] - cs[2]};
    const double off = d[0] * ns[0] + d[1] * ns[1] + d[2] * ns[2];
    f = off * off > kFoldSin2 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
  return f;
}

}  // namespace

void update_folds(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  const std::size_t nseg = pr.folded.size();
  std::vector<double>& c = pr.fold_centroid;
  // The segments' normals: this cycle's from update_master_normals() where the pass keeps them
  // (the same numbers), else computed here.
  const bool reuse = pr.st.seg_normal_current;
  double* n = reuse ? pr.st.seg_normal.data() : pr.fold_normal.data();
  // A rigid master's folds are those of its first cycle: a rigid motion turns a segment's
  // normal and the offsets of its neighbours' centroids together. Its centroids (which
  // rises_towards reads) move with it.
  const bool fixed = pr.folds_fixed;
  // Only the parts this cycle's kinematics read (surface_reads.hpp), but a rigid master's
  // folds, found once for the run, whole.
  const PassRuntime::SurfaceReads& r = pr.reads;
  const bool whole = r.all_master || (!fixed && pr.rigid_master);
  const std::size_t nc = whole ? nseg : r.centroids.size();
  if (!whole) {
    poison_unlisted(c);
    if (core::kCheckInvariants && !fixed)  // a rigid master's folds stay, found once
      std::fill(pr.folded.begin(), pr.folded.end(), kUnlistedFold);
  }
#pragma omp parallel for schedule(static) if (nc > kLightLoop)
  for (long ls = 0; ls < static_cast<long>(nc); ++ls) {
    const auto sg = whole ? static_cast<std::size_t>(ls)
                          : static_cast<std::size_t>(r.centroids[static_cast<std::size_t>(ls)]);
    const core::Index* q = &cp.segments[4 * sg];
    centroid(q, packed, &c[3 * sg]);
    if (!reuse && !fixed)
      face_normal(q, packed, &n[3 * sg]);
  }
  if (fixed)
    return;
  pr.folds_fixed = pr.rigid_master;
  const std::size_t nf = whole ? nseg : r.folds.size();
#pragma omp parallel for schedule(static) if (nf > kLightLoop)
  for (long ls = 0; ls < static_cast<long>(nf); ++ls) {
    const auto sg = whole ? static_cast<std::size_t>(ls)
                          : static_cast<std::size_t>(r.folds[static_cast<std::size_t>(ls)]);
    pr.folded[sg] = folds_at(pr, sg, c.data(), n);
  }
}

namespace {

// The normals of `faces` faces (4 node indices each) at the current positions, then each
// node's: the mean of the normals of the faces around it (CSR `start`, `index`), each turned
// by its sign fixed at t = 0 (init_nodal_normals). With `face_list` and `node_list` (not null)
// only the faces and nodes they name, `faces` and `nodes` of them.
void normals_of_faces_and_nodes(std::size_t faces, const core::Index* corners, std::size_t nodes,
                                const std::size_t* start, const core::Index* index,
                                const signed char* sign, const double* packed, double* face_normals,
                                double* node_normals, const core::Index* face_list = nullptr,
                                const core::Index* node_list = nullptr) {
#pragma omp parallel for schedule(static) if (faces > kLightLoop)
  for (long lf = 0; lf < static_cast<long>(faces); ++lf) {
    const auto f = face_list != nullptr ? static_cast<std::size_t>(face_list[lf])
                                        : static_cast<std::size_t>(lf);
    face_normal(&corners[4 * f], packed, &face_normals[3 * f]);
  }
#pragma omp parallel for schedule(static) if (nodes > kLightLoop)
  for (long li = 0; li < static_cast<long>(nodes); ++li) {
    const auto i = node_list != nullptr ? static_cast<std::size_t>(node_list[li])
                                        : static_cast<std::size_t>(li);
    node_normal(i, start, index, sign, face_normals, &node_normals[3 * i]);
  }
}

}  // namespace

// The master's segment and nodal normals at the current positions.
void update_master_normals(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  const PassRuntime::SurfaceReads& r = pr.reads;
  const bool whole = r.all_master;
  if (!whole) {
    poison_unlisted(pr.st.seg_normal);
    poison_unlisted(pr.st.master_normal);
  }
  normals_of_faces_and_nodes(whole ? cp.segment_count() : r.segs.size(), cp.segments.data(),
                             whole ? pr.master_nodes.size() : r.nodes.size(),
                             pr.node_seg_start.data(), pr.node_seg.data(), pr.node_seg_sign.data(),
                             packed, pr.st.seg_normal.data(), pr.st.master_normal.data(),
                             whole ? nullptr : r.segs.data(), whole ? nullptr : r.nodes.data());
}

// The slave nodes' normals at the current positions, from their faces.
void update_slave_normals(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  const PassRuntime::SurfaceReads& r = pr.reads;
  const bool whole = r.all_slaves;
  if (!whole) {
    poison_unlisted(pr.st.slave_face_normal);
    poison_unlisted(pr.st.slave_normal);
  }
  normals_of_faces_and_nodes(whole ? cp.slave_faces.size() / 4 : r.faces.size(),
                             cp.slave_faces.data(), whole ? cp.slave_count() : r.slaves.size(),
                             cp.slave_face_start.data(), cp.slave_face_index.data(),
                             pr.slave_face_sign.data(), packed, pr.st.slave_face_normal.data(),
                             pr.st.slave_normal.data(), whole ? nullptr : r.faces.data(),
                             whole ? nullptr : r.slaves.data());
}

// The master's nodal normals at t = 0 (the mean normal of the faces around each node) and the
// signs that turn each segment's normal to agree with them, kept for the run.
void init_nodal_normals(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  for (std::size_t i = 0; i < pr.master_nodes.size(); ++i) {
    const std::size_t b = pr.node_seg_start[i];
    mean_normal(
        pr.node_seg_start[i + 1] - b,
        [&](std::size_t f) {
          return &cp.segments[4 * static_cast<std::size_t>(pr.node_seg[b + f])];
        },
        packed, &pr.st.master_normal[3 * i]);
  }
  // Each corner's nodal normal against its segment's normal: the sign that turns it to the side
  // of the segment a slave node is on. Fixed: nodal normals and segments turn together.
  for (std::size_t c = 0; c < pr.corner_sign.size(); ++c) {
    double ns[3];
    segment_normal(&cp.segments[c - c % 4], packed, ns);
    const double* d = &pr.st.master_normal[3 * static_cast<std::size_t>(pr.corner[c])];
    pr.corner_sign[c] = d[0] * ns[0] + d[1] * ns[1] + d[2] * ns[2] < 0.0 ? -1 : 1;
  }
  for (std::size_t i = 0; i < pr.master_nodes.size(); ++i) {
    const double* d = &pr.st.master_normal[3 * i];
    for (std::size_t e = pr.node_seg_start[i]; e < pr.node_seg_start[i + 1]; ++e) {
      double ns[3];
      segment_normal(&cp.segments[4 * static_cast<std::size_t>(pr.node_seg[e])], packed, ns);
      pr.node_seg_sign[e] = d[0] * ns[0] + d[1] * ns[1] + d[2] * ns[2] < 0.0 ? -1 : 1;
    }
  }
  if (cp.slave_face_start.empty())
    return;
  for (std::size_t k = 0; k < cp.slave_count(); ++k) {
    const std::size_t b = cp.slave_face_start[k];
    mean_normal(
        cp.slave_face_start[k + 1] - b,
        [&](std::size_t f) {
          return &cp.slave_faces[4 * static_cast<std::size_t>(cp.slave_face_index[b + f])];
        },
        packed, &pr.st.slave_normal[3 * k]);
    const double* d = &pr.st.slave_normal[3 * k];
    for (std::size_t e = b; e < cp.slave_face_start[k + 1]; ++e) {
      double nf[3];
      segment_normal(&cp.slave_faces[4 * static_cast<std::size_t>(cp.slave_face_index[e])], packed,
                     nf);
      pr.slave_face_sign[e] = d[0] * nf[0] + d[1] * nf[1] + d[2] * nf[2] < 0.0 ? -1 : 1;
    }
  }
}

}  // namespace plyform::contact
