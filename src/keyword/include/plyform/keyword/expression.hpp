#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "plyform/keyword/parameter_table.hpp"

namespace plyform::keyword {

struct ExpressionResult {
  std::optional<double> value;
  std::string error;  ///< set when value is empty
};

/// Evaluates a *PARAMETER_EXPRESSION: numbers, parameters (&name or name), + - * / **,
/// parentheses, unary minus and the functions sin cos tan asin acos atan atan2 sqrt exp log
/// log10 abs min max (angles in radians). Anything else, a non-finite result or a division by
/// zero is an error.
ExpressionResult evaluate_expression(std::string_view text, const ParameterTable& parameters);

}  // namespace plyform::keyword
