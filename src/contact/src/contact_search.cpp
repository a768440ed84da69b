#include "contact_search.hpp"

#include <algorithm>
#include <cmath>

#include "penalty.hpp"

namespace plyform::contact {

namespace {

// Self contact: each slave node's candidates less the segments it touches through the mesh
// (both lists sorted: one merge), and rigid segments for a rigid node. Compacts the CSR in place.
void drop_own_segments(PassRuntime& pr, const unsigned char* rigid) {
  const core::ContactPass& cp = *pr.pass;
  const std::size_t ns = cp.slave_count();
  const auto is_rigid = [&](core::Index n) {
    return rigid != nullptr && rigid[static_cast<std::size_t>(n)] != 0;
  };
  std::size_t out = 0;
  std::size_t begin = pr.st.cand_start[0];
  for (std::size_t k = 0; k < ns; ++k) {
    const std::size_t end = pr.st.cand_start[k + 1];
    const bool rigid_node = cp.skip_rigid_pairs && is_rigid(cp.slave_nodes[k]);
    std::size_t e = cp.exclude_start[k];
    const std::size_t e_end = cp.exclude_start[k + 1];
    pr.st.cand_start[k] = out;
    for (std::size_t c = begin; c < end; ++c) {
      const core::Index s = pr.st.cand[c];
      while (e < e_end && cp.exclude[e] < s)
        ++e;
      if (e < e_end && cp.exclude[e] == s)
        continue;
      if (rigid_node && is_rigid(cp.segments[4 * static_cast<std::size_t>(s)]))
        continue;
      pr.st.cand[out++] = s;
    }
    begin = end;
  }
  pr.st.cand_start[ns] = out;
  pr.st.cand.resize(out);
}

}  // namespace

void search(PassRuntime& pr, const double* packed, const std::vector<double>& mass,
            const unsigned char* rigid, const Rotations& rot, double tssfac) {
  const core::ContactPass& cp = *pr.pass;
  if (cp.offsets_follow_thickness) {
    double max_slave_offset = 0.0;
    for (double o : pr.st.slave_offset)
      max_slave_offset = std::max(max_slave_offset, o);
    for (std::size_t s = 0; s < pr.st.seg_radius.size(); ++s)
      pr.st.seg_radius[s] = pr.st.seg_offset[s] + max_slave_offset + pr.capture + pr.margin;
  }
  pr.grid.build(cp.segments, packed, kStride, pr.st.seg_radius);
  pr.grid.query(cp.slave_nodes, packed, kStride, pr.st.cand_start, pr.st.cand);
  if (!cp.exclude_start.empty())
    drop_own_segments(pr, rigid);
  for (std::size_t t = 0; t < pr.tracked_nodes.size(); ++t) {
    const double* p = at(packed, pr.tracked_nodes[t]);
    pr.st.tracked_ref[3 * t] = p[0];
    pr.st.tracked_ref[3 * t + 1] = p[1];
    pr.st.tracked_ref[3 * t + 2] = p[2];
  }
  pr.st.cycles_since_search = 0;
  pr.st.searched = true;
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
    if (pr.st.cand_start[k] == pr.st.cand_start[k + 1])
      continue;
    const double ms = node_mass(mass, rigid, cp.slave_nodes[k]);
    const double turn_s = turn(cp.slave_nodes[k], pr.st.slave_offset[k]);
    for (std::size_t c = pr.st.cand_start[k]; c < pr.st.cand_start[k + 1]; ++c) {
      const core::Index s = pr.st.cand[c];
      const auto su = static_cast<std::size_t>(s);
      double mm = kInf, turn_m = 0.0;
      for (int j = 0; j < 4; ++j) {
        const core::Index m = cp.segments[4 * su + static_cast<std::size_t>(j)];
        mm = std::min(mm, node_mass(mass, rigid, m));
        turn_m = std::max(turn_m, turn(m, pr.st.seg_offset[su]));
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
  pr.st.dt_vote = vote;
}

}  // namespace plyform::contact
