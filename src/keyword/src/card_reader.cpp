#include "plyform/keyword/card_reader.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "plyform/keyword/number_parser.hpp"
#include "text_utils.hpp"

namespace plyform::keyword {
namespace {

FieldError field_error(std::string_view field, std::string message) {
  return FieldError{std::string(field), std::move(message)};
}

std::string format_number(double value, FieldType type) {
  if (type == FieldType::kInteger) {
    return fmt::format("{}", static_cast<long long>(value));
  }
  return fmt::format("{}", value);
}

/// Checks spec's allowed range; empty string when the value is allowed.
std::string range_problem(const FieldSpec& spec, double value) {
  const bool low = spec.min_value && value < *spec.min_value;
  const bool high =
      spec.max_value && (spec.max_exclusive ? value >= *spec.max_value : value > *spec.max_value);
  if (!low && !high) {
    if (!spec.allowed.empty() &&
        std::find(spec.allowed.begin(), spec.allowed.end(), value) == spec.allowed.end()) {
      return fmt::format("value {} is not supported: must be one of {}{}{}",
                         format_number(value, spec.type), fmt::join(spec.allowed, ", "),
                         spec.allowed_note.empty() ? "" : "; ", spec.allowed_note);
    }
    return {};
  }
  const std::string shown = format_number(value, spec.type);
  if (spec.min_value && spec.max_value) {
    return fmt::format("value {} is out of range: must be in [{}, {}{}", shown,
                       format_number(*spec.min_value, spec.type),
                       format_number(*spec.max_value, spec.type), spec.max_exclusive ? ")" : "]");
  }
  if (low) {
    return fmt::format("value {} is out of range: must be >= {}", shown,
                       format_number(*spec.min_value, spec.type));
  }
  return fmt::format("value {} is out of range: must be {} {}", shown,
                     spec.max_exclusive ? "<" : "<=", format_number(*spec.max_value, spec.type));
}

/// A real with a point or an exponent letter; "1+2", Fortran's 1e2 without its letter, is not
/// taken for an integer.
bool written_as_real(std::string_view text) {
  return text.find_first_of(".eEdD") != std::string_view::npos;
}

/// The number of an integer field's text, or what is wrong with it. Digits are read as they
/// are; a real written with a point or an exponent ("0.0", "3.", "2.0E+00", "2.0D+00") is read
/// as the integer it equals, as LS-DYNA does (decks written by other tools put reals in integer
/// fields), and refused when it is not a whole number. The int range is checked by the caller.
std::variant<double, std::string> integer_number(std::string_view text) {
  if (const std::optional<long long> parsed = parse_integer(text)) {
    if (*parsed < INT_MIN || *parsed > INT_MAX) {
      return fmt::format("value {} does not fit a 32-bit integer", *parsed);
    }
    return static_cast<double>(*parsed);
  }
  const std::string_view digits = text.substr(text[0] == '-' || text[0] == '+' ? 1 : 0);
  if (!digits.empty() && std::all_of(digits.begin(), digits.end(), is_digit)) {
    return fmt::format("value {} does not fit a 32-bit integer", text);  // beyond 64 bits
  }
  const std::optional<double> real = parse_real(text);
  if (!real || !written_as_real(text)) {
    return fmt::format("expected an integer, got '{}'", text);
  }
  if (*real != std::trunc(*real)) {
    return fmt::format("expected an integer, got '{}', which is not a whole number", text);
  }
  return *real + 0.0;  // -0.0 reads as 0
}

/// Column where the first field taking the rest of the line starts (npos if none).
std::size_t rest_of_line_column(const CardSpec& card) {
  std::size_t column = 0;
  for (const FieldSpec& field : card.fields) {
    if (field.rest_of_line) {
      return column;
    }
    column += static_cast<std::size_t>(field.width);
  }
  return std::string_view::npos;
}

/// Cuts a line into the raw texts of the card's fields; returns false if there are more
/// non-blank free-format fields than the card has.
bool split_fields(const CardSpec& card, std::string_view line, std::vector<std::string_view>& raw) {
  const std::size_t n = card.fields.size();
  raw.assign(n, std::string_view{});
  if (!is_free_format(card, line)) {
    std::size_t column = 0;
    for (std::size_t i = 0; i < n && column < line.size(); ++i) {
      const FieldSpec& field = card.fields[i];
      raw[i] = field.rest_of_line ? line.substr(column)
                                  : line.substr(column, static_cast<std::size_t>(field.width));
      column += static_cast<std::size_t>(field.width);
    }
    return true;
  }
  std::string_view rest = line;
  bool more = true;
  for (std::size_t i = 0; i < n && more; ++i) {
    const std::size_t comma = rest.find(',');
    if (card.fields[i].rest_of_line || comma == std::string_view::npos) {
      raw[i] = rest;
      more = false;
    } else {
      raw[i] = rest.substr(0, comma);
      rest.remove_prefix(comma + 1);
    }
  }
  if (more) {
    for (char c : rest) {
      if (c != ',' && !is_blank_char(c)) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace

CardValues::CardValues(const CardSpec& card, std::vector<FieldValue> values)
    : card_(&card), values_(std::move(values)) {}

const FieldValue& CardValues::at(std::string_view name) const {
  for (std::size_t i = 0; i < card_->fields.size(); ++i) {
    if (card_->fields[i].name == name) {
      return values_.at(i);
    }
  }
  throw std::out_of_range(fmt::format("card '{}' has no field {}", card_->title, name));
}

bool is_free_format(const CardSpec& card, std::string_view line) {
  const std::size_t comma = line.find(',');
  if (comma == std::string_view::npos) {
    return false;
  }
  // A comma inside a text field that takes the rest of the line (a title, an expression)
  // does not make the card free format.
  return comma <= rest_of_line_column(card);
}

std::variant<FieldValue, FieldError> convert_field(const FieldSpec& spec, std::string_view text,
                                                   const ParameterTable& parameters,
                                                   std::string_view display_name) {
  FieldValue value;
  text = trim(text);
  if (text.empty()) {
    if (spec.required) {
      return field_error(display_name, "a value is required");
    }
    value.real = spec.default_value;
    value.integer = static_cast<long long>(spec.default_value);
    return value;
  }
  value.blank = false;
  if (spec.type == FieldType::kText) {
    value.text = std::string(text);
    return value;
  }

  double number = 0.0;
  const bool negated_reference = text.size() > 1 && text[0] == '-' && text[1] == '&';
  if (text[0] == '&' || negated_reference) {
    const std::string_view name = trim(text.substr(negated_reference ? 2 : 1));
    const Parameter* parameter = parameters.find(name);
    if (parameter == nullptr) {
      return field_error(display_name, fmt::format("undefined parameter &{}", name));
    }
    if (parameter->type == 'C') {
      return field_error(
          display_name,
          fmt::format("parameter &{} is a character parameter; a number is needed", name));
    }
    number = negated_reference ? -parameter->number : parameter->number;
    if (spec.type == FieldType::kInteger && number != std::trunc(number)) {
      return field_error(display_name,
                         fmt::format("parameter &{} = {} is not an integer", name, number));
    }
  } else if (spec.type == FieldType::kInteger) {
    auto read = integer_number(text);
    if (auto* message = std::get_if<std::string>(&read)) {
      return field_error(display_name, std::move(*message));
    }
    number = std::get<double>(read);
  } else {
    const std::optional<double> parsed = parse_real(text);
    if (!parsed) {
      return field_error(display_name, fmt::format("expected a real number, got '{}'", text));
    }
    number = *parsed;
  }

  if (spec.type == FieldType::kInteger) {
    if (number < static_cast<double>(INT_MIN) || number > static_cast<double>(INT_MAX)) {
      return field_error(display_name,
                         fmt::format("value {} does not fit a 32-bit integer", number));
    }
    value.integer = static_cast<long long>(number);
  }
  value.real = number;
  if (std::string problem = range_problem(spec, number); !problem.empty()) {
    return field_error(display_name, std::move(problem));
  }
  return value;
}

std::variant<CardValues, FieldError> read_card(const CardSpec& card, std::string_view line,
                                               const ParameterTable& parameters, int repeat) {
  std::string untabbed;
  if (line.find('\t') != std::string_view::npos) {
    // A tab counts as one blank, which keeps trailing tabs (the common case) harmless.
    untabbed.assign(line);
    for (char& c : untabbed) {
      if (c == '\t') {
        c = ' ';
      }
    }
    line = untabbed;
  }
  std::vector<std::string_view> raw;
  if (!split_fields(card, line, raw)) {
    return FieldError{"",
                      fmt::format("too many fields on the card: it has {}", card.fields.size())};
  }
  std::vector<FieldValue> values;
  values.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    auto converted =
        convert_field(card.fields[i], raw[i], parameters, field_display_name(card, i, repeat));
    if (auto* error = std::get_if<FieldError>(&converted)) {
      return std::move(*error);
    }
    values.push_back(std::move(std::get<FieldValue>(converted)));
  }
  return CardValues(card, std::move(values));
}

}  // namespace plyform::keyword
