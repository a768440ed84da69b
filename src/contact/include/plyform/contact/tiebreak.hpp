#pragma once
// LS-DYNA's built-in tiebreak (the _TIEBREAK option of the automatic contacts) over a pass's
// slave nodes: a tied node is held to its point of the master surface by the penalty springs,
// normal and (OPTION 1-3) tangential, in tension as in compression; OPTION 2-4 fail the tie by
// a stress criterion, after which the node is an ordinary penalty-Coulomb contact node (the
// interface's law) and never ties again. docs/contact.md.

#include <cstddef>
#include <cstdint>

#include "plyform/core/contact.hpp"
#include "plyform/law/law.hpp"

namespace plyform::contact {

/// Tie state of a slave node.
enum class TieState : std::int8_t {
  free = 0,    ///< not tied (yet): the law alone
  tied = 1,    ///< held by the tie springs
  failed = 2,  ///< the tie failed: the law alone, for good
};

/// The tie arrays of a pass (host-owned, one entry per slave node).
struct TieArrays {
  std::int8_t* state = nullptr;
  double* gap0 = nullptr;  ///< the gap the node was tied at (the springs' rest length)
};

/// Ties a node at its current gap: the law history says CONTACT (or SEPARATING when the gap is
/// open) with beta = 1, so that the contact keeps the node on its side and segment; the stick
/// spring starts unstretched.
void tie_node(const law::BatchHistory& h, const TieArrays& tie, std::size_t k, double gap);

/// One cycle of the tiebreak interface over `in.count` nodes (arrays offset like `in`): tied
/// nodes get the tie tractions and the failure check, the others the law (`law`, penalty-
/// Coulomb); OPTION 1 and 3 tie a free node on contact (gap <= 0). A failing node releases
/// the energy its springs held (booked as damage) and takes the law's contact from the next
/// cycle.
void tiebreak_update(const core::Tiebreak& tb, const law::Law& law, const law::BatchInput& in,
                     const law::BatchHistory& h, const TieArrays& tie, const law::BatchOutput& out);

}  // namespace plyform::contact
