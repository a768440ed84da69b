#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "plyform/keyword/card_reader.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kFields{
    FieldSpec{.name = "N",
              .type = FieldType::kInteger,
              .default_value = 5,
              .min_value = 0,
              .max_value = 10},
    FieldSpec{.name = "X", .type = FieldType::kReal, .default_value = 1.5},
    FieldSpec{.name = "T", .type = FieldType::kText},
};
constexpr CardSpec kCard{.title = "test card", .fields = kFields};

constexpr std::array kWideFields{
    FieldSpec{.name = "A", .type = FieldType::kReal, .width = 20},
    FieldSpec{.name = "O", .type = FieldType::kReal, .width = 20},
};
constexpr CardSpec kPointCard{
    .title = "points", .fields = kWideFields, .numbering = FieldNumbering::kPerCard};

constexpr std::array kTitleFields{
    FieldSpec{.name = "TITLE", .type = FieldType::kText, .width = 80, .rest_of_line = true},
};
constexpr CardSpec kTitleCard{.title = "title", .fields = kTitleFields};

CardValues read_ok(const CardSpec& card, std::string_view line, const ParameterTable& table = {}) {
  auto result = read_card(card, line, table);
  if (auto* error = std::get_if<FieldError>(&result)) {
    ADD_FAILURE() << "field " << error->field << ": " << error->message;
  }
  return std::get<CardValues>(result);
}

FieldError read_error(const CardSpec& card, std::string_view line, const ParameterTable& table = {},
                      int repeat = 0) {
  auto result = read_card(card, line, table, repeat);
  EXPECT_TRUE(std::holds_alternative<FieldError>(result)) << "'" << line << "' was accepted";
  return std::holds_alternative<FieldError>(result) ? std::get<FieldError>(result) : FieldError{};
}

ParameterTable parameters() {
  ParameterTable table;
  table.define("p", {.type = 'R', .number = 2.5}, false);
  table.define("n", {.type = 'I', .number = 7}, false);
  table.define("c", {.type = 'C', .text = "word"}, false);
  return table;
}

TEST(CardReader, FixedFormatFields) {
  const CardValues v = read_ok(kCard, "         3       2.5     hello");
  EXPECT_EQ(v.integer("N"), 3);
  EXPECT_DOUBLE_EQ(v.real("X"), 2.5);
  EXPECT_EQ(v.text("T"), "hello");
  EXPECT_FALSE(v.blank("N"));
}

TEST(CardReader, BlankAndMissingFieldsTakeDefaults) {
  for (const char* line : {"", "                              ", "          "}) {
    const CardValues v = read_ok(kCard, line);
    EXPECT_TRUE(v.blank("N"));
    EXPECT_EQ(v.integer("N"), 5);
    EXPECT_DOUBLE_EQ(v.real("X"), 1.5);
    EXPECT_EQ(v.text("T"), "");
  }
}

TEST(CardReader, FreeFormat) {
  CardValues v = read_ok(kCard, "3, 2.5, hi there");
  EXPECT_EQ(v.integer("N"), 3);
  EXPECT_DOUBLE_EQ(v.real("X"), 2.5);
  EXPECT_EQ(v.text("T"), "hi there");
  v = read_ok(kCard, "4,,");
  EXPECT_EQ(v.integer("N"), 4);
  EXPECT_TRUE(v.blank("X"));
  EXPECT_DOUBLE_EQ(v.real("X"), 1.5);
  v = read_ok(kPointCard, "30.01,0.0");
  EXPECT_DOUBLE_EQ(v.real("A"), 30.01);
  v = read_ok(kCard, " 8 , .01 ,");
  EXPECT_EQ(v.integer("N"), 8);
  EXPECT_DOUBLE_EQ(v.real("X"), 0.01);
}

TEST(CardReader, FortranExponentsAndWideFields) {
  const CardValues v = read_ok(kPointCard, "           1.00000+4              1.0-3");
  EXPECT_DOUBLE_EQ(v.real("A"), 1.0e4);
  EXPECT_DOUBLE_EQ(v.real("O"), 1.0e-3);
}

TEST(CardReader, ParameterReferences) {
  const ParameterTable table = parameters();
  CardValues v = read_ok(kCard, "&n        -&p", table);
  EXPECT_EQ(v.integer("N"), 7);
  EXPECT_DOUBLE_EQ(v.real("X"), -2.5);
  v = read_ok(kCard, "        &n        &p", table);
  EXPECT_DOUBLE_EQ(v.real("X"), 2.5);
  v = read_ok(kCard, "&n,-&p", table);
  EXPECT_EQ(v.integer("N"), 7);
  EXPECT_DOUBLE_EQ(v.real("X"), -2.5);
}

TEST(CardReader, ParameterErrors) {
  const ParameterTable table = parameters();
  FieldError e = read_error(kCard, "&nope", table);
  EXPECT_EQ(e.field, "N");
  EXPECT_EQ(e.message, "undefined parameter &nope");
  e = read_error(kCard, "&p", table);
  EXPECT_EQ(e.message, "parameter &p = 2.5 is not an integer");
  e = read_error(kCard, "          &c", table);
  EXPECT_EQ(e.field, "X");
  EXPECT_NE(e.message.find("character parameter"), std::string::npos);
}

TEST(CardReader, BadNumbers) {
  FieldError e = read_error(kCard, "          abc");
  EXPECT_EQ(e.field, "X");
  EXPECT_EQ(e.message, "expected a real number, got 'abc'");
  e = read_error(kCard, "       2.5");
  EXPECT_EQ(e.field, "N");
  EXPECT_EQ(e.message, "expected an integer, got '2.5', which is not a whole number");
  e = read_error(kCard, "       abc");
  EXPECT_EQ(e.message, "expected an integer, got 'abc'");
  e = read_error(kCard, "3, 1.2.3");
  EXPECT_EQ(e.field, "X");
  e = read_error(kCard, "99999999999,");
  EXPECT_EQ(e.message, "value 99999999999 does not fit a 32-bit integer");
}

// LS-DYNA reads a real with a whole value in an integer field as that integer (decks written by
// other tools have TGRLC 0.0, NIP 3., ...), in fixed and free format, and D exponents too.
constexpr std::array kIntegerFields{
    FieldSpec{.name = "I", .type = FieldType::kInteger},
    FieldSpec{.name = "J", .type = FieldType::kInteger},
};
constexpr CardSpec kIntegerCard{.title = "integers", .fields = kIntegerFields};

int integer_of(std::string_view line, const char* field = "I") {
  return read_ok(kIntegerCard, line).integer(field);
}

TEST(CardReader, IntegralRealInIntegerFieldIsThatInteger) {
  EXPECT_EQ(integer_of("       0.0"), 0);
  EXPECT_EQ(integer_of("0.0,"), 0);
}

TEST(CardReader, IntegralRealWithTrailingPoint) {
  EXPECT_EQ(integer_of("        3."), 3);
  EXPECT_EQ(integer_of("3.,"), 3);
}

TEST(CardReader, IntegralRealWithExponent) {
  EXPECT_EQ(integer_of("   2.0E+00"), 2);
  EXPECT_EQ(integer_of(" 2.0e+00,1.5e1"), 2);
  EXPECT_EQ(integer_of(" 2.0e+00,1.5e1", "J"), 15);
  EXPECT_EQ(integer_of("     1.E3"), 1000);
}

TEST(CardReader, IntegralRealWithFortranDExponent) {
  EXPECT_EQ(integer_of("   2.0D+00"), 2);
  EXPECT_EQ(integer_of("2.0d+00,"), 2);
}

TEST(CardReader, NegativeIntegralReal) {
  EXPECT_EQ(integer_of("      -1.0"), -1);
  EXPECT_EQ(integer_of(",-1.0", "J"), -1);
  const CardValues v = read_ok(kIntegerCard, "      -0.0");
  EXPECT_EQ(v.integer("I"), 0);
  EXPECT_FALSE(std::signbit(v.real("I")));  // read as the integer 0
}

TEST(CardReader, IntegralRealStillMeetsTheFieldsRange) {
  const CardValues v = read_ok(kCard, "      10.0");
  EXPECT_EQ(v.integer("N"), 10);
  EXPECT_EQ(read_error(kCard, "      11.0").message,
            "value 11 is out of range: must be in [0, 10]");
}

TEST(CardReader, NonIntegralRealInIntegerFieldIsAnError) {
  for (const char* line : {"       2.5", "2.5,", "   2.5E+00", "  2.5D+00", "    0.1E-0"}) {
    const FieldError e = read_error(kIntegerCard, line);
    EXPECT_EQ(e.field, "I") << line;
    EXPECT_NE(e.message.find("which is not a whole number"), std::string::npos)
        << line << ": " << e.message;
  }
  EXPECT_EQ(read_error(kIntegerCard, "      -2.5").message,
            "expected an integer, got '-2.5', which is not a whole number");
}

TEST(CardReader, IntegralRealOutOfIntRangeIsAnError) {
  EXPECT_EQ(read_error(kIntegerCard, "   3.0E+10").message,
            "value 30000000000 does not fit a 32-bit integer");
  EXPECT_EQ(read_error(kIntegerCard, "-3.0D+10,").message,
            "value -30000000000 does not fit a 32-bit integer");
  EXPECT_EQ(read_error(kIntegerCard, "99999999999999999999999,").message,
            "value 99999999999999999999999 does not fit a 32-bit integer");
  EXPECT_EQ(integer_of("2147483647.0,"), 2147483647);
  EXPECT_EQ(integer_of("-2.147483648E9,"), -2147483647 - 1);
}

TEST(CardReader, OnlyRealsWithAPointOrExponentLetterCountAsIntegers) {
  // Fortran's exponent without its letter ("1+2" = 100) is not taken for an integer.
  EXPECT_EQ(read_error(kIntegerCard, "       1+2").message, "expected an integer, got '1+2'");
  EXPECT_EQ(read_error(kIntegerCard, "         .").message, "expected an integer, got '.'");
}

TEST(CardReader, RangeIsChecked) {
  const FieldError e = read_error(kCard, "        11");
  EXPECT_EQ(e.field, "N");
  EXPECT_EQ(e.message, "value 11 is out of range: must be in [0, 10]");
}

TEST(CardReader, NumberedFieldNamesInErrors) {
  const FieldError e = read_error(kPointCard, "1.0,x", {}, 2);
  EXPECT_EQ(e.field, "O3");
}

TEST(CardReader, TooManyFreeFields) {
  const FieldError e = read_error(kPointCard, "1,2,3");
  EXPECT_NE(e.message.find("too many fields"), std::string::npos);
  read_ok(kPointCard, "1,2,,");  // trailing empty fields are fine
}

TEST(CardReader, TabsCountAsBlanks) {
  const CardValues v = read_ok(kCard, "         4\t\t ");
  EXPECT_EQ(v.integer("N"), 4);
}

TEST(CardReader, TextTakingTheLineIsNotSplitAtCommas) {
  const CardValues v = read_ok(kTitleCard, "  My deck, version 2   ");
  EXPECT_EQ(v.text("TITLE"), "My deck, version 2");
}

TEST(CardReader, IsFreeFormat) {
  EXPECT_TRUE(is_free_format(kCard, "1,2"));
  EXPECT_FALSE(is_free_format(kCard, "1 2"));
  EXPECT_FALSE(is_free_format(kTitleCard, "a,b"));
}

}  // namespace
}  // namespace plyform::keyword
