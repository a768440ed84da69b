#include "plyform/contact/initial_penetrations.hpp"

#include <unordered_map>
#include <variant>

namespace plyform::contact {

std::vector<InitialPenetration> initial_penetrations(const core::Model& model) {
  if (model.contacts.empty())
    return {};
  const std::size_t n = model.node_count();
  // Nodes of rigid parts stay: a rigid body's shape is not the contact's to change.
  std::vector<unsigned char> rigid(n, 0);
  const auto mark = [&](const auto& blocks, std::size_t nodes_per) {
    for (const auto& b : blocks) {
      if (!std::holds_alternative<core::RigidMaterial>(
              model.materials[static_cast<std::size_t>(b.material)]))
        continue;
      for (std::size_t c = 0; c < b.size() * nodes_per; ++c)
        rigid[static_cast<std::size_t>(b.connectivity[c])] = 1;
    }
  };
  mark(model.shell_blocks, 4);
  mark(model.solid_blocks, 8);
  // Unit masses: the gaps and normals do not depend on them (only the penalty of SOFT = 1 and
  // the step vote do, which are not used here).
  const std::vector<double> mass(n, 1.0);
  ContactSet contacts(model, mass, rigid.data(), 1.0, 0.9);
  std::vector<double> packed(6 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    packed[6 * i] = model.x0[i];
    packed[6 * i + 1] = model.y0[i];
    packed[6 * i + 2] = model.z0[i];
  }
  contacts.start(packed.data(), false);
  std::vector<InitialPenetration> all;
  contacts.initial_penetrations(all);
  std::unordered_map<core::Index, std::size_t> deepest;
  std::vector<InitialPenetration> out;
  for (const InitialPenetration& p : all) {
    const auto [it, fresh] = deepest.emplace(p.node, out.size());
    if (fresh)
      out.push_back(p);
    else if (p.depth > out[it->second].depth)
      out[it->second] = p;
  }
  return out;
}

}  // namespace plyform::contact
