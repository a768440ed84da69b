#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace plyform::keyword {

enum class FieldType { kInteger, kReal, kText };

/// One field of a card: the data the reader checks against and the reference is made from.
struct FieldSpec {
  std::string_view name;
  FieldType type = FieldType::kReal;
  int width = 10;                     ///< characters in fixed format
  double default_value = 0.0;         ///< value of a blank numeric field
  std::optional<double> min_value{};  ///< allowed range, inclusive
  std::optional<double> max_value{};
  std::string_view unit{};  ///< "-" for dimensionless; empty when it depends on use
  std::string_view description{};
  bool required = false;       ///< a blank field is an error
  bool rest_of_line = false;   ///< text taking the rest of the line (no comma splitting after it)
  bool max_exclusive = false;  ///< the range excludes max_value: [min, max)
  /// Integer fields: the only values accepted (checked after the range); empty = any.
  std::span<const int> allowed{};
  /// Added to the message when a value is not in `allowed` (what is not supported, and why).
  std::string_view allowed_note{};
};

/// How the names of fields of a repeated card are shown in messages.
enum class FieldNumbering {
  kPlain,      ///< the name as is
  kPerCard,    ///< name + card number: A1 O1, A2 O2, ...
  kSequential  ///< name + running number over all cards: UC1..UC8, UC9..UC16, ...
};

/// One card (line) of a keyword.
struct CardSpec {
  std::string_view title;  ///< e.g. "Card 1", "Point cards"
  std::span<const FieldSpec> fields;
  std::string_view presence{};  ///< when the card appears, e.g. "repeated until the next keyword"
  FieldNumbering numbering = FieldNumbering::kPlain;
};

/// The name of field `index` of the `repeat`-th (0-based) occurrence of a card, as shown in
/// messages: "SFA", "A3", "UC12".
std::string field_display_name(const CardSpec& card, std::size_t index, int repeat);

}  // namespace plyform::keyword
