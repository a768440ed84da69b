#include "plyform/core/model.hpp"

namespace plyform::core {

std::size_t Model::solid_count() const {
  std::size_t n = 0;
  for (const SolidBlock& b : solid_blocks)
    n += b.size();
  return n;
}

}  // namespace plyform::core
