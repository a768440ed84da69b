#pragma once

#include <string>
#include <string_view>

namespace plyform::keyword {

/// Blank for the reader: space, tab, and the other ASCII white space.
inline bool is_blank_char(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank_char(s.front())) {
    s.remove_prefix(1);
  }
  while (!s.empty() && is_blank_char(s.back())) {
    s.remove_suffix(1);
  }
  return s;
}

inline bool is_blank_line(std::string_view s) {
  return trim(s).empty();
}

/// ASCII upper case; other bytes (Latin-1, UTF-8) unchanged.
inline std::string to_upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'a' && c <= 'z') {
      c = static_cast<char>(c - 'a' + 'A');
    }
  }
  return out;
}

inline bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
inline bool is_alpha(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

}  // namespace plyform::keyword
