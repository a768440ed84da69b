#pragma once
// Checks of the keyword reader on deck text, shared by the keyword tests: read a deck that must
// be valid, or expect exactly one located error (file, line, keyword, field, message part).

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword::test {

/// Every error of a read, one per line (for failure messages).
inline std::string all_errors(const ReadResult& result) {
  std::string out;
  for (const Diagnostic& d : result.errors)
    out += d.to_string() + "\n";
  return out;
}

/// Reads `text` as "deck.k"; a failure lists every error.
inline ReadResult read_ok(std::string_view text) {
  ReadResult result = read_deck_text(text, "deck.k");
  EXPECT_TRUE(result.ok()) << all_errors(result);
  return result;
}

/// The one error of reading `text` (an empty Diagnostic, and a failure, when there is not
/// exactly one).
inline Diagnostic single_error(std::string_view text) {
  const ReadResult result = read_deck_text(text, "deck.k");
  EXPECT_EQ(result.errors.size(), 1u) << all_errors(result);
  return result.errors.empty() ? Diagnostic{} : result.errors.front();
}

inline bool contains(const std::string& text, std::string_view part) {
  return text.find(part) != std::string::npos;
}

/// Expects one error at `line` on `field` of `keyword` whose message contains `part`.
inline void expect_error(std::string_view deck, int line, std::string_view keyword,
                         std::string_view field, std::string_view part) {
  SCOPED_TRACE(std::string(deck));
  const Diagnostic d = single_error(deck);
  EXPECT_EQ(d.where.file, "deck.k");
  EXPECT_EQ(d.where.line, line);
  EXPECT_EQ(d.keyword, keyword);
  EXPECT_EQ(d.field, field);
  EXPECT_TRUE(contains(d.message, part)) << d.to_string();
}

}  // namespace plyform::keyword::test
