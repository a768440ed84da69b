#include "plyform/keyword/number_parser.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

#include "text_utils.hpp"

namespace plyform::keyword {
namespace {

/// Appends the run of digits starting at i to out; returns how many there were.
std::size_t take_digits(std::string_view text, std::size_t& i, std::string& out) {
  const std::size_t start = i;
  while (i < text.size() && is_digit(text[i])) {
    out.push_back(text[i]);
    ++i;
  }
  return i - start;
}

}  // namespace

std::optional<double> parse_real(std::string_view text) {
  std::string normal;  // the number rewritten for from_chars: [-]digits[.digits][e[-]digits]
  normal.reserve(text.size() + 2);
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
    if (text[i] == '-') {
      normal.push_back('-');
    }
    ++i;
  }
  std::size_t mantissa_digits = take_digits(text, i, normal);
  if (i < text.size() && text[i] == '.') {
    normal.push_back('.');
    ++i;
    mantissa_digits += take_digits(text, i, normal);
  }
  if (mantissa_digits == 0) {
    return std::nullopt;
  }
  if (i < text.size()) {
    const char c = text[i];
    const bool letter = c == 'e' || c == 'E' || c == 'd' || c == 'D';
    if (!letter && c != '+' && c != '-') {
      return std::nullopt;
    }
    if (letter) {
      ++i;
    }
    normal.push_back('e');
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
      if (text[i] == '-') {
        normal.push_back('-');
      }
      ++i;
    }
    if (take_digits(text, i, normal) == 0 || i != text.size()) {
      return std::nullopt;
    }
  }
  double value = 0.0;
  const char* first = normal.data();
  const char* last = normal.data() + normal.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc{} || ptr != last || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<long long> parse_integer(std::string_view text) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') {
      return std::nullopt;
    }
  }
  if (text.empty()) {
    return std::nullopt;
  }
  long long value = 0;
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), last, value);
  if (ec != std::errc{} || ptr != last) {
    return std::nullopt;
  }
  return value;
}

}  // namespace plyform::keyword
