// The metal plasticity keywords of real decks: *MAT_PLASTIC_KINEMATIC (*MAT_003) and
// *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (*MAT_037). Each value lands in its own member
// (distinct values, so a transposition shows), blanks take LS-DYNA's defaults, and each value
// plyform rejects names its line, keyword and field.
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, single_error, expect_error, ...

// --- *MAT_PLASTIC_KINEMATIC

TEST(MatPlasticKinematic, EveryFieldWithTitleFixedFormat) {
  const ReadResult r = read_ok(
      "*MAT_PLASTIC_KINEMATIC_TITLE\n"
      "steel\n"
      "         7   7.85e-9  210000.0      0.29     250.0    2100.0      0.35\n"
      "      40.0       5.0                 0.0\n");
  ASSERT_EQ(r.model.plastic_kinematic_materials.size(), 1u);
  const model::MatPlasticKinematicDesc& m = r.model.plastic_kinematic_materials[0];
  EXPECT_EQ(m.id, 7);
  EXPECT_EQ(m.title, "steel");
  EXPECT_DOUBLE_EQ(m.density, 7.85e-9);
  EXPECT_DOUBLE_EQ(m.young, 210000.0);
  EXPECT_DOUBLE_EQ(m.poisson, 0.29);
  EXPECT_DOUBLE_EQ(m.sigy, 250.0);
  EXPECT_DOUBLE_EQ(m.etan, 2100.0);
  EXPECT_DOUBLE_EQ(m.beta, 0.35);
  EXPECT_DOUBLE_EQ(m.src, 40.0);
  EXPECT_DOUBLE_EQ(m.srp, 5.0);
  EXPECT_DOUBLE_EQ(m.fs, 1.0e20);  // blank: no erosion
  EXPECT_DOUBLE_EQ(m.vp, 0.0);
  EXPECT_EQ(m.where.line, 3);
}

TEST(MatPlasticKinematic, Mat003AliasAndDefaults) {
  // Card 2 missing; ETAN and BETA blank: perfectly plastic, kinematic.
  const ReadResult r = read_ok("*MAT_003\n2,7.8e-9,2e5,0.3,300\n");
  ASSERT_EQ(r.model.plastic_kinematic_materials.size(), 1u);
  const auto& m = r.model.plastic_kinematic_materials[0];
  EXPECT_EQ(m.id, 2);
  EXPECT_DOUBLE_EQ(m.etan, 0.0);
  EXPECT_DOUBLE_EQ(m.beta, 0.0);
  EXPECT_DOUBLE_EQ(m.src, 0.0);
  EXPECT_DOUBLE_EQ(m.srp, 0.0);
  EXPECT_DOUBLE_EQ(m.fs, 1.0e20);
  // FS written as 0 or as LS-DYNA's 1e20: no erosion.
  EXPECT_DOUBLE_EQ(
      read_ok("*MAT_003\n2,7.8e-9,2e5,0.3,300\n0,0,0,0\n").model.plastic_kinematic_materials[0].fs,
      1.0e20);
  EXPECT_DOUBLE_EQ(read_ok("*MAT_003_TITLE\nt\n2,7.8e-9,2e5,0.3,300\n0,0,1e20\n")
                       .model.plastic_kinematic_materials[0]
                       .fs,
                   1.0e20);
}

TEST(MatPlasticKinematic, Rejections) {
  constexpr std::string_view kKw = "*MAT_003";
  expect_error("*MAT_003\n1,0,2e5,0.3,300\n", 2, kKw, "RO", "RO must be > 0");
  expect_error("*MAT_003\n1,7.8e-9,0,0.3,300\n", 2, kKw, "E", "E must be > 0");
  expect_error("*MAT_003\n1,7.8e-9,2e5,0.3\n", 2, kKw, "SIGY", "a value is required");
  expect_error("*MAT_003\n1,7.8e-9,2e5,0.3,300,2e5\n", 2, kKw, "ETAN", "must be below E");
  expect_error("*MAT_003\n1,7.8e-9,2e5,0.3,300,0,1.5\n", 2, kKw, "BETA", "");
  expect_error("*MAT_003\n1,7.8e-9,2e5,0.3,300\n40\n", 3, kKw, "SRP", "needs both");
  expect_error("*MAT_003\n1,7.8e-9,2e5,0.3,300\n0,5\n", 3, kKw, "SRC", "needs both");
  expect_error("*MAT_003\n1,7.8e-9,2e5,0.3,300\n,,0.8\n", 3, kKw, "FS",
               "FS = 0.8 (element erosion at that effective plastic strain) is not supported");
  expect_error("*MAT_003\n1,7.8e-9,2e5,0.3,300\n,,,1\n", 3, kKw, "VP",
               "1: the viscoplastic formulation");
  expect_error("*MAT_003\n1,7.8e-9,2e5,0.3,300\n,,,-1\n", 3, kKw, "VP", "VP = -1 is not");
  const Diagnostic none = single_error("*MAT_PLASTIC_KINEMATIC\n");
  EXPECT_EQ(none.keyword, "*MAT_PLASTIC_KINEMATIC");
  EXPECT_TRUE(contains(none.message, "missing card 1")) << none.message;
}

// --- *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC

TEST(MatTransverselyAnisotropic, EveryFieldWithTitle) {
  const ReadResult r = read_ok(
      "*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC_TITLE\n"
      "dc04\n"
      "$#     mid        ro         e        pr      sigy      etan         r     hlcid\n"
      "         17.90000E-9  207000.0       0.3     201.3     900.0     1.593         4\n"
      "         0       0.0       0.0        12                 0.0\n");
  ASSERT_EQ(r.model.transversely_anisotropic_materials.size(), 1u);
  const model::MatTransverselyAnisotropicDesc& m = r.model.transversely_anisotropic_materials[0];
  EXPECT_EQ(m.id, 1);
  EXPECT_EQ(m.title, "dc04");
  EXPECT_DOUBLE_EQ(m.density, 7.9e-9);
  EXPECT_DOUBLE_EQ(m.young, 207000.0);
  EXPECT_DOUBLE_EQ(m.poisson, 0.3);
  EXPECT_DOUBLE_EQ(m.sigy, 201.3);
  EXPECT_DOUBLE_EQ(m.etan, 900.0);
  EXPECT_DOUBLE_EQ(m.r, 1.593);
  EXPECT_EQ(m.hlcid, 4);
  EXPECT_EQ(m.icfld, 12);
  EXPECT_EQ(m.idscale, 0);
  EXPECT_DOUBLE_EQ(m.strainlt, 0.0);
  EXPECT_EQ(m.where.line, 4);
  // ICFLD: read, and a warning that the formability output is not written.
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].field, "ICFLD");
}

TEST(MatTransverselyAnisotropic, Mat037AliasAndDefaults) {
  const ReadResult r = read_ok("*MAT_037\n3,7.8e-9,2e5,0.3,250,,2.1\n");
  ASSERT_EQ(r.model.transversely_anisotropic_materials.size(), 1u);
  const auto& m = r.model.transversely_anisotropic_materials[0];
  EXPECT_EQ(m.id, 3);
  EXPECT_DOUBLE_EQ(m.etan, 0.0);
  EXPECT_DOUBLE_EQ(m.r, 2.1);
  EXPECT_EQ(m.hlcid, 0);
  EXPECT_EQ(m.icfld, 0);
  EXPECT_TRUE(r.warnings.empty());
  // With HLCID, SIGY may be blank.
  EXPECT_EQ(read_ok("*MAT_037\n3,7.8e-9,2e5,0.3,,,2.1,5\n")
                .model.transversely_anisotropic_materials[0]
                .hlcid,
            5);
}

// LS-DYNA: R < 0 selects its stabilised return with the ratio |R| (the pydyna metalforming
// deck's DC04 has R = -1.593): read as written, the law takes |R|.
TEST(MatTransverselyAnisotropic, NegativeRIsReadAsWritten) {
  const ReadResult r = read_ok("*MAT_037\n1,7.9e-9,207000,0.3,201.3,0,-1.593,1\n");
  EXPECT_DOUBLE_EQ(r.model.transversely_anisotropic_materials[0].r, -1.593);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(MatTransverselyAnisotropic, Rejections) {
  constexpr std::string_view kKw = "*MAT_037";
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,201.3,0,0\n", 2, kKw, "R", "R = 0: give the");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,201.3,0\n", 2, kKw, "R", "a value is required");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,0,0,1.5\n", 2, kKw, "SIGY", "SIGY must be > 0");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,200,-5,1.5\n", 2, kKw, "ETAN", "");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,200,0,1.5,-2\n", 2, kKw, "HLCID", "");
  expect_error("*MAT_037\n1,0,207000,0.3,200,0,1.5\n", 2, kKw, "RO", "RO must be > 0");
  const std::string card1 = "*MAT_037\n1,7.9e-9,207000,0.3,200,0,1.5\n";
  expect_error(card1 + "3\n", 3, kKw, "IDSCALE", "IDSCALE = 3 (Young's modulus against");
  expect_error(card1 + "0,1.2\n", 3, kKw, "EA", "EA = 1.2");
  expect_error(card1 + "0,0,0.5\n", 3, kKw, "COE", "COE = 0.5");
  expect_error(card1 + "0,0,0,0,0,0.1\n", 3, kKw, "STRAINLT", "strain averaging");
  expect_error(card1 + "0,0,0,0,7\n", 3, kKw, "UNUSED", "LS-DYNA does not use it");
}

// --- *MAT_3-PARAMETER_BARLAT

TEST(Mat3ParameterBarlat, EveryFieldWithTitle) {
  const ReadResult r = read_ok(
      "*MAT_3-PARAMETER_BARLAT_TITLE\n"
      "aa6111\n"
      "         5   2.70e-9   70000.0      0.33       2.0     550.0      0.22       1.0\n"
      "       8.0      0.71      0.58      0.81         0     0.004       0.0       0.0\n"
      "       2.0      40.0       5.0         0                 0.0\n"
      "       0.0       0.0       0.0       0.6       0.8       0.0\n"
      "       0.0       0.0       1.0       0.0       0.0       1.0      30.0\n"
      "       0.0\n");
  ASSERT_EQ(r.model.barlat89_materials.size(), 1u);
  const model::MatBarlat89Desc& m = r.model.barlat89_materials[0];
  EXPECT_EQ(m.id, 5);
  EXPECT_EQ(m.title, "aa6111");
  EXPECT_DOUBLE_EQ(m.density, 2.7e-9);
  EXPECT_DOUBLE_EQ(m.young, 70000.0);
  EXPECT_DOUBLE_EQ(m.poisson, 0.33);
  EXPECT_EQ(m.hardening.hr, 2);
  EXPECT_DOUBLE_EQ(m.hardening.p1, 550.0);
  EXPECT_DOUBLE_EQ(m.hardening.p2, 0.22);
  EXPECT_DOUBLE_EQ(m.m, 8.0);
  EXPECT_DOUBLE_EQ(m.r00, 0.71);
  EXPECT_DOUBLE_EQ(m.r45, 0.58);
  EXPECT_DOUBLE_EQ(m.r90, 0.81);
  EXPECT_DOUBLE_EQ(m.hardening.e0, 0.004);
  EXPECT_EQ(m.axes.aopt, 2);
  EXPECT_DOUBLE_EQ(m.c, 40.0);
  EXPECT_DOUBLE_EQ(m.p, 5.0);
  EXPECT_DOUBLE_EQ(m.axes.a[0], 0.6);
  EXPECT_DOUBLE_EQ(m.axes.a[1], 0.8);
  EXPECT_DOUBLE_EQ(m.axes.v[2], 1.0);
  EXPECT_DOUBLE_EQ(m.axes.d[2], 1.0);
  EXPECT_DOUBLE_EQ(m.axes.beta, 30.0);
  EXPECT_EQ(m.where.line, 3);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(Mat3ParameterBarlat, Mat036AliasAndDefaults) {
  const ReadResult r = read_ok("*MAT_036\n3,2.7e-9,7e4,0.33,,10.0,150.0\n8,0.7,0.6,0.8\n");
  ASSERT_EQ(r.model.barlat89_materials.size(), 1u);
  const auto& m = r.model.barlat89_materials[0];
  EXPECT_EQ(m.hardening.hr, 1);  // blank HR: linear
  EXPECT_DOUBLE_EQ(m.hardening.p1, 10.0);
  EXPECT_DOUBLE_EQ(m.hardening.p2, 150.0);
  EXPECT_EQ(m.axes.aopt, 0);
  EXPECT_DOUBLE_EQ(m.pb, 0.0);
}

TEST(Mat3ParameterBarlat, Rejections) {
  constexpr std::string_view kKw = "*MAT_036";
  const std::string card1 = "*MAT_036\n1,2.7e-9,7e4,0.33,1,0,150\n";
  expect_error(card1 + "-8,0.7,0.6,0.8\n", 3, kKw, "M", "Chaboche-Rousselier kinematic");
  expect_error(card1 + "1.5,0.7,0.6,0.8\n", 3, kKw, "M", "must be >= 2");
  expect_error(card1 + "8,0,0.6,0.8\n", 3, kKw, "R00", "a Lankford ratio must be > 0");
  expect_error("*MAT_036\n1,2.7e-9,7e4,0.33,5,1,1\n8,0.7,0.6,0.8\n", 2, kKw, "HR", "Gosh");
  expect_error("*MAT_036\n1,2.7e-9,7e4,0.33,1,0,0\n8,0.7,0.6,0.8\n", 2, kKw, "P2",
               "the yield stress");
  expect_error("*MAT_036\n1,2.7e-9,7e4,0.33,2,500,1.2\n8,0.7,0.6,0.8\n", 2, kKw, "P2", "0 < n < 1");
  expect_error("*MAT_036\n1,2.7e-9,7e4,0.33,3\n8,0.7,0.6,0.8\n", 3, kKw, "LCID",
               "HR 3 needs the hardening curve");
  expect_error("*MAT_036\n1,2.7e-9,7e4,0.33,4,300,400\n8,0.7,0.6,0.8,0,0,0,10\n", 2, kKw, "P2",
               "a - b = P1 - P2 must be > 0");
  const std::string cards12 = card1 + "8,0.7,0.6,0.8\n";
  expect_error(cards12 + "1\n", 4, kKw, "AOPT", "AOPT 1, 4 and coordinate systems");
  expect_error(cards12 + "0,40\n", 4, kKw, "P", "the Cowper-Symonds factor needs both");
  expect_error(cards12 + "0,0,0,7\n", 4, kKw, "VLCID", "volume correction");
  expect_error(cards12 + "0,0,0,0,0,0,3\n", 4, kKw, "HTA", "heat treatment");
  expect_error(cards12 + "2\n0,0,0,0,0,0\n", 5, kKw, "A1", "AOPT = 2 needs a non-zero vector a");
  expect_error(cards12 + "3\n\n0,0,0\n", 6, kKw, "V1", "AOPT = 3 needs a non-zero vector v");
  expect_error(cards12 + "0\n\n\n1\n", 7, kKw, "USRFAIL", "user failure");
}

// --- *MAT_HILL_3R

TEST(MatHill3R, TheJfriedleinCard) {
  // The card of jfriedlein/tensSpeci_SEP1230 (an aluminium: E 63 GPa, yield 178.8 MPa, ETAN
  // 5 GPa), as LS-PrePost writes it.
  const ReadResult r = read_ok(
      "*MAT_HILL_3R_TITLE\n"
      "Hill-plasti\n"
      "$#     mid        ro         e        pr        hr        p1        p2  \n"
      "       1222.70000E-9   63000.0      0.34       1.0    5000.0  178.7811\n"
      "$#     r00       r45       r90      lcid        e0  \n"
      "  1.123572  1.195013  1.012971         0       0.0\n"
      "$#    aopt    \n"
      "       0.0\n"
      "$#  unused    unused    unused        a1        a2        a3  \n"
      "                                     0.0       0.0       0.0\n"
      "$#      v1        v2        v3        d1        d2        d3      beta    \n"
      "       0.0       0.0       0.0       0.0       0.0       0.0       0.0\n");
  ASSERT_EQ(r.model.hill_3r_materials.size(), 1u);
  const model::MatHill3RDesc& m = r.model.hill_3r_materials[0];
  EXPECT_EQ(m.id, 122);
  EXPECT_EQ(m.title, "Hill-plasti");
  EXPECT_DOUBLE_EQ(m.density, 2.7e-9);
  EXPECT_DOUBLE_EQ(m.young, 63000.0);
  EXPECT_DOUBLE_EQ(m.poisson, 0.34);
  EXPECT_EQ(m.hardening.hr, 1);
  EXPECT_DOUBLE_EQ(m.hardening.p1, 5000.0);
  EXPECT_DOUBLE_EQ(m.hardening.p2, 178.7811);
  EXPECT_DOUBLE_EQ(m.r00, 1.123572);
  EXPECT_DOUBLE_EQ(m.r45, 1.195013);
  EXPECT_DOUBLE_EQ(m.r90, 1.012971);
  EXPECT_EQ(m.axes.aopt, 0);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(MatHill3R, Rejections) {
  constexpr std::string_view kKw = "*MAT_122";
  expect_error("*MAT_122\n1,2.7e-9,63000,0.34,4,1,1\n1,1,1\n", 2, kKw, "HR", "HR 4 is *MAT_036's");
  expect_error("*MAT_122\n1,2.7e-9,63000,0.34,1,0,170\n1,0,1\n", 3, kKw, "R45", "R45 must be > 0");
  expect_error("*MAT_122\n1,2.7e-9,63000,0.34,1,63000,170\n1,1,1\n", 2, kKw, "P1", "0 <= P1 < E");
  expect_error("*MAT_122\n1,2.7e-9,63000,0.34\n", 2, kKw, "", "missing card 2");
}

}  // namespace
}  // namespace plyform::keyword
