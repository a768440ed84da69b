#pragma once
// The penalty per area of a contact pass's two sides as built (stiffness over area at t = 0):
// what PENOPT chooses between, what `plyform check` shows and what the soft-side warning
// compares.

#include <vector>

#include "plyform/core/contact.hpp"
#include "plyform/core/model.hpp"

namespace plyform::setup {

/// Per slave node: its penalty stiffness over its tributary area.
[[nodiscard]] std::vector<double> slave_penalty_per_area(const core::ContactPass& p);

/// Per master segment with an area and a stiffness: the stiffness over the segment's area at
/// t = 0 (segments without either are left out).
[[nodiscard]] std::vector<double> master_penalty_per_area(const core::Model& m,
                                                          const core::ContactPass& p);

/// The area-weighted means of each side: sum of stiffness over sum of area (0 for none).
struct SidePenalty {
  double slave = 0.0, master = 0.0;
};
[[nodiscard]] SidePenalty side_penalty(const core::Model& m, const core::ContactPass& p);

}  // namespace plyform::setup
