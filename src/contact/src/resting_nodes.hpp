#pragma once
// Resting slave nodes: a node clear of every segment it could meet before the next search, by
// more than the pass's nodes have moved since, has no force, no heat link and no book to keep;
// the kinematics, the law and the forces pass over it until its margin is spent
// (resting_nodes.cpp says how the margin is measured and why it is safe).

#include "pass_runtime.hpp"

namespace plyform::contact {

/// Whether a pass lets its slave nodes rest: a plain contact (no cohesive law, no tie, not a
/// guard), whose law has no force, no history and no heat for a node clear of the master by
/// more than `rest_reach(pr)`.
[[nodiscard]] bool may_rest(const PassRuntime& pr);

/// The gap within which the pass still acts on a node that has no force: the thermal link's
/// reach (LMAX) where the contact carries heat, 0 otherwise.
[[nodiscard]] double rest_reach(const PassRuntime& pr);

/// Before the kinematics of a cycle: wakes the resting nodes whose margin the motion since
/// they came to rest has spent, and lays to rest the awake ones that have been clear of the
/// master, with no force, for the last two cycles. `master_moved`: the largest distance any of
/// the master's nodes has moved since the last search (0 in a cycle that searched: a search
/// wakes every node). Returns how many of the pass's nodes (this rank's) rest this cycle.
std::size_t rest_or_wake(PassRuntime& pr, const double* packed, double master_moved);

}  // namespace plyform::contact
