#include "deck_blocks.hpp"

#include "text_utils.hpp"

namespace plyform::keyword {
namespace {

KeywordLine parse_keyword_line(std::string_view text, int line) {
  KeywordLine keyword;
  keyword.line = line;
  text.remove_prefix(1);  // '*'
  std::size_t end = 0;
  while (end < text.size() && !is_blank_char(text[end])) {
    ++end;
  }
  std::string_view name = text.substr(0, end);
  std::string_view after = trim(text.substr(end));
  if (!name.empty() && (name.back() == '+' || name.back() == '-' || name.back() == '%')) {
    keyword.format = name.back();
    name.remove_suffix(1);
  } else if (after == "+" || after == "-" || after == "%") {
    keyword.format = after.front();
    after = {};
  }
  keyword.name = to_upper(name);
  keyword.text_after = std::string(after);
  return keyword;
}

}  // namespace

DeckBlocks split_into_blocks(std::string_view text) {
  DeckBlocks out;
  int line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) {
      end = text.size();
    }
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') {
      line.remove_suffix(1);
    }
    if (!line.empty() && line.front() == '$') {
      continue;
    }
    if (!line.empty() && line.front() == '*') {
      out.blocks.push_back({parse_keyword_line(line, line_number), {}});
      continue;
    }
    DataLine data{line, line_number};
    if (out.blocks.empty()) {
      out.before_first_keyword.push_back(data);
    } else {
      out.blocks.back().data.push_back(data);
    }
  }
  return out;
}

}  // namespace plyform::keyword
