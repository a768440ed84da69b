#pragma once
// Spatial bucket sort of contact segments: a uniform grid over the segments' boxes (each
// grown by its search radius), each cell listing the segments whose box overlaps it. A query
// point then reads one cell. Building and querying cost time linear in the number of segments
// and points (the cell size follows the segment size, and the grid is capped at a few cells
// per segment).

#include <cstddef>
#include <vector>

#include "plyform/core/types.hpp"

namespace plyform::contact {

class BucketSearch {
 public:
  /// `segments`: 4 node indices each; node coordinates at `coords + stride * node`; `radius`
  /// per segment: how far from its box a point is still a candidate.
  void build(const std::vector<core::Index>& segments, const double* coords, std::size_t stride,
             const std::vector<double>& radius);

  /// Candidate segments of each node of `nodes` (CSR: the candidates of node k are
  /// cand[start[k] .. start[k+1]), in increasing segment order).
  void query(const std::vector<core::Index>& nodes, const double* coords, std::size_t stride,
             std::vector<std::size_t>& start, std::vector<core::Index>& cand) const;

  [[nodiscard]] std::size_t cell_count() const {
    return cell_start_.empty() ? 0 : cell_start_.size() - 1;
  }

 private:
  [[nodiscard]] long cell_of(const double* p) const;
  std::vector<double> box_;  ///< 6 per segment: min x y z, max x y z (grown by the radius)
  double origin_[3] = {0, 0, 0};
  double inv_h_ = 1.0;
  long dims_[3] = {0, 0, 0};
  std::vector<std::size_t> cell_start_;
  std::vector<core::Index> cell_segments_;
};

}  // namespace plyform::contact
