#include "node_roles.hpp"

#include <variant>

namespace plyform::setup {

std::vector<unsigned char> node_roles(const core::Model& m) {
  std::vector<unsigned char> role(m.node_count(), kNoElement);
  const auto mark = [&](const auto& blocks) {
    for (const auto& b : blocks) {
      const bool rigid = std::holds_alternative<core::RigidMaterial>(
          m.materials[static_cast<std::size_t>(b.material)]);
      for (core::Index c : b.connectivity) {
        unsigned char& r = role[static_cast<std::size_t>(c)];
        if (rigid)
          r = kRigidNode;
        else if (r == kNoElement)
          r = kFreeNode;
      }
    }
  };
  mark(m.solid_blocks);
  mark(m.shell_blocks);
  constexpr unsigned kTranslations = core::dof_x | core::dof_y | core::dof_z;
  for (const core::FixedDofs& f : m.fixed) {
    unsigned char& r = role[static_cast<std::size_t>(f.node)];
    if ((f.dofs & kTranslations) != 0 && r == kFreeNode)
      r = kHeldNode;
  }
  for (const core::PrescribedMotion& p : m.motions) {
    unsigned char& r = role[static_cast<std::size_t>(p.node)];
    if (r == kFreeNode)
      r = kHeldNode;
  }
  return role;
}

}  // namespace plyform::setup
