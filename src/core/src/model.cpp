#include "plyform/core/model.hpp"

#include <variant>

namespace plyform::core {

std::size_t Model::solid_count() const {
  std::size_t n = 0;
  for (const SolidBlock& b : solid_blocks)
    n += b.size();
  return n;
}

std::size_t Model::shell_count() const {
  std::size_t n = 0;
  for (const ShellBlock& b : shell_blocks)
    n += b.size();
  return n;
}

std::size_t Model::deformable_element_count() const {
  std::size_t n = 0;
  const auto rigid = [&](Index material) {
    return std::holds_alternative<RigidMaterial>(materials[static_cast<std::size_t>(material)]);
  };
  for (const SolidBlock& b : solid_blocks)
    n += rigid(b.material) ? 0 : b.size();
  for (const ShellBlock& b : shell_blocks)
    n += rigid(b.material) ? 0 : b.size();
  return n;
}

}  // namespace plyform::core
