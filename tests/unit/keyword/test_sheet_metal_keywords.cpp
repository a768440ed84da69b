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

TEST(MatTransverselyAnisotropic, Rejections) {
  constexpr std::string_view kKw = "*MAT_037";
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,201.3,0,-1.593,1\n", 2, kKw, "R",
               "R = -1.593: a Lankford ratio is positive, and LS-DYNA gives a negative R a "
               "meaning of its own that plyform does not implement");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,201.3,0,-4,1\n", 2, kKw, "R",
               "(R against plastic strain from curve -R)");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,201.3,0,0\n", 2, kKw, "R", "R must be > 0");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,201.3,0\n", 2, kKw, "R", "a value is required");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,0,0,1.5\n", 2, kKw, "SIGY", "SIGY must be > 0");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,200,207000,1.5\n", 2, kKw, "ETAN", "must be below E");
  expect_error("*MAT_037\n1,7.9e-9,207000,0.3,200,0,1.5,-2\n", 2, kKw, "HLCID", "");
  expect_error("*MAT_037\n1,0,207000,0.3,200,0,1.5\n", 2, kKw, "RO", "RO must be > 0");
  const std::string card1 = "*MAT_037\n1,7.9e-9,207000,0.3,200,0,1.5\n";
  expect_error(card1 + "3\n", 3, kKw, "IDSCALE", "IDSCALE = 3 (Young's modulus against");
  expect_error(card1 + "0,1.2\n", 3, kKw, "EA", "EA = 1.2");
  expect_error(card1 + "0,0,0.5\n", 3, kKw, "COE", "COE = 0.5");
  expect_error(card1 + "0,0,0,0,0,0.1\n", 3, kKw, "STRAINLT", "strain averaging");
  expect_error(card1 + "0,0,0,0,7\n", 3, kKw, "UNUSED", "LS-DYNA does not use it");
}

}  // namespace
}  // namespace plyform::keyword
