#pragma once
// Node-wise gathering of element forces: each node sums the force slots of its elements in a
// fixed order (element order), so the result is the same for any number of threads.

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/element/solid_kernels.hpp"

namespace plyform::engine {

class ForceGather {
 public:
  explicit ForceGather(const core::Model& model);
  /// f[n] = sum of the element force slots of node n (parallel over nodes).
  void gather(const std::vector<element::SolidBlockState>& solids, double* fx, double* fy,
              double* fz) const;
  /// Number of elements touching node n (0: a node outside every element).
  [[nodiscard]] int element_count(std::size_t n) const {
    return static_cast<int>(offset_[n + 1] - offset_[n]);
  }

 private:
  struct Slot {
    core::Index block;
    std::size_t offset;  ///< into SolidBlockState::force
  };
  std::vector<std::size_t> offset_;  ///< CSR row starts, node_count + 1
  std::vector<Slot> slots_;
};

}  // namespace plyform::engine
