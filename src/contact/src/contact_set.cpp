#include "plyform/contact/contact_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "plyform/contact/bucket_search.hpp"
#include "plyform/contact/segment_projection.hpp"
#include "plyform/contact/tiebreak.hpp"
#include "plyform/core/invariant.hpp"
#include "plyform/core/stopwatch.hpp"
#include "plyform/law/law.hpp"

namespace plyform::contact {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kStride = 6;  // packed node data: x y z vx vy vz

// Below these counts a loop runs on the calling thread alone: a parallel region's start and
// join cost a few microseconds on a busy machine, more than a small loop's work. Light: a
// loop of a few arithmetic operations per item (normals, folds, motion since the search);
// heavy: a slave node's projection and kinematics, or its forces. Each item's arithmetic is
// the same either way (the same bits for any thread count).
constexpr std::size_t kLightLoop = 1024;
constexpr std::size_t kHeavyLoop = 256;

// Sums of per-slave values in fixed chunks, then the chunks in order: the same bits for any
// number of threads.
// `part`: a buffer kept by the caller (no allocation per cycle once it has grown).
template <class F>
double chunked_sum(std::size_t n, std::vector<double>& part, F&& f) {
  constexpr std::size_t kChunk = 1024;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  part.resize(chunks);
  // One chunk: the team has nothing to share (its start-up alone costs some microseconds).
#pragma omp parallel for schedule(static) if (chunks > 1)
  for (long lc = 0; lc < static_cast<long>(chunks); ++lc) {
    const auto c = static_cast<std::size_t>(lc);
    double s = 0.0;
    for (std::size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i)
      s += f(i);
    part[c] = s;
  }
  double total = 0.0;
  for (double v : part)
    total += v;
  return total;
}

// The largest sigma_max of a law over its temperature range (the cohesive capture distance).
// The law of a cohesive interface's guard pass: the same normal damping, pressure only.
law::Parameters guard_law(const law::Parameters& bonded) {
  law::Parameters p = bonded;
  p.beta0 = 0.0;  // no adhesion, ever: beta stays 0
  p.bond_tol = 0.0;
  p.zeta = {0.0, 0.0, -1};
  p.mu = {0.0, 0.0, -1};
  p.friction = law::FrictionModel::coulomb;
  p.ct = 0.0;
  p.decay_dc = 0.0;
  p.friction_limit = 0.0;
  p.release_gap = std::numeric_limits<double>::infinity();
  p.vdc = 0.0;
  return p;
}

double largest_sigma_max(const law::Parameters& p) {
  if (p.sigma_max.curve >= 0) {
    const law::Curve& c = p.curves[static_cast<std::size_t>(p.sigma_max.curve)];
    double m = 0.0;
    for (double y : c.y())
      m = std::max(m, y);
    return m;
  }
  return std::max(p.sigma_max.lo, p.sigma_max.hi);
}

}  // namespace

/// The runtime state of one pass: its law, the search, and the per-slave arrays.
struct PassRuntime {
  const core::ContactInterface* iface = nullptr;
  const core::ContactPass* pass = nullptr;
  // Wall seconds in apply(): search, projection, law, forces (InterfaceTiming).
  double seconds[4] = {0.0, 0.0, 0.0, 0.0};
  law::Law law;
  law::HistoryStore history;
  law::BatchHistory hist;
  BucketSearch grid;
  std::vector<std::size_t> cand_start;
  std::vector<core::Index> cand;
  std::vector<double> seg_radius;
  /// Segments sharing a corner with each segment (CSR), and whether any of them rises towards
  /// a side of it this cycle (a fold: deeper_across_valley looks across it).
  std::vector<std::size_t> nb_start;
  std::vector<core::Index> nb;
  std::vector<unsigned char> folded;
  std::vector<double> fold_centroid, fold_normal;  // update_folds' scratch, 3 per segment
  std::vector<core::Index> tracked_nodes;  // slave and master nodes, for motion since search
  std::vector<double> tracked_ref;         // their positions at the last search
  double margin = 0.0;
  double capture = 0.0;  // the cohesive band
  bool bonds = false;    // the pass carries the cohesive law (not a plain contact, not a guard)
  bool guard = false;    // core::ContactPass::guard
  // Contact half-thicknesses now (they follow the shells' thickness when the pass says so).
  std::vector<double> slave_offset, seg_offset;
  double far_gap = 0.0;  // the gap given to the law for a node with no segment in reach
  long cycles_since_search = 0;
  bool searched = false;
  double dt_vote = kInf;
  // Per slave node.
  std::vector<core::Index> seg, prev_seg;
  std::vector<double> shape, prev_shape;  // 4 each
  std::vector<double> frame;              // 9 each: normal (slave side), e1, e2
  std::vector<signed char> side;
  std::vector<double> gap, slip_x, slip_y, temperature, k_normal, k_tangent, m_eff;
  // Penetration tolerated (<= 0): the depth at which a node arrived inside the band of the
  // offsets from beyond the master's edge, shrinking as it comes out (measure()).
  std::vector<double> arrival_depth;
  bool measured = false;  // a first cycle has been measured (initial penetrations push out)
  std::vector<double> pressure, tau_x, tau_y, stored;
  std::vector<double> force, prev_force;  // 3 each
  std::vector<double> work_part;
  // The normal gap change of the step that no motion of the nodes made (the layers' thickness
  // followed by the offsets, a node passing to a segment of another offset or height, an
  // arrival depth let go, the surface's curvature), per slave node, and the tractions' work on
  // it: the interface's `surface` book (measure() and the force loop, as work_part).
  std::vector<double> gap_jump, surface_part;
  double surface = 0.0;
  // Each node's force power at the end of the last step (-f . du/dt, f of t_n on that step's
  // rate) and that step's length: measure() books the step change's share of the work with them
  // (the central differences move the nodes with f of t_n over dt_avg, not the steps' halves).
  std::vector<double> end_power;
  double dt_last = 0.0;
  std::vector<double> chunk_sums;  // buffer of chunked_sum
  double work = 0.0;
  std::array<double, 3> resultant{}, master_resultant{};
  double dt0 = 0.0;
  // Offset surfaces of shell layers: the master surface is the mid-surface moved by its offset
  // along the nodal normals (continuous from segment to segment), a slave node's surface point
  // its position moved by its offset along its own nodal normal. Nodal normals are the mean of
  // the faces around the node, each turned to agree with the node's first face.
  bool master_offsets = false;              // some segment has a non-zero offset
  std::vector<core::Index> master_nodes;    // the distinct segment nodes
  std::vector<core::Index> corner;          // per segment corner: index into master_nodes
  std::vector<std::size_t> node_seg_start;  // CSR master node -> segments around it
  std::vector<core::Index> node_seg;
  // The master's nodal normals, recomputed every cycle from the current positions (the mean
  // of the normals of the segments around each node, each turned by its fixed sign to agree
  // with the node's normal at t = 0). They are geometry, not the shells' nodal rotations: a
  // rotation of a one-point shell's node is held against its element's mid-surface only by the
  // weak rotational hourglass control, and a surface that followed it would let a contact
  // pressure tip it further (the pressure at the offset point makes a couple that grows with
  // the tilt), which an explicit run cannot survive under forming pressures.
  std::vector<double> master_normal;       // 3 per master node
  std::vector<double> seg_normal;          // 3 per segment, current
  bool seg_normal_current = false;         // seg_normal updated for this cycle's positions
  std::vector<signed char> corner_sign;    // per segment corner: its nodal normal against it
  std::vector<signed char> node_seg_sign;  // per node_seg entry: the same sign
  // The slave nodes' normals, the same way from the faces around them (none for a node set's
  // node without faces: its offset then follows the contact normal).
  std::vector<double> slave_normal;          // 3 per slave node
  std::vector<double> slave_face_normal;     // 3 per slave face, current
  std::vector<signed char> slave_face_sign;  // per slave_face_index entry
  std::vector<double> rs, prev_rs;           // 3 per slave: its surface point minus the node
  bool slave_face_normals_absent = false;    // a node set's slave side: no faces, no normals
  std::vector<double> friction_heated;       // per slave: friction dissipation turned to heat
  // The _TIEBREAK option: per slave node its tie state and rest gap (empty without it).
  std::vector<std::int8_t> tie_state;
  std::vector<double> tie_gap0;
  // Per model node: how many tiebreak passes hold it (ContactSet::tie_passes_at_), or null
  // when this pass does not tie.
  const std::uint8_t* ties_at = nullptr;
  [[nodiscard]] TieArrays ties() { return {tie_state.data(), tie_gap0.data()}; }

  explicit PassRuntime(const law::Parameters& p) : law(p) {}
};

ContactSet::ContactSet(const core::Model& model, const std::vector<double>& mass,
                       const unsigned char* rigid, double dt0, double tssfac)
    : model_(model), mass_(mass), rigid_(rigid) {
  for (const core::ContactInterface& ci : model.contacts) {
    // The search reaches the cohesive band: beyond 2 g_c / sqrt(BETA_MIN) a bonded node has
    // lost all but a negligible part of its adhesion, and the law releases it there.
    double bond_capture = 0.0;
    law::Parameters bond_params = ci.law;
    if (ci.cohesive) {
      const double gc = largest_sigma_max(bond_params) / bond_params.cn;
      bond_capture = 2.0 * gc / std::sqrt(std::max(bond_params.beta_min, 1e-12));
      bond_params.release_gap = std::min(bond_params.release_gap, bond_capture);
    }
    for (const core::ContactPass& cp : ci.passes) {
      const bool bonds = ci.cohesive && !cp.guard;
      const double capture = bonds ? bond_capture : 0.0;
      const law::Parameters params = cp.guard ? guard_law(ci.law) : bond_params;
      if constexpr (core::kCheckInvariants) {
        const auto in_range = [&](core::Index n) {
          return n >= 0 && static_cast<std::size_t>(n) < model.node_count();
        };
        for (core::Index n : cp.slave_nodes)
          PLYFORM_INVARIANT(in_range(n), "slave node indices in range");
        for (core::Index n : cp.segments)
          PLYFORM_INVARIANT(in_range(n), "segment node indices in range");
        PLYFORM_INVARIANT(cp.segments.size() == 4 * cp.segment_offset.size() &&
                              cp.slave_offset.size() == cp.slave_count() &&
                              cp.slave_area.size() == cp.slave_count(),
                          "a pass's arrays of matching lengths");
      }
      auto pr = std::make_unique<PassRuntime>(params);
      pr->iface = &ci;
      pr->pass = &cp;
      pr->bonds = bonds;
      pr->guard = cp.guard;
      pr->dt0 = dt0;
      const std::size_t ns = cp.slave_count();
      const std::size_t nseg = cp.segment_count();
      pr->history = law::HistoryStore(ns);
      pr->hist = pr->history.view();
      // Margin: half the mean segment size, so that a re-search is needed only after the
      // surfaces moved that far relative to each other.
      double size_sum = 0.0;
      for (std::size_t s = 0; s < nseg; ++s) {
        const core::Index* q = &cp.segments[4 * s];
        const auto d = [&](core::Index a, core::Index b) {
          const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
          const double dx = model.x0[i] - model.x0[j], dy = model.y0[i] - model.y0[j],
                       dz = model.z0[i] - model.z0[j];
          return std::sqrt(dx * dx + dy * dy + dz * dz);
        };
        size_sum += std::max(d(q[0], q[2]), d(q[1], q[3]));
      }
      pr->margin = nseg > 0 ? 0.5 * size_sum / static_cast<double>(nseg) : 0.0;
      pr->capture = capture;
      pr->slave_offset = cp.slave_offset;
      pr->seg_offset = cp.segment_offset;
      double max_slave_offset = 0.0;
      for (double o : cp.slave_offset)
        max_slave_offset = std::max(max_slave_offset, o);
      // Each segment's neighbours: the segments that share a corner with it.
      {
        std::vector<std::vector<core::Index>> at_node;
        for (std::size_t sg = 0; sg < nseg; ++sg)
          for (int j = 0; j < 4; ++j) {
            const auto n =
                static_cast<std::size_t>(cp.segments[4 * sg + static_cast<std::size_t>(j)]);
            if (at_node.size() <= n)
              at_node.resize(n + 1);
            if (at_node[n].empty() || at_node[n].back() != static_cast<core::Index>(sg))
              at_node[n].push_back(static_cast<core::Index>(sg));
          }
        pr->nb_start.assign(nseg + 1, 0);
        std::vector<core::Index> mine;
        for (std::size_t sg = 0; sg < nseg; ++sg) {
          mine.clear();
          for (int j = 0; j < 4; ++j)
            for (core::Index o : at_node[static_cast<std::size_t>(
                     cp.segments[4 * sg + static_cast<std::size_t>(j)])])
              if (o != static_cast<core::Index>(sg))
                mine.push_back(o);
          std::sort(mine.begin(), mine.end());
          mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
          pr->nb.insert(pr->nb.end(), mine.begin(), mine.end());
          pr->nb_start[sg + 1] = pr->nb.size();
        }
        pr->folded.assign(nseg, 0);
        pr->fold_centroid.assign(3 * nseg, 0.0);
        pr->fold_normal.assign(3 * nseg, 0.0);
      }
      pr->seg_radius.resize(nseg);
      double max_radius = 0.0;
      for (std::size_t s = 0; s < nseg; ++s) {
        // A touching node is within the two offsets of the segment's mid-surface (a deeper
        // one is closer still); the cohesive band; the margin for motion between searches.
        pr->seg_radius[s] = cp.segment_offset[s] + max_slave_offset + capture + pr->margin;
        max_radius = std::max(max_radius, pr->seg_radius[s]);
      }
      // Just beyond the band where the law releases a bonded node: the node is released, and
      // the elastic energy it is booked as giving up is that of its spring at the band's edge
      // (a gap far beyond would book an energy the interface never held).
      pr->far_gap = bonds ? params.release_gap * (1.0 + 1e-9) + 1.0e-30
                          : 2.0 * (capture + max_radius) + 1.0e-30;
      // Nodes whose motion can bring a slave node within reach of a new segment.
      std::vector<char> mark(model.node_count(), 0);
      for (core::Index n : cp.slave_nodes)
        mark[static_cast<std::size_t>(n)] = 1;
      for (core::Index n : cp.segments)
        mark[static_cast<std::size_t>(n)] = 1;
      for (std::size_t i = 0; i < mark.size(); ++i) {
        if (mark[i])
          pr->tracked_nodes.push_back(static_cast<core::Index>(i));
      }
      pr->tracked_ref.assign(3 * pr->tracked_nodes.size(), 0.0);
      pr->seg.assign(ns, -1);
      pr->prev_seg.assign(ns, -1);
      pr->shape.assign(4 * ns, 0.0);
      pr->friction_heated.assign(ns, 0.0);
      if (ci.tiebreak.enabled()) {
        pr->tie_state.assign(ns, static_cast<std::int8_t>(TieState::free));
        pr->tie_gap0.assign(ns, 0.0);
      }
      pr->prev_shape.assign(4 * ns, 0.0);
      pr->frame.assign(9 * ns, 0.0);
      pr->side.assign(ns, 0);
      for (auto* v :
           {&pr->gap, &pr->slip_x, &pr->slip_y, &pr->temperature, &pr->k_normal, &pr->k_tangent,
            &pr->m_eff, &pr->pressure, &pr->tau_x, &pr->tau_y, &pr->stored, &pr->work_part,
            &pr->end_power, &pr->arrival_depth, &pr->gap_jump, &pr->surface_part})
        v->assign(ns, 0.0);
      pr->force.assign(3 * ns, 0.0);
      pr->prev_force.assign(3 * ns, 0.0);
      pr->rs.assign(3 * ns, 0.0);
      pr->prev_rs.assign(3 * ns, 0.0);
      pr->slave_normal.assign(3 * ns, 0.0);
      pr->slave_face_normal.assign(3 * (cp.slave_faces.size() / 4), 0.0);
      pr->slave_face_sign.assign(cp.slave_face_index.size(), 1);
      pr->slave_face_normals_absent = cp.slave_face_start.empty() || cp.slave_face_index.empty();
      for (double o : cp.segment_offset)
        pr->master_offsets = pr->master_offsets || o > 0.0;
      if (cp.offsets_follow_thickness) {
        for (double f : cp.segment_offset_factor)
          pr->master_offsets = pr->master_offsets || f > 0.0;
      }
      if (pr->master_offsets) {
        std::vector<core::Index> local(model.node_count(), -1);
        pr->corner.resize(cp.segments.size());
        std::vector<std::size_t> count;
        for (std::size_t c = 0; c < cp.segments.size(); ++c) {
          const auto node = static_cast<std::size_t>(cp.segments[c]);
          if (local[node] < 0) {
            local[node] = static_cast<core::Index>(pr->master_nodes.size());
            pr->master_nodes.push_back(cp.segments[c]);
            count.push_back(0);
          }
          pr->corner[c] = local[node];
          // A triangle's repeated corner counts once.
          if (c % 4 != 3 || cp.segments[c] != cp.segments[c - 1])
            ++count[static_cast<std::size_t>(local[node])];
        }
        pr->node_seg_start.assign(pr->master_nodes.size() + 1, 0);
        for (std::size_t i = 0; i < count.size(); ++i)
          pr->node_seg_start[i + 1] = pr->node_seg_start[i] + count[i];
        pr->node_seg.resize(pr->node_seg_start.back());
        std::vector<std::size_t> fill(pr->node_seg_start.begin(), pr->node_seg_start.end() - 1);
        for (std::size_t c = 0; c < cp.segments.size(); ++c) {
          if (c % 4 == 3 && cp.segments[c] == cp.segments[c - 1])
            continue;
          const auto i = static_cast<std::size_t>(pr->corner[c]);
          pr->node_seg[fill[i]++] = static_cast<core::Index>(c / 4);
        }
        pr->master_normal.assign(3 * pr->master_nodes.size(), 0.0);
        pr->seg_normal.assign(3 * (cp.segments.size() / 4), 0.0);
        pr->corner_sign.assign(cp.segments.size(), 1);
        pr->node_seg_sign.assign(pr->node_seg.size(), 1);
      }
      passes_.push_back(std::move(pr));
    }
  }
  count_tie_passes();
  tssfac_ = tssfac;
}

void ContactSet::count_tie_passes() {
  std::vector<char> mark;
  for (const auto& pr : passes_) {
    if (pr->tie_state.empty())
      continue;
    if (tie_passes_at_.empty())
      tie_passes_at_.assign(model_.node_count(), 0);
    mark.assign(model_.node_count(), 0);
    for (core::Index n : pr->pass->slave_nodes)
      mark[static_cast<std::size_t>(n)] = 1;
    for (core::Index n : pr->pass->segments)
      mark[static_cast<std::size_t>(n)] = 1;
    for (std::size_t i = 0; i < mark.size(); ++i)
      if (mark[i] && tie_passes_at_[i] < 255)
        ++tie_passes_at_[i];
    pr->ties_at = tie_passes_at_.data();
  }
}

ContactSet::~ContactSet() = default;

void ContactSet::follow_shell_thickness(std::vector<const double*> thickness) {
  shell_thickness_ = std::move(thickness);
}

void ContactSet::follow_rotations(const Rotations& rotations) {
  rot_ = rotations;
}

void ContactSet::follow_thickness(PassRuntime& pr) const {
  const core::ContactPass& cp = *pr.pass;
  const auto t = [&](core::Index shell) {
    return *shell_thickness_[static_cast<std::size_t>(shell)];
  };
  for (std::size_t s = 0; s < cp.segment_shell.size(); ++s) {
    if (cp.segment_shell[s] >= 0)
      pr.seg_offset[s] = cp.segment_offset_factor[s] * t(cp.segment_shell[s]);
  }
  const std::size_t ns = cp.slave_count();
  for (std::size_t k = 0; k < ns; ++k) {
    const std::size_t b = cp.slave_shell_start[k], e = cp.slave_shell_start[k + 1];
    if (e == b)
      continue;
    double sum = 0.0;
    for (std::size_t j = b; j < e; ++j)
      sum += t(cp.slave_shells[j]);
    pr.slave_offset[k] = cp.slave_offset_factor[k] * sum / static_cast<double>(e - b);
  }
}

std::size_t ContactSet::slave_count() const {
  std::size_t n = 0;
  for (const auto& p : passes_)
    n += p->pass->slave_count();
  return n;
}

namespace {

const double* at(const double* packed, core::Index node) {
  return packed + kStride * static_cast<std::size_t>(node);
}

// Unit normal of a segment's mid-surface (N1 N2 N3 right hand), from its corner positions:
// the cross product of the diagonals (of the two edges at N1 for a triangle).
inline void segment_normal(const core::Index* q, const double* packed, double n[3]) {
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

/// A slave node against one segment: the projection of its surface point on the segment's
/// offset surface, the side it is on, and where that surface point lies.
struct Located {
  SegmentPoint sp;  // on the offset surface: distance = signed gap along the segment normal
  signed char side = 0;
  double rs[3] = {0, 0, 0};  // slave surface point minus the slave node
};

// Offset vector of corner j of segment s for a slave on `side`: along the corner's nodal
// normal, turned to the slave's side (the normal's sign relative to the segment, fixed at t = 0).
inline void corner_offset(const PassRuntime& pr, std::size_t s, int j, int side, double r[3]) {
  const double o = side * pr.seg_offset[s] * pr.corner_sign[4 * s + static_cast<std::size_t>(j)];
  const double* d = &pr.master_normal[3 * static_cast<std::size_t>(pr.corner[4 * s + j])];
  r[0] = o * d[0], r[1] = o * d[1], r[2] = o * d[2];
}

// Segment s's unit normal at this cycle's positions: the one update_master_normals() computed
// (the same numbers), or computed here when the pass keeps none.
inline const double* current_segment_normal(const PassRuntime& pr, core::Index s,
                                            const double* packed, double* scratch) {
  const auto su = static_cast<std::size_t>(s);
  if (pr.seg_normal_current)
    return &pr.seg_normal[3 * su];
  segment_normal(&pr.pass->segments[4 * su], packed, scratch);
  return scratch;
}

// Projects slave k, on `side` of segment s, on the segment's offset surface. The slave's
// surface point is the node moved by its offset o_s towards the master along its nodal normal
// (geometry, like the master's), so that the point lies on the layer's face: a node going
// round a faceted tool's kink then sees the gap of its face, not of a point o_s above it. A
// node without faces is moved along the contact normal (the gap is its distance minus o_s).
// `towards`: about the contact normal (last cycle's), or null to take the segment's.
void project_surface(const PassRuntime& pr, std::size_t k, core::Index s, const double* packed,
                     const double* guess, const double* towards, Located& L) {
  const core::ContactPass& cp = *pr.pass;
  const auto su = static_cast<std::size_t>(s);
  const core::Index* q = &cp.segments[4 * su];
  const double* p = at(packed, cp.slave_nodes[k]);
  const double om = pr.seg_offset[su];
  const double os = pr.slave_offset[k];
  const double* dir = &pr.slave_normal[3 * k];
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
Located project_on(const PassRuntime& pr, std::size_t k, core::Index s, bool free, bool was_located,
                   const double* packed, const double* guess) {
  const core::ContactPass& cp = *pr.pass;
  const core::Index* q = &cp.segments[4 * static_cast<std::size_t>(s)];
  const double offsets = pr.slave_offset[k] + pr.seg_offset[static_cast<std::size_t>(s)];
  Located L;
  if (!cp.segment_one_sided.empty() && cp.segment_one_sided[static_cast<std::size_t>(s)]) {
    // A solid's face: the node is outside, on the outward normal's side, whatever its motion.
    L.side = 1;
    project_surface(pr, k, s, packed, guess, nullptr, L);
    return L;
  }
  L.side = pr.side[k];
  if (L.side != 0 && was_located) {
    // The side is relative to a segment's normal, and a surface's segments need not be
    // oriented alike (a tool mesh from several patches): on another segment than last cycle's,
    // the side is the one last cycle's contact normal is on.
    if (s != pr.seg[k]) {
      double scratch[3];
      const double* ns = current_segment_normal(pr, s, packed, scratch);
      const double* fr = &pr.frame[9 * k];
      L.side = fr[0] * ns[0] + fr[1] * ns[1] + fr[2] * ns[2] < 0.0 ? -1 : 1;
    }
    project_surface(pr, k, s, packed, guess, &pr.frame[9 * k], L);
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
    if (!((free || s != pr.seg[k]) && L.side * L.sp.distance < -through))
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
  const double* own = &pr.slave_normal[3 * k];
  const double f =
      L.side * (own[0] * L.sp.normal[0] + own[1] * L.sp.normal[1] + own[2] * L.sp.normal[2]);
  return pr.slave_offset[k] > 0.0 ? -std::fabs(f) : f;
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

// The segment of slave k: its current one while the projection stays within MAXPAR - 1 of it
// (parametric measure) and the node's surface faces it, else the nearest candidate within that
// tolerance, the candidates the node's surface faces first. A node on an edge of the master (a
// slice's bottom corner on the edge between the top and the side faces of the slice below) is
// as near to the side face whose plane it lies in as to the top face it presses into, nearer
// once it has pressed in; it must take the top face, which its own surface faces (as LS-DYNA
// does), or it falls through. Returns -1 when no candidate is within reach.
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
  const double r = pr.seg_radius[su];
  return along * along > 1.1 * r * r * det;  // |n|^2 = det
}

// Within this share of a segment's edge (the smallest shape function of the projection) a
// pressed node looks for a deeper neighbour across a concave junction (deeper_across_valley).
constexpr double kEdgeBand = 0.05;

// Which segments have a neighbour out of their plane this cycle (its centroid off the plane by
// more than sin 0.5 degree of the distance between the centroids): only a node on such a
// segment looks across to its neighbours (deeper_across_valley), so flat and gently bent
// surfaces (a DCB's arms) pay one load per node. Below that fold a gap's jump at a segment
// change is under a hundredth of the overshoot MAXPAR allows.
constexpr double kFoldSin2 = 7.6e-5;  // sin^2(0.5 degree)
void update_folds(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  const std::size_t nseg = pr.folded.size();
  std::vector<double>& c = pr.fold_centroid;
  // The segments' normals: this cycle's from update_master_normals() where the pass keeps them
  // (the same numbers), else computed here.
  const bool reuse = pr.seg_normal_current;
  double* n = reuse ? pr.seg_normal.data() : pr.fold_normal.data();
#pragma omp parallel for schedule(static) if (nseg > kLightLoop)
  for (long ls = 0; ls < static_cast<long>(nseg); ++ls) {
    const auto sg = static_cast<std::size_t>(ls);
    const core::Index* q = &cp.segments[4 * sg];
    const double *x0 = at(packed, q[0]), *x1 = at(packed, q[1]), *x2 = at(packed, q[2]),
                 *x3 = at(packed, q[3]);
    for (int i = 0; i < 3; ++i)
      c[3 * sg + i] = 0.25 * (x0[i] + x1[i] + x2[i] + x3[i]);
    if (!reuse)
      segment_normal(q, packed, &n[3 * sg]);
  }
#pragma omp parallel for schedule(static) if (nseg > kLightLoop)
  for (long ls = 0; ls < static_cast<long>(nseg); ++ls) {
    const auto sg = static_cast<std::size_t>(ls);
    unsigned char f = 0;
    const double* cs = &c[3 * sg];
    const double* ns = &n[3 * sg];
    for (std::size_t j = pr.nb_start[sg]; j < pr.nb_start[sg + 1] && !f; ++j) {
      const double* co = &c[3 * static_cast<std::size_t>(pr.nb[j])];
      const double d[3] = {co[0] - cs[0], co[1] - cs[1], co[2] - cs[2]};
      const double off = d[0] * ns[0] + d[1] * ns[1] + d[2] * ns[2];
      f = off * off > kFoldSin2 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    pr.folded[sg] = f;
  }
}

// Whether segment s rises towards the slave's side of the plane of L (a valley between them,
// seen from the slave): its centroid lies on that side.
inline bool rises_towards(const PassRuntime& pr, core::Index s, const Located& L) {
  const double* c = &pr.fold_centroid[3 * static_cast<std::size_t>(s)];  // this cycle's
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
core::Index deeper_across_valley(const PassRuntime& pr, std::size_t k, core::Index cur, bool free,
                                 bool was_located, const double* packed, double tol,
                                 Located& best) {
  const auto cu = static_cast<std::size_t>(cur);
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
        std::fabs(L.sp.distance) > pr.seg_radius[static_cast<std::size_t>(s)] || behind(pr, s, L) ||
        !(facing(pr, k, L) <= kFaces || pr.slave_face_normals_absent))
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

core::Index locate(const PassRuntime& pr, std::size_t k, bool free, bool was_located,
                   const double* packed, Located& best) {
  const core::Index cur = pr.seg[k];
  const double tol = pr.iface->maxpar - 1.0;
  if (cur >= 0) {
    // prev_shape holds last cycle's projection on `cur` (apply() swaps the arrays).
    const Located L = project_on(pr, k, cur, free, was_located, packed, &pr.prev_shape[4 * k]);
    if (!L.sp.degenerate && L.sp.outside <= tol &&
        std::fabs(L.sp.distance) <= pr.seg_radius[static_cast<std::size_t>(cur)] &&
        !behind(pr, cur, L) && (facing(pr, k, L) <= kFaces || pr.slave_face_normals_absent)) {
      best = L;
      return deeper_across_valley(pr, k, cur, free, was_located, packed, tol, best);
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
  for (std::size_t c = pr.cand_start[k]; c < pr.cand_start[k + 1]; ++c) {
    const core::Index s = pr.cand[c];
    // A candidate out of reach is passed over before the projection (a Newton solve): a
    // point that projects inside the segment (to MAXPAR) lies within its corners' distance
    // from its centroid, scaled by MAXPAR, in the plane, and within its radius along the
    // normal. Nodes with no segment (a layer's nodes beyond the other layer's edge) try their
    // candidates every cycle, and most are out of reach.
    if (out_of_reach(pr, s, p, tol, packed))
      continue;
    const Located L = project_on(pr, k, s, free, was_located, packed, nullptr);
    if (L.sp.degenerate || L.sp.outside > acquire ||
        std::fabs(L.sp.distance) > pr.seg_radius[static_cast<std::size_t>(s)] || behind(pr, s, L))
      continue;
    // About the true distance to the segment: the normal distance and, outside the segment,
    // the parametric overshoot times half the segment size.
    const double score = std::hypot(L.sp.distance, L.sp.outside * pr.margin);
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
  return found;
}

// Effective mass m_s m_m / (m_s + m_m) of a slave node against a point of a segment; rigid
// nodes count as infinitely heavy.
double effective_mass(double ms, double mm) {
  if (!std::isfinite(ms))
    return std::isfinite(mm) ? mm : 0.0;
  if (!std::isfinite(mm))
    return ms;
  return ms + mm > 0.0 ? ms * mm / (ms + mm) : 0.0;
}

// A guard pass acts beyond this share of the two offsets' depth (core::ContactPass::guard):
// deep enough that the interface's own penalty carries every pressure of a healthy run alone
// (two stiff springs taking turns at one place chatter, and the friction's return mapping then
// books more than the friction force's work), shallow enough to stop a node well before its
// mid-surface reaches the other layer's.
constexpr double kGuardDepth = 0.1;

// A layer interface's penalty is held below kLayerPenaltyScale m* / dt0^2.
constexpr double kLayerPenaltyScale = 0.25;

// The stick spring of friction acts in the sheet's plane, where its elements' highest mode is
// already at the step's limit (at TSSFAC 0.9, 81 % of it in frequency squared); a spring of the
// normal penalty there (a 7 mm aluminium skin on a rigid die) outran what was left and the
// nodes chattered along the die. Held at sqrt(k / m*) dt0 = 1/2, as a layer's penalty.
constexpr double kStickScale = 0.25;

// A tool's (or any non-layer) material penalty is held below kToolPenaltyScale m* / dt0^2
// (sqrt(k / m*) dt0 = 1). A skin's edge node pressed by a rigid holder (7.5 mm elements of a
// 0.25 mm aluminium skin: sqrt(k / m*) dt0 = 1.22 at SFS 1) carries, beside that spring, its
// elements' transverse mode and the layer interface below it; together they passed the
// central difference's limit, the node flipped its velocity every cycle between the two
// springs and the contact gave energy (the restart tests' square cup at n 10 without backup
// contacts: -1.5 mJ, 1.7 % of the entered energy). The step vote cannot see it: it takes each
// spring alone.
constexpr double kToolPenaltyScale = 1.0;

// The passes that tie a node hold it together, in tension as in compression, all the time: a
// core between two skins tied by two-pass tiebreak contacts is held by four springs, each
// voting a step as if alone. At kToolPenaltyScale each, their sum reached the central
// difference's limit on their own (sqrt(k / m*) dt0 = 2 for the four), the ties failed within
// microseconds at sub-micrometre motions and the interface gave energy (the hot draw with
// tiebreak interfaces, n 10: 6 of 31 history nodes failed in 60 us, contact energy -1.9 % of
// what entered, the kinetic book negative). Each tie's spring gets its share of one tool
// spring's budget: the budget over the most tie passes at any of its nodes. A layer's cohesive
// passes meet the same budget by their scale (four at kLayerPenaltyScale make one).
double tie_share(const PassRuntime& pr, std::size_t k, core::Index s) {
  const core::ContactPass& cp = *pr.pass;
  unsigned most = pr.ties_at[static_cast<std::size_t>(cp.slave_nodes[k])];
  for (int j = 0; j < 4; ++j)
    most = std::max<unsigned>(
        most, pr.ties_at[static_cast<std::size_t>(
                  cp.segments[4 * static_cast<std::size_t>(s) + static_cast<std::size_t>(j)])]);
  return most > 1 ? 1.0 / most : 1.0;
}

// The penalty stiffness [force/length] of slave k against segment s (PENOPT, SOFT).
double penalty(const PassRuntime& pr, std::size_t k, core::Index s, double m_eff) {
  const core::ContactInterface& ci = *pr.iface;
  const double ks = pr.pass->slave_stiffness[k];
  const double km = pr.pass->segment_stiffness[static_cast<std::size_t>(s)];
  double kk = ci.penopt == 2 ? km : ci.penopt == 3 ? ks : std::min(ks, km);
  if (ci.penopt == 0) {
    // A layer interface (core::ContactInterface::penopt): the stiffer side's penalty, so that
    // a soft core does not let the press sink stiff skins into it, held where the spring's
    // frequency on the pair's mass would reach half the first step's (sqrt(k / m*) dt0 =
    // 1/2): together with the elements' highest mode at the node, still inside the central
    // difference's limit, and its step vote never binds.
    double hi = std::max(ks, km);
    if (pr.dt0 > 0.0 && m_eff > 0.0)
      hi = std::min(hi, kLayerPenaltyScale * m_eff / (pr.dt0 * pr.dt0));
    kk = std::max(kk, hi);
  }
  if (ci.penalty == core::PenaltyKind::mass && pr.dt0 > 0.0)
    kk = std::max(kk, 0.5 * ci.sofscl * m_eff / (pr.dt0 * pr.dt0));
  else if (ci.penopt != 0 && pr.dt0 > 0.0 && m_eff > 0.0) {
    const double budget = kToolPenaltyScale * (pr.ties_at != nullptr ? tie_share(pr, k, s) : 1.0);
    kk = std::min(kk, budget * m_eff / (pr.dt0 * pr.dt0));
  }
  return kk;
}

}  // namespace

double ContactSet::stable_step() const {
  double dt = kInf;
  for (const auto& p : passes_)
    dt = std::min(dt, p->dt_vote);
  return dt;
}

double ContactSet::energy() const {
  double e = 0.0;
  for (const auto& p : passes_)
    e += p->work;
  return e;
}

namespace {

double node_mass(const std::vector<double>& mass, const unsigned char* rigid, core::Index n) {
  const auto i = static_cast<std::size_t>(n);
  return rigid != nullptr && rigid[i] ? kInf : mass[i];
}

// Self contact: each slave node's candidates less the segments it touches through the mesh
// (both lists sorted: one merge), and rigid segments for a rigid node. Compacts the CSR in place.
void drop_own_segments(PassRuntime& pr, const unsigned char* rigid) {
  const core::ContactPass& cp = *pr.pass;
  const std::size_t ns = cp.slave_count();
  const auto is_rigid = [&](core::Index n) {
    return rigid != nullptr && rigid[static_cast<std::size_t>(n)] != 0;
  };
  std::size_t out = 0;
  std::size_t begin = pr.cand_start[0];
  for (std::size_t k = 0; k < ns; ++k) {
    const std::size_t end = pr.cand_start[k + 1];
    const bool rigid_node = cp.skip_rigid_pairs && is_rigid(cp.slave_nodes[k]);
    std::size_t e = cp.exclude_start[k];
    const std::size_t e_end = cp.exclude_start[k + 1];
    pr.cand_start[k] = out;
    for (std::size_t c = begin; c < end; ++c) {
      const core::Index s = pr.cand[c];
      while (e < e_end && cp.exclude[e] < s)
        ++e;
      if (e < e_end && cp.exclude[e] == s)
        continue;
      if (rigid_node && is_rigid(cp.segments[4 * static_cast<std::size_t>(s)]))
        continue;
      pr.cand[out++] = s;
    }
    begin = end;
  }
  pr.cand_start[ns] = out;
  pr.cand.resize(out);
}

void search(PassRuntime& pr, const double* packed, const std::vector<double>& mass,
            const unsigned char* rigid, const Rotations& rot, double tssfac) {
  const core::ContactPass& cp = *pr.pass;
  if (cp.offsets_follow_thickness) {
    double max_slave_offset = 0.0;
    for (double o : pr.slave_offset)
      max_slave_offset = std::max(max_slave_offset, o);
    for (std::size_t s = 0; s < pr.seg_radius.size(); ++s)
      pr.seg_radius[s] = pr.seg_offset[s] + max_slave_offset + pr.capture + pr.margin;
  }
  pr.grid.build(cp.segments, packed, kStride, pr.seg_radius);
  pr.grid.query(cp.slave_nodes, packed, kStride, pr.cand_start, pr.cand);
  if (!cp.exclude_start.empty())
    drop_own_segments(pr, rigid);
  for (std::size_t t = 0; t < pr.tracked_nodes.size(); ++t) {
    const double* p = at(packed, pr.tracked_nodes[t]);
    pr.tracked_ref[3 * t] = p[0];
    pr.tracked_ref[3 * t + 1] = p[1];
    pr.tracked_ref[3 * t + 2] = p[2];
  }
  pr.cycles_since_search = 0;
  pr.searched = true;
  // The step vote: a slave node on the stiffest spring it may meet, against the lightest
  // master node, gets dt = TSSFAC sqrt(2 m_eff / k): half the two-mass spring's limit in
  // frequency squared, leaving the other half to the elements at that node. A tangential
  // spring on offset surface points also turns the nodes: its inverse mass adds o^2 / I of
  // each side (the rotary inertia of the shells).
  const bool cohesive = pr.bonds;
  const double cn = pr.law.parameters().cn;
  const double ct = cohesive ? pr.law.parameters().ct : 0.0;
  double vote = kInf;
  const std::size_t ns = cp.slave_count();
  const auto turn = [&](core::Index node, double o) {  // o^2 / I of a node, 0 without rotation
    const auto i = static_cast<std::size_t>(node);
    if (rot.inertia == nullptr || !(rot.inertia[i] > 0.0) || (rigid != nullptr && rigid[i]))
      return 0.0;
    return o * o / rot.inertia[i];
  };
#pragma omp parallel for schedule(static) reduction(min : vote)
  for (long lk = 0; lk < static_cast<long>(ns); ++lk) {
    const auto k = static_cast<std::size_t>(lk);
    if (pr.cand_start[k] == pr.cand_start[k + 1])
      continue;
    const double ms = node_mass(mass, rigid, cp.slave_nodes[k]);
    const double turn_s = turn(cp.slave_nodes[k], pr.slave_offset[k]);
    for (std::size_t c = pr.cand_start[k]; c < pr.cand_start[k + 1]; ++c) {
      const core::Index s = pr.cand[c];
      const auto su = static_cast<std::size_t>(s);
      double mm = kInf, turn_m = 0.0;
      for (int j = 0; j < 4; ++j) {
        const core::Index m = cp.segments[4 * su + static_cast<std::size_t>(j)];
        mm = std::min(mm, node_mass(mass, rigid, m));
        turn_m = std::max(turn_m, turn(m, pr.seg_offset[su]));
      }
      const double me = effective_mass(ms, mm);
      const double kp = penalty(pr, k, s, me);
      double kk = kp;
      if (cohesive)
        kk = std::max(kk, cn * cp.slave_area[k]);
      if (me > 0.0 && kk > 0.0)
        vote = std::min(vote, tssfac * std::sqrt(2.0 * me / kk));
      // Tangential: the stick spring (the penalty) or the adhesive shear C_T.
      const double kt = std::max(kp, ct * cp.slave_area[k]);
      const double inv_m = (me > 0.0 ? 1.0 / me : 0.0) + turn_s + turn_m;
      if (inv_m > 0.0 && kt > 0.0 && turn_s + turn_m > 0.0)
        vote = std::min(vote, tssfac * std::sqrt(2.0 / (kt * inv_m)));
    }
  }
  pr.dt_vote = vote;
}

// The master's nodal normals at the current positions: the mean of the normals of the segments
// around each node, each turned by its sign fixed at t = 0 (init_nodal_normals).
void update_master_normals(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  const std::size_t nseg = cp.segments.size() / 4;
#pragma omp parallel for schedule(static) if (nseg > kLightLoop)
  for (long ls = 0; ls < static_cast<long>(nseg); ++ls) {
    const auto su = static_cast<std::size_t>(ls);
    segment_normal(&cp.segments[4 * su], packed, &pr.seg_normal[3 * su]);
  }
  const std::size_t nm = pr.master_nodes.size();
#pragma omp parallel for schedule(static) if (nm > kLightLoop)
  for (long li = 0; li < static_cast<long>(nm); ++li) {
    const auto i = static_cast<std::size_t>(li);
    double n0 = 0.0, n1 = 0.0, n2 = 0.0;
    for (std::size_t e = pr.node_seg_start[i]; e < pr.node_seg_start[i + 1]; ++e) {
      const double* ns = &pr.seg_normal[3 * static_cast<std::size_t>(pr.node_seg[e])];
      const double sg = pr.node_seg_sign[e];
      n0 += sg * ns[0], n1 += sg * ns[1], n2 += sg * ns[2];
    }
    const double len = std::sqrt(n0 * n0 + n1 * n1 + n2 * n2);
    const double inv = len > 0.0 ? 1.0 / len : 0.0;
    double* out = &pr.master_normal[3 * i];
    out[0] = n0 * inv, out[1] = n1 * inv, out[2] = n2 * inv;
  }
}

// The slave nodes' normals at the current positions, from their faces (init_nodal_normals' signs).
void update_slave_normals(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  const std::size_t nf = cp.slave_faces.size() / 4;
#pragma omp parallel for schedule(static) if (nf > kLightLoop)
  for (long lf = 0; lf < static_cast<long>(nf); ++lf) {
    const auto f = static_cast<std::size_t>(lf);
    segment_normal(&cp.slave_faces[4 * f], packed, &pr.slave_face_normal[3 * f]);
  }
  const std::size_t ns = cp.slave_count();
#pragma omp parallel for schedule(static) if (ns > kLightLoop)
  for (long lk = 0; lk < static_cast<long>(ns); ++lk) {
    const auto k = static_cast<std::size_t>(lk);
    double n0 = 0.0, n1 = 0.0, n2 = 0.0;
    for (std::size_t e = cp.slave_face_start[k]; e < cp.slave_face_start[k + 1]; ++e) {
      const double* nf3 =
          &pr.slave_face_normal[3 * static_cast<std::size_t>(cp.slave_face_index[e])];
      const double sg = pr.slave_face_sign[e];
      n0 += sg * nf3[0], n1 += sg * nf3[1], n2 += sg * nf3[2];
    }
    const double len = std::sqrt(n0 * n0 + n1 * n1 + n2 * n2);
    const double inv = len > 0.0 ? 1.0 / len : 0.0;
    double* out = &pr.slave_normal[3 * k];
    out[0] = n0 * inv, out[1] = n1 * inv, out[2] = n2 * inv;
  }
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
  const bool offset_spin = spin && pr.seg_offset[su] > 0.0;
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

// The law's tangential history of a slave node (its stick slip and its adhesive opening) is
// written in the node's tangent axes. Those axes come from the global x axis (y where the normal
// is close to x), so they jump by up to 90 degrees when the normal passes near x, and they turn
// with the surface. Before the axes are replaced, each history vector is taken back to global
// components, turned by the smallest rotation that takes the old normal to the new one (the
// surface carries it along), and written in the new axes: its direction and length stay what
// they were on the surface, whatever the axes do.
inline void carry_tangential_history(const law::BatchHistory& h, std::size_t k,
                                     const double* old_frame, const double* n, const double* e1,
                                     const double* e2) {
  const double* n0 = old_frame;
  const double c = n0[0] * n[0] + n0[1] * n[1] + n0[2] * n[2];
  if (!(c > -0.5))  // no frame yet (zeros), or the node turned onto a far side: start afresh
    return;
  const double* a1 = old_frame + 3;
  const double* a2 = old_frame + 6;
  const auto carry = [&](double& x, double& y) {
    if (x == 0.0 && y == 0.0)
      return;
    double v[3] = {x * a1[0] + y * a2[0], x * a1[1] + y * a2[1], x * a1[2] + y * a2[2]};
    // R v = v - (v . n) (n0 + n) / (1 + c) for v normal to n0 (Rodrigues, the rotation about
    // n0 x n that takes n0 to n).
    const double vn = (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / (1.0 + c);
    for (int d = 0; d < 3; ++d)
      v[d] -= vn * (n0[d] + n[d]);
    x = v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2];
    y = v[0] * e2[0] + v[1] * e2[1] + v[2] * e2[2];
  };
  carry(h.slip_x[k], h.slip_y[k]);
  carry(h.opening_x[k], h.opening_y[k]);
}

// A bonded slave node that left the master surface (a skin's edge sliding past the core's edge)
// lets go of its bond without any work: the energy its springs held goes to damage, as a
// release does, and so does the adhesion omega(T) beta it takes with it, which no work paid
// for: the surface book takes that as the surfaces' own doing, and the interface's books still
// close. Before, the law released it at the stand-in gap and booked omega beta as damage
// against nothing (the coarse hot draw's lower interface: books 33 % above work + surface at
// 2.2 ms, twelve edge nodes of 1.4 mJ each).
void leave_master_bonded(PassRuntime& pr, std::size_t k) {
  const law::BatchHistory& h = pr.hist;
  const law::Parameters& p = pr.law.parameters();
  const double smax = law::evaluate(p.sigma_max, p, pr.temperature[k]);
  const double area = pr.pass->slave_area[k];
  const double adhesion = smax * smax / p.cn * h.beta[k] * area;
  // The stick spring's share is friction's, as when the law lets a node out of contact (it
  // turns to heat with the friction).
  const double stick =
      0.5 * pr.k_tangent[k] * (h.slip_x[k] * h.slip_x[k] + h.slip_y[k] * h.slip_y[k]) * area;
  h.e_friction[k] += stick;
  h.e_damage[k] += pr.stored[k] - stick + adhesion;
  pr.surface_part[k] += adhesion;
  h.state[k] = static_cast<std::int32_t>(law::NodeState::detached);
  h.beta[k] = 0.0;
  h.slip_x[k] = h.slip_y[k] = 0.0;
  h.opening_x[k] = h.opening_y[k] = 0.0;
}

// A node pressed on the master that left it (a sheet sliding off a holder's inner edge) takes
// its normal spring's energy with it: no work unloaded that spring, so the surface book pays it
// out (the law turns the stick spring's to friction as the node detaches). Unbooked, the
// coarse hot draw's holder contact fell 1.6 % below its work by such steps of 5-15 mJ.
void leave_master_pressed(PassRuntime& pr, std::size_t k) {
  const law::BatchHistory& h = pr.hist;
  const double stick = 0.5 * pr.k_tangent[k] *
                       (h.slip_x[k] * h.slip_x[k] + h.slip_y[k] * h.slip_y[k]) *
                       pr.pass->slave_area[k];
  pr.surface_part[k] -= pr.stored[k] - stick;
}

// Geometry and law inputs of every slave node of a pass at the current positions; the first
// half of the step's contact work with last cycle's forces. Fills the arrays.
void measure(PassRuntime& pr, double dt, const double* packed, const double* temperature,
             const std::vector<double>& mass, const unsigned char* rigid, const Rotations& rot) {
  const core::ContactPass& cp = *pr.pass;
  const std::size_t ns = cp.slave_count();
  const law::BatchHistory& h = pr.hist;
  pr.seg_normal_current = pr.master_offsets && dt > 0.0;
  if (pr.seg_normal_current)
    update_master_normals(pr, packed);
  if (!cp.slave_face_start.empty() && dt > 0.0)
    update_slave_normals(pr, packed);
  update_folds(pr, packed);
#pragma omp parallel for schedule(static) if (ns > kHeavyLoop)
  for (long lk = 0; lk < static_cast<long>(ns); ++lk) {
    const auto k = static_cast<std::size_t>(lk);
    const core::Index node = cp.slave_nodes[k];
    // First half of the trapezoidal work of the step just taken, with last cycle's force (and
    // last cycle's frame and surface point, still in the arrays). Where the step changed, that
    // force moved the nodes over dt_avg / 2 on each side of its time: (dt - dt_last) / 4 times
    // its power on the last step less its power on this one (docs/energy.md).
    double w = 0.0;
    double moved_before = 0.0;  // the step's normal motion at last cycle's point and normal
    // Last cycle's tangential traction (global axes), its work on the step's motion at last
    // cycle's point, and last cycle's normal: the surface book's tangential half below.
    double tau_before[3] = {0.0, 0.0, 0.0}, n_before[3] = {0.0, 0.0, 0.0};
    double slid_before = 0.0;
    if (pr.prev_seg[k] >= 0) {
      const double* f = &pr.prev_force[3 * k];
      double du[3];
      relative_velocity(pr, k, pr.prev_seg[k], &pr.prev_shape[4 * k], &pr.prev_rs[3 * k],
                        pr.side[k], &pr.frame[9 * k], packed, rot, du);
      const double* fr0 = &pr.frame[9 * k];
      for (int d = 0; d < 3; ++d) {
        n_before[d] = fr0[d];
        tau_before[d] = pr.tau_x[k] * fr0[3 + d] + pr.tau_y[k] * fr0[6 + d];
      }
      moved_before = dt * (du[0] * n_before[0] + du[1] * n_before[1] + du[2] * n_before[2]);
      slid_before = dt * (du[0] * tau_before[0] + du[1] * tau_before[1] + du[2] * tau_before[2]);
      const double start_power = -(f[0] * du[0] + f[1] * du[1] + f[2] * du[2]);
      w += 0.5 * dt * start_power;
      if (pr.dt_last > 0.0)
        w += 0.25 * (dt - pr.dt_last) * (pr.end_power[k] - start_power);
    }
    pr.work_part[k] = w;
    pr.gap_jump[k] = 0.0;
    pr.temperature[k] = temperature != nullptr ? temperature[static_cast<std::size_t>(node)] : 0.0;
    const auto state = static_cast<law::NodeState>(h.state[k]);
    const bool free = state == law::NodeState::approaching || state == law::NodeState::detached;
    const bool was_located = pr.seg[k] >= 0;
    Located L;
    const core::Index s = locate(pr, k, free, was_located, packed, L);
    pr.seg[k] = s;
    double* rs = &pr.rs[3 * k];
    if (s < 0) {
      pr.surface_part[k] = 0.0;
      // The law sees the stand-in gap: its last damping traction's second half (half a step's
      // work of it) is not booked against that jump.
      h.damping[k] = 0.0;
      if (was_located && !free) {
        if (pr.bonds && h.beta[k] > 0.0)
          leave_master_bonded(pr, k);
        else if (pr.tie_state.empty() || static_cast<TieState>(pr.tie_state[k]) != TieState::tied)
          leave_master_pressed(pr, k);
      }
      pr.gap[k] = pr.far_gap;
      pr.arrival_depth[k] = 0.0;
      pr.slip_x[k] = pr.slip_y[k] = 0.0;
      pr.m_eff[k] = 0.0;
      rs[0] = rs[1] = rs[2] = 0.0;
      continue;
    }
    const core::Index* q = &cp.segments[4 * static_cast<std::size_t>(s)];
    for (int j = 0; j < 4; ++j)
      pr.shape[4 * k + j] = L.sp.shape[j];
    pr.side[k] = L.side;
    rs[0] = L.rs[0], rs[1] = L.rs[1], rs[2] = L.rs[2];
    // A node that comes onto the master from beyond its edge (a layer's edge sliding back over
    // the layer below, a sheet coming round a tool's edge) may arrive inside the band of the
    // offsets: a penetration it never made. Pushing it out would give the model energy that
    // never entered it. Beyond a shallow first part (1 % of the band, an interference of
    // meshes the penalty should remove, as before), the depth it arrived at is tolerated, and
    // the tolerance shrinks to the node's depth whenever it comes out (there is no force then,
    // so nothing is stored): the penalty acts on penetration beyond the arrival depth only, and
    // the usual rule resumes once the node is clear. Penetrations at t = 0 are pushed out, as
    // LS-DYNA does with IGNORE = 0.
    const double g = L.side * L.sp.distance;
    double& tol = pr.arrival_depth[k];
    const double band = pr.slave_offset[k] + pr.seg_offset[static_cast<std::size_t>(s)];
    const double push = 0.01 * band;
    // A located node arrives too when its depth jumps by half the band or more in one cycle,
    // which no motion does: it took another surface's segment (an intersecting part) whose
    // band it was inside already, or its segment turned over (a crushed fold's quadrilateral
    // flips its normal); the penalty would fire the node out (the crush box deck: 1.3 mm deep
    // at once, 150 mm/ms; a segment flipped under a node 9 mm above it, 12 mm deep, 17 kJ).
    const double g_before = pr.gap[k] + tol;
    const bool jumped = was_located && band > 0.0 && g < g_before - 0.5 * band;
    if (((!was_located && pr.measured) || jumped) && g < -push)
      tol = std::min(tol, g + push);
    else if (tol < 0.0 && g > tol)
      tol = g < 0.0 ? g : 0.0;
    pr.gap[k] = g - tol;
    // A guard acts only beyond kGuardDepth of the two offsets' depth.
    if (pr.guard)
      pr.gap[k] += kGuardDepth * (pr.slave_offset[k] + pr.seg_offset[static_cast<std::size_t>(s)]);
    // Its last gap was the stand-in `far_gap`: start the gap rate (normal damping) afresh.
    if (!was_located)
      h.gap[k] = pr.gap[k];
    double* fr = &pr.frame[9 * k];
    const double n[3] = {L.side * L.sp.normal[0], L.side * L.sp.normal[1], L.side * L.sp.normal[2]};
    // Tangent axes from the global x axis (y where the normal is close to x): continuous as
    // the node moves from segment to segment, so the stick spring keeps its meaning.
    double e1[3] = {1.0 - n[0] * n[0], -n[0] * n[1], -n[0] * n[2]};
    double len = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    if (len < 0.1) {
      e1[0] = -n[1] * n[0];
      e1[1] = 1.0 - n[1] * n[1];
      e1[2] = -n[1] * n[2];
      len = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    }
    const double inv_len = 1.0 / len;
    e1[0] *= inv_len;
    e1[1] *= inv_len;
    e1[2] *= inv_len;
    const double e2[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2],
                          n[0] * e1[1] - n[1] * e1[0]};
    carry_tangential_history(h, k, fr, n, e1, e2);
    for (int c = 0; c < 3; ++c) {
      fr[c] = n[c];
      fr[3 + c] = e1[c];
      fr[6 + c] = e2[c];
    }
    // Relative displacement of the step: the slave's surface point minus the segment's
    // surface point (same shape functions as the force distribution).
    double du[3];
    relative_velocity(pr, k, s, L.sp.shape, rs, L.side, fr, packed, rot, du);
    // The effective mass, which every pass needs: damping (VDC), SOFT = 1, a layer interface's
    // penalty, the cap on any other penalty (kToolPenaltyScale), friction's stick spring.
    double mm = 0.0;
    for (int j = 0; j < 4; ++j) {
      const double nj = L.sp.shape[j];
      if (nj > 0.0)
        mm += nj * node_mass(mass, rigid, q[j]);
    }
    pr.slip_x[k] = dt * (du[0] * e1[0] + du[1] * e1[1] + du[2] * e1[2]);
    pr.slip_y[k] = dt * (du[0] * e2[0] + du[1] * e2[1] + du[2] * e2[2]);
    // The surface book: the law's gap changed by pr.gap - h.gap over the step, the nodes'
    // motion moved it by dt du . n; the rest no work of the nodes paid for. Each half of the
    // step's work is measured as the work is: last cycle's pressure with last cycle's point and
    // normal (the pressure still last cycle's here), this cycle's with this cycle's (the force
    // loop). A node found again starts afresh.
    pr.surface_part[k] = 0.0;
    if (was_located) {
      const double changed = pr.gap[k] - h.gap[k];
      pr.gap_jump[k] = changed - dt * (du[0] * n[0] + du[1] * n[1] + du[2] * n[2]);
      pr.surface_part[k] = -0.5 * pr.pressure[k] * cp.slave_area[k] * (changed - moved_before);
      // Tangential: the law works last cycle's traction, carried into this cycle's frame (as
      // carry_tangential_history carries its springs), on this cycle's slip; the nodes moved
      // under it at last cycle's point and frame. Where a node passes between facets at an
      // angle, the two differ (a node switching facets every cycle under 21 MPa in the
      // three-layer square cup: 2.5 % of its interface's work).
      double slid = 0.0;
      const double c = n_before[0] * n[0] + n_before[1] * n[1] + n_before[2] * n[2];
      if (c > -0.5) {
        double v[3] = {tau_before[0], tau_before[1], tau_before[2]};
        const double vn = (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / (1.0 + c);
        for (int d = 0; d < 3; ++d)
          v[d] -= vn * (n_before[d] + n[d]);
        slid = dt * (v[0] * du[0] + v[1] * du[1] + v[2] * du[2]);
      }
      pr.surface_part[k] -= 0.5 * cp.slave_area[k] * (slid - slid_before);
    }
    const double me = effective_mass(node_mass(mass, rigid, node), mm);
    pr.m_eff[k] = me;
    const double kk = penalty(pr, k, s, me);
    pr.k_normal[k] = kk / cp.slave_area[k];
    pr.k_tangent[k] = pr.k_normal[k];
    if (pr.dt0 > 0.0 && me > 0.0)
      pr.k_tangent[k] =
          std::min(pr.k_tangent[k], kStickScale * me / (pr.dt0 * pr.dt0) / cp.slave_area[k]);
  }
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
        packed, &pr.master_normal[3 * i]);
  }
  // Each corner's nodal normal against its segment's normal: the sign that turns it to the side
  // of the segment a slave node is on. Fixed: nodal normals and segments turn together.
  for (std::size_t c = 0; c < pr.corner_sign.size(); ++c) {
    double ns[3];
    segment_normal(&cp.segments[c - c % 4], packed, ns);
    const double* d = &pr.master_normal[3 * static_cast<std::size_t>(pr.corner[c])];
    pr.corner_sign[c] = d[0] * ns[0] + d[1] * ns[1] + d[2] * ns[2] < 0.0 ? -1 : 1;
  }
  for (std::size_t i = 0; i < pr.master_nodes.size(); ++i) {
    const double* d = &pr.master_normal[3 * i];
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
        packed, &pr.slave_normal[3 * k]);
    const double* d = &pr.slave_normal[3 * k];
    for (std::size_t e = b; e < cp.slave_face_start[k + 1]; ++e) {
      double nf[3];
      segment_normal(&cp.slave_faces[4 * static_cast<std::size_t>(cp.slave_face_index[e])], packed,
                     nf);
      pr.slave_face_sign[e] = d[0] * nf[0] + d[1] * nf[1] + d[2] * nf[2] < 0.0 ? -1 : 1;
    }
  }
}

}  // namespace

// The _TIEBREAK option at t = 0: a slave node in contact (its surface gap, penetration or
// opening, within 5 % of its segment's shorter diagonal, LS-DYNA's tolerance of tied contacts)
// is tied where it is, so the mesh as given starts at rest.
void tie_initial_contacts(PassRuntime& pr, const double* packed) {
  const core::ContactPass& cp = *pr.pass;
  const TieArrays tie = pr.ties();
  for (std::size_t k = 0; k < cp.slave_count(); ++k) {
    const core::Index s = pr.seg[k];
    if (s < 0)
      continue;
    const core::Index* q = &cp.segments[4 * static_cast<std::size_t>(s)];
    const auto dist = [&](core::Index a, core::Index b) {
      const double *pa = at(packed, a), *pb = at(packed, b);
      return std::hypot(pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]);
    };
    // A triangle (N3 = N4): its shortest edge at N1 stands in for the diagonal.
    const double diagonal = q[2] == q[3] ? std::min(dist(q[0], q[1]), dist(q[0], q[2]))
                                         : std::min(dist(q[0], q[2]), dist(q[1], q[3]));
    if (std::abs(pr.gap[k]) <= 0.05 * diagonal)
      tie_node(pr.hist, tie, k, pr.gap[k]);
  }
}

// IGNORE 1 and 2: a node that penetrates at t = 0 keeps that depth as its tolerance (the law
// sees gap 0 there), so the penalty acts only on deeper penetration and nothing is pushed out;
// the tolerance shrinks as the node comes out (measure()). IGNORE 2 lists each node with the
// position that would have cleared it (moved out along the contact normal).
void track_initial_penetrations(PassRuntime& pr, const double* packed, const core::Model& model,
                                std::vector<std::string>& warnings) {
  const core::ContactPass& cp = *pr.pass;
  std::size_t count = 0, listed = 0;
  double deepest = 0.0;
  for (std::size_t k = 0; k < cp.slave_count(); ++k) {
    if (pr.seg[k] < 0 || pr.gap[k] >= 0.0)
      continue;
    const double g = pr.gap[k];
    pr.arrival_depth[k] = g;
    pr.gap[k] = 0.0;
    ++count;
    deepest = std::min(deepest, g);
    if (pr.iface->ignore == 2 && listed < 50) {
      ++listed;
      const core::Index node = cp.slave_nodes[k];
      const double* p = at(packed, node);
      const double* n = &pr.frame[9 * k];  // towards the slave's side
      std::ostringstream os;
      os << pr.iface->keyword << " " << pr.iface->id << ": node "
         << model.node_id[static_cast<std::size_t>(node)] << " penetrates " << -g << " at (" << p[0]
         << ", " << p[1] << ", " << p[2] << "); clear at (" << p[0] - g * n[0] << ", "
         << p[1] - g * n[1] << ", " << p[2] - g * n[2] << "): tracked (IGNORE 2)";
      warnings.push_back(os.str());
    }
  }
  if (count > 0) {
    std::ostringstream os;
    os << pr.iface->keyword << " " << pr.iface->id << ": " << count
       << " slave nodes penetrate at t = 0 (deepest " << -deepest << "): tracked ("
       << (pr.iface->ignore == 0 ? std::string("IGNORE 0 could not move them clear")
                                 : "IGNORE " + std::to_string(pr.iface->ignore))
       << "), the penalty acts only beyond that depth, which shrinks as they come out";
    if (listed < count && pr.iface->ignore == 2)
      os << " (" << listed << " listed)";
    warnings.push_back(os.str());
  }
}

void ContactSet::start(const double* packed, bool track_leftovers) {
  for (auto& pp : passes_) {
    PassRuntime& pr = *pp;
    init_nodal_normals(pr, packed);
    search(pr, packed, mass_, rigid_, rot_, tssfac_);
    ++searches_;
    const std::size_t ns = pr.pass->slave_count();
    measure(pr, 0.0, packed, nullptr, mass_, rigid_, rot_);
    // IGNORE 0: setup moved the penetrating nodes out (setup::build_contacts); what it could
    // not clear (coplanar flanges of two parts, each moved into the other's band) is tracked
    // as IGNORE 1 does: pushed out, it gave the model energy from nowhere (the crush box deck:
    // 18 nodes, 156 J at once). A cohesive or tiebreak interface bonds instead.
    if (pr.iface->ignore > 0 || (track_leftovers && pr.iface->leftovers_tracked &&
                                 !pr.iface->cohesive && !pr.iface->tiebreak.enabled()))
      track_initial_penetrations(pr, packed, model_, warnings_);
    pr.law.initialize_batch(ns, pr.gap.data(), pr.hist);
    if (pr.iface->tiebreak.enabled())
      tie_initial_contacts(pr, packed);
    // Initial penetrations of nodes that are not bonded: the penalty will push them out in
    // the first cycles (a jolt the user should know about).
    std::size_t count = 0;
    double deepest = 0.0;
    core::Index where = -1;
    for (std::size_t k = 0; k < ns; ++k) {
      // Round-off of nodes placed on the surface (or moved onto it, IGNORE = 0) is no
      // penetration.
      if (pr.seg[k] < 0 || pr.gap[k] >= -1e-9 * pr.margin)
        continue;
      if (static_cast<law::NodeState>(pr.hist.state[k]) == law::NodeState::contact && pr.bonds &&
          pr.law.parameters().bond_tol >= -pr.gap[k])
        continue;  // bonded at t = 0 within BOND_TOL
      if (!pr.tie_state.empty() && static_cast<TieState>(pr.tie_state[k]) == TieState::tied)
        continue;  // tied where it is
      ++count;
      if (pr.gap[k] < deepest) {
        deepest = pr.gap[k];
        where = pr.pass->slave_nodes[k];
      }
    }
    if (count > 0) {
      std::ostringstream os;
      os << pr.iface->keyword << " " << pr.iface->id << ": " << count
         << " slave nodes penetrate at t = 0 (deepest " << -deepest << " at node "
         << model_.node_id[static_cast<std::size_t>(where)] << ")";
      warnings_.push_back(os.str());
    }
  }
}

void ContactSet::apply(double t, double dt, const double* packed, const double* temperature,
                       double* fx, double* fy, double* fz) {
  for (auto& pp : passes_) {
    PassRuntime& pr = *pp;
    const core::ContactPass& cp = *pr.pass;
    const std::size_t ns = cp.slave_count();
    if (t < pr.iface->birth || t > pr.iface->death) {
      pr.resultant = {0.0, 0.0, 0.0};
      pr.master_resultant = {0.0, 0.0, 0.0};
      std::fill(pr.prev_seg.begin(), pr.prev_seg.end(), -1);
      pr.dt_last = 0.0;
      // An interface that is not there does not set the step; it searches (and votes) anew
      // once it is.
      pr.dt_vote = kInf;
      pr.searched = false;
      continue;
    }
    core::Stopwatch clock;
    if (cp.offsets_follow_thickness && !shell_thickness_.empty())
      follow_thickness(pr);
    // Re-search once the contact nodes moved far enough to bring a slave node near a segment
    // outside its candidate list (or at the deck's fixed interval).
    ++pr.cycles_since_search;
    double moved = 0.0;
    const std::size_t nt = pr.tracked_nodes.size();
#pragma omp parallel for schedule(static) reduction(max : moved) if (nt > kLightLoop)
    for (long lt = 0; lt < static_cast<long>(nt); ++lt) {
      const auto i = static_cast<std::size_t>(lt);
      const double* p = at(packed, pr.tracked_nodes[i]);
      const double dx = p[0] - pr.tracked_ref[3 * i], dy = p[1] - pr.tracked_ref[3 * i + 1],
                   dz = p[2] - pr.tracked_ref[3 * i + 2];
      moved = std::max(moved, dx * dx + dy * dy + dz * dz);
    }
    const int interval = pr.iface->search_interval;
    if (!pr.searched || 2.0 * std::sqrt(moved) >= pr.margin ||
        (interval > 0 && pr.cycles_since_search >= interval)) {
      search(pr, packed, mass_, rigid_, rot_, tssfac_);
      ++searches_;
    }
    pr.seconds[0] += clock.lap();

    measure(pr, dt, packed, temperature, mass_, rigid_, rot_);
    pr.measured = true;
    if (!pr.tie_state.empty()) {
      // A tied node that lost its segment (the master's edge passed it) lets go: the energy its
      // springs held is released.
      for (std::size_t k = 0; k < ns; ++k) {
        if (pr.seg[k] >= 0 || static_cast<TieState>(pr.tie_state[k]) != TieState::tied)
          continue;
        pr.tie_state[k] = static_cast<std::int8_t>(TieState::failed);
        pr.hist.e_damage[k] += pr.stored[k];
        pr.hist.damping[k] = 0.0;
        pr.hist.state[k] = static_cast<std::int32_t>(law::NodeState::detached);
        pr.hist.beta[k] = 0.0;
        pr.hist.slip_x[k] = pr.hist.slip_y[k] = 0.0;
      }
    }
    pr.seconds[1] += clock.lap();
    law::BatchInput in;
    in.count = ns;
    in.gap = pr.gap.data();
    in.slip_x = pr.slip_x.data();
    in.slip_y = pr.slip_y.data();
    in.temperature = pr.temperature.data();
    in.k_normal = pr.k_normal.data();
    in.k_tangent = pr.k_tangent.data();
    in.area = cp.slave_area.data();
    in.mass = pr.m_eff.data();
    in.dt = dt;
    // The law is immutable and every node's update independent: chunks of the batch run in
    // parallel (same arithmetic per node, so the same bits for any thread count).
    constexpr std::size_t kLawChunk = 4096;
    const std::size_t chunks = (ns + kLawChunk - 1) / kLawChunk;
#pragma omp parallel for schedule(static) if (chunks > 1)
    for (long lc = 0; lc < static_cast<long>(chunks); ++lc) {
      const std::size_t b = static_cast<std::size_t>(lc) * kLawChunk;
      const std::size_t e = std::min(ns, b + kLawChunk);
      law::BatchInput ci = in;
      ci.count = e - b;
      for (const double** a : {&ci.gap, &ci.slip_x, &ci.slip_y, &ci.temperature, &ci.k_normal,
                               &ci.k_tangent, &ci.area, &ci.mass})
        *a += b;
      law::BatchHistory ch = pr.hist;
      ch.state += b;
      for (double** a :
           {&ch.beta, &ch.gap, &ch.slip_x, &ch.slip_y, &ch.opening_x, &ch.opening_y, &ch.e_damage,
            &ch.e_viscous, &ch.e_friction, &ch.e_damping, &ch.e_healing, &ch.damping})
        *a += b;
      const law::BatchOutput co{pr.pressure.data() + b, pr.tau_x.data() + b, pr.tau_y.data() + b,
                                pr.stored.data() + b};
      if (pr.tie_state.empty()) {
        pr.law.update_batch(ci, ch, co);
      } else {
        const TieArrays tie = pr.ties();
        tiebreak_update(pr.iface->tiebreak, pr.law, ci, ch, {tie.state + b, tie.gap0 + b}, co);
      }
    }

    pr.seconds[2] += clock.lap();
    // Forces from the tractions, and the second half of the step's work.
#pragma omp parallel for schedule(static) if (ns > kHeavyLoop)
    for (long lk = 0; lk < static_cast<long>(ns); ++lk) {
      const auto k = static_cast<std::size_t>(lk);
      double* f = &pr.force[3 * k];
      const core::Index s = pr.seg[k];
      pr.end_power[k] = 0.0;
      pr.surface_part[k] -= 0.5 * pr.pressure[k] * cp.slave_area[k] * pr.gap_jump[k];
      if (s < 0) {
        f[0] = f[1] = f[2] = 0.0;
        continue;
      }
      const double* fr = &pr.frame[9 * k];
      const double a = cp.slave_area[k];
      const double pn = pr.pressure[k] * a, t1 = pr.tau_x[k] * a, t2 = pr.tau_y[k] * a;
      for (int c = 0; c < 3; ++c)
        f[c] = pn * fr[c] + t1 * fr[3 + c] + t2 * fr[6 + c];
      if (f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0)
        continue;
      double du[3];
      relative_velocity(pr, k, s, &pr.shape[4 * k], &pr.rs[3 * k], pr.side[k], fr, packed, rot_,
                        du);
      pr.end_power[k] = -(f[0] * du[0] + f[1] * du[1] + f[2] * du[2]);
      pr.work_part[k] += 0.5 * dt * pr.end_power[k];
    }
    pr.dt_last = dt;
    pr.work += chunked_sum(ns, pr.chunk_sums, [&](std::size_t k) { return pr.work_part[k]; });
    pr.surface += chunked_sum(ns, pr.chunk_sums, [&](std::size_t k) { return pr.surface_part[k]; });

    // Scatter in slave order: each node receives its contributions in the same order for any
    // number of threads.
    std::array<double, 3> r{}, rm{};
    const double sign = cp.slave_side_sign;
    for (std::size_t k = 0; k < ns; ++k) {
      const core::Index s = pr.seg[k];
      pr.prev_seg[k] = s;
      if (s < 0)
        continue;
      const double* f = &pr.force[3 * k];
      if (f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0) {
        pr.prev_seg[k] = -1;
        continue;
      }
      PLYFORM_INVARIANT(std::isfinite(f[0] + f[1] + f[2]), "a finite contact force");
      PLYFORM_INVARIANT(static_cast<std::size_t>(s) < cp.segment_count(), "a segment in range");
      const auto sn = static_cast<std::size_t>(cp.slave_nodes[k]);
      fx[sn] -= f[0];
      fy[sn] -= f[1];
      fz[sn] -= f[2];
      // The force acts on the surface points: on nodes with rotations, the couples r x f of its
      // tangential part (the part relative_velocity() lets the rotations move). The engine's
      // moment arrays are internal moments, like its force arrays.
      const bool spin = rot_.inertia != nullptr;
      const double* fn = &pr.frame[9 * k];
      const double f_n = f[0] * fn[0] + f[1] * fn[1] + f[2] * fn[2];
      const double ft[3] = {f[0] - f_n * fn[0], f[1] - f_n * fn[1], f[2] - f_n * fn[2]};
      if (spin && rot_.inertia[sn] > 0.0) {
        const double* rs = &pr.rs[3 * k];
        rot_.mx[sn] -= rs[1] * ft[2] - rs[2] * ft[1];
        rot_.my[sn] -= rs[2] * ft[0] - rs[0] * ft[2];
        rot_.mz[sn] -= rs[0] * ft[1] - rs[1] * ft[0];
      }
      const auto su = static_cast<std::size_t>(s);
      const core::Index* q = &cp.segments[4 * su];
      const int nodes = q[2] == q[3] ? 3 : 4;
      const double om = pr.seg_offset[su];
      for (int j = 0; j < nodes; ++j) {
        const double nj = pr.shape[4 * k + j];
        const auto m = static_cast<std::size_t>(q[j]);
        fx[m] += nj * f[0];
        fy[m] += nj * f[1];
        fz[m] += nj * f[2];
        if (spin && om > 0.0 && rot_.inertia[m] > 0.0) {
          double rm_[3];
          corner_offset(pr, su, j, pr.side[k], rm_);
          rot_.mx[m] += nj * (rm_[1] * ft[2] - rm_[2] * ft[1]);
          rot_.my[m] += nj * (rm_[2] * ft[0] - rm_[0] * ft[2]);
          rot_.mz[m] += nj * (rm_[0] * ft[1] - rm_[1] * ft[0]);
        }
        for (int c = 0; c < 3; ++c)
          rm[static_cast<std::size_t>(c)] -= sign * nj * f[c];
      }
      for (int c = 0; c < 3; ++c)
        r[static_cast<std::size_t>(c)] += sign * f[c];
    }
    pr.resultant = r;
    pr.master_resultant = rm;
    std::swap(pr.prev_force, pr.force);
    std::swap(pr.prev_rs, pr.rs);
    // `shape` then holds older values: measure() rewrites it for every located node, and
    // only located nodes read it. Until the next apply(), the projection on pr.seg[k] is in
    // prev_shape (what the heat between cycles reads: located_shape()).
    std::swap(pr.prev_shape, pr.shape);
    pr.seconds[3] += clock.lap();
  }
}

std::vector<InterfaceTiming> ContactSet::timing() const {
  std::vector<InterfaceTiming> out;
  const core::ContactInterface* last = nullptr;
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    if (pr.iface != last) {
      out.push_back({});
      out.back().index = static_cast<std::size_t>(pr.iface - model_.contacts.data());
      out.back().id = pr.iface->id;
      last = pr.iface;
    }
    InterfaceTiming& r = out.back();
    r.search += pr.seconds[0];
    r.projection += pr.seconds[1];
    r.law += pr.seconds[2];
    r.forces += pr.seconds[3];
  }
  return out;
}

std::vector<InterfaceReport> ContactSet::report() const {
  std::vector<InterfaceReport> out;
  const core::ContactInterface* last = nullptr;
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    if (pr.iface != last) {
      out.push_back({});
      out.back().id = pr.iface->id;
      last = pr.iface;
    }
    InterfaceReport& r = out.back();
    for (std::size_t c = 0; c < 3; ++c) {
      r.force[c] += pr.resultant[c];
      r.master_force[c] += pr.master_resultant[c];
    }
    r.work += pr.work;
    r.surface += pr.surface;
    const law::BatchHistory& h = pr.hist;
    const std::size_t ns = pr.pass->slave_count();
    for (std::size_t k = 0; k < ns; ++k) {
      r.stored += pr.stored[k];
      r.damage += h.e_damage[k];
      r.viscous += h.e_viscous[k];
      r.friction += h.e_friction[k];
      r.damping += h.e_damping[k];
      r.healing += h.e_healing[k];
      if (pr.guard)
        continue;  // the counts are the interface's points, the first pass's nodes
      const auto st = static_cast<law::NodeState>(h.state[k]);
      if (st == law::NodeState::contact && pr.pressure[k] > 0.0)
        ++r.in_contact;
      if (st == law::NodeState::separating)
        ++r.bonded;
    }
  }
  return out;
}

void ContactSet::cohesive_results(std::vector<SlaveNodeResult>& out) const {
  out.clear();
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    // A tiebreak's history is the law's too: beta 1 while a node is tied, 0 once it failed.
    if ((!pr.bonds && pr.iface->tiebreak.option == 0) || pr.guard)
      continue;
    const std::size_t ns = pr.pass->slave_count();
    for (std::size_t k = 0; k < ns; ++k) {
      SlaveNodeResult r;
      r.node = pr.pass->slave_nodes[k];
      r.interface = pr.iface->id;
      r.state = static_cast<law::NodeState>(pr.hist.state[k]);
      r.gap = pr.seg[k] >= 0 ? pr.gap[k] : std::numeric_limits<double>::quiet_NaN();
      r.pressure = pr.pressure[k];
      r.tau = std::hypot(pr.tau_x[k], pr.tau_y[k]);
      r.beta = pr.hist.beta[k];
      out.push_back(r);
    }
  }
}

namespace {

// The shape functions of slave k's projection on its segment pr.seg[k], as the heat reads
// them: the engine takes a thermal step between cycles, after the elements and before the
// contact (Simulation::State::cycle_once), so the last projection is that of the last
// apply(), which swapped it into prev_shape at the end of the pass (the arrays are swapped
// for the next cycle's warm start and first half of the work). Before the first apply() of a
// pass (the thermal step of the first cycle, a thermal-only run, a pass not yet born) the
// projection is start()'s, which measures without swapping: in shape. `measured` is set by
// apply() only, in the same pass as the swap, and is in the checkpoint with both arrays.
const double* located_shape(const PassRuntime& pr, std::size_t k) {
  return pr.measured ? &pr.prev_shape[4 * k] : &pr.shape[4 * k];
}

}  // namespace

void ContactSet::heat_links(const double* packed, std::vector<core::ContactHeatLink>& out) const {
  out.clear();
  // A face's area vector: half the cross product of its diagonals (a triangle, N3 = N4,
  // included), from the packed positions (x y z vx vy vz per node).
  const auto area_vector = [&](const core::Index* f) {
    const auto x = [&](core::Index n, int c) {
      return packed[6 * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)];
    };
    double d1[3], d2[3];
    for (int c = 0; c < 3; ++c) {
      d1[c] = x(f[2], c) - x(f[0], c);
      d2[c] = x(f[3], c) - x(f[1], c);
    }
    return std::array<double, 3>{0.5 * (d1[1] * d2[2] - d1[2] * d2[1]),
                                 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                                 0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
  };
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    const core::ContactHeat& heat = pr.iface->heat;
    if (!heat.enabled)
      continue;
    // A one-way link (ALGO 1) keeps the deck's master side: only the first pass (the deck's
    // slave against its master) carries heat, with the whole slave area.
    if ((heat.one_way && pr.pass != &pr.iface->passes.front()) || pr.guard)
      continue;
    // A guard pass (core::ContactPass::guard) carries no heat: the first pass has the area.
    const auto heat_passes = std::count_if(pr.iface->passes.begin(), pr.iface->passes.end(),
                                           [](const core::ContactPass& p) { return !p.guard; });
    const double share = heat.one_way ? 1.0 : 1.0 / static_cast<double>(heat_passes);
    const std::size_t ns = pr.pass->slave_count();
    for (std::size_t k = 0; k < ns; ++k) {
      const core::Index sg = pr.seg[k];
      if (sg < 0 || pr.gap[k] > heat.lmax)
        continue;
      core::ContactHeatLink l;
      l.slave = pr.pass->slave_nodes[k];
      const double* w = located_shape(pr, k);
      for (std::size_t j = 0; j < 4; ++j) {
        l.master[j] = pr.pass->segments[4 * static_cast<std::size_t>(sg) + j];
        l.weight[j] = w[j];
      }
      // The area the node presents to its segment: its share of each face around it,
      // projected on the segment's plane (a solid's side faces, at right angles to the
      // interface, carry no heat across it). A node-set slave has no faces: its area.
      const core::ContactPass& cp = *pr.pass;
      double area = cp.slave_area[k];
      if (!cp.slave_face_start.empty()) {
        const std::array<double, 3> nseg =
            area_vector(&cp.segments[4 * static_cast<std::size_t>(sg)]);
        const double ln = std::sqrt(nseg[0] * nseg[0] + nseg[1] * nseg[1] + nseg[2] * nseg[2]);
        area = 0.0;
        for (std::size_t e = cp.slave_face_start[k]; e < cp.slave_face_start[k + 1]; ++e) {
          const core::Index* f =
              &cp.slave_faces[4 * static_cast<std::size_t>(cp.slave_face_index[e])];
          const std::array<double, 3> af = area_vector(f);
          const double corners = f[2] == f[3] ? 3.0 : 4.0;
          if (ln > 0.0)
            area += std::abs(af[0] * nseg[0] + af[1] * nseg[1] + af[2] * nseg[2]) / ln / corners;
        }
      }
      l.area = share * area;
      l.gap = pr.gap[k];
      l.pressure = pr.pressure[k];
      l.heat = &heat;
      out.push_back(l);
    }
  }
}

void ContactSet::take_friction_heat(std::vector<double>& energy) {
  for (const auto& pp : passes_) {
    PassRuntime& pr = *pp;
    const core::ContactHeat& heat = pr.iface->heat;
    if (!heat.enabled || !heat.friction_heat || pr.guard)
      continue;
    // The swapped pass of a two-way contact has the deck's master nodes as its slaves.
    const double to_slave = pr.pass->slave_side_sign > 0 ? heat.ftosa : 1.0 - heat.ftosa;
    const std::size_t ns = pr.pass->slave_count();
    for (std::size_t k = 0; k < ns; ++k) {
      const double d = pr.hist.e_friction[k] - pr.friction_heated[k];
      if (d == 0.0)
        continue;
      pr.friction_heated[k] = pr.hist.e_friction[k];
      const core::Index sg = pr.seg[k];
      const double slave_part = sg >= 0 ? to_slave : 1.0;
      energy[static_cast<std::size_t>(pr.pass->slave_nodes[k])] += slave_part * d;
      if (sg < 0)
        continue;
      const double* w = located_shape(pr, k);
      for (std::size_t j = 0; j < 4; ++j)
        energy[static_cast<std::size_t>(pr.pass->segments[4 * static_cast<std::size_t>(sg) + j])] +=
            (1.0 - slave_part) * d * w[j];
    }
  }
}

void ContactSet::initial_penetrations(std::vector<InitialPenetration>& out) const {
  out.clear();
  for (const auto& pp : passes_) {
    const PassRuntime& pr = *pp;
    if (pr.iface->ignore != 0 || pr.iface->cohesive)
      continue;
    const auto index = static_cast<std::size_t>(pr.iface - model_.contacts.data());
    const auto is_rigid = [&](core::Index v) {
      return rigid_ != nullptr && rigid_[static_cast<std::size_t>(v)] != 0;
    };
    for (std::size_t k = 0; k < pr.pass->slave_count(); ++k) {
      const core::Index node = pr.pass->slave_nodes[k];
      if (pr.seg[k] < 0 || !(pr.gap[k] < 0.0))
        continue;
      if (!pr.tie_state.empty() && static_cast<TieState>(pr.tie_state[k]) == TieState::tied)
        continue;
      const double* n = &pr.frame[9 * k];  // towards the slave's side
      const double d = -pr.gap[k];
      if (!is_rigid(node)) {
        out.push_back({node, index, d, {d * n[0], d * n[1], d * n[2]}});
        continue;
      }
      // A rigid node (a tool's) in a deformable surface: that surface's nodes move away.
      const core::Index* q = &pr.pass->segments[4 * static_cast<std::size_t>(pr.seg[k])];
      for (int j = 0; j < (q[2] == q[3] ? 3 : 4); ++j) {
        if (!is_rigid(q[j]))
          out.push_back({q[j], index, d, {-d * n[0], -d * n[1], -d * n[2]}});
      }
    }
  }
}

void ContactSet::visit_state(core::StateArchive& a) {
  a.value("searches", searches_);
  for (std::size_t p = 0; p < passes_.size(); ++p) {
    const auto scope = a.scope("pass/" + std::to_string(p));
    PassRuntime& pr = *passes_[p];
    // The law's history per slave node, in place (the batch view points into it).
    {
      const std::size_t ns = pr.history.size();
      const law::BatchHistory& h = pr.hist;
      a.fixed("law/state", std::span<std::int32_t>(h.state, ns));
      for (auto [name, v] : {std::pair{"beta", h.beta},
                             {"gap", h.gap},
                             {"slip_x", h.slip_x},
                             {"slip_y", h.slip_y},
                             {"opening_x", h.opening_x},
                             {"opening_y", h.opening_y},
                             {"e_damage", h.e_damage},
                             {"e_viscous", h.e_viscous},
                             {"e_friction", h.e_friction},
                             {"e_damping", h.e_damping},
                             {"e_healing", h.e_healing},
                             {"damping", h.damping}}) {
        a.fixed(std::string("law/") + name, std::span<double>(v, ns));
      }
    }
    a.fixed("friction_heated", std::span<double>(pr.friction_heated));
    a.fixed("tie_state", std::span<std::int8_t>(pr.tie_state));
    a.fixed("tie_gap0", std::span<double>(pr.tie_gap0));
    a.array("cand_start", pr.cand_start);
    a.array("cand", pr.cand);
    a.array("seg_radius", pr.seg_radius);
    a.array("tracked_ref", pr.tracked_ref);
    a.value("cycles_since_search", pr.cycles_since_search);
    a.value("searched", pr.searched);
    a.value("dt_vote", pr.dt_vote);
    a.value("measured", pr.measured);
    a.value("work", pr.work);
    a.value("surface", pr.surface);
    a.value("dt_last", pr.dt_last);
    a.value("resultant", pr.resultant);
    a.value("master_resultant", pr.master_resultant);
    a.value("seg_normal_current", pr.seg_normal_current);
    a.array("seg", pr.seg);
    a.array("prev_seg", pr.prev_seg);
    a.array("side", pr.side);
    for (auto [name, v] : {std::pair{"slave_offset", &pr.slave_offset},
                           {"seg_offset", &pr.seg_offset},
                           {"shape", &pr.shape},
                           {"prev_shape", &pr.prev_shape},
                           {"frame", &pr.frame},
                           {"gap", &pr.gap},
                           {"slip_x", &pr.slip_x},
                           {"slip_y", &pr.slip_y},
                           {"temperature", &pr.temperature},
                           {"k_normal", &pr.k_normal},
                           {"k_tangent", &pr.k_tangent},
                           {"m_eff", &pr.m_eff},
                           {"arrival_depth", &pr.arrival_depth},
                           {"pressure", &pr.pressure},
                           {"tau_x", &pr.tau_x},
                           {"tau_y", &pr.tau_y},
                           {"stored", &pr.stored},
                           {"force", &pr.force},
                           {"prev_force", &pr.prev_force},
                           {"work_part", &pr.work_part},
                           {"gap_jump", &pr.gap_jump},
                           {"surface_part", &pr.surface_part},
                           {"end_power", &pr.end_power},
                           {"master_normal", &pr.master_normal},
                           {"seg_normal", &pr.seg_normal},
                           {"slave_normal", &pr.slave_normal},
                           {"slave_face_normal", &pr.slave_face_normal},
                           {"rs", &pr.rs},
                           {"prev_rs", &pr.prev_rs}}) {
      a.array(name, *v);
    }
  }
}

}  // namespace plyform::contact
