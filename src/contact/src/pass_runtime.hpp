#pragma once
// The runtime state of one contact pass (PassRuntime) and what every job of the pass shares:
// the packed node layout, the loop sizes worth a thread team, the deterministic chunked sum.
// Internal to src/contact: each job has its own file (docs/architecture.md).

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "plyform/contact/bucket_search.hpp"
#include "plyform/contact/contact_set.hpp"
#include "plyform/contact/tiebreak.hpp"
#include "plyform/core/state_archive.hpp"
#include "plyform/law/law.hpp"

namespace plyform::contact {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kStride = 6;  // packed node data: x y z vx vy vz

// Below these counts a loop runs on the calling thread alone: a parallel region's start and
// join cost a few microseconds on a busy machine, more than a small loop's work. Light: a
// loop of a few arithmetic operations per item (normals, folds, motion since the search);
// heavy: a slave node's projection and kinematics, or its forces. Each item's arithmetic is
// the same either way (the same bits for any thread count).
constexpr std::size_t kLightLoop = 1024;
constexpr std::size_t kHeavyLoop = 256;

// The packed node data of `node` (positions, then velocities).
inline const double* at(const double* packed, core::Index node) {
  return packed + kStride * static_cast<std::size_t>(node);
}

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

/// What changes during a pass's run, for the pass and per slave node: the search's candidates
/// and reach, the segment and projection of each node, its gap, slip, frame, penalty and
/// tractions, the forces and the books, the nodal normals, the offsets, the ties. `visit`
/// saves and restores all of it (the checkpoint, contact_state.cpp); with the law's history
/// (PassRuntime::history) it is the pass's whole state.
struct PassState {
  // The search: each slave node's candidate segments (CSR), the segments' reach, the tracked
  // nodes' positions at the last search.
  std::vector<std::size_t> cand_start;
  std::vector<core::Index> cand;
  std::vector<double> seg_radius;
  std::vector<double> tracked_ref;
  long cycles_since_search = 0;
  bool searched = false;
  double dt_vote = kInf;
  // Contact half-thicknesses now (they follow the shells' thickness when the pass says so).
  std::vector<double> slave_offset, seg_offset;
  // Per master node, the mean of its segments' offsets: the offset surface's corners sit there,
  // so that two segments of different thickness meet (update_node_offsets).
  std::vector<double> node_offset;
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
  double work = 0.0;
  std::array<double, 3> resultant{}, master_resultant{};
  // The master's nodal normals, recomputed every cycle from the current positions (the mean
  // of the normals of the segments around each node, each turned by its fixed sign to agree
  // with the node's normal at t = 0). They are geometry, not the shells' nodal rotations: a
  // rotation of a one-point shell's node is held against its element's mid-surface only by the
  // weak rotational hourglass control, and a surface that followed it would let a contact
  // pressure tip it further (the pressure at the offset point makes a couple that grows with
  // the tilt), which an explicit run cannot survive under forming pressures.
  std::vector<double> master_normal;  // 3 per master node
  std::vector<double> seg_normal;     // 3 per segment, current
  bool seg_normal_current = false;    // seg_normal updated for this cycle's positions
  // The slave nodes' normals, the same way from the faces around them (none for a node set's
  // node without faces: its offset then follows the contact normal).
  std::vector<double> slave_normal;       // 3 per slave node
  std::vector<double> slave_face_normal;  // 3 per slave face, current
  std::vector<double> rs, prev_rs;        // 3 per slave: its surface point minus the node
  std::vector<double> friction_heated;    // per slave: friction dissipation turned to heat
  // The _TIEBREAK option: per slave node its tie state and rest gap (empty without it).
  std::vector<std::int8_t> tie_state;
  std::vector<double> tie_gap0;
  // Resting slave nodes (resting_nodes.hpp): per node whether it rests, the cycles before it is
  // tried again when it was too close to rest, the margin its motion and the surfaces' may spend
  // before it wakes, and where it came to rest (3 each).
  std::vector<std::uint8_t> resting, rest_wait;
  std::vector<double> rest_room, rest_from;

  /// Saves or restores every member (contact_state.cpp).
  void visit(core::StateArchive& a);
};

/// One pass at run time: its law and the law's history, the topology the set-up fixed, the
/// run's state (`st`), and the scratch of a cycle.
struct PassRuntime {
  const core::ContactInterface* iface = nullptr;
  const core::ContactPass* pass = nullptr;
  // Wall seconds in apply(): search, projection, law, forces (InterfaceTiming).
  double seconds[4] = {0.0, 0.0, 0.0, 0.0};
  law::Law law;
  law::HistoryStore history;
  law::BatchHistory hist;
  PassState st;
  // Over several MPI ranks: 1 for the slave nodes this rank handles (null: all of them).
  const unsigned char* mine = nullptr;
  std::size_t own_slaves = 0;  // how many of its slave nodes this rank handles

  // Fixed by the set-up (and start(), for the normals' signs).
  double margin = 0.0;
  double capture = 0.0;  // the cohesive band
  bool bonds = false;    // the pass carries the cohesive law (not a plain contact, not a guard)
  bool guard = false;    // core::ContactPass::guard
  double far_gap = 0.0;  // the gap given to the law for a node with no segment in reach
  double dt0 = 0.0;
  std::vector<core::Index> tracked_nodes;     // slave and master nodes, for motion since search
  std::vector<unsigned char> tracked_master;  // per tracked node: 1 for a master's node
  /// Segments sharing a corner with each segment (CSR).
  std::vector<std::size_t> nb_start;
  std::vector<core::Index> nb;
  // Offset surfaces of shell layers: the master surface is the mid-surface moved by its offset
  // along the nodal normals (continuous from segment to segment), a slave node's surface point
  // its position moved by its offset along its own nodal normal. Nodal normals are the mean of
  // the faces around the node, each turned to agree with the node's first face.
  bool master_offsets = false;              // some segment has a non-zero offset
  std::vector<core::Index> master_nodes;    // the distinct segment nodes
  std::vector<core::Index> corner;          // per segment corner: index into master_nodes
  std::vector<std::size_t> node_seg_start;  // CSR master node -> segments around it
  std::vector<core::Index> node_seg;
  std::vector<signed char> corner_sign;      // per segment corner: its nodal normal against it
  std::vector<signed char> node_seg_sign;    // per node_seg entry: the same sign
  std::vector<signed char> slave_face_sign;  // per slave_face_index entry
  bool slave_face_normals_absent = false;    // a node set's slave side: no faces, no normals
  // Every master node is a rigid body's (a tool): its folds, once found, stay (update_folds).
  bool rigid_master = false;
  // Whether the pass lets its clear nodes rest, and the gap within which a node with no force
  // still matters to it (resting_nodes.hpp).
  bool may_rest = false;
  double rest_reach = 0.0;
  // Per model node: how many tiebreak passes hold it (ContactSet::tie_passes_at_), or null
  // when this pass does not tie.
  const std::uint8_t* ties_at = nullptr;

  // Scratch of a cycle (not in the checkpoint: each cycle or search rebuilds it).
  BucketSearch grid;
  /// Whether any neighbour of a segment rises towards a side of it this cycle (a fold:
  /// deeper_across_valley looks across it); a rigid master's once found (a restarted run finds
  /// them again).
  std::vector<unsigned char> folded;
  std::vector<double> fold_centroid, fold_normal;  // update_folds' scratch, 3 per segment
  bool folds_fixed = false;
  std::vector<double> chunk_sums;  // buffer of chunked_sum
  /// Per slave node, the cycles in a row the kinematics found it far: no segment last cycle or
  /// the one before, no candidate (at most 2); and whether they passed over it this cycle. Two
  /// such cycles wrote everything a third would (the stand-in gap, zero slip, force and books,
  /// in both halves of the double-buffered arrays), so the kinematics and the forces pass over
  /// it until it has a candidate again (measure_slaves): far from a small tool, most of a
  /// blank's nodes. Not in the checkpoint: a restarted run measures such a node twice again and
  /// writes the same values.
  std::vector<std::uint8_t> far_cycles, passed_over;
  /// The parts of the surfaces this cycle's kinematics read (surface_reads.hpp), so that only
  /// those normals, folds and centroids are computed; `all_master`, `all_slaves`: every one of
  /// that side is.
  struct SurfaceReads {
    bool all_master = true, all_slaves = true;
    long looks = 0, whole_until = 0;     // find_surface_reads() calls; lists again from this one
    std::vector<core::Index> segs;       // segments whose normal is computed (the master's)
    std::vector<core::Index> nodes;      // master nodes whose nodal normal is computed
    std::vector<core::Index> folds;      // segments whose fold is tested
    std::vector<core::Index> centroids;  // segments whose centroid is computed
    std::vector<core::Index> slaves;     // slave nodes whose normal is computed
    std::vector<core::Index> faces;      // slave faces whose normal is computed
    std::vector<core::Index> near;       // the segments the slave nodes' kinematics project on
    // Per item, the last look that listed it (a look's lists without clearing the marks).
    std::vector<std::uint32_t> near_mark, seg_mark, fold_mark, centroid_mark, node_mark, slave_mark,
        face_mark;
    std::uint32_t mark = 0;
  } reads;

  [[nodiscard]] TieArrays ties() { return {st.tie_state.data(), st.tie_gap0.data()}; }

  explicit PassRuntime(const law::Parameters& p) : law(p) {}
};

}  // namespace plyform::contact
