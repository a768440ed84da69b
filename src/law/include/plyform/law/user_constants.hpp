#pragma once
// The constants of *USER_INTERFACE_FRICTION (product.md) as data: name, unit, default, range.
// The same table validates a deck, documents the keyword and names the constant in errors.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "plyform/law/parameters.hpp"

namespace plyform::law {

/// One user constant UCn.
struct ConstantSpec {
  int index;             ///< n of UCn, 1-based
  const char* name;      ///< e.g. "SMAX_LO"
  const char* unit;      ///< in words, consistent units
  const char* meaning;   ///< one line
  double default_value;  ///< used when blank or beyond NOC (if not required)
  bool required;         ///< no default: blank or missing is an error
  int default_from;      ///< 1-based index whose value is the default (0: none), e.g. HI <- LO
  double min;            ///< allowed range
  double max;
  bool min_open;               ///< true: value must be > min (else >= min)
  bool integer;                ///< must be a whole number
  bool temperature_dependent;  ///< a negative value -N selects load curve N
};

/// All constants, UC1 first.
[[nodiscard]] std::span<const ConstantSpec> user_constant_table();

/// A constant that is wrong: which, its value, and what was expected.
struct ConstantError {
  int index = 0;     ///< 1-based UC index; 0 when the error concerns the set as a whole
  std::string name;  ///< the constant's name, or empty
  double value = 0.0;
  std::string message;  ///< a complete sentence naming the constant, value and allowed range
};

struct FromConstantsResult {
  Parameters parameters;
  std::vector<ConstantError> errors;
  [[nodiscard]] bool ok() const { return errors.empty(); }
};

/// Builds parameters from UC1..UCn (nullopt = blank field: the default applies). `curves` are
/// the load curves of the deck by id; those referenced by a -N slot are copied into the result.
/// Every error is reported, not just the first.
[[nodiscard]] FromConstantsResult from_user_constants(std::span<const std::optional<double>> uc,
                                                      std::span<const Curve> curves);

/// The constants that `from_user_constants` turns back into `p` (curves as -id).
[[nodiscard]] std::vector<std::optional<double>> to_user_constants(const Parameters& p);

/// Checks hand-built parameters with the same rules as the deck constants.
[[nodiscard]] std::vector<ConstantError> validate(const Parameters& p);

}  // namespace plyform::law
