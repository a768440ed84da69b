#include "surface_reads.hpp"

#include <algorithm>

namespace plyform::contact {

namespace {

// Cycles the lists are not tried again after a look found them to cover most of a surface.
constexpr long kWholeFor = 64;
// Above this share of a surface's items listed, the whole surface is cheaper.
constexpr double kMostOf = 0.5;

}  // namespace

void find_surface_reads(PassRuntime& pr, bool spins) {
  PassRuntime::SurfaceReads& r = pr.reads;
  ++r.looks;
  r.all_master = r.all_slaves = true;
  if (r.looks < r.whole_until)
    return;
  const core::ContactPass& cp = *pr.pass;
  const std::size_t ns = cp.slave_count();
  const std::size_t nseg = cp.segment_count();
  const std::size_t nfaces = cp.slave_faces.size() / 4;
  if (r.near_mark.size() != nseg) {
    for (auto* m : {&r.near_mark, &r.seg_mark, &r.fold_mark, &r.centroid_mark})
      m->assign(nseg, 0);
    r.node_mark.assign(pr.master_nodes.size(), 0);
    r.slave_mark.assign(ns, 0);
    r.face_mark.assign(nfaces, 0);
    r.mark = 0;
  }
  if (++r.mark == 0) {  // the marks wrapped round: start them again
    for (auto* m : {&r.near_mark, &r.seg_mark, &r.fold_mark, &r.centroid_mark, &r.node_mark,
                    &r.slave_mark, &r.face_mark})
      std::fill(m->begin(), m->end(), 0);
    r.mark = 1;
  }
  const std::uint32_t now = r.mark;
  for (auto* l : {&r.segs, &r.nodes, &r.folds, &r.centroids, &r.slaves, &r.faces, &r.near})
    l->clear();
  const auto add = [now](std::vector<std::uint32_t>& mark, std::vector<core::Index>& list,
                         core::Index i) {
    std::uint32_t& m = mark[static_cast<std::size_t>(i)];
    if (m != now) {
      m = now;
      list.push_back(i);
    }
  };
  // Over several ranks the scatter, which every rank runs for every slave node, reads the
  // nodal normals at the corners of each node's segment for the couples of an offset surface on
  // nodes that turn: the master's parts are then those of every slave node, as on one rank.
  const bool every_node_reads_master = spins && pr.master_offsets;
  for (std::size_t k = 0; k < ns; ++k) {
    const bool own = pr.mine == nullptr || pr.mine[k] != 0;
    if (!own && !every_node_reads_master)
      continue;
    const core::Index cur = pr.st.seg[k];
    const std::size_t c0 = pr.st.cand_start[k], c1 = pr.st.cand_start[k + 1];
    if ((cur < 0 && c0 == c1) || (own && pr.st.resting[k] != 0))
      continue;  // far, or resting (resting_nodes.hpp): the kinematics pass over it
    if (!own) {  // its segment as the owner may find it: last cycle's, a neighbour, a candidate
      if (cur >= 0) {
        const auto cu = static_cast<std::size_t>(cur);
        add(r.near_mark, r.near, cur);
        for (std::size_t j = pr.nb_start[cu]; j < pr.nb_start[cu + 1]; ++j)
          add(r.near_mark, r.near, pr.nb[j]);
      }
      for (std::size_t c = c0; c < c1; ++c)
        add(r.near_mark, r.near, pr.st.cand[c]);
      continue;
    }
    add(r.slave_mark, r.slaves, static_cast<core::Index>(k));
    if (cur >= 0) {
      const auto cu = static_cast<std::size_t>(cur);
      add(r.near_mark, r.near, cur);
      add(r.fold_mark, r.folds, cur);
      add(r.centroid_mark, r.centroids, cur);
      for (std::size_t j = pr.nb_start[cu]; j < pr.nb_start[cu + 1]; ++j) {
        add(r.near_mark, r.near, pr.nb[j]);
        add(r.centroid_mark, r.centroids, pr.nb[j]);
      }
    }
    for (std::size_t c = c0; c < c1; ++c)
      add(r.near_mark, r.near, pr.st.cand[c]);
  }
  // The folds' tests read the centroids of their segments' neighbours.
  for (const core::Index s : r.folds) {
    const auto su = static_cast<std::size_t>(s);
    for (std::size_t j = pr.nb_start[su]; j < pr.nb_start[su + 1]; ++j)
      add(r.centroid_mark, r.centroids, pr.nb[j]);
  }
  std::size_t listed = std::max(r.centroids.size(), r.near.size());
  if (pr.master_offsets) {
    // The normals of the segments read and of the faces around their corners, which the
    // corners' nodal normals average.
    for (const core::Index s : r.near) {
      const auto su = static_cast<std::size_t>(s);
      add(r.seg_mark, r.segs, s);
      for (std::size_t j = 0; j < 4; ++j) {
        const core::Index node = pr.corner[4 * su + j];
        if (r.node_mark[static_cast<std::size_t>(node)] == now)
          continue;
        r.node_mark[static_cast<std::size_t>(node)] = now;
        r.nodes.push_back(node);
        const auto nu = static_cast<std::size_t>(node);
        for (std::size_t e = pr.node_seg_start[nu]; e < pr.node_seg_start[nu + 1]; ++e)
          add(r.seg_mark, r.segs, pr.node_seg[e]);
      }
    }
    listed = std::max(listed, r.segs.size());
  }
  if (!cp.slave_face_start.empty()) {
    for (const core::Index k : r.slaves) {
      const auto ku = static_cast<std::size_t>(k);
      for (std::size_t e = cp.slave_face_start[ku]; e < cp.slave_face_start[ku + 1]; ++e)
        add(r.face_mark, r.faces, cp.slave_face_index[e]);
    }
  }
  // Each side on its own: a small tool's segments may be read most of them while few of a
  // large blank's nodes are near it.
  r.all_master = static_cast<double>(listed) > kMostOf * static_cast<double>(nseg);
  r.all_slaves = static_cast<double>(r.slaves.size()) > kMostOf * static_cast<double>(ns);
  if (r.all_master && r.all_slaves)
    r.whole_until = r.looks + kWholeFor;
}

}  // namespace plyform::contact
