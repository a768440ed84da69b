#include "plyform/keyword/expression.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "plyform/keyword/number_parser.hpp"
#include "text_utils.hpp"

namespace plyform::keyword {
namespace {

struct ExpressionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Recursive-descent evaluator. Grammar:
///   sum     := product (('+' | '-') product)*
///   product := unary (('*' | '/') unary)*
///   unary   := ('+' | '-') unary | power
///   power   := primary ('**' unary)?          (right associative, -2**2 = -4)
///   primary := number | ['&'] name | name '(' sum (',' sum)* ')' | '(' sum ')'
class Evaluator {
 public:
  Evaluator(std::string_view text, const ParameterTable& parameters)
      : text_(text), parameters_(parameters) {}

  double run() {
    const double value = sum();
    skip_blanks();
    if (pos_ < text_.size()) {
      fail(fmt::format("unexpected '{}' at position {}", text_[pos_], pos_ + 1));
    }
    return value;
  }

 private:
  static constexpr int kMaxDepth = 200;

  [[noreturn]] static void fail(const std::string& message) { throw ExpressionError(message); }

  void skip_blanks() {
    while (pos_ < text_.size() && is_blank_char(text_[pos_])) {
      ++pos_;
    }
  }

  bool accept(std::string_view token) {
    skip_blanks();
    if (text_.substr(pos_, token.size()) == token) {
      pos_ += token.size();
      return true;
    }
    return false;
  }

  static double checked(double value, std::string_view what) {
    if (!std::isfinite(value)) {
      fail(fmt::format("{} does not give a finite number", what));
    }
    return value;
  }

  double sum() {
    double value = product();
    for (;;) {
      if (accept("+")) {
        value = checked(value + product(), "+");
      } else if (accept("-")) {
        value = checked(value - product(), "-");
      } else {
        return value;
      }
    }
  }

  double product() {
    double value = unary();
    for (;;) {
      skip_blanks();
      if (text_.substr(pos_, 2) == "**") {
        return value;  // handled in power(); cannot occur here
      }
      if (accept("*")) {
        value = checked(value * unary(), "*");
      } else if (accept("/")) {
        const double divisor = unary();
        if (divisor == 0.0) {
          fail("division by zero");
        }
        value = checked(value / divisor, "/");
      } else {
        return value;
      }
    }
  }

  double unary() {
    if (++depth_ > kMaxDepth) {
      fail("expression nested too deeply");
    }
    double value = 0.0;
    if (accept("-")) {
      value = -unary();
    } else if (accept("+")) {
      value = unary();
    } else {
      value = power();
    }
    --depth_;
    return value;
  }

  double power() {
    const double base = primary();
    if (accept("**")) {
      return checked(std::pow(base, unary()), "**");
    }
    return base;
  }

  double primary() {
    skip_blanks();
    if (pos_ >= text_.size()) {
      fail("expression ends where a value is expected");
    }
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      const double value = sum();
      if (!accept(")")) {
        fail("missing ')'");
      }
      return value;
    }
    if (is_digit(c) || c == '.') {
      return number();
    }
    const bool ampersand = c == '&';
    if (ampersand) {
      ++pos_;
    }
    const std::string_view name = identifier();
    if (name.empty()) {
      fail(fmt::format("unexpected '{}' at position {}", c, pos_ + 1));
    }
    if (!ampersand && accept("(")) {
      return call(name);
    }
    const Parameter* parameter = parameters_.find(name);
    if (parameter == nullptr) {
      fail(fmt::format("undefined parameter &{}", name));
    }
    if (parameter->type == 'C') {
      fail(fmt::format("parameter &{} is a character parameter", name));
    }
    return parameter->number;
  }

  std::string_view identifier() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (is_alpha(text_[pos_]) || is_digit(text_[pos_]) || text_[pos_] == '_')) {
      ++pos_;
    }
    return text_.substr(start, pos_ - start);
  }

  double number() {
    // Digits, a point, digits, then an exponent with e/E/d/D (no Fortran "1.0-3" here: the
    // minus is an operator in an expression).
    const std::size_t start = pos_;
    while (pos_ < text_.size() && (is_digit(text_[pos_]) || text_[pos_] == '.')) {
      ++pos_;
    }
    if (pos_ < text_.size() &&
        std::string_view("eEdD").find(text_[pos_]) != std::string_view::npos) {
      std::size_t after = pos_ + 1;
      if (after < text_.size() && (text_[after] == '+' || text_[after] == '-')) {
        ++after;
      }
      if (after < text_.size() && is_digit(text_[after])) {
        pos_ = after;
        while (pos_ < text_.size() && is_digit(text_[pos_])) {
          ++pos_;
        }
      }
    }
    const std::string_view literal = text_.substr(start, pos_ - start);
    const std::optional<double> value = parse_real(literal);
    if (!value) {
      fail(fmt::format("bad number '{}'", literal));
    }
    return *value;
  }

  double call(std::string_view name) {
    std::vector<double> args;
    if (!accept(")")) {
      do {
        args.push_back(sum());
      } while (accept(","));
      if (!accept(")")) {
        fail(fmt::format("missing ')' after the arguments of {}", name));
      }
    }
    const std::string upper = to_upper(name);
    const auto one = [&](double (*f)(double)) {
      if (args.size() != 1) {
        fail(fmt::format("{} takes 1 argument, got {}", name, args.size()));
      }
      return checked(f(args[0]), fmt::format("{}({})", name, args[0]));
    };
    if (upper == "SIN")
      return one([](double x) { return std::sin(x); });
    if (upper == "COS")
      return one([](double x) { return std::cos(x); });
    if (upper == "TAN")
      return one([](double x) { return std::tan(x); });
    if (upper == "ASIN")
      return one([](double x) { return std::asin(x); });
    if (upper == "ACOS")
      return one([](double x) { return std::acos(x); });
    if (upper == "ATAN")
      return one([](double x) { return std::atan(x); });
    if (upper == "SQRT")
      return one([](double x) { return std::sqrt(x); });
    if (upper == "EXP")
      return one([](double x) { return std::exp(x); });
    if (upper == "LOG")
      return one([](double x) { return std::log(x); });
    if (upper == "LOG10")
      return one([](double x) { return std::log10(x); });
    if (upper == "ABS")
      return one([](double x) { return std::fabs(x); });
    if (upper == "ATAN2") {
      if (args.size() != 2) {
        fail(fmt::format("{} takes 2 arguments, got {}", name, args.size()));
      }
      return std::atan2(args[0], args[1]);
    }
    if (upper == "MIN" || upper == "MAX") {
      if (args.empty()) {
        fail(fmt::format("{} needs at least 1 argument", name));
      }
      double value = args[0];
      for (double arg : args) {
        value = upper == "MIN" ? std::min(value, arg) : std::max(value, arg);
      }
      return value;
    }
    fail(fmt::format("unknown function {}", name));
  }

  std::string_view text_;
  const ParameterTable& parameters_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

ExpressionResult evaluate_expression(std::string_view text, const ParameterTable& parameters) {
  try {
    return {Evaluator(trim(text), parameters).run(), {}};
  } catch (const ExpressionError& error) {
    return {std::nullopt, error.what()};
  }
}

}  // namespace plyform::keyword
