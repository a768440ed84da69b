#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "plyform/keyword/card_spec.hpp"
#include "plyform/keyword/parameter_table.hpp"

namespace plyform::keyword {

/// The value of one field after reading: blank fields hold the field's default.
struct FieldValue {
  bool blank = true;
  long long integer = 0;  ///< integer fields
  double real = 0.0;      ///< real fields (and integer fields, converted)
  std::string text;       ///< text fields
};

/// A field that could not be read; field is the display name ("SFA", "A3").
struct FieldError {
  std::string field;
  std::string message;
};

/// The values of one card, in the order of its CardSpec.
class CardValues {
 public:
  CardValues(const CardSpec& card, std::vector<FieldValue> values);

  std::size_t size() const { return values_.size(); }
  const FieldValue& at(std::size_t index) const { return values_.at(index); }
  /// By field name as in the CardSpec; an unknown name is a programming error (throws).
  const FieldValue& at(std::string_view name) const;

  int integer(std::string_view name) const { return static_cast<int>(at(name).integer); }
  double real(std::string_view name) const { return at(name).real; }
  const std::string& text(std::string_view name) const { return at(name).text; }
  bool blank(std::string_view name) const { return at(name).blank; }

 private:
  const CardSpec* card_;
  std::vector<FieldValue> values_;
};

/// True when the line is read in free format (it has a comma and the card is not one text
/// field taking the whole line).
bool is_free_format(const CardSpec& card, std::string_view line);

/// Converts the trimmed text of one field: a blank gives the default (or an error if required),
/// "&name" and "-&name" take a parameter's value, numbers follow parse_real/parse_integer, and
/// the allowed range is checked. display_name names the field in errors.
std::variant<FieldValue, FieldError> convert_field(const FieldSpec& spec, std::string_view text,
                                                   const ParameterTable& parameters,
                                                   std::string_view display_name);

/// Reads one card line in fixed format (fields of spec widths) or free format (comma
/// separated). repeat is the 0-based occurrence of a repeated card, for field names.
std::variant<CardValues, FieldError> read_card(const CardSpec& card, std::string_view line,
                                               const ParameterTable& parameters, int repeat = 0);

}  // namespace plyform::keyword
