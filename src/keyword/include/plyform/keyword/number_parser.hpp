#pragma once

#include <optional>
#include <string_view>

namespace plyform::keyword {

/// A real number as keyword decks write it: "1.5", "-.5", "2.", "1e3", "1.0D-3", and the
/// Fortran forms without exponent letter "1.00000+4" (= 1e4) and "1.0-3" (= 1e-3).
/// The text must be trimmed. Returns nullopt for anything else (including inf and nan).
std::optional<double> parse_real(std::string_view text);

/// An integer: optional sign and decimal digits only. nullopt if not one, or if it overflows.
std::optional<long long> parse_integer(std::string_view text);

}  // namespace plyform::keyword
