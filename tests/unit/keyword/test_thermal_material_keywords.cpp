// The temperature-dependent mechanics keywords: *MAT_ELASTIC_PLASTIC_THERMAL (*MAT_004) and
// *MAT_ADD_THERMAL_EXPANSION. Each value lands in its own member (distinct values, so a
// transposition shows), the table has one point per temperature written, and each value
// plyform rejects names its file, line, keyword and field.
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace test_thermal_material_keywords {

using namespace test;  // read_ok, single_error, expect_error, ...

/// One fixed-format card line: each value right-aligned in its 10 columns ("" leaves a field
/// blank).
std::string fixed(std::initializer_list<std::string_view> fields) {
  std::string line;
  for (std::string_view f : fields) {
    line += std::string(10 - f.size(), ' ');
    line += f;
  }
  return line + "\n";
}

// --- *MAT_ELASTIC_PLASTIC_THERMAL

/// Cards 2-7 of a valid 3-point table (free format).
constexpr std::string_view kThreePoints =
    "20,300,600\n"
    "2.1e5,1.9e5,1.5e5\n"
    "0.3,0.31,0.32\n"
    "1.2e-5,1.3e-5,1.4e-5\n"
    "250,180,90\n"
    "1000,800,500\n";

std::string mat004(std::string_view card1, std::string_view cards2to7) {
  return "*MAT_004\n" + std::string(card1) + "\n" + std::string(cards2to7);
}

/// The 3-point deck with card `card` (2-7) replaced by `text`.
std::string with_card(int card, std::string_view text) {
  std::vector<std::string> lines;
  std::string_view rest = kThreePoints;
  while (!rest.empty()) {
    const std::size_t end = rest.find('\n');
    lines.emplace_back(rest.substr(0, end));
    rest.remove_prefix(end + 1);
  }
  lines.at(static_cast<std::size_t>(card - 2)) = std::string(text);
  std::string out;
  for (const std::string& l : lines) {
    out += l + "\n";
  }
  return mat004("1,7.85e-9", out);
}

TEST(MatElasticPlasticThermal, ThreePointsWithTitleFixedFormat) {
  const ReadResult r = read_ok(
      "*KEYWORD\n"
      "*MAT_ELASTIC_PLASTIC_THERMAL_TITLE\n"
      "hot steel\n"
      "$#     mid        ro\n" +
      fixed({"7", "7.85e-9"}) + "$#      t1        t2        t3\n" +
      fixed({"20.0", "300.0", "600.0"}) + fixed({"210000.0", "190000.0", "150000.0"}) +
      fixed({"0.3", "0.31", "0.32"}) + fixed({"1.2e-5", "1.3e-5", "1.4e-5"}) +
      fixed({"250.0", "180.0", "90.0"}) + fixed({"1000.0", "800.0", "500.0"}));
  const auto& m = r.model.elastic_plastic_thermal_materials;
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].id, 7);
  EXPECT_EQ(m[0].title, "hot steel");
  EXPECT_DOUBLE_EQ(m[0].density, 7.85e-9);
  EXPECT_EQ(m[0].temperature, (std::vector<double>{20.0, 300.0, 600.0}));
  EXPECT_EQ(m[0].young, (std::vector<double>{210000.0, 190000.0, 150000.0}));
  EXPECT_EQ(m[0].poisson, (std::vector<double>{0.3, 0.31, 0.32}));
  EXPECT_EQ(m[0].alpha, (std::vector<double>{1.2e-5, 1.3e-5, 1.4e-5}));
  EXPECT_EQ(m[0].sigy, (std::vector<double>{250.0, 180.0, 90.0}));
  EXPECT_EQ(m[0].etan, (std::vector<double>{1000.0, 800.0, 500.0}));
  EXPECT_EQ(m[0].where.file, "deck.k");
  EXPECT_EQ(m[0].where.line, 5);
  EXPECT_TRUE(r.model.piecewise_linear_materials.empty());
}

TEST(MatElasticPlasticThermal, Mat004AliasZeroTemperatureAndBlanks) {
  // T1 = 0 is a temperature (a blank ends the table); blank PR and ALPHA are 0; ETAN 0 is
  // perfect plasticity; blank fields after the last point are fine.
  const ReadResult r = read_ok(
      "*MAT_004\n"
      "2,2.7e-9\n"
      "-50,0,,\n"
      "70000,68000\n"
      ",\n"
      ",2.4e-5\n"
      "120,100\n"
      "0,0\n"
      "*MAT_004_TITLE\n"
      "aluminium\n"
      "3,2.7e-9\n" +
      std::string(kThreePoints));
  const auto& m = r.model.elastic_plastic_thermal_materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].id, 2);
  EXPECT_TRUE(m[0].title.empty());
  EXPECT_EQ(m[0].temperature, (std::vector<double>{-50.0, 0.0}));
  EXPECT_EQ(m[0].young, (std::vector<double>{70000.0, 68000.0}));
  EXPECT_EQ(m[0].poisson, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(m[0].alpha, (std::vector<double>{0.0, 2.4e-5}));
  EXPECT_EQ(m[0].sigy, (std::vector<double>{120.0, 100.0}));
  EXPECT_EQ(m[0].etan, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(m[0].where.line, 2);
  EXPECT_EQ(m[1].id, 3);
  EXPECT_EQ(m[1].title, "aluminium");
  EXPECT_EQ(m[1].temperature.size(), 3u);
  EXPECT_EQ(m[1].where.line, 11);
}

TEST(MatElasticPlasticThermal, EightPoints) {
  const ReadResult r = read_ok(mat004("1,7.85e-9",
                                      "0,100,200,300,400,500,600,700\n"
                                      "8,7,6,5,4,3,2,1\n"
                                      "\n"
                                      "\n"
                                      "8,7,6,5,4,3,2,1\n"
                                      "\n"));
  const auto& m = r.model.elastic_plastic_thermal_materials;
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].temperature.size(), 8u);
  EXPECT_DOUBLE_EQ(m[0].young[7], 1.0);
  EXPECT_DOUBLE_EQ(m[0].etan[7], 0.0);
}

TEST(MatElasticPlasticThermal, CardOneAndMissingCards) {
  constexpr std::string_view kKw = "*MAT_004";
  expect_error(mat004("1,0", kThreePoints), 2, kKw, "RO", "RO must be > 0");
  expect_error(mat004(",7.85e-9", kThreePoints), 2, kKw, "MID", "a value is required");
  expect_error(mat004("1,7.85e-9,210000", kThreePoints), 2, kKw, "UNUSED",
               "LS-DYNA does not use it");
  const Diagnostic none = single_error("*MAT_004\n");
  EXPECT_EQ(none.keyword, kKw);
  EXPECT_TRUE(contains(none.message, "missing card 1")) << none.message;
  // Card 7 left out: reported at card 6 (line 7), naming card 7.
  expect_error(mat004("1,7.85e-9", "20,300\n2e5,1.9e5\n0.3,0.3\n1e-5,1e-5\n250,200\n"), 7, kKw, "",
               "missing card 7 (ETAN1..ETAN8)");
  expect_error(mat004("1,7.85e-9", "20,300\n"), 3, kKw, "", "missing card 3 (E1..E8)");
  expect_error("*MAT_ELASTIC_PLASTIC_THERMAL_TITLE\n", 1, "*MAT_ELASTIC_PLASTIC_THERMAL_TITLE", "",
               "missing title card");
}

TEST(MatElasticPlasticThermal, Temperatures) {
  constexpr std::string_view kKw = "*MAT_004";
  expect_error(with_card(2, "20"), 3, kKw, "T2", "at least 2 temperatures");
  expect_error(with_card(2, ""), 3, kKw, "T1", "at least 2 temperatures");
  expect_error(with_card(2, "20,,600"), 3, kKw, "T3", "T3 is written after a blank T2");
  expect_error(with_card(2, ",300,600"), 3, kKw, "T2", "T2 is written after a blank T1");
  expect_error(with_card(2, "20,300,300"), 3, kKw, "T3",
               "the temperatures must increase: T3 = 300 is not above T2 = 300");
  // Written zeros after the last point are temperatures, so the table does not increase.
  expect_error(with_card(2, "20,300,600,0,0,0,0,0"), 3, kKw, "T4", "leave the fields after");
}

TEST(MatElasticPlasticThermal, ValuesOfThePoints) {
  constexpr std::string_view kKw = "*MAT_004";
  expect_error(with_card(3, "2.1e5,0,1.5e5"), 4, kKw, "E2", "E2 must be > 0, got 0");
  expect_error(with_card(3, "2.1e5,1.9e5"), 4, kKw, "E3", "E3 must be > 0");
  expect_error(with_card(3, "2.1e5,-1.9e5,1.5e5"), 4, kKw, "E2", "out of range");
  expect_error(with_card(4, "0.3,0.5,0.3"), 5, kKw, "PR2", "out of range");
  expect_error(with_card(4, "0.3,0.3,-1"), 5, kKw, "PR3", "PR3 must be in (-1, 0.5), got -1");
  expect_error(with_card(6, "250,0,90"), 7, kKw, "SIGY2", "SIGY2 must be > 0, got 0");
  expect_error(with_card(6, ""), 7, kKw, "SIGY1", "thermo-elastic");
  expect_error(with_card(7, "1000,800,1.5e5"), 8, kKw, "ETAN3",
               "ETAN3 must be >= 0 and below E3 = 150000, got 150000");
  expect_error(with_card(7, "1000,-1,500"), 8, kKw, "ETAN2", "out of range");
}

TEST(MatElasticPlasticThermal, AValueAfterTheLastPointIsAnError) {
  constexpr std::string_view kKw = "*MAT_004";
  expect_error(with_card(3, "2.1e5,1.9e5,1.5e5,1.4e5"), 4, kKw, "E4",
               "E4 is written, but the table has 3 points (T1..T3 on card 2)");
  expect_error(with_card(4, "0.3,0.31,0.32,0"), 5, kKw, "PR4", "the table has 3 points");
  expect_error(with_card(5, "1.2e-5,1.3e-5,1.4e-5,,,,,1.5e-5"), 6, kKw, "ALPHA8",
               "the table has 3 points");
  expect_error(with_card(6, "250,180,90,50"), 7, kKw, "SIGY4", "the table has 3 points");
  expect_error(with_card(7, "1000,800,500,400"), 8, kKw, "ETAN4", "the table has 3 points");
}

// --- *MAT_ADD_THERMAL_EXPANSION

TEST(MatAddThermalExpansion, ReadsCurveAndConstant) {
  const ReadResult r = read_ok(
      "*MAT_ADD_THERMAL_EXPANSION\n"
      "$#     pid      lcid      mult     lcidy     multy     lcidz     multz      tref\n" +
      fixed({"4", "12", "", "0", "0.0", "0", "0.0", "0.0"}) +
      "*MAT_ADD_THERMAL_EXPANSION\n"
      "5,0,1.2e-5\n"
      "*MAT_ADD_THERMAL_EXPANSION\n"
      "6,3,0.0\n");
  const auto& x = r.model.thermal_expansions;
  ASSERT_EQ(x.size(), 3u);
  EXPECT_EQ(x[0].pid, 4);
  EXPECT_EQ(x[0].lcid, 12);
  EXPECT_DOUBLE_EQ(x[0].mult, 1.0);  // blank: 1
  EXPECT_EQ(x[0].where.file, "deck.k");
  EXPECT_EQ(x[0].where.line, 3);
  EXPECT_EQ(x[1].pid, 5);
  EXPECT_EQ(x[1].lcid, 0);
  EXPECT_DOUBLE_EQ(x[1].mult, 1.2e-5);
  EXPECT_EQ(x[1].where.line, 5);
  EXPECT_DOUBLE_EQ(x[2].mult, 0.0);  // a written 0 stays 0
}

TEST(MatAddThermalExpansion, Rejections) {
  constexpr std::string_view kKw = "*MAT_ADD_THERMAL_EXPANSION";
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n1,0,1e-5,7\n", 2, kKw, "LCIDY",
               "LCIDY = 7: orthotropic thermal expansion is not supported");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n1,0,1e-5,0,2e-5\n", 2, kKw, "MULTY",
               "orthotropic thermal expansion is not supported");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n1,0,1e-5,,,8\n", 2, kKw, "LCIDZ",
               "orthotropic thermal expansion is not supported");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n1,0,1e-5,,,,1.0\n", 2, kKw, "MULTZ",
               "orthotropic thermal expansion is not supported");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n1,0,1e-5,,,,,20.0\n", 2, kKw, "TREF",
               "TREF = 20 (the secant form of the thermal strain) is not supported");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n1,-3,1e-5\n", 2, kKw, "LCID", "out of range");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n-2,0,1e-5\n", 2, kKw, "PID",
               "PID = -2 (all parts of material 2) is not supported");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n0,0,1e-5\n", 2, kKw, "PID", "PID must be >= 1");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n,0,1e-5\n", 2, kKw, "PID", "a value is required");
  expect_error("*MAT_ADD_THERMAL_EXPANSION\n1,0,1e-5\n2,0,1e-5\n", 3, kKw, "",
               "unexpected data line");
  const Diagnostic none = single_error("*MAT_ADD_THERMAL_EXPANSION\n");
  EXPECT_EQ(none.keyword, kKw);
  EXPECT_TRUE(contains(none.message, "missing card 1")) << none.message;
  expect_error("*MAT_ADD_THERMAL_EXPANSION_TITLE\nx\n1\n", 1, "*MAT_ADD_THERMAL_EXPANSION_TITLE",
               "", "unsupported option");
}

}  // namespace test_thermal_material_keywords
}  // namespace plyform::keyword
