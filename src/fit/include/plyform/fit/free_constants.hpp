#pragma once
// The constants a fit varies, named as in the law's constant table (user_constants.hpp), plus
// SMAX and ZETA for the pairs SMAX_LO/SMAX_HI and ZETA_LO/ZETA_HI tied to one value (a
// temperature-independent law stays one).

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace plyform::fit {

/// How the optimiser's variable x maps to the constant's value v. Positive constants are fitted
/// as x = ln v and constants of [0, 1] as x = logit v, so no step can leave their range; T_LO and
/// T_HI, of any sign, as x = v / scale.
enum class Transform { log, logit, linear };

struct FreeConstant {
  std::string name;        ///< upper case, as named on the command line
  std::vector<int> slots;  ///< the 1-based UC indices set to the value (two for SMAX, ZETA)
  Transform transform = Transform::log;
  double scale = 1.0;  ///< Transform::linear only
};

/// Parses "CN,SMAX,ETA" (case-insensitive, commas and/or spaces); throws FitError naming an
/// unknown constant, one that the normal traction does not depend on, or one given twice.
[[nodiscard]] std::vector<FreeConstant> parse_free_constants(std::string_view list);

/// The value of a free constant in the UC vector (its first slot; the default when blank).
[[nodiscard]] double value_of(const FreeConstant& c, std::span<const std::optional<double>> uc);

/// Sets every slot of `c` to `value`.
void set_value(const FreeConstant& c, double value, std::vector<std::optional<double>>& uc);

[[nodiscard]] double to_variable(const FreeConstant& c, double value);
[[nodiscard]] double from_variable(const FreeConstant& c, double x);
/// d value / d x, for the standard errors of the values.
[[nodiscard]] double value_derivative(const FreeConstant& c, double x);

/// The starting value of a free constant must lie inside its transform's open range (> 0 for
/// log, in (0, 1) for logit); throws FitError naming the constant otherwise. Also rejects a
/// slot given by a load curve (-N) and a tied pair whose two values differ.
void check_start(const FreeConstant& c, std::span<const std::optional<double>> uc);

}  // namespace plyform::fit
