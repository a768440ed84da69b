#include "plyform/contact/bucket_search.hpp"

#include <algorithm>
#include <cmath>

namespace plyform::contact {

void BucketSearch::build(const std::vector<core::Index>& segments, const double* coords,
                         std::size_t stride, const std::vector<double>& radius) {
  const std::size_t ns = segments.size() / 4;
  box_.assign(6 * ns, 0.0);
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  double extent_sum = 0.0;
  for (std::size_t s = 0; s < ns; ++s) {
    double* b = &box_[6 * s];
    for (int k = 0; k < 3; ++k) {
      b[k] = 1e300;
      b[3 + k] = -1e300;
    }
    for (int j = 0; j < 4; ++j) {
      const double* p = coords + stride * static_cast<std::size_t>(segments[4 * s + j]);
      for (int k = 0; k < 3; ++k) {
        b[k] = std::min(b[k], p[k]);
        b[3 + k] = std::max(b[3 + k], p[k]);
      }
    }
    double extent = 0.0;
    for (int k = 0; k < 3; ++k) {
      extent = std::max(extent, b[3 + k] - b[k]);
      b[k] -= radius[s];
      b[3 + k] += radius[s];
      lo[k] = std::min(lo[k], b[k]);
      hi[k] = std::max(hi[k], b[3 + k]);
    }
    extent_sum += extent + 2.0 * radius[s];
  }
  if (ns == 0) {
    cell_start_.assign(1, 0);
    cell_segments_.clear();
    dims_[0] = dims_[1] = dims_[2] = 0;
    return;
  }
  // Cell size: the mean grown segment size, enlarged until the grid has at most a few cells
  // per segment (a thin sheet gets one cell through its thickness).
  double h = std::max(extent_sum / static_cast<double>(ns), 1e-30);
  const double max_cells = 4.0 * static_cast<double>(ns) + 64.0;
  for (;;) {
    double cells = 1.0;
    for (int k = 0; k < 3; ++k)
      cells *= std::floor((hi[k] - lo[k]) / h) + 1.0;
    if (cells <= max_cells)
      break;
    h *= 1.25;
  }
  inv_h_ = 1.0 / h;
  for (int k = 0; k < 3; ++k) {
    origin_[k] = lo[k];
    dims_[k] = static_cast<long>(std::floor((hi[k] - lo[k]) * inv_h_)) + 1;
  }
  const auto cell_range = [&](std::size_t s, long(&c0)[3], long(&c1)[3]) {
    const double* b = &box_[6 * s];
    for (int k = 0; k < 3; ++k) {
      c0[k] =
          std::clamp(static_cast<long>(std::floor((b[k] - origin_[k]) * inv_h_)), 0L, dims_[k] - 1);
      c1[k] = std::clamp(static_cast<long>(std::floor((b[3 + k] - origin_[k]) * inv_h_)), 0L,
                         dims_[k] - 1);
    }
  };
  const auto ncell = static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]);
  cell_start_.assign(ncell + 1, 0);
  long c0[3], c1[3];
  for (std::size_t s = 0; s < ns; ++s) {  // count
    cell_range(s, c0, c1);
    for (long z = c0[2]; z <= c1[2]; ++z)
      for (long y = c0[1]; y <= c1[1]; ++y)
        for (long x = c0[0]; x <= c1[0]; ++x)
          ++cell_start_[static_cast<std::size_t>((z * dims_[1] + y) * dims_[0] + x) + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c)
    cell_start_[c + 1] += cell_start_[c];
  cell_segments_.resize(cell_start_[ncell]);
  std::vector<std::size_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t s = 0; s < ns; ++s) {  // fill, in segment order
    cell_range(s, c0, c1);
    for (long z = c0[2]; z <= c1[2]; ++z)
      for (long y = c0[1]; y <= c1[1]; ++y)
        for (long x = c0[0]; x <= c1[0]; ++x)
          cell_segments_[fill[static_cast<std::size_t>((z * dims_[1] + y) * dims_[0] + x)]++] =
              static_cast<core::Index>(s);
  }
}

long BucketSearch::cell_of(const double* p) const {
  long c[3];
  for (int k = 0; k < 3; ++k) {
    const double f = std::floor((p[k] - origin_[k]) * inv_h_);
    if (!(f >= 0.0) || f >= static_cast<double>(dims_[k]))
      return -1;
    c[k] = static_cast<long>(f);
  }
  return (c[2] * dims_[1] + c[1]) * dims_[0] + c[0];
}

void BucketSearch::query(const std::vector<core::Index>& nodes, const double* coords,
                         std::size_t stride, std::vector<std::size_t>& start,
                         std::vector<core::Index>& cand) const {
  const std::size_t nq = nodes.size();
  start.assign(nq + 1, 0);
  const auto inside = [&](const double* p, core::Index s) {
    const double* b = &box_[6 * static_cast<std::size_t>(s)];
    return p[0] >= b[0] && p[0] <= b[3] && p[1] >= b[1] && p[1] <= b[4] && p[2] >= b[2] &&
           p[2] <= b[5];
  };
  const auto for_each = [&](std::size_t q, auto&& f) {
    const double* p = coords + stride * static_cast<std::size_t>(nodes[q]);
    const long c = dims_[0] > 0 ? cell_of(p) : -1;
    if (c < 0)
      return;
    for (std::size_t k = cell_start_[static_cast<std::size_t>(c)];
         k < cell_start_[static_cast<std::size_t>(c) + 1]; ++k) {
      if (inside(p, cell_segments_[k]))
        f(cell_segments_[k]);
    }
  };
#pragma omp parallel for schedule(static)
  for (long lq = 0; lq < static_cast<long>(nq); ++lq) {
    const auto q = static_cast<std::size_t>(lq);
    std::size_t count = 0;
    for_each(q, [&](core::Index) { ++count; });
    start[q + 1] = count;
  }
  for (std::size_t q = 0; q < nq; ++q)
    start[q + 1] += start[q];
  cand.resize(start[nq]);
#pragma omp parallel for schedule(static)
  for (long lq = 0; lq < static_cast<long>(nq); ++lq) {
    const auto q = static_cast<std::size_t>(lq);
    std::size_t at = start[q];
    for_each(q, [&](core::Index s) { cand[at++] = s; });
  }
}

}  // namespace plyform::contact
