// Resting slave nodes (resting_nodes.hpp).
//
// A forming contact's slave side is mostly clear of its tool: the blank's nodes under the
// holder but outside its pad, those of a lower layer under a tool that presses the upper one.
// Each has candidate segments (it is within the search's reach), so the kinematics projected
// it on them every cycle, and the law and the force loop ran for a node with no force: in the
// hot deep drawing with the tools on both skins, most of those contacts' cost.
//
// The margin. At the cycle a node comes to rest, the box of each candidate segment's corners,
// grown by what can lie outside it and still be the segment's surface (the master's offset,
// twice over for a thickness that grows; MAXPAR's tolerance, twice the box's extent), is
// farther from the node than its clearance c plus the slave's offset (twice over) and the
// reach within which a node with no force still matters (LMAX). Until the next search the
// segments' corners move at most M + M0 from where they were (M: the largest motion of the
// master's nodes since the search, M0 its value when the node came to rest), the node
// |x - x0|. So while |x - x0| + M < c - M0 the node's surface point cannot reach any
// candidate's surface, and a segment that is not a candidate cannot come within its reach
// before the next search (the search's own guarantee, contact_search.cpp). A search wakes every
// node: its candidates and M start again. The master's motion and the node's own are taken
// apart: a tool at rest (the holder, the die) leaves a node its whole clearance even while the
// blank's wall runs down with the punch.
//
// Nothing changes in what the model feels: a resting node has no force either way. It comes to
// rest only after two cycles with no force (both halves of the double-buffered force arrays
// hold zeros, and its work and surface books are zero), and wakes with its last segment, which
// the kinematics takes as the start of its projection. What it leaves stale is its gap, frame
// and projection, which only a node with a force, a heat link (its last gap beyond LMAX, and it
// stays so) or a cohesive output reads; passes with a cohesive law do not rest their nodes.

#include "resting_nodes.hpp"

#include <algorithm>
#include <cmath>

namespace plyform::contact {

namespace {

// How much an offset may grow between two searches (the shells' thickness followed): twice.
constexpr double kOffsetGrowth = 2.0;
// A node comes to rest only with a margin above this share of the pass's search margin (half a
// segment): below it, the node would wake again within a few cycles, each rest costing its
// candidates' boxes.
constexpr double kMinRoom = 0.1;
// Cycles a node found too close to rest waits before it is tried again: its candidates' boxes
// cost about what its kinematics do, and a node near the tool with no force (at the pad's edge,
// under a wall it does not touch yet) would try every cycle.
constexpr std::uint8_t kRetryAfter = 16;

// The squared distance from p to the box of segment s's corners grown by its surface's reach
// beyond them.
double box_distance2(const PassRuntime& pr, core::Index s, const double* p, const double* packed,
                     double tol) {
  const auto su = static_cast<std::size_t>(s);
  const core::Index* q = &pr.pass->segments[4 * su];
  const int corners = q[2] == q[3] ? 3 : 4;
  double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
  double offset = pr.st.seg_offset[su];
  for (int j = 0; j < corners; ++j) {
    const double* x = at(packed, q[j]);
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], x[c]);
      hi[c] = std::max(hi[c], x[c]);
    }
    if (pr.master_offsets)
      offset = std::max(offset, pr.st.node_offset[static_cast<std::size_t>(
                                    pr.corner[4 * su + static_cast<std::size_t>(j)])]);
  }
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double grow = 2.0 * tol * extent + kOffsetGrowth * offset;
  double d2 = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double d = std::max({lo[c] - grow - p[c], p[c] - hi[c] - grow, 0.0});
    d2 += d * d;
  }
  return d2;
}

}  // namespace

bool may_rest(const PassRuntime& pr) {
  return !pr.bonds && !pr.guard && pr.st.tie_state.empty() && pr.iface->tiebreak.option == 0;
}

double rest_reach(const PassRuntime& pr) {
  return pr.iface->heat.enabled ? std::max(pr.iface->heat.lmax, 0.0) : 0.0;
}

std::size_t rest_or_wake(PassRuntime& pr, const double* packed, double master_moved) {
  if (!pr.may_rest || !pr.st.measured)
    return 0;
  const core::ContactPass& cp = *pr.pass;
  const std::size_t ns = cp.slave_count();
  const double tol = pr.iface->maxpar - 1.0;
  const double min_room = kMinRoom * pr.margin;
  long resting = 0;
#pragma omp parallel for schedule(static) reduction(+ : resting) if (ns > kLightLoop)
  for (long lk = 0; lk < static_cast<long>(ns); ++lk) {
    const auto k = static_cast<std::size_t>(lk);
    if (pr.mine != nullptr && pr.mine[k] == 0)
      continue;
    const double* p = at(packed, cp.slave_nodes[k]);
    const double* x0 = &pr.st.rest_from[3 * k];
    if (pr.st.resting[k] != 0) {
      const double left = pr.st.rest_room[k] - master_moved;
      const double dx = p[0] - x0[0], dy = p[1] - x0[1], dz = p[2] - x0[2];
      if (left <= 0.0 || dx * dx + dy * dy + dz * dz >= left * left)
        pr.st.resting[k] = 0;  // measured this cycle again, from its last segment
      else
        ++resting;
      continue;
    }
    const std::size_t c0 = pr.st.cand_start[k], c1 = pr.st.cand_start[k + 1];
    if (c0 == c1)
      continue;  // no candidate: far (pass_runtime.hpp), which the kinematics passes over
    if (pr.st.rest_wait[k] > 0) {
      --pr.st.rest_wait[k];
      continue;
    }
    const auto state = static_cast<law::NodeState>(pr.hist.state[k]);
    if (state != law::NodeState::approaching && state != law::NodeState::detached)
      continue;
    const double* f0 = &pr.st.force[3 * k];
    const double* f1 = &pr.st.prev_force[3 * k];
    if (f0[0] != 0.0 || f0[1] != 0.0 || f0[2] != 0.0 || f1[0] != 0.0 || f1[1] != 0.0 ||
        f1[2] != 0.0 || pr.st.pressure[k] != 0.0)
      continue;
    if (pr.st.seg[k] >= 0 && !(pr.st.gap[k] > pr.rest_reach))
      continue;  // a heat link reads its gap (contact_heat.cpp)
    double d2 = kInf;
    for (std::size_t c = c0; c < c1; ++c)
      d2 = std::min(d2, box_distance2(pr, pr.st.cand[c], p, packed, tol));
    if (pr.st.seg[k] >= 0)
      d2 = std::min(d2, box_distance2(pr, pr.st.seg[k], p, packed, tol));
    const double room =
        std::sqrt(d2) - kOffsetGrowth * pr.st.slave_offset[k] - pr.rest_reach - master_moved;
    if (!(room > min_room + master_moved)) {
      pr.st.rest_wait[k] = kRetryAfter;
      continue;
    }
    pr.st.resting[k] = 1;
    pr.st.rest_room[k] = room;
    pr.st.rest_from[3 * k] = p[0];
    pr.st.rest_from[3 * k + 1] = p[1];
    pr.st.rest_from[3 * k + 2] = p[2];
    // Its books as a measured node with no force leaves them (the sums read every node's).
    pr.st.work_part[k] = pr.st.surface_part[k] = pr.st.gap_jump[k] = 0.0;
    ++resting;
  }
  return static_cast<std::size_t>(resting);
}

}  // namespace plyform::contact
