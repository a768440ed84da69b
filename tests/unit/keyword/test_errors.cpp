#include <string>

#include <gtest/gtest.h>

#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

/// Reads text that must give exactly one error and returns it.
Diagnostic single_error(std::string_view text) {
  const ReadResult result = read_deck_text(text, "deck.k");
  std::string all;
  for (const Diagnostic& d : result.errors) {
    all += d.to_string() + "\n";
  }
  EXPECT_EQ(result.errors.size(), 1u) << all;
  return result.errors.empty() ? Diagnostic{} : result.errors.front();
}

bool contains(const std::string& text, std::string_view part) {
  return text.find(part) != std::string::npos;
}

TEST(Errors, UnknownKeyword) {
  const Diagnostic d = single_error("*KEYWORD\n*ELEMENT_BEAM\n       1       1\n");
  EXPECT_EQ(d.where.file, "deck.k");
  EXPECT_EQ(d.where.line, 2);
  EXPECT_EQ(d.keyword, "*ELEMENT_BEAM");
  EXPECT_EQ(d.field, "");
  EXPECT_TRUE(contains(d.message, "unsupported keyword")) << d.message;
}

TEST(Errors, BadNumberNamesTheField) {
  const Diagnostic d =
      single_error("*KEYWORD\n*DEFINE_CURVE\n         1         0       abc\n0,0\n1,1\n");
  EXPECT_EQ(d.to_string(), "deck.k:3: *DEFINE_CURVE: field SFA: expected a real number, got 'abc'");
}

TEST(Errors, ValueOutOfRange) {
  const Diagnostic d = single_error("*DEFINE_CURVE\n         1         5\n0,0\n1,1\n");
  EXPECT_EQ(d.where.line, 2);
  EXPECT_EQ(d.field, "SIDR");
  EXPECT_EQ(d.message, "value 5 is out of range: must be in [0, 2]");
}

TEST(Errors, RequiredFieldBlank) {
  const Diagnostic d = single_error("*DEFINE_CURVE\n\n0,0\n1,1\n");
  EXPECT_EQ(d.where.line, 2);
  EXPECT_EQ(d.field, "LCID");
  EXPECT_EQ(d.message, "a value is required");
}

TEST(Errors, MissingCardNamesIt) {
  const Diagnostic d = single_error(
      "*USER_INTERFACE_FRICTION\n         1        12         0\n       1.0       2.0\n");
  EXPECT_EQ(d.where.line, 1);
  EXPECT_EQ(d.keyword, "*USER_INTERFACE_FRICTION");
  EXPECT_TRUE(contains(d.message, "missing card 3 (constants UC9..UC12)")) << d.message;
  const Diagnostic d1 = single_error("*DEFINE_CURVE\n");
  EXPECT_TRUE(contains(d1.message, "missing card 1")) << d1.message;
}

TEST(Errors, ConstantBeyondNoc) {
  const Diagnostic d =
      single_error("*USER_INTERFACE_FRICTION\n1,3\n       1.0       2.0       3.0       4.0\n");
  EXPECT_EQ(d.where.line, 3);
  EXPECT_EQ(d.field, "UC4");
}

TEST(Errors, ConstantFieldNamesCountAcrossCards) {
  const Diagnostic d = single_error("*USER_INTERFACE_FRICTION\n1,10\n1,2,3,4,5,6,7,8\n9,x\n");
  EXPECT_EQ(d.where.line, 4);
  EXPECT_EQ(d.field, "UC10");
}

TEST(Errors, MissingInclude) {
  const Diagnostic d = single_error("*KEYWORD\n*INCLUDE\n$# filename\nno_such_file.k\n");
  EXPECT_EQ(d.where.line, 4);
  EXPECT_EQ(d.keyword, "*INCLUDE");
  EXPECT_EQ(d.field, "FILENAME");
  EXPECT_TRUE(contains(d.message, "'no_such_file.k' not found")) << d.message;
}

TEST(Errors, UndefinedParameter) {
  const Diagnostic d = single_error("*DEFINE_CURVE\n         1\n0,0\n&tend,1\n");
  EXPECT_EQ(d.to_string(), "deck.k:4: *DEFINE_CURVE: field A2: undefined parameter &tend");
}

TEST(Errors, NonIncreasingAbscissa) {
  const Diagnostic d = single_error("*DEFINE_CURVE\n1\n0,0\n1,1\n1,2\n");
  EXPECT_EQ(d.where.line, 5);
  EXPECT_EQ(d.field, "A3");
  EXPECT_TRUE(contains(d.message, "strictly increase")) << d.message;
}

TEST(Errors, TooFewPoints) {
  const Diagnostic d = single_error("*DEFINE_CURVE\n1\n0,0\n");
  EXPECT_EQ(d.where.line, 1);
  EXPECT_EQ(d.message, "a curve needs at least 2 points, got 1");
}

TEST(Errors, UnsupportedOption) {
  const Diagnostic d = single_error("*DEFINE_CURVE_SMOOTH\n1\n");
  EXPECT_EQ(d.where.line, 1);
  EXPECT_EQ(d.keyword, "*DEFINE_CURVE_SMOOTH");
  EXPECT_TRUE(contains(d.message, "unsupported option _SMOOTH of *DEFINE_CURVE")) << d.message;
  EXPECT_TRUE(contains(d.message, "_TITLE")) << d.message;
  const Diagnostic i = single_error("*INCLUDE_TRANSFORM\nx.k\n");
  EXPECT_TRUE(contains(i.message, "unsupported option _TRANSFORM of *INCLUDE")) << i.message;
}

TEST(Errors, LongFormatIsRejected) {
  EXPECT_TRUE(contains(single_error("*KEYWORD LONG=Y\n").message, "long format"));
  EXPECT_TRUE(contains(single_error("*DEFINE_CURVE +\n1\n0,0\n1,1\n").message, "'+' format"));
  EXPECT_TRUE(contains(single_error("*DEFINE_CURVE+\n1\n0,0\n1,1\n").message, "'+' format"));
}

TEST(Errors, TextAfterKeywordName) {
  const Diagnostic d = single_error("*TITLE CID=1\nA title\n");
  EXPECT_TRUE(contains(d.message, "unexpected text 'CID=1'")) << d.message;
}

TEST(Errors, ExtraDataLine) {
  const Diagnostic d = single_error("*TITLE\nA title\nsecond line\n");
  EXPECT_EQ(d.where.line, 3);
  EXPECT_EQ(d.keyword, "*TITLE");
}

TEST(Errors, DataBeforeFirstKeyword) {
  const Diagnostic d = single_error("\n$ comment\nstray data\n*KEYWORD\n");
  EXPECT_EQ(d.where.line, 3);
  EXPECT_EQ(d.keyword, "");
}

TEST(Errors, BadParameterCards) {
  EXPECT_EQ(single_error("*PARAMETER\nX     name       1.0\n").field, "PRMR1");
  EXPECT_EQ(single_error("*PARAMETER\nI     name       1.5\n").field, "VAL1");
  const Diagnostic e = single_error("*PARAMETER_EXPRESSION\nR     name foo(1)\n");
  EXPECT_EQ(e.field, "EXPRESSION");
  EXPECT_EQ(e.message, "unknown function foo");
}

TEST(Errors, ReportsEveryBlockAndKeepsReading) {
  const ReadResult result = read_deck_text(
      "*KEYWORD\n"
      "*ELEMENT_BEAM\n"  // 2: unsupported
      "1 0 0 0\n"
      "*DEFINE_CURVE\n"  // 4
      "1,0,x\n"          // 5: bad SFA
      "*DEFINE_CURVE\n"  // 6: good
      "2\n"
      "0,0\n"
      "1,1\n"
      "*ELEMENT_TSHELL\n"  // 10: unsupported
      "*DEFINE_CURVE\n"    // 11
      "3\n"
      "1,0\n"
      "0,1\n",  // 14: not increasing
      "deck.k");
  ASSERT_EQ(result.errors.size(), 4u);
  EXPECT_EQ(result.errors[0].where.line, 2);
  EXPECT_EQ(result.errors[1].where.line, 5);
  EXPECT_EQ(result.errors[2].where.line, 10);
  EXPECT_EQ(result.errors[3].where.line, 14);
  ASSERT_EQ(result.model.curves.size(), 1u);
  EXPECT_EQ(result.model.curves[0].id, 2);
}

TEST(Errors, DiagnosticFormat) {
  Diagnostic d;
  d.where.file = "a.k";
  d.message = "cannot open the deck";
  EXPECT_EQ(d.to_string(), "a.k: cannot open the deck");
  d.where.line = 3;
  d.keyword = "*NODE";
  d.message = "unsupported keyword";
  EXPECT_EQ(d.to_string(), "a.k:3: *NODE: unsupported keyword");
}

TEST(Errors, MissingDeck) {
  const ReadResult result = read_deck("/nonexistent/plyform/deck.k");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].to_string(), "/nonexistent/plyform/deck.k: cannot open the deck");
}

}  // namespace
}  // namespace plyform::keyword
