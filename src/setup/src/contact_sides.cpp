#include "plyform/setup/contact_sides.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <variant>

namespace plyform::setup {
namespace {

// Whether some face (4 node indices each, a triangle repeating its third) has all its nodes
// marked.
bool face_inside(const std::vector<core::Index>& faces, const std::vector<char>& mark) {
  for (std::size_t f = 0; f + 3 < faces.size(); f += 4) {
    bool all = true;
    for (std::size_t j = 0; j < 4 && all; ++j)
      all = mark[static_cast<std::size_t>(faces[f + j])] != 0;
    if (all)
      return true;
  }
  return false;
}

// Whether the pass's slave side and master side touch the block whose nodes are marked.
void sides_of(const core::ContactPass& p, const std::vector<char>& mark, bool& slave,
              bool& master) {
  if (p.slave_faces.empty()) {
    slave = std::any_of(p.slave_nodes.begin(), p.slave_nodes.end(),
                        [&](core::Index n) { return mark[static_cast<std::size_t>(n)] != 0; });
  } else {
    slave = face_inside(p.slave_faces, mark);
  }
  master = face_inside(p.segments, mark);
}

}  // namespace

ContactSides contact_sides(const core::Model& model, const core::ContactInterface& c) {
  ContactSides out;
  if (c.passes.empty())
    return out;
  const core::ContactPass& p = c.passes.front();
  std::vector<char> mark(model.node_count(), 0);
  // One block at a time: mark its nodes, look at the faces, clear the marks.
  const auto visit = [&](const std::vector<core::Index>& connectivity, std::size_t index,
                         std::vector<std::size_t>& slave_list,
                         std::vector<std::size_t>& master_list) {
    for (core::Index k : connectivity)
      mark[static_cast<std::size_t>(k)] = 1;
    bool slave = false, master = false;
    sides_of(p, mark, slave, master);
    if (slave)
      slave_list.push_back(index);
    if (master)
      master_list.push_back(index);
    for (core::Index k : connectivity)
      mark[static_cast<std::size_t>(k)] = 0;
  };
  for (std::size_t b = 0; b < model.shell_blocks.size(); ++b)
    visit(model.shell_blocks[b].connectivity, b, out.slave_shells, out.master_shells);
  for (std::size_t b = 0; b < model.solid_blocks.size(); ++b)
    visit(model.solid_blocks[b].connectivity, b, out.slave_solids, out.master_solids);
  return out;
}

bool is_rigid(const core::Model& model, const core::ShellBlock& block) {
  return std::holds_alternative<core::RigidMaterial>(
      model.materials[static_cast<std::size_t>(block.material)]);
}

bool is_layer_interface(const core::Model& model, const core::ContactInterface& c,
                        const ContactSides& sides) {
  if (c.kind == core::ContactKind::single_surface || sides.slave_shells.empty() ||
      sides.master_shells.empty() || !sides.slave_solids.empty() || !sides.master_solids.empty())
    return false;
  for (const auto* list : {&sides.slave_shells, &sides.master_shells})
    for (std::size_t b : *list)
      if (is_rigid(model, model.shell_blocks[b]))
        return false;
  for (std::size_t b : sides.slave_shells)
    if (std::find(sides.master_shells.begin(), sides.master_shells.end(), b) !=
        sides.master_shells.end())
      return false;
  return true;
}

std::string contact_name(const core::Model& model, const core::ContactInterface& c) {
  if (c.id != 0)
    return fmt::format("contact {} ({})", c.id, c.keyword);
  const auto at = static_cast<std::size_t>(&c - model.contacts.data());
  return fmt::format("contact number {} of the deck ({}, no CID)", at + 1, c.keyword);
}

std::string part_name(const core::Model& model, core::Index part) {
  const core::Part& p = model.parts[static_cast<std::size_t>(part)];
  return p.title.empty() ? fmt::format("part {}", p.id)
                         : fmt::format("part {} '{}'", p.id, p.title);
}

}  // namespace plyform::setup
