#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace plyform::keyword {

/// A data line of a keyword block (comment lines are already dropped).
struct DataLine {
  std::string_view text;  ///< without line end
  int line = 0;           ///< 1-based
};

/// A keyword line: "*define_curve_title" gives name "DEFINE_CURVE_TITLE".
struct KeywordLine {
  std::string name;        ///< upper case, without '*' and without a format suffix
  std::string text_after;  ///< what follows the name on the line, trimmed
  char format = ' ';       ///< ' ' standard, '+' long, '-' standard (explicit), '%' i10
  int line = 0;

  std::string display() const { return "*" + name; }
};

/// A keyword line and the data lines up to the next keyword line.
struct Block {
  KeywordLine keyword;
  std::vector<DataLine> data;
};

/// A file's text cut into keyword blocks. Line ends may be LF or CRLF; '$' in column 1 starts
/// a comment line; '*' in column 1 starts a keyword line.
struct DeckBlocks {
  std::vector<DataLine> before_first_keyword;  ///< data lines (blank ones included)
  std::vector<Block> blocks;
};

DeckBlocks split_into_blocks(std::string_view text);

}  // namespace plyform::keyword
