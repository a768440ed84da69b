// *INITIAL_STRESS_SHELL, *INITIAL_STRAIN_SHELL and *INTERFACE_SPRINGBACK_LSDYNA: the cards of
// LS-DYNA's dynain in its field widths (LARGE 0 and 1, and pydyna's 20-character variant of
// LARGE 1), the history cards read over with a warning, and what plyform does not do refused
// or warned about by name with its line.
#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, expect_error

// LARGE 1: LS-DYNA's large format, five fields of 16 characters to a card of 80 columns (as
// OpenRadioss's reader of LS-DYNA decks takes it); a card that runs past column 80 is in fields
// of 20 (pydyna's), and the point's second card and history cards follow its first card's width.
TEST(InitialStressShell, ReadsTenSixteenAndTwentyCharacterCards) {
  const ReadResult r = read_ok(
      "*INITIAL_STRESS_SHELL\n"
      "$#     eid    nplane    nthick     nhisv    ntensr     large    nthint    nthhsv\n"
      "         7         1         2         0         0         0         0         0\n"
      "      -1.0     100.0     -20.0       0.0       5.0       1.0       2.0      0.01\n"
      "       1.0     200.0       0.0       0.0       0.0       0.0       0.0      0.02\n"
      "         8         1         1         0         0         1\n"
      "  0.000000000000E+00  1.234567890123E+02 -2.000000000000E+00  0.000000000000E+00"
      "  3.000000000000E+00\n"
      "  4.000000000000E+00  5.000000000000E+00  1.000000000000E-01\n"
      "         9         1         1         6         0         1\n"
      "$#             t           sigxx           sigyy           sigzz           sigxy\n"
      " -7.74596669E-01-1.234567890E+02 -2.00000000E+00  0.00000000E+00  3.00000000E+00\n"
      "  4.00000000E+00 -5.00000000E+00  1.00000000E-01\n"
      "              1.              2.              3.              4.              5.\n"
      "              6.\n");
  ASSERT_EQ(r.model.initial_shell_stresses.size(), 3u);
  const model::InitialStressShellDesc& a = r.model.initial_shell_stresses[0];
  EXPECT_EQ(a.element_id, 7);
  EXPECT_EQ(a.nplane, 1);
  EXPECT_EQ(a.nthick, 2);
  EXPECT_FALSE(a.large);
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.where.line, 3);
  EXPECT_EQ(a.points[0].t, -1.0);
  EXPECT_EQ(a.points[0].sigma[0], 100.0);
  EXPECT_EQ(a.points[0].sigma[1], -20.0);
  EXPECT_EQ(a.points[0].sigma[3], 5.0);
  EXPECT_EQ(a.points[0].sigma[4], 1.0);
  EXPECT_EQ(a.points[0].sigma[5], 2.0);
  EXPECT_EQ(a.points[0].eps, 0.01);
  EXPECT_EQ(a.points[1].where.line, 5);
  const model::InitialStressShellDesc& b = r.model.initial_shell_stresses[1];
  EXPECT_TRUE(b.large);
  ASSERT_EQ(b.points.size(), 1u);
  EXPECT_EQ(b.points[0].sigma[0], 123.4567890123);
  EXPECT_EQ(b.points[0].sigma[4], 4.0);
  EXPECT_EQ(b.points[0].sigma[5], 5.0);
  EXPECT_EQ(b.points[0].eps, 0.1);
  // 16 characters: the second field's value has no blank before it (the columns decide).
  const model::InitialStressShellDesc& c = r.model.initial_shell_stresses[2];
  EXPECT_TRUE(c.large);
  ASSERT_EQ(c.points.size(), 1u);
  EXPECT_EQ(c.points[0].t, -0.774596669);
  EXPECT_EQ(c.points[0].sigma[0], -123.456789);
  EXPECT_EQ(c.points[0].sigma[1], -2.0);
  EXPECT_EQ(c.points[0].sigma[3], 3.0);
  EXPECT_EQ(c.points[0].sigma[4], 4.0);
  EXPECT_EQ(c.points[0].sigma[5], -5.0);
  EXPECT_EQ(c.points[0].eps, 0.1);
}

TEST(InitialStressShell, HistoryValuesAreReadOverWithAWarning) {
  const ReadResult r = read_ok(
      "*INITIAL_STRESS_SHELL\n"
      "1,1,1,9\n"
      "0.0,1.0,2.0,0,0,0,0,0.5\n"
      "1,2,3,4,5,6,7,8\n"
      "9\n"
      "2,4,1\n"
      "0,1,1,0,0,0,0,0\n0,1,1,0,0,0,0,0\n0,1,1,0,0,0,0,0\n0,1,1,0,0,0,0,0\n");
  ASSERT_EQ(r.model.initial_shell_stresses.size(), 2u);
  EXPECT_EQ(r.model.initial_shell_stresses[1].points.size(), 4u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].field, "NHISV");
  EXPECT_TRUE(contains(r.warnings[0].message, "not applied"));
}

TEST(InitialStressShell, RefusesWhatItCannotApplyByName) {
  expect_error("*INITIAL_STRESS_SHELL\n1,1,1,0,1\n0,0,0,0,0,0,0,0\n", 2, "*INITIAL_STRESS_SHELL",
               "NTENSR", "range");
  expect_error("*INITIAL_STRESS_SHELL\n1,1,1,0,0,0,2\n0,0,0,0,0,0,0,0\n", 2,
               "*INITIAL_STRESS_SHELL", "NTHINT", "range");
  expect_error("*INITIAL_STRESS_SHELL\n1,2,1\n", 2, "*INITIAL_STRESS_SHELL", "NPLANE",
               "must be one of");
  expect_error("*INITIAL_STRESS_SHELL\n1,1\n", 2, "*INITIAL_STRESS_SHELL", "NTHICK", "");
  expect_error("*INITIAL_STRESS_SHELL\n1,1,2\n0,0,0,0,0,0,0,0\n", 2, "*INITIAL_STRESS_SHELL", "T",
               "missing point card");
  expect_error("*INITIAL_STRESS_SHELL\n1,1,1\n1.5,0,0,0,0,0,0,0\n", 3, "*INITIAL_STRESS_SHELL", "T",
               "range");
  expect_error("*INITIAL_STRESS_SHELL_SET\n1,1,1\n", 1, "*INITIAL_STRESS_SHELL_SET", "SID",
               "not supported");
}

TEST(InitialStrainShell, ReadsBothSurfacesInBothWidths) {
  const ReadResult r = read_ok(
      "*INITIAL_STRAIN_SHELL\n"
      "         3         1         2         0\n"
      "      0.01     -0.02       0.0     0.005       0.0       0.0      -1.0\n"
      "      0.03     -0.01       0.0       0.0       0.0       0.0       1.0\n"
      "         4         1         2         1                                       0\n"
      "  1.000000000000E-02  2.000000000000E-02  3.000000000000E-02  4.000000000000E-02"
      "  5.000000000000E-02\n"
      "  6.000000000000E-02 -1.000000000000E+00\n"
      "  1.000000000000E-02  2.000000000000E-02  3.000000000000E-02  4.000000000000E-02"
      "  5.000000000000E-02\n"
      "  6.000000000000E-02  1.000000000000E+00\n"
      "         5         1         2         1                                       0\n"
      "  1.00000000E-02-2.000000000E-02  3.00000000E-02  4.00000000E-02  5.00000000E-02\n"
      " -6.00000000E-02 -1.00000000E+00\n"
      "  1.00000000E-02  2.00000000E-02  3.00000000E-02  4.00000000E-02  5.00000000E-02\n"
      "  6.00000000E-02  1.00000000E+00\n");
  ASSERT_EQ(r.model.initial_shell_strains.size(), 3u);
  EXPECT_EQ(r.model.initial_shell_strains[0].points[1].eps[0], 0.03);
  EXPECT_EQ(r.model.initial_shell_strains[0].points[0].eps[3], 0.005);
  EXPECT_EQ(r.model.initial_shell_strains[0].points[1].t, 1.0);
  EXPECT_EQ(r.model.initial_shell_strains[1].points[0].eps[5], 0.06);
  EXPECT_EQ(r.model.initial_shell_strains[1].points[0].t, -1.0);
  // LS-DYNA's 16-character fields (the columns decide, blank or not).
  EXPECT_EQ(r.model.initial_shell_strains[2].points[0].eps[1], -0.02);
  EXPECT_EQ(r.model.initial_shell_strains[2].points[0].eps[5], -0.06);
  EXPECT_EQ(r.model.initial_shell_strains[2].points[0].t, -1.0);
  EXPECT_EQ(r.model.initial_shell_strains[2].points[1].eps[4], 0.05);
  EXPECT_EQ(r.model.initial_shell_strains[2].points[1].t, 1.0);
  expect_error("*INITIAL_STRAIN_SHELL\n1,1,2,0,,,,1\n", 2, "*INITIAL_STRAIN_SHELL", "ILOCAL",
               "must be one of");
}

TEST(InterfaceSpringback, KeepsTheRequestAndNamesWhatIsNotWritten) {
  const ReadResult r = read_ok(
      "*INTERFACE_SPRINGBACK_LSDYNA\n"
      "$#    psid      nshv     ftype         -    ftensr    nthhsv     rflag   intstrn\n"
      "        11         0         0                   0         0         0         0\n");
  ASSERT_TRUE(r.model.springback.has_value());
  EXPECT_EQ(r.model.springback->psid, 11);
  EXPECT_EQ(r.model.springback->where.line, 3);
  EXPECT_TRUE(r.warnings.empty());
  const ReadResult w = read_ok("*INTERFACE_SPRINGBACK_LSDYNA\n0,100,2,,1,0,1,1\n1,7,7\n");
  // NSHV, FTYPE 2, FTENSR, RFLAG, INTSTRN and the node card: each named.
  ASSERT_EQ(w.warnings.size(), 6u);
  EXPECT_EQ(w.warnings[0].field, "FTYPE");
  EXPECT_EQ(w.warnings[1].field, "NSHV");
  EXPECT_EQ(w.warnings[5].field, "NID");
  EXPECT_EQ(w.warnings[5].where.line, 3);
  expect_error("*INTERFACE_SPRINGBACK_LSDYNA\n0,0,1\n", 2, "*INTERFACE_SPRINGBACK_LSDYNA", "FTYPE",
               "binary");
  expect_error("*INTERFACE_SPRINGBACK_LSDYNA\n0,0,3\n", 2, "*INTERFACE_SPRINGBACK_LSDYNA", "FTYPE",
               "must be one of");
}

}  // namespace
}  // namespace plyform::keyword
