#include "assembly.hpp"

namespace plyform::engine {

ForceGather::ForceGather(const core::Model& model) : offset_(model.node_count() + 1, 0) {
  for (const core::SolidBlock& b : model.solid_blocks) {
    for (core::Index n : b.connectivity)
      ++offset_[static_cast<std::size_t>(n) + 1];
  }
  for (std::size_t i = 1; i < offset_.size(); ++i)
    offset_[i] += offset_[i - 1];
  slots_.resize(offset_.back());
  std::vector<std::size_t> fill(offset_.begin(), offset_.end() - 1);
  for (std::size_t b = 0; b < model.solid_blocks.size(); ++b) {
    const core::SolidBlock& blk = model.solid_blocks[b];
    for (std::size_t k = 0; k < blk.connectivity.size(); ++k) {
      const auto n = static_cast<std::size_t>(blk.connectivity[k]);
      slots_[fill[n]++] = Slot{static_cast<core::Index>(b), 3 * k};
    }
  }
}

void ForceGather::gather(const std::vector<element::SolidBlockState>& solids, double* fx,
                         double* fy, double* fz) const {
  const auto n = static_cast<long>(offset_.size() - 1);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    double sx = 0.0, sy = 0.0, sz = 0.0;
    for (std::size_t k = offset_[static_cast<std::size_t>(i)];
         k < offset_[static_cast<std::size_t>(i) + 1]; ++k) {
      const double* f = &solids[static_cast<std::size_t>(slots_[k].block)].force[slots_[k].offset];
      sx += f[0];
      sy += f[1];
      sz += f[2];
    }
    fx[i] = sx;
    fy[i] = sy;
    fz[i] = sz;
  }
}

}  // namespace plyform::engine
