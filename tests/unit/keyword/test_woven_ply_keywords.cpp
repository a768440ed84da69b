// *MAT_REINFORCED_THERMOPLASTIC (*MAT_249) and *DEFINE_TABLE: each value lands in its own
// member (distinct values), the card layout follows NFIB (LS-PrePost's blank cards of unused
// families included), and each value plyform rejects names its line, keyword and field.
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;

// Cards 1-6 of a woven ply (free format), AOPT 2; card 1 at line 2 after the keyword line.
constexpr std::string_view kWoven =
    "*MAT_REINFORCED_THERMOPLASTIC\n"
    "5,1.5e-9,3.0,11,0.35,12,0,0\n"
    "2,2,0,0,0,1,0,0\n"
    "0,0,0,0,1,0,0,0\n"
    "101,0,40000,0,5,6\n"
    "0.2,0,0.9,2,0\n"
    "102,90,38000,0,7,8\n";

TEST(MatReinforcedThermoplastic, WovenPlyReadsEveryField) {
  const ReadResult r = read_ok(kWoven);
  const auto& m = r.model.reinforced_thermoplastic_materials;
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].id, 5);
  EXPECT_DOUBLE_EQ(m[0].density, 1.5e-9);
  EXPECT_DOUBLE_EQ(m[0].em, 3.0);
  EXPECT_EQ(m[0].lcem, 11);
  EXPECT_DOUBLE_EQ(m[0].prm, 0.35);
  EXPECT_EQ(m[0].lcprm, 12);
  EXPECT_EQ(m[0].nfib, 2);
  EXPECT_EQ(m[0].aopt, 2);
  EXPECT_EQ(m[0].a, (std::array<double, 3>{1, 0, 0}));
  EXPECT_EQ(m[0].d, (std::array<double, 3>{0, 1, 0}));
  ASSERT_EQ(m[0].fibres.size(), 2u);
  ASSERT_EQ(m[0].shears.size(), 1u);
  EXPECT_EQ(m[0].fibres[0].idf, 101);
  EXPECT_DOUBLE_EQ(m[0].fibres[0].ef, 40000.0);
  EXPECT_DOUBLE_EQ(m[0].fibres[0].g23, 5.0);
  EXPECT_DOUBLE_EQ(m[0].fibres[0].g31, 6.0);
  EXPECT_DOUBLE_EQ(m[0].fibres[1].alpha, 90.0);
  EXPECT_DOUBLE_EQ(m[0].fibres[1].ef, 38000.0);
  EXPECT_DOUBLE_EQ(m[0].fibres[1].g23, 7.0);
  EXPECT_DOUBLE_EQ(m[0].shears[0].g, 0.2);
  EXPECT_DOUBLE_EQ(m[0].shears[0].aloc, 0.9);
  EXPECT_DOUBLE_EQ(m[0].shears[0].gloc, 2.0);
  EXPECT_EQ(m[0].shears[0].where.line, 6);
  EXPECT_EQ(m[0].where.line, 2);
}

TEST(MatReinforcedThermoplastic, LsPrePostBlankCardsOfAThirdFamilyAndCard9) {
  // NFIB 2 with cards 7 and 8 written blank, then card 9; the _TITLE and *MAT_249 forms.
  const ReadResult r = read_ok(
      "*MAT_249_TITLE\nwoven CF/PA6\n"
      "7,1.5e-9,3.0,0,0.35,0,0,0\n"
      "2,0,0,0,0,0,0,0\n"
      "0,0,0,0,0,0,30,0\n"
      "1,0,40000,0,0,0\n"
      "0.2,0,0,0,0\n"
      "2,90,40000,0,0,0\n"
      ",,,,\n"
      ",,,,,\n"
      "0,0\n"
      "*MAT_REINFORCED_THERMOPLASTIC\n"
      "8,1.5e-9,3.0,0,0.3,0,0,0\n"
      "3,3,0,0,0,0,0,0\n"
      "0,0,1,0,0,0,15,0\n"
      "1,0,40000,0,0,0\n"
      "0.2,0,0,0,0\n"
      "2,60,40000,0,0,0\n"
      "0.3,0,0,0,0\n"
      "3,120,40000,0,0,0\n");
  const auto& m = r.model.reinforced_thermoplastic_materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].title, "woven CF/PA6");
  EXPECT_EQ(m[0].fibres.size(), 2u);
  EXPECT_DOUBLE_EQ(m[0].mangl, 30.0);
  EXPECT_EQ(m[1].nfib, 3);
  EXPECT_EQ(m[1].aopt, 3);
  EXPECT_EQ(m[1].fibres.size(), 3u);
  EXPECT_EQ(m[1].shears.size(), 2u);
  EXPECT_DOUBLE_EQ(m[1].fibres[2].alpha, 120.0);
  EXPECT_DOUBLE_EQ(m[1].shears[1].g, 0.3);
}

std::string woven_with(int card, std::string_view text) {
  std::string deck(kWoven);
  std::size_t at = 0;
  for (int k = 0; k < card; ++k)
    at = deck.find('\n', at) + 1;
  const std::size_t end = deck.find('\n', at);
  return deck.substr(0, at) + std::string(text) + deck.substr(end);
}

/// The deck with `extra` cards after its last one.
std::string woven_plus(std::string_view extra) {
  std::string deck(kWoven);
  deck.append(extra);
  return deck;
}

TEST(MatReinforcedThermoplastic, WhatPlyformDoesNotImplementIsRejectedByName) {
  const std::string_view kw = "*MAT_REINFORCED_THERMOPLASTIC";
  expect_error(woven_with(1, "5,1.5e-9,3.0,0,0.35,0,9,0"), 2, kw, "BETA", "kinematic");
  expect_error(woven_with(2, "2,1,0,0,0,1,0,0"), 3, kw, "AOPT", "AOPT");
  expect_error(woven_with(2, "2,-4,0,0,0,1,0,0"), 3, kw, "AOPT", "AOPT");
  expect_error(woven_with(3, "0,0,0,0,1,0,0,1"), 4, kw, "THICK", "THICK");
  expect_error(woven_with(5, "0.2,9,0,0,0"), 6, kw, "METH12", "METH12 = 0");
  expect_error(woven_with(5, "0,9,0,0,3"), 6, kw, "G12", "unloading");
  expect_error(woven_with(5, "0.2,0,0,2,0"), 6, kw, "GLOC12", "locking angle");
  expect_error(woven_with(5, "0.2,0,45,2,0"), 6, kw, "ALOC12", "radians");
  expect_error(woven_with(4, "101,0,0,0,5,6"), 5, kw, "EF1", "EF1 > 0");
  expect_error(woven_with(2, "2,2,0,0,0,0,0,0"), 3, kw, "A1", "vector a");
  expect_error(woven_with(1, "5,1.5e-9,0,0,0.35,0,0,0"), 2, kw, "EM", "EM must be > 0");
  expect_error(woven_plus("0.1,0,0,0,0\n9,0,1,0,0,0\n"), 8, kw, "G23", "NFIB = 2");
  expect_error(woven_plus("0,1\n"), 8, kw, "IHIS", "IHIS");
}

TEST(MatReinforcedThermoplastic, Meth2LockingFieldsAndPostvAreWarnedAbout) {
  const ReadResult r = read_ok(woven_with(5, "0,9,0.9,2,2") + "3,0\n");
  std::string warnings;
  for (const Diagnostic& d : r.warnings)
    warnings += d.to_string() + "\n";
  EXPECT_NE(warnings.find("ALOC12"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("POSTV"), std::string::npos) << warnings;
}

TEST(DefineTable, ValuesAndTheCurvesThatFollow) {
  const ReadResult r = read_ok(
      "*DEFINE_TABLE_TITLE\nshear by temperature\n"
      "30,2,10\n"
      "240,31\n"
      "260\n"
      "*DEFINE_CURVE\n31\n0,0\n1,1\n"
      "*DEFINE_CURVE\n32\n0,0\n1,2\n");
  ASSERT_EQ(r.model.tables.size(), 1u);
  const model::DefineTableDesc& t = r.model.tables[0];
  EXPECT_EQ(t.id, 30);
  EXPECT_EQ(t.title, "shear by temperature");
  EXPECT_EQ(t.values, (std::vector<double>{240.0, 260.0}));
  EXPECT_EQ(model::effective_values(t), (std::vector<double>{500.0, 540.0}));
  EXPECT_EQ(model::table_curve_ids(r.model, t), (std::vector<int>{31, 32}));
  EXPECT_EQ(t.lcid_written, (std::vector<int>{31, 0}));
}

TEST(DefineTable, ValuesMustIncrease) {
  expect_error("*DEFINE_TABLE\n30\n260\n240\n", 4, "*DEFINE_TABLE", "VALUE2", "increase");
}

}  // namespace
}  // namespace plyform::keyword
