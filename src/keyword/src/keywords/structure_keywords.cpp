// *KEYWORD, *TITLE, *END, *COMMENT: the structure of a deck.
#include <array>
#include <sstream>

#include "../keyword_input.hpp"
#include "../keyword_registry.hpp"
#include "../text_utils.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<std::string_view, 1> kNoOption{""};

void read_keyword(KeywordInput& in) {
  const std::string& text = in.keyword().text_after;
  std::istringstream tokens(text);
  for (std::string token; tokens >> token;) {
    const std::string upper = to_upper(token);
    if (upper.rfind("LONG=", 0) == 0 && upper != "LONG=S" && upper != "LONG=N") {
      in.fail(in.keyword().line, "",
              "long format (" + token +
                  ") is not supported; write the deck in standard "
                  "10-character fields");
    }
  }
  if (!text.empty()) {
    in.model().keyword_options = text;
  }
}

constexpr std::array kTitleFields{
    FieldSpec{.name = "TITLE",
              .type = FieldType::kText,
              .width = 80,
              .description = "title of the deck",
              .rest_of_line = true},
};
constexpr std::array kTitleCards{
    CardSpec{.title = "Title card", .fields = kTitleFields, .presence = "one card"},
};

void read_title(KeywordInput& in) {
  if (const auto line = in.next_line()) {
    in.model().title = in.read(kTitleCards[0], *line).text("TITLE");
  }
}

void read_end(KeywordInput& in) {
  in.skip_rest();
  in.stop_file();
}

void read_comment(KeywordInput& in) {
  in.skip_rest();
}

}  // namespace

KeywordSpec keyword_keyword() {
  return {.name = "KEYWORD",
          .options = kNoOption,
          .handler = read_keyword,
          .cards = {},
          .summary =
              "Marks a keyword deck. Text after the name on the same line (a memory size "
              "such as `100m`, `MEMORY=...`, `NCPU=...`) is kept in "
              "`ModelDesc::keyword_options`; `LONG=Y` (long format) is rejected. "
              "Optional in included files.",
          .takes_line_text = true};
}

KeywordSpec title_keyword() {
  return {.name = "TITLE",
          .options = kNoOption,
          .handler = read_title,
          .cards = kTitleCards,
          .summary = "The title of the deck (the last *TITLE read wins)."};
}

KeywordSpec end_keyword() {
  return {.name = "END",
          .options = kNoOption,
          .handler = read_end,
          .cards = {},
          .summary =
              "Ends the file it is in: the rest of that file is not read; reading goes on "
              "in the file that included it."};
}

KeywordSpec comment_keyword() {
  return {.name = "COMMENT",
          .options = kNoOption,
          .handler = read_comment,
          .cards = {},
          .summary =
              "Free text: the rest of the keyword line and every line up to the next "
              "keyword are ignored.",
          .takes_line_text = true};
}

}  // namespace plyform::keyword
