#include <string>

#include <gtest/gtest.h>

#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

std::string all_errors(const ReadResult& result) {
  std::string out;
  for (const Diagnostic& d : result.errors) {
    out += d.to_string() + "\n";
  }
  return out;
}

constexpr std::string_view kDeck = R"($# LS-DYNA Keyword file created by hand
*KEYWORD 100m
$* a comment of another kind
*TITLE
Two plates, bonded
*COMMENT  *NODE
this text is ignored, *NODE included
         1       0.0
$$ commented card
*PARAMETER
$#    name       val
R     tend    2.0E-3I     lcid         7C     word     hello
Rscale, 0.5
*PARAMETER_EXPRESSION
R     half &tend/2
R      two sqrt(4)*&scale*2
*DEFINE_CURVE
$#    lcid      sidr       sfa       sfo      offa      offo    dattyp
     &lcid         0       1.0       1.0       0.0       0.0         0
$#                a1                  o1
                 0.0                 0.0
               &half             1.0-3
               &tend           1.00000+4
*define_curve_title   
Pressure, in MPa
11,0,&two,,1.0
0.0,20.0

20.,-&scale
*USER_INTERFACE_FRICTION
$#   nosid       noc      noci
         1        12         0
$#     uc1       uc2       uc3       uc4       uc5       uc6       uc7       uc8
       1.0     1.0E4      0.30               390.0     420.0       1.0      1e-3
$#     uc9      uc10      uc11      uc12
                          0.01         0
*END
*NODE
this is after *END and is not read
)";

TEST(ReadDeck, ReadsTheSupportedKeywords) {
  const ReadResult result = read_deck_text(kDeck, "deck.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  EXPECT_TRUE(result.warnings.empty());
  const model::ModelDesc& model = result.model;
  EXPECT_EQ(model.title, "Two plates, bonded");
  EXPECT_EQ(model.keyword_options, "100m");
  ASSERT_EQ(model.files_read.size(), 1u);
  EXPECT_EQ(model.files_read[0], "deck.k");

  ASSERT_EQ(model.curves.size(), 2u);
  const model::CurveDesc& c7 = model.curves[0];
  EXPECT_EQ(c7.id, 7);
  EXPECT_EQ(c7.where.line, 17);
  EXPECT_EQ(c7.where.file, "deck.k");
  ASSERT_EQ(c7.abscissa.size(), 3u);
  EXPECT_DOUBLE_EQ(c7.abscissa[1], 1.0e-3);
  EXPECT_DOUBLE_EQ(c7.ordinate[1], 1.0e-3);
  EXPECT_DOUBLE_EQ(c7.abscissa[2], 2.0e-3);
  EXPECT_DOUBLE_EQ(c7.ordinate[2], 1.0e4);

  const model::CurveDesc& c11 = model.curves[1];
  EXPECT_EQ(c11.id, 11);
  EXPECT_EQ(c11.title, "Pressure, in MPa");
  EXPECT_DOUBLE_EQ(c11.sfa, 2.0);
  EXPECT_DOUBLE_EQ(c11.sfo, 1.0);  // blank: default
  EXPECT_DOUBLE_EQ(c11.offa, 1.0);
  ASSERT_EQ(c11.ordinate.size(), 2u);  // the blank line between points is skipped
  EXPECT_DOUBLE_EQ(c11.ordinate[1], -0.5);

  ASSERT_EQ(model.user_interface_frictions.size(), 1u);
  const model::UserInterfaceFrictionDesc& f = model.user_interface_frictions[0];
  EXPECT_EQ(f.contact_id, 1);
  EXPECT_EQ(f.noc, 12);
  ASSERT_EQ(f.constants.size(), 12u);
  ASSERT_EQ(f.constant_where.size(), 12u);
  EXPECT_DOUBLE_EQ(*f.constants[1], 1.0e4);
  EXPECT_FALSE(f.constants[3].has_value());
  EXPECT_DOUBLE_EQ(*f.constants[7], 1.0e-3);
  EXPECT_FALSE(f.constants[8].has_value());
  EXPECT_DOUBLE_EQ(*f.constants[10], 0.01);
  EXPECT_DOUBLE_EQ(*f.constants[11], 0.0);
  EXPECT_EQ(f.constant_where[0].line, 34);
  EXPECT_EQ(f.constant_where[8].line, 36);
}

TEST(ReadDeck, SurvivesCrlfCaseBlanksLatin1AndNoFinalNewline) {
  const std::string deck =
      "$ storage temp: 23 \xB0"
      "C\r\n"
      "*keyword   \r\n"
      "*Define_Curve  \r\n"
      "         3\t\t \r\n"
      "0.0,1.0\r\n"
      "1.0,2.0";
  const ReadResult result = read_deck_text(deck, "crlf.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  ASSERT_EQ(result.model.curves.size(), 1u);
  EXPECT_EQ(result.model.curves[0].id, 3);
  EXPECT_DOUBLE_EQ(result.model.curves[0].ordinate[1], 2.0);
}

TEST(ReadDeck, IntegerParameterTruncatesExpressions) {
  const ReadResult result =
      read_deck_text("*PARAMETER_EXPRESSION\nI        n 7/2\n*DEFINE_CURVE\n&n\n0,0\n1,1\n", "i.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  EXPECT_EQ(result.model.curves[0].id, 3);
}

TEST(ReadDeck, ExpressionWithCommaInFixedFormat) {
  const ReadResult result = read_deck_text(
      "*PARAMETER\nR        a       2.0\n*PARAMETER_EXPRESSION\n"
      "R        b max(&a, 3.0)\n"
      "*DEFINE_CURVE\n1\n0,0\n&b,1\n",
      "e.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  EXPECT_DOUBLE_EQ(result.model.curves[0].abscissa[1], 3.0);
}

TEST(ReadDeck, DuplicateParameterKeepsTheFirstWithAWarning) {
  const ReadResult result = read_deck_text(
      "*PARAMETER\nR        a       2.0\nR        a       3.0\n*DEFINE_CURVE\n1\n0,0\n&a,1\n",
      "dup.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  EXPECT_DOUBLE_EQ(result.model.curves[0].abscissa[1], 2.0);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].where.line, 3);
}

TEST(ReadDeck, EmptyTextIsAnEmptyValidDeck) {
  const ReadResult result = read_deck_text("", "empty.k");
  EXPECT_TRUE(result.ok());
}

}  // namespace
}  // namespace plyform::keyword
