#pragma once
// Which element blocks (parts) each side of a contact interface holds, read from what the build
// made of it: the checks of `plyform check` that name parts need it, the runtime model keeps
// only nodes and segments.

#include <cstddef>
#include <string>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::setup {

/// Indices into Model::shell_blocks and Model::solid_blocks, ascending.
struct ContactSides {
  std::vector<std::size_t> slave_shells, master_shells;
  std::vector<std::size_t> slave_solids, master_solids;
};

/// The blocks of the interface's slave side (its first pass: the deck's slave side) and master
/// side: a block is on a side when one of the side's faces (a master segment, a face of the
/// slave surface) has all its nodes in the block, or, for a slave side of bare nodes (a node
/// set), when one of those nodes is the block's. A single-surface contact has every block of
/// its surface on both sides.
[[nodiscard]] ContactSides contact_sides(const core::Model& model, const core::ContactInterface& c);

/// A layer interface: two sides of deformable shells only (no rigid tool, no solid), not a
/// single-surface contact, and no block on both sides: two layers of a laminate.
[[nodiscard]] bool is_layer_interface(const core::Model& model, const core::ContactInterface& c,
                                      const ContactSides& sides);

/// Whether a block's material is rigid (a tool).
[[nodiscard]] bool is_rigid(const core::Model& model, const core::ShellBlock& block);

/// "contact 3 (*CONTACT_ONE_WAY_SURFACE_TO_SURFACE)", or the interface's place in the deck
/// when it has no id.
[[nodiscard]] std::string contact_name(const core::Model& model, const core::ContactInterface& c);

/// "part 2 'upper arm'" of a block (its part's deck id and title).
[[nodiscard]] std::string part_name(const core::Model& model, core::Index part);

}  // namespace plyform::setup
