#pragma once

#include <optional>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *USER_INTERFACE_FRICTION as written: the constants of a user contact law for one contact.
/// The meaning of each constant belongs to the law (see docs/contact-law.md); this reader only
/// keeps what the deck says.
struct UserInterfaceFrictionDesc {
  int contact_id = 0;  ///< NOSID: id of the contact interface the law applies to
  int noc = 0;         ///< NOC: number of constants
  int noci = 0;        ///< NOCI: number of constants to initialise
  /// UC1..UCnoc in order; std::nullopt = blank field (the law applies its default).
  std::vector<std::optional<double>> constants;
  std::vector<SourceLocation> constant_where;  ///< the card line of each constant
  SourceLocation where;                        ///< the keyword line
};

}  // namespace plyform::model
