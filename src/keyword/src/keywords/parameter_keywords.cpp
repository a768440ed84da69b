// *PARAMETER, *PARAMETER_LOCAL, *PARAMETER_EXPRESSION(_LOCAL): named values for &name fields.
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "../keyword_input.hpp"
#include "../keyword_registry.hpp"
#include "../text_utils.hpp"
#include "plyform/keyword/expression.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<std::string_view, 4> kOptions{"", "LOCAL", "EXPRESSION", "EXPRESSION_LOCAL"};

constexpr std::string_view kPrmrDescription =
    "type letter R (real), I (integer) or C (character) in column 1, then the name (up to 9 "
    "characters in fixed format); blank: no parameter";
constexpr std::string_view kValDescription =
    "value: a number for R and I (&name allowed), text for C";

constexpr std::array kValueFields{
    FieldSpec{.name = "PRMR1", .type = FieldType::kText, .description = kPrmrDescription},
    FieldSpec{.name = "VAL1", .type = FieldType::kText, .description = kValDescription},
    FieldSpec{.name = "PRMR2", .type = FieldType::kText, .description = kPrmrDescription},
    FieldSpec{.name = "VAL2", .type = FieldType::kText, .description = kValDescription},
    FieldSpec{.name = "PRMR3", .type = FieldType::kText, .description = kPrmrDescription},
    FieldSpec{.name = "VAL3", .type = FieldType::kText, .description = kValDescription},
    FieldSpec{.name = "PRMR4", .type = FieldType::kText, .description = kPrmrDescription},
    FieldSpec{.name = "VAL4", .type = FieldType::kText, .description = kValDescription},
};
constexpr std::array kExpressionFields{
    FieldSpec{.name = "PRMR", .type = FieldType::kText, .description = kPrmrDescription},
    FieldSpec{.name = "EXPRESSION",
              .type = FieldType::kText,
              .width = 70,
              .description = "numbers, parameters (&name or name), + - * / **, parentheses and "
                             "sin cos tan asin acos atan atan2 sqrt exp log log10 abs min max "
                             "(radians); I parameters take the value truncated toward zero",
              .rest_of_line = true},
};
constexpr std::array kCards{
    CardSpec{.title = "Value cards",
             .fields = kValueFields,
             .presence = "without _EXPRESSION; until the next keyword"},
    CardSpec{.title = "Expression cards",
             .fields = kExpressionFields,
             .presence = "with _EXPRESSION; one parameter per card, until the next keyword"},
};

struct TypedName {
  char type;
  std::string name;
};

/// "R    dtout" -> {'R', "dtout"}; throws (via in.fail) on a bad type or name.
TypedName parse_typed_name(KeywordInput& in, std::string_view text, int line,
                           std::string_view field) {
  const char type = to_upper(text.substr(0, 1)).front();
  if (type != 'R' && type != 'I' && type != 'C') {
    in.fail(line, std::string(field),
            fmt::format("'{}' does not start with a type letter R, I or C", text));
  }
  const std::string_view name = trim(text.substr(1));
  if (name.empty()) {
    in.fail(line, std::string(field), "the parameter name is missing after the type letter");
  }
  for (char c : name) {
    if (!is_alpha(c) && !is_digit(c) && c != '_') {
      in.fail(line, std::string(field),
              fmt::format("bad parameter name '{}': use letters, digits and '_'", name));
    }
  }
  return {type, std::string(name)};
}

void define(KeywordInput& in, TypedName typed, Parameter value, bool local, int line) {
  value.type = typed.type;
  value.where = in.where(line);
  if (typed.type == 'I') {
    value.number = std::trunc(value.number);
  }
  if (const Parameter* earlier = in.parameters().define(typed.name, std::move(value), local)) {
    in.warn(line, "",
            fmt::format("parameter {} is already defined at {}:{}; the first definition is kept",
                        typed.name, earlier->where.file, earlier->where.line));
  }
}

void read_values(KeywordInput& in, bool local) {
  const CardSpec& card = kCards[0];
  while (const auto line = in.next_nonblank_line()) {
    const CardValues values = in.read(card, *line);
    for (std::size_t pair = 0; pair < 4; ++pair) {
      const FieldValue& prmr = values.at(2 * pair);
      const FieldValue& val = values.at(2 * pair + 1);
      const std::string_view prmr_name = card.fields[2 * pair].name;
      const std::string_view val_name = card.fields[2 * pair + 1].name;
      if (prmr.blank) {
        if (!val.blank) {
          in.fail(line->line, std::string(prmr_name), "a value is given without a parameter name");
        }
        continue;
      }
      const TypedName typed = parse_typed_name(in, prmr.text, line->line, prmr_name);
      Parameter parameter;
      if (typed.type == 'C') {
        parameter.text = val.text;
      } else {
        const FieldSpec spec{.name = val_name,
                             .type = typed.type == 'I' ? FieldType::kInteger : FieldType::kReal,
                             .required = true};
        auto converted = convert_field(spec, val.text, in.parameters(), val_name);
        if (auto* error = std::get_if<FieldError>(&converted)) {
          in.fail(line->line, error->field, error->message);
        }
        parameter.number = std::get<FieldValue>(converted).real;
      }
      define(in, typed, std::move(parameter), local, line->line);
    }
  }
}

void read_expressions(KeywordInput& in, bool local) {
  const CardSpec& card = kCards[1];
  while (const auto line = in.next_nonblank_line()) {
    const CardValues values = in.read(card, *line);
    if (values.blank("PRMR")) {
      in.fail(line->line, "PRMR", "the parameter name is missing");
    }
    const TypedName typed = parse_typed_name(in, values.text("PRMR"), line->line, "PRMR");
    if (typed.type == 'C') {
      in.fail(line->line, "PRMR", "a character parameter cannot be an expression");
    }
    if (values.blank("EXPRESSION")) {
      in.fail(line->line, "EXPRESSION", "the expression is missing");
    }
    const ExpressionResult result = evaluate_expression(values.text("EXPRESSION"), in.parameters());
    if (!result.value) {
      in.fail(line->line, "EXPRESSION", result.error);
    }
    Parameter parameter;
    parameter.number = *result.value;
    define(in, typed, std::move(parameter), local, line->line);
  }
}

void read_parameter(KeywordInput& in) {
  const std::string_view option = in.option();
  const bool local = option == "LOCAL" || option == "EXPRESSION_LOCAL";
  if (option == "EXPRESSION" || option == "EXPRESSION_LOCAL") {
    read_expressions(in, local);
  } else {
    read_values(in, local);
  }
}

}  // namespace

KeywordSpec parameter_keyword() {
  return {.name = "PARAMETER",
          .options = kOptions,
          .handler = read_parameter,
          .cards = kCards,
          .summary =
              "Named values that numeric fields use as `&name` (or `-&name` for the "
              "negated value), in any card read after the definition. *PARAMETER values "
              "are global; _LOCAL ones are seen only in the file that defines them and "
              "the files it includes. Names are case sensitive. A name defined twice "
              "keeps its first value, with a warning."};
}

}  // namespace plyform::keyword
