#include <gtest/gtest.h>

#include "plyform/keyword/number_parser.hpp"

namespace plyform::keyword {
namespace {

TEST(ParseReal, AcceptsTheUsualForms) {
  EXPECT_DOUBLE_EQ(*parse_real("1.5"), 1.5);
  EXPECT_DOUBLE_EQ(*parse_real(".5"), 0.5);
  EXPECT_DOUBLE_EQ(*parse_real("-.5"), -0.5);
  EXPECT_DOUBLE_EQ(*parse_real("2."), 2.0);
  EXPECT_DOUBLE_EQ(*parse_real("+3"), 3.0);
  EXPECT_DOUBLE_EQ(*parse_real("0"), 0.0);
  EXPECT_DOUBLE_EQ(*parse_real("1e3"), 1000.0);
  EXPECT_DOUBLE_EQ(*parse_real("1.0E+3"), 1000.0);
  EXPECT_DOUBLE_EQ(*parse_real("1.000000E8"), 1.0e8);
  EXPECT_DOUBLE_EQ(*parse_real("1.0d3"), 1000.0);
  EXPECT_DOUBLE_EQ(*parse_real("1.0D-3"), 1.0e-3);
  EXPECT_DOUBLE_EQ(*parse_real("0.89999998"), 0.89999998);
}

TEST(ParseReal, AcceptsFortranExponentsWithoutLetter) {
  EXPECT_DOUBLE_EQ(*parse_real("1.00000+4"), 1.0e4);
  EXPECT_DOUBLE_EQ(*parse_real("1.0-3"), 1.0e-3);
  EXPECT_DOUBLE_EQ(*parse_real("-1.5-2"), -0.015);
  EXPECT_DOUBLE_EQ(*parse_real("2+10"), 2.0e10);
}

TEST(ParseReal, RejectsEverythingElse) {
  for (const char* bad : {"", "abc", "1.2.3", "e5", ".", "-", "1e", "1.0+", "--1", "+-1", "nan",
                          "inf", "1 2", "0x10", "1.0e3x", "<PAB_TTF-1.1>", "1,5", "1e999"}) {
    EXPECT_FALSE(parse_real(bad).has_value()) << "'" << bad << "'";
  }
}

TEST(ParseInteger, AcceptsSignAndDigitsOnly) {
  EXPECT_EQ(*parse_integer("42"), 42);
  EXPECT_EQ(*parse_integer("-7"), -7);
  EXPECT_EQ(*parse_integer("+3"), 3);
  EXPECT_EQ(*parse_integer("1004160"), 1004160);
  for (const char* bad : {"", "4.0", "1e3", "+-1", "-", "x1", "99999999999999999999999"}) {
    EXPECT_FALSE(parse_integer(bad).has_value()) << "'" << bad << "'";
  }
}

}  // namespace
}  // namespace plyform::keyword
