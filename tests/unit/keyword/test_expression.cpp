#include <cmath>

#include <gtest/gtest.h>

#include "plyform/keyword/expression.hpp"

namespace plyform::keyword {
namespace {

double eval(std::string_view text, const ParameterTable& table = {}) {
  const ExpressionResult result = evaluate_expression(text, table);
  EXPECT_TRUE(result.value.has_value()) << text << ": " << result.error;
  return result.value.value_or(std::nan(""));
}

std::string eval_error(std::string_view text, const ParameterTable& table = {}) {
  const ExpressionResult result = evaluate_expression(text, table);
  EXPECT_FALSE(result.value.has_value()) << text << " gave " << *result.value;
  return result.error;
}

TEST(Expression, Arithmetic) {
  EXPECT_DOUBLE_EQ(eval("1+2*3"), 7.0);
  EXPECT_DOUBLE_EQ(eval("(1+2)*3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("2-3-4"), -5.0);
  EXPECT_DOUBLE_EQ(eval("8/4/2"), 1.0);
  EXPECT_DOUBLE_EQ(eval("2**3**2"), 512.0);
  EXPECT_DOUBLE_EQ(eval("-2**2"), -4.0);
  EXPECT_DOUBLE_EQ(eval("2**-1"), 0.5);
  EXPECT_DOUBLE_EQ(eval(" - ( 3 ) "), -3.0);
  EXPECT_DOUBLE_EQ(eval("1.5e3 + 2.d0"), 1502.0);
  EXPECT_DOUBLE_EQ(eval("1/3*3"), 1.0);
}

TEST(Expression, Functions) {
  EXPECT_NEAR(eval("sin(0.5)"), std::sin(0.5), 1e-15);
  EXPECT_NEAR(eval("COS(0.5)+tan(0.1)"), std::cos(0.5) + std::tan(0.1), 1e-15);
  EXPECT_NEAR(eval("asin(0.5)+acos(0.5)+atan(1)"), std::asin(0.5) + std::acos(0.5) + std::atan(1.0),
              1e-15);
  EXPECT_DOUBLE_EQ(eval("sqrt(16)"), 4.0);
  EXPECT_DOUBLE_EQ(eval("exp(0)+log(1)"), 1.0);
  EXPECT_DOUBLE_EQ(eval("abs(-2)"), 2.0);
  EXPECT_DOUBLE_EQ(eval("min(3, 1, 2)"), 1.0);
  EXPECT_DOUBLE_EQ(eval("max(3, 1, 2)"), 3.0);
}

TEST(Expression, Parameters) {
  ParameterTable table;
  table.define("a", {.type = 'R', .number = 2.0}, false);
  table.define("f_f", {.type = 'R', .number = 1.0}, false);
  EXPECT_DOUBLE_EQ(eval("&a*3", table), 6.0);
  EXPECT_DOUBLE_EQ(eval("2-f_f", table), 1.0);  // names without & as in real decks
  EXPECT_DOUBLE_EQ(eval("(&a)*&a", table), 4.0);
  EXPECT_EQ(eval_error("&b+1", table), "undefined parameter &b");
}

TEST(Expression, Errors) {
  EXPECT_EQ(eval_error("foo(1)"), "unknown function foo");
  EXPECT_EQ(eval_error("1/0"), "division by zero");
  EXPECT_NE(eval_error("sqrt(-1)").find("finite"), std::string::npos);
  EXPECT_NE(eval_error("log(0)").find("finite"), std::string::npos);
  EXPECT_NE(eval_error("1+").find("value is expected"), std::string::npos);
  EXPECT_NE(eval_error("(1+2").find("missing ')'"), std::string::npos);
  EXPECT_NE(eval_error("1 2").find("unexpected '2'"), std::string::npos);
  EXPECT_NE(eval_error("2^3").find("unexpected '^'"), std::string::npos);
  EXPECT_NE(eval_error("sin(1,2)").find("takes 1 argument"), std::string::npos);
  EXPECT_NE(eval_error("").find("value is expected"), std::string::npos);
  EXPECT_NE(eval_error(std::string(500, '(') + "1" + std::string(500, ')')).find("deeply"),
            std::string::npos);
}

}  // namespace
}  // namespace plyform::keyword
