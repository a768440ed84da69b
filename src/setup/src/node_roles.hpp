#pragma once
// What moves a node other than its own equation of motion: a rigid body, a constraint or
// prescribed motion, or nothing at all (a node of no element has no mass). The rigid walls and
// the tied contacts leave such nodes out of their slaves.

#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::setup {

enum NodeRole : unsigned char {
  kFreeNode = 0,  ///< moved by its forces
  kNoElement,     ///< of no element: no mass
  kRigidNode,     ///< of a rigid body
  kHeldNode,      ///< a translation constrained (SPC, TC) or prescribed
};

/// One role per node. The blocks, constraints and prescribed motions must be built.
[[nodiscard]] std::vector<unsigned char> node_roles(const core::Model& model);

}  // namespace plyform::setup
