// The sheet-forming keywords: shells, shell sections, plasticity, orthotropic elasticity, rigid
// bodies and their motions and loads. Fixed and free format, defaults, options, and every
// "not supported yet" error with its file, line, keyword and field.
#include <string>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, single_error, expect_error, ...

TEST(ElementShell, FixedAndFreeFormatQuadsAndTriangles) {
  const ReadResult r = read_ok(
      "*ELEMENT_SHELL\n"
      "$#   eid     pid      n1      n2      n3      n4      n5      n6      n7      n8\n"
      "       1       4      51      73      74      52       0       0       0       0\n"
      "12345678       4       1       2       3       3\n"
      "3,5,7,8,9,10\n");
  const auto& e = r.model.shells;
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].id, 1);
  EXPECT_EQ(e[0].part_id, 4);
  EXPECT_EQ(e[0].nodes, (std::array<int, 4>{51, 73, 74, 52}));
  EXPECT_EQ(e[0].where.line, 3);
  EXPECT_FALSE(e[0].has_thickness_card);
  EXPECT_EQ(e[0].thickness, (std::array<double, 4>{}));
  EXPECT_EQ(e[1].id, 12345678);
  EXPECT_EQ(e[1].nodes[3], 3);  // triangle
  EXPECT_EQ(e[2].nodes, (std::array<int, 4>{7, 8, 9, 10}));
}

TEST(ElementShell, ThicknessOption) {
  const ReadResult r = read_ok(
      "*ELEMENT_SHELL_THICKNESS\n"
      "       1       2      11      12      13      14\n"
      "             1.5             1.6             1.7             1.8            30.0\n"
      "2,2,1,2,3,3\n"
      "0.8,0.8,0.8\n");
  const auto& e = r.model.shells;
  ASSERT_EQ(e.size(), 2u);
  EXPECT_TRUE(e[0].has_thickness_card);
  EXPECT_EQ(e[0].thickness, (std::array<double, 4>{1.5, 1.6, 1.7, 1.8}));
  EXPECT_DOUBLE_EQ(e[0].beta, 30.0);
  EXPECT_EQ(e[0].where.line, 2);
  EXPECT_EQ(e[1].thickness, (std::array<double, 4>{0.8, 0.8, 0.8, 0.0}));
  EXPECT_DOUBLE_EQ(e[1].beta, 0.0);
}

TEST(ElementShell, Errors) {
  expect_error("*ELEMENT_SHELL\n1,1,1,2\n", 2, "*ELEMENT_SHELL", "N3", "N4 = N3");
  expect_error("*ELEMENT_SHELL\n1,1,1,2,3\n", 2, "*ELEMENT_SHELL", "N4",
               "write a triangle with N4 = N3");
  expect_error("*ELEMENT_SHELL\n1,1,1,2,3,4,5,6,7,8\n", 2, "*ELEMENT_SHELL", "N5", "must be <= 0");
  expect_error("*ELEMENT_SHELL_THICKNESS\n1,1,1,2,3,4\n", 2, "*ELEMENT_SHELL_THICKNESS", "THIC1",
               "missing thickness card");
  expect_error("*ELEMENT_SHELL_THICKNESS\n1,1,1,2,3,4\n-1.0\n", 3, "*ELEMENT_SHELL_THICKNESS",
               "THIC1", "out of range");
}

TEST(SectionShell, FixedFormatDefaultsAndTitle) {
  const ReadResult r = read_ok(
      "*SECTION_SHELL\n"
      "$#   secid    elform      shrf       nip     propt   qr/irid     icomp     setyp\n"
      "         1        16     0.833         5       1.0         0         0         1\n"
      "$#      t1        t2        t3        t4      nloc     marea      idof    edgset\n"
      "       1.5       1.5       1.5       1.5       0.0       0.0       0.0         0\n"
      "         2\n"
      "       0.7\n"
      "*SECTION_SHELL\n"
      "         4         0 0.0000000 3.0000000 0.0000000 0.0000000         0\n"
      " 0.0200000 0.0200000 0.0200000 0.0200000 0.0000000\n"
      "*SECTION_SHELL_TITLE\n"
      "blank holder\n"
      "3,0,0.0,0\n"
      "1.0,1.1\n");
  const auto& s = r.model.shell_sections;
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].id, 1);
  EXPECT_EQ(s[0].elform, 16);
  EXPECT_DOUBLE_EQ(s[0].shear_factor, 0.833);
  EXPECT_EQ(s[0].nip, 5);
  EXPECT_EQ(s[0].quadrature, 0);
  EXPECT_EQ(s[0].thickness, (std::array<double, 4>{1.5, 1.5, 1.5, 1.5}));
  EXPECT_EQ(s[0].where.line, 3);
  EXPECT_TRUE(s[0].title.empty());
  // Blank fields: LS-DYNA's defaults (ELFORM 2, SHRF 1, NIP 2); T2..T4 = T1.
  EXPECT_EQ(s[1].id, 2);
  EXPECT_EQ(s[1].elform, 2);
  EXPECT_DOUBLE_EQ(s[1].shear_factor, 1.0);
  EXPECT_EQ(s[1].nip, 2);
  EXPECT_DOUBLE_EQ(s[1].propt, 1.0);
  EXPECT_EQ(s[1].setyp, 1);
  EXPECT_EQ(s[1].thickness, (std::array<double, 4>{0.7, 0.7, 0.7, 0.7}));
  EXPECT_TRUE(s[1].angles.empty());
  // NIP and QR/IRID are real fields in LS-DYNA: "3.0000000" is 3 points.
  EXPECT_EQ(s[2].nip, 3);
  EXPECT_EQ(s[2].quadrature, 0);
  EXPECT_DOUBLE_EQ(s[2].shear_factor, 1.0);
  EXPECT_EQ(s[2].thickness, (std::array<double, 4>{0.02, 0.02, 0.02, 0.02}));
  EXPECT_EQ(s[3].title, "blank holder");
  EXPECT_EQ(s[3].elform, 2);  // 0 is read as 2
  EXPECT_DOUBLE_EQ(s[3].shear_factor, 1.0);
  EXPECT_EQ(s[3].nip, 2);
  EXPECT_EQ(s[3].thickness, (std::array<double, 4>{1.0, 1.1, 1.0, 1.0}));
  EXPECT_EQ(s[3].where.line, 13);
}

TEST(SectionShell, AnglesOfIcomp) {
  const ReadResult r = read_ok(
      "*SECTION_SHELL\n"
      "1,2,0.8333,10,,,1\n"
      "1.0\n"
      "0,45,90,-45,0,45,90,-45\n"
      "0,90\n"
      "*SECTION_SHELL\n"
      "2,2,,3,,,1\n"
      "1.0\n"
      "0.0,90.0,0.0\n");
  const auto& s = r.model.shell_sections;
  ASSERT_EQ(s.size(), 2u);
  ASSERT_EQ(s[0].angles.size(), 10u);
  EXPECT_DOUBLE_EQ(s[0].angles[1], 45.0);
  EXPECT_DOUBLE_EQ(s[0].angles[9], 90.0);
  EXPECT_EQ(s[0].icomp, 1);
  EXPECT_EQ(s[1].angles, (std::vector<double>{0.0, 90.0, 0.0}));
}

TEST(SectionShell, Errors) {
  expect_error("*SECTION_SHELL\n1,1\n1.0\n", 2, "*SECTION_SHELL", "ELFORM",
               "value 1 is not supported: must be one of 0, 2, 16");
  expect_error("*SECTION_SHELL\n1,-16\n1.0\n", 2, "*SECTION_SHELL", "ELFORM", "not supported");
  expect_error("*SECTION_SHELL\n1,2,1,11\n1.0\n", 2, "*SECTION_SHELL", "NIP", "[0, 10]");
  expect_error("*SECTION_SHELL\n1,2,1,2.5\n1.0\n", 2, "*SECTION_SHELL", "NIP",
               "NIP = 2.5 is not a whole number of points");
  expect_error("*SECTION_SHELL\n1,2,1,3,1,1\n1.0\n", 2, "*SECTION_SHELL", "QR/IRID",
               "trapezoidal (1) and user rules");
  expect_error("*SECTION_SHELL\n1,2,1,3,1,-2\n1.0\n", 2, "*SECTION_SHELL", "QR/IRID",
               "not supported");
  expect_error("*SECTION_SHELL\n1,2,1,3,1,0,2\n1.0\n", 2, "*SECTION_SHELL", "ICOMP",
               "must be one of 0, 1");
  expect_error("*SECTION_SHELL\n1,2\n", 2, "*SECTION_SHELL", "", "missing card 2");
  expect_error("*SECTION_SHELL\n1,2\n1.0,,,,1.0\n", 3, "*SECTION_SHELL", "NLOC",
               "NLOC = 1 (a reference surface off the mid-plane) is not supported yet");
  expect_error("*SECTION_SHELL\n1,2\n1.0,,,,,0.1\n", 3, "*SECTION_SHELL", "MAREA",
               "not supported yet");
  expect_error("*SECTION_SHELL\n1,2\n1.0,,,,,,3\n", 3, "*SECTION_SHELL", "IDOF",
               "not supported yet");
  expect_error("*SECTION_SHELL\n1,2\n1.0,,,,,,,4\n", 3, "*SECTION_SHELL", "EDGSET",
               "not supported yet");
  expect_error("*SECTION_SHELL\n1,2,1,9,,,1\n1.0\n1,2,3,4,5,6,7,8\n", 3, "*SECTION_SHELL", "B9",
               "ICOMP = 1 needs 9 material angles B1..B9");
}

TEST(MatPiecewiseLinearPlasticity, CurveTableAndBilinear) {
  const ReadResult r = read_ok(
      "*MAT_PIECEWISE_LINEAR_PLASTICITY_TITLE\n"
      "steel DC04\n"
      "$#     mid        ro         e        pr      sigy      etan      fail      tdel\n"
      "         17.85000E-9  210000.0       0.3     180.0\n"
      "$#       c         p      lcss      lcsr        vp       lcf\n"
      "       0.0       0.0        12         0       0.0         0\n"
      "*MAT_024\n"
      "2,7.85e-9,2.1e5,0.3\n"
      "\n"
      "0.0,0.1,0.2,0.5\n"
      "200.0,300.0,350.0,400.0\n"
      "*MAT_PIECEWISE_LINEAR_PLASTICITY\n"
      "3,2.7e-9,70000,0.33,100.0,500.0,0.4,1e-7\n");
  const auto& m = r.model.piecewise_linear_materials;
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].title, "steel DC04");
  EXPECT_EQ(m[0].id, 1);
  EXPECT_DOUBLE_EQ(m[0].density, 7.85e-9);
  EXPECT_DOUBLE_EQ(m[0].youngs_modulus, 210000.0);
  EXPECT_DOUBLE_EQ(m[0].yield_stress, 180.0);
  EXPECT_DOUBLE_EQ(m[0].fail, 1.0e21);  // blank: never
  EXPECT_EQ(m[0].lcss, 12);
  EXPECT_TRUE(m[0].eps.empty());
  EXPECT_EQ(m[0].where.line, 4);
  EXPECT_EQ(m[1].eps, (std::vector<double>{0.0, 0.1, 0.2, 0.5}));
  EXPECT_EQ(m[1].es, (std::vector<double>{200.0, 300.0, 350.0, 400.0}));
  EXPECT_EQ(m[1].lcss, 0);
  EXPECT_DOUBLE_EQ(m[2].tangent_modulus, 500.0);
  EXPECT_DOUBLE_EQ(m[2].fail, 0.4);
  EXPECT_DOUBLE_EQ(m[2].tdel, 1e-7);
}

TEST(MatPiecewiseLinearPlasticity, RatesNotSupportedYetAndBadTables) {
  constexpr std::string_view kKeyword = "*MAT_PIECEWISE_LINEAR_PLASTICITY";
  // Cowper-Symonds: C and P together (read), one alone an error on the other; VP 1 and -1
  // with rates are errors, without rates VP is kept.
  const ReadResult rates =
      read_ok("*MAT_PIECEWISE_LINEAR_PLASTICITY\n1,7.8e-9,2e5,0.3,200\n40.0,5.0\n");
  ASSERT_EQ(rates.model.piecewise_linear_materials.size(), 1u);
  EXPECT_DOUBLE_EQ(rates.model.piecewise_linear_materials[0].c, 40.0);
  EXPECT_DOUBLE_EQ(rates.model.piecewise_linear_materials[0].p, 5.0);
  EXPECT_EQ(read_ok("*MAT_024\n1,7.8e-9,2e5,0.3,200\n0,0,0,0,1.0\n")
                .model.piecewise_linear_materials.size(),
            1u);
  expect_error("*MAT_PIECEWISE_LINEAR_PLASTICITY\n1,7.8e-9,2e5,0.3,200\n40.0\n", 3, kKeyword, "P",
               "C = 40, P = 0: the Cowper-Symonds factor needs both");
  expect_error("*MAT_PIECEWISE_LINEAR_PLASTICITY\n1,7.8e-9,2e5,0.3,200\n0,5.0\n", 3, kKeyword, "C",
               "needs both");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3,200\n40.0,5.0,0,0,1.0\n", 3, "*MAT_024", "VP",
               "VP = 1 is not supported (1: the viscoplastic formulation");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3,200\n0,0,0,7\n", 3, "*MAT_024", "LCSR",
               "LCSR = 7 (a strain rate scaling curve) is not supported yet");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3,200\n0,0,0,0,0,9\n", 3, "*MAT_024", "LCF",
               "not supported yet");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3,200\n0,0,-4\n", 3, "*MAT_024", "LCSS",
               "negative curve or table id is not supported");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3,200,0,-1\n", 2, "*MAT_024", "FAIL",
               "user failure routine");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3\n", 2, "*MAT_024", "SIGY",
               "neither LCSS nor the EPS/ES table");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3\n\n0.0\n200.0\n", 5, "*MAT_024", "ES2",
               "at least 2 points");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3\n\n0.0,0.2,0.1\n200,300,400\n", 4, "*MAT_024", "EPS3",
               "must be >= 0 and increase");
  expect_error("*MAT_024\n1,7.8e-9,2e5,0.3\n\n0.0,0.2\n200,-300\n", 5, "*MAT_024", "ES2",
               "ES2 must be > 0");
  expect_error("*MAT_024\n1,0,2e5,0.3,200\n", 2, "*MAT_024", "RO", "RO must be > 0");
}

TEST(MatPowerLawPlasticity, ReadsRatesAndRejectsHalfAPair) {
  const ReadResult r = read_ok(
      "*MAT_POWER_LAW_PLASTICITY_TITLE\n"
      "aluminium\n"
      "         12.70000E-9   70000.0      0.33     500.0      0.22\n"
      "      0.02\n"
      "*MAT_018\n"
      "2,7.8e-9,2e5,0.3,600,0.2\n");
  const auto& m = r.model.power_law_materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].title, "aluminium");
  EXPECT_DOUBLE_EQ(m[0].k, 500.0);
  EXPECT_DOUBLE_EQ(m[0].n, 0.22);
  EXPECT_DOUBLE_EQ(m[0].sigy, 0.02);
  EXPECT_EQ(m[0].where.line, 3);
  EXPECT_DOUBLE_EQ(m[1].sigy, 0.0);
  EXPECT_DOUBLE_EQ(m[1].epsf, 0.0);
  const ReadResult rates = read_ok("*MAT_018\n1,7.8e-9,2e5,0.3,600,0.2,40,5\n");
  EXPECT_DOUBLE_EQ(rates.model.power_law_materials[0].src, 40.0);
  EXPECT_DOUBLE_EQ(rates.model.power_law_materials[0].srp, 5.0);
  expect_error("*MAT_018\n1,7.8e-9,2e5,0.3,600,0.2,40\n", 2, "*MAT_018", "SRP",
               "SRC = 40, SRP = 0: the Cowper-Symonds factor needs both");
  expect_error("*MAT_POWER_LAW_PLASTICITY\n1,7.8e-9,2e5,0.3,600,0.2,0,5\n", 2,
               "*MAT_POWER_LAW_PLASTICITY", "SRC", "needs both");
  expect_error("*MAT_018\n1,7.8e-9,2e5,0.3,600,0.2,40,5\n0,-1\n", 3, "*MAT_018", "VP",
               "VP = -1 is not supported");
  expect_error("*MAT_018\n1,7.8e-9,2e5,0.3\n", 2, "*MAT_018", "K", "a value is required");
}

TEST(MatOrthotropicElastic, AoptZeroAndTwo) {
  const ReadResult r = read_ok(
      "*MAT_ORTHOTROPIC_ELASTIC_TITLE\n"
      "woven ply\n"
      "$#     mid        ro        ea        eb        ec      prba      prca      prcb\n"
      "         11.80000E-9   20000.0   20000.0    3000.0      0.05       0.3       0.3\n"
      "    1200.0    1000.0    1000.0       0.0\n"
      "*MAT_002\n"
      "2,1.8e-9,2e4,1e4,3e3,0.05,0.3,0.3\n"
      "1200,1000,1000,2\n"
      "0,0,0,1,1,0\n"
      "0,0,0,0,1,0,15.0\n");
  const auto& m = r.model.orthotropic_elastic_materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].title, "woven ply");
  EXPECT_DOUBLE_EQ(m[0].ec, 3000.0);
  EXPECT_DOUBLE_EQ(m[0].gab, 1200.0);
  EXPECT_EQ(m[0].aopt, 0);
  EXPECT_EQ(m[0].macf, 1);
  EXPECT_EQ(m[1].aopt, 2);
  EXPECT_EQ(m[1].a, (std::array<double, 3>{1.0, 1.0, 0.0}));
  EXPECT_EQ(m[1].d, (std::array<double, 3>{0.0, 1.0, 0.0}));
  EXPECT_DOUBLE_EQ(m[1].beta, 15.0);
}

TEST(MatOrthotropicElastic, Errors) {
  constexpr std::string_view kCard1 = "*MAT_002\n1,1e-9,2e4,1e4,3e3,0.05,0.3,0.3\n";
  expect_error(std::string(kCard1) + "1200,1000,1000,3\n", 3, "*MAT_002", "AOPT",
               "AOPT 1, 3, 4 and coordinate systems (< 0) are not supported yet");
  expect_error(std::string(kCard1) + "1200,1000,1000,-5\n", 3, "*MAT_002", "AOPT", "not supported");
  expect_error(std::string(kCard1) + "1200,1000,1000,0,300\n", 3, "*MAT_002", "G",
               "not supported yet");
  expect_error(std::string(kCard1) + "1200,1000,1000,0,0,5\n", 3, "*MAT_002", "SIGF",
               "not supported yet");
  expect_error(std::string(kCard1) + "1200,1000,1000\n0,0,0,0,0,0,2\n", 4, "*MAT_002", "MACF",
               "switching material axes is not supported yet");
  expect_error(std::string(kCard1) + "1200,1000,1000\n0,0,0,0,0,0,1,1\n", 4, "*MAT_002", "IHIS",
               "not supported yet");
  expect_error(std::string(kCard1) + "1200,1000,1000\n\n0,0,0,0,0,0,0,1\n", 5, "*MAT_002", "REF",
               "not supported yet");
  expect_error(std::string(kCard1) + "1200,1000,1000,2\n0,0,0,1,0,0\n0,0,0,2,0,0\n", 5, "*MAT_002",
               "D1", "not parallel to a");
  expect_error(std::string(kCard1) + "1200,1000,1000,2\n", 3, "*MAT_002", "A1",
               "non-zero vector a");
  expect_error(std::string(kCard1) + "0,1000,1000\n", 3, "*MAT_002", "GAB",
               "GAB must be > 0, got 0");
  expect_error(std::string(kCard1), 2, "*MAT_002", "", "missing card 2");
}

TEST(MatRigid, ReadsAllCardsAsWritten) {
  const ReadResult r = read_ok(
      "*MAT_RIGID\n"
      "$#     mid        ro         e        pr         n    couple         m     alias\n"
      "         27.83000E-9  207000.0      0.28       0.0       0.0       0.0          \n"
      "$#     cmo      con1      con2    spcnid      xspc      yspc      zspc\n"
      "       1.0         7         6         0       0.0       0.0       0.0\n"
      "$#lco or a1        a2        a3        v1        v2        v3\n"
      "       0.0       0.0       1.0       1.0       0.0       0.0\n"
      "*MAT_020_TITLE\n"
      "die\n"
      "3,7.8e-9,2.1e5,0.3\n");
  const auto& m = r.model.rigid_materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].id, 2);
  EXPECT_DOUBLE_EQ(m[0].density, 7.83e-9);
  EXPECT_DOUBLE_EQ(m[0].poisson_ratio, 0.28);
  EXPECT_EQ(m[0].cmo, 1);
  EXPECT_EQ(m[0].con1, 7);
  EXPECT_EQ(m[0].con2, 6);
  EXPECT_EQ(m[0].a, (std::array<double, 3>{0.0, 0.0, 1.0}));
  EXPECT_EQ(m[0].v, (std::array<double, 3>{1.0, 0.0, 0.0}));
  EXPECT_EQ(m[0].where.line, 3);
  EXPECT_EQ(m[1].title, "die");
  EXPECT_EQ(m[1].cmo, 0);  // cards 2 and 3 missing: blank
  EXPECT_EQ(m[1].con1, 0);
}

TEST(MatRigid, Errors) {
  expect_error("*MAT_RIGID\n1,7.8e-9,2e5,0.3,1\n", 2, "*MAT_RIGID", "N",
               "N = 1 (MADYMO coupling) is not supported yet");
  expect_error("*MAT_RIGID\n1,7.8e-9,2e5,0.3,0,-1\n", 2, "*MAT_RIGID", "COUPLE",
               "not supported yet");
  expect_error("*MAT_RIGID\n1,7.8e-9,2e5,0.3,0,0,3\n", 2, "*MAT_RIGID", "M", "not supported yet");
  expect_error("*MAT_RIGID\n1,7.8e-9,2e5,0.3\n3.0\n", 3, "*MAT_RIGID", "CMO",
               "must be one of -2, -1, 0, 1, 2");
  expect_error("*MAT_RIGID\n1,7.8e-9,2e5,0.3\n1.0,8\n", 3, "*MAT_RIGID", "CON1",
               "with CMO > 0 it must be in [0, 7]");
  expect_error("*MAT_RIGID\n1,7.8e-9,2e5,0.3\n1.0,7,2.5\n", 3, "*MAT_RIGID", "CON2",
               "not an integer code");
  expect_error("*MAT_RIGID\n1,7.8e-9,0,0.3\n", 2, "*MAT_RIGID", "E", "E must be > 0");
}

TEST(PrescribedMotionRigid, TranslationsRotationsAndId) {
  const ReadResult r = read_ok(
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n"
      "$#     pid       dof       vad      lcid        sf       vid     death     birth\n"
      "         2         3         2         2      -1.0         0       0.0       0.0\n"
      "3,7,0,3\n"
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID_ID\n"
      "        12punch stroke\n"
      "4,1,1,5,2.0,0,0.5,0.1\n");
  const auto& m = r.model.rigid_motions;
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].part_id, 2);
  EXPECT_EQ(m[0].dof, 3);
  EXPECT_EQ(m[0].vad, 2);
  EXPECT_EQ(m[0].curve_id, 2);
  EXPECT_DOUBLE_EQ(m[0].scale, -1.0);
  EXPECT_DOUBLE_EQ(m[0].death, 1.0e28);  // 0 is read as 1e28
  EXPECT_EQ(m[0].where.line, 3);
  EXPECT_EQ(m[1].dof, 7);
  EXPECT_DOUBLE_EQ(m[1].scale, 1.0);
  EXPECT_EQ(m[2].id, 12);
  EXPECT_EQ(m[2].heading, "punch stroke");
  EXPECT_DOUBLE_EQ(m[2].death, 0.5);
  EXPECT_DOUBLE_EQ(m[2].birth, 0.1);
  EXPECT_EQ(m[2].where.line, 7);
  EXPECT_TRUE(r.model.prescribed_motions.empty());
}

TEST(PrescribedMotionRigid, Errors) {
  constexpr std::string_view kKeyword = "*BOUNDARY_PRESCRIBED_MOTION_RIGID";
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,4,0,1\n", 2, kKeyword, "DOF",
               "value 4 is not supported: must be one of 1, 2, 3, 5, 6, 7");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,-8,0,1\n", 2, kKeyword, "DOF",
               "not supported");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,11,0,1\n", 2, kKeyword, "DOF",
               "not supported");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,1,4,1\n", 2, kKeyword, "VAD",
               "relative displacement");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,1,0,1,1.0,-3\n", 2, kKeyword, "VID",
               "VID = -3 (a vector or local coordinate system) is not supported yet");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,1,0,1,1.0,0,1.0,2.0\n", 2, kKeyword, "DEATH",
               "not after BIRTH");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,1,0\n", 2, kKeyword, "LCID",
               "a value is required");
}

TEST(LoadRigidBody, ForcesAndMoments) {
  const ReadResult r = read_ok(
      "*LOAD_RIGID_BODY\n"
      "$#     pid       dof      lcid        sf       cid        m1        m2        m3\n"
      "         5         3         7     -50.0\n"
      "5,6,8\n");
  const auto& l = r.model.rigid_body_loads;
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].part_id, 5);
  EXPECT_EQ(l[0].dof, 3);
  EXPECT_EQ(l[0].curve_id, 7);
  EXPECT_DOUBLE_EQ(l[0].scale, -50.0);
  EXPECT_EQ(l[0].where.line, 3);
  EXPECT_EQ(l[1].dof, 6);
  EXPECT_DOUBLE_EQ(l[1].scale, 1.0);
  expect_error("*LOAD_RIGID_BODY\n1,4,1\n", 2, "*LOAD_RIGID_BODY", "DOF",
               "follower forces and moments (4, 8) are not supported yet");
  expect_error("*LOAD_RIGID_BODY\n1,1,1,1.0,2\n", 2, "*LOAD_RIGID_BODY", "CID",
               "CID = 2 (a local coordinate system) is not supported yet");
}

}  // namespace
}  // namespace plyform::keyword

namespace plyform::keyword {
namespace {

TEST(ControlShell, ReadsLobattoAndRejectsWhatIsNotImplemented) {
  const auto ok = read_deck_text(
      "*KEYWORD\n*CONTROL_SHELL\n      20.0         0        -1         1         2         2"
      "         1         0\n       1.0         1         0         1         0\n*END\n",
      "shell.k");
  ASSERT_TRUE(ok.ok()) << ok.errors.front().to_string();
  ASSERT_TRUE(ok.model.control_shell.has_value());
  EXPECT_EQ(ok.model.control_shell->intgrd, 1);
  EXPECT_EQ(ok.model.control_shell->istupd, 1);
  const auto bad = read_deck_text(
      "*KEYWORD\n*CONTROL_SHELL\n      20.0         0        -1         1         2         1\n"
      "*END\n",
      "shell.k");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.errors.front().where.line, 3);
  EXPECT_EQ(bad.errors.front().keyword, "*CONTROL_SHELL");
  EXPECT_EQ(bad.errors.front().field, "BWC");
}

// Cards 3 and 4 as LS-PrePost writes them (the metal-forming and coach-peel decks' layouts),
// ESORT read; what would change the shells or delete elements named.
TEST(ControlShell, Cards3And4AsLsPrePostWritesThem) {
  const auto ok = read_deck_text(
      "*KEYWORD\n*CONTROL_SHELL\n      20.0         1        -1         1         2         2"
      "         1         0\n       1.0         0         0         1         0\n"
      "         0         0         0         0         2       0.0       0.0         0\n"
      "         1         1   6600000         0         0         0       0.0         0\n*END\n",
      "shell.k");
  ASSERT_TRUE(ok.ok()) << ok.errors.front().to_string();
  EXPECT_EQ(ok.model.control_shell->esort, 1);
  const std::string head = "*CONTROL_SHELL\n20.0,1,-1,1,2,2,1,0\n\n";
  expect_error(head + "1\n", 4, "*CONTROL_SHELL", "PSSTUPD", "every shell");
  expect_error(head + "0,0,0,0,0,5.0\n", 4, "*CONTROL_SHELL", "W-MODE", "out of range");
  expect_error(head + "0,0,0,0,0,0,0,1\n", 4, "*CONTROL_SHELL", "ICRQ", "ICRQ 1");
  expect_error(head + "\n2\n", 5, "*CONTROL_SHELL", "NFAIL1", "deleting");
  expect_error(head + "\n\n1\n", 6, "*CONTROL_SHELL", "", "cards 5 and after");
}

TEST(ControlSolid, ReadAsLsPrePostWritesIt) {
  const auto ok = read_deck_text(
      "*KEYWORD\n*CONTROL_SOLID\n         1         0         0         1         0       0.0"
      "         0         0\n       0       0       0       0       0       0       0       0"
      "       0       0\n*END\n",
      "solid.k");
  ASSERT_TRUE(ok.ok()) << ok.errors.front().to_string();
  expect_error("*CONTROL_SOLID\n1,0,0,1,5\n", 2, "*CONTROL_SOLID", "PSFAIL", "deletes no");
  expect_error("*CONTROL_SOLID\n1,1\n", 2, "*CONTROL_SOLID", "FMATRX", "default");
  expect_error("*CONTROL_SOLID\n1\n0,0,3\n", 3, "*CONTROL_SOLID", "PM3", "must be 0");
}

// Adaptivity: read and warned about by name; LS-DYNA's springback file is written
// (docs/outputs.md), the history values it asks for (NSHV) are not, and that is named.
TEST(ControlAdapstepAndSpringback, AreReadAndWarnedAbout) {
  const auto r = read_deck_text(
      "*KEYWORD\n*CONTROL_ADAPSTEP\n       1.0      0.01\n*INTERFACE_SPRINGBACK_LSDYNA\n"
      "        11       100         0                   0         0         0         0\n"
      "*END\n",
      "forming.k");
  ASSERT_TRUE(r.ok()) << r.errors.front().to_string();
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[0].keyword, "*CONTROL_ADAPSTEP");
  EXPECT_NE(r.warnings[0].message.find("does not refine meshes"), std::string::npos);
  EXPECT_EQ(r.warnings[1].keyword, "*INTERFACE_SPRINGBACK_LSDYNA");
  EXPECT_EQ(r.warnings[1].field, "NSHV");
  ASSERT_TRUE(r.model.springback.has_value());
  EXPECT_EQ(r.model.springback->psid, 11);
}

}  // namespace
}  // namespace plyform::keyword
