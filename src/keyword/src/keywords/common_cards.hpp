#pragma once
// Cards and checks shared by several keywords: the title card of _TITLE, the ID card of _ID,
// the "not supported yet" check for fields that must stay 0, and the storing of keywords read
// once per deck.

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "../keyword_input.hpp"

namespace plyform::keyword {

inline constexpr std::array<std::string_view, 2> kNoneOrTitle{"", "TITLE"};
inline constexpr std::array<std::string_view, 2> kNoneOrId{"", "ID"};
inline constexpr std::array<std::string_view, 1> kNoOptions{""};

/// The field width of a LARGE = 1 card of a dynain (*INITIAL_STRESS_SHELL,
/// *INITIAL_STRAIN_SHELL): LS-DYNA's large format, five fields of 16 characters to a card of 80
/// columns, as OpenRadioss's reader of LS-DYNA decks takes it (and as LS-PrePost's dynain
/// headers space it); a card whose text runs past column 80 is in fields of 20 characters
/// (pydyna writes those: docs/outputs.md).
inline int large_field_width(const DataLine& line) {
  std::size_t end = line.text.size();
  while (end > 0 &&
         (line.text[end - 1] == ' ' || line.text[end - 1] == '\t' || line.text[end - 1] == '\r'))
    --end;
  return end > 80 ? 20 : 16;
}

inline constexpr std::array kTitleCardFields{
    FieldSpec{.name = "TITLE",
              .type = FieldType::kText,
              .width = 80,
              .description = "title (the _TITLE option)",
              .rest_of_line = true},
};

inline constexpr std::array kIdCardFields{
    FieldSpec{.name = "ID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "id of the item (the _ID option)"},
    FieldSpec{.name = "HEADING",
              .type = FieldType::kText,
              .width = 70,
              .description = "a name for the item",
              .rest_of_line = true},
};

/// A corner of a segment (*SET_SEGMENT, *LOAD_SEGMENT): N1..N3 required, N4 blank, 0 or N3 for
/// a triangle.
inline constexpr FieldSpec segment_node(std::string_view name, bool required) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = required ? 1 : 0,
                   .unit = "-",
                   .description = required ? "node id" : "node id (blank, 0 or N3: a triangle)",
                   .required = required};
}

/// Fails with "<FIELD> = <value> ... is not supported yet" when a field that plyform cannot
/// honour yet is not 0.
inline void require_zero(KeywordInput& in, int line, std::string_view field, double value,
                         std::string_view what) {
  if (value != 0.0) {
    in.fail(
        line, std::string(field),
        fmt::format("{} = {} ({}) is not supported yet; leave it blank or 0", field, value, what));
  }
}

/// Stores a once-per-deck keyword: the last one read wins, with a warning naming the first.
template <typename Desc>
void store_once(KeywordInput& in, std::optional<Desc>& slot, Desc desc) {
  if (slot) {
    in.warn(in.keyword().line, "",
            fmt::format("{} given again: this one replaces the one at {}:{}",
                        in.keyword().display(), slot->where.file, slot->where.line));
  }
  slot = std::move(desc);
}

/// A written 0 (or a blank) stands for LS-DYNA's default in the fields that use it so.
inline double zero_means(double value, double fallback) {
  return value == 0.0 ? fallback : value;
}

/// Reads the optional ID card of _ID (cards[0]) before each item; returns the data line that
/// follows, or nothing when the block is done.
struct IdAndLine {
  int id = 0;
  std::string heading;
  std::optional<DataLine> line;
};

inline IdAndLine next_item(KeywordInput& in, std::span<const CardSpec> cards) {
  IdAndLine item;
  const auto first = in.next_nonblank_line();
  if (!first || in.option() != "ID") {
    item.line = first;
    return item;
  }
  const CardValues id = in.read(cards[0], *first);
  item.id = id.integer("ID");
  item.heading = id.text("HEADING");
  item.line = in.next_line();
  if (!item.line) {
    in.fail(first->line, "", "missing card 1 after the ID card");
  }
  return item;
}

/// True when a data line that is not blank is left in the block.
inline bool has_more_cards(const KeywordInput& in) {
  for (const DataLine& line : in.remaining()) {
    for (char c : line.text) {
      if (c != ' ' && c != '\t' && c != '\r') {
        return true;
      }
    }
  }
  return false;
}

}  // namespace plyform::keyword
