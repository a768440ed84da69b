// *DATABASE_ELOUT and *DATABASE_HISTORY_SHELL / _SOLID as LS-PrePost writes them: the card
// read with its four extra-variable counts (warned about by name: plyform writes none), the
// element ids of the history keywords, the _SET forms passed over as output requests, and the
// warnings when one comes without the other.
#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, expect_error

std::string warnings_of(const ReadResult& r) {
  std::string out;
  for (const Diagnostic& d : r.warnings)
    out += d.to_string() + "\n";
  return out;
}

TEST(DatabaseElout, ReadsTheCardAsLsPrePostWritesIt) {
  const ReadResult r = read_ok(
      "*DATABASE_ELOUT\n"
      "$#      dt    binary      lcur     ioopt   option1   option2   option3   option4\n"
      "2.00000E-4         0         0         1         0         0         0         0\n"
      "*DATABASE_HISTORY_SHELL\n"
      "$#     id1       id2       id3       id4       id5       id6       id7       id8\n"
      "      2611      3007      3403      3799         0         0         0         0\n"
      "        12\n"
      "*DATABASE_HISTORY_SOLID\n7,,0,8\n");
  ASSERT_TRUE(r.model.elout.has_value());
  EXPECT_DOUBLE_EQ(r.model.elout->dt, 2e-4);
  EXPECT_EQ(r.model.elout->ioopt, 1);
  EXPECT_EQ(r.model.elout->where.line, 3);
  ASSERT_EQ(r.model.history_elements.size(), 2u);
  const auto& shells = r.model.history_elements[0];
  EXPECT_TRUE(shells.shell);
  EXPECT_EQ(shells.element_ids, (std::vector<int>{2611, 3007, 3403, 3799, 12}));
  EXPECT_EQ(shells.ids_where[4].line, 7);
  EXPECT_EQ(shells.where.line, 4);
  const auto& solids = r.model.history_elements[1];
  EXPECT_FALSE(solids.shell);
  EXPECT_EQ(solids.element_ids, (std::vector<int>{7, 8}));  // blank and 0: none
  EXPECT_TRUE(r.warnings.empty()) << warnings_of(r);
  // The short card (DT only) and BINARY 2 or 3 (binout): CSV all the same.
  const ReadResult short_card = read_ok("*DATABASE_ELOUT\n0.1,3\n*DATABASE_HISTORY_SOLID\n1\n");
  EXPECT_EQ(short_card.model.elout->binary, 3);
  EXPECT_EQ(short_card.model.elout->option1, 0);
}

TEST(DatabaseElout, ExtraHistoryVariablesAreWarnedAboutByName) {
  const ReadResult r = read_ok("*DATABASE_ELOUT\n0.1,1,0,1,4,0,0,2\n*DATABASE_HISTORY_SHELL\n1\n");
  ASSERT_EQ(r.warnings.size(), 2u) << warnings_of(r);
  EXPECT_EQ(r.warnings[0].field, "OPTION1");
  EXPECT_EQ(r.warnings[0].where.line, 2);
  EXPECT_TRUE(contains(r.warnings[0].message,
                       "4 extra history variables per integration point "
                       "not written"))
      << r.warnings[0].message;
  EXPECT_EQ(r.warnings[1].field, "OPTION4");
  EXPECT_TRUE(contains(r.warnings[1].message, "no beams")) << r.warnings[1].message;
  EXPECT_EQ(r.model.elout->option1, 4);
  EXPECT_EQ(r.model.elout->option4, 2);
}

TEST(DatabaseElout, IntervalCurveIsRejectedByName) {
  expect_error("*DATABASE_ELOUT\n0.1,1,5\n", 2, "*DATABASE_ELOUT", "LCUR", "");
  expect_error("*DATABASE_ELOUT\n-0.1\n", 2, "*DATABASE_ELOUT", "DT", "range");
  expect_error("*DATABASE_ELOUT\n0.1,1,0,1,-1\n", 2, "*DATABASE_ELOUT", "OPTION1", "range");
}

TEST(DatabaseElout, GivenTwiceTheLastOneIsUsed) {
  const ReadResult r =
      read_ok("*DATABASE_ELOUT\n0.1\n*DATABASE_ELOUT\n0.2\n*DATABASE_HISTORY_SHELL\n1\n");
  EXPECT_DOUBLE_EQ(r.model.elout->dt, 0.2);
  ASSERT_EQ(r.warnings.size(), 1u) << warnings_of(r);
  EXPECT_EQ(r.warnings[0].where.line, 3);
  EXPECT_TRUE(contains(r.warnings[0].message, "replaces the one at deck.k:2"));
}

TEST(DatabaseHistoryElement, IdFormTakesOneElementAndHeadingPerCard) {
  const ReadResult r = read_ok(
      "*DATABASE_ELOUT\n0.1\n"
      "*DATABASE_HISTORY_SHELL_ID\n"
      "$#      id                                                               heading\n"
      "        41middle of the blank\n"
      "        42\n");
  ASSERT_EQ(r.model.history_elements.size(), 1u);
  const auto& h = r.model.history_elements[0];
  EXPECT_EQ(h.element_ids, (std::vector<int>{41, 42}));
  EXPECT_EQ(h.headings[0], "middle of the blank");
  EXPECT_EQ(h.ids_where[1].line, 6);
  expect_error("*DATABASE_HISTORY_SOLID_ID\n0\n", 2, "*DATABASE_HISTORY_SOLID_ID", "ID", "range");
}

TEST(DatabaseHistoryElement, SetFormsArePassedOverAsOutputRequests) {
  // Plyform has no shell or solid element sets: the request is named, never an error.
  const ReadResult r =
      read_ok("*DATABASE_ELOUT\n0.1\n*DATABASE_HISTORY_SHELL_SET\n3\n*DATABASE_HISTORY_SOLID\n1\n");
  ASSERT_EQ(r.warnings.size(), 1u) << warnings_of(r);
  EXPECT_EQ(r.warnings[0].where.line, 3);
  EXPECT_TRUE(contains(r.warnings[0].message, "output request not written"));
}

TEST(DatabaseHistoryElement, EloutWithoutElementsHasNothingToWrite) {
  const ReadResult r = read_ok("*DATABASE_ELOUT\n0.1\n*DATABASE_HISTORY_SHELL\n0,0\n");
  ASSERT_EQ(r.warnings.size(), 1u) << warnings_of(r);
  EXPECT_EQ(r.warnings[0].keyword, "*DATABASE_ELOUT");
  EXPECT_EQ(r.warnings[0].where.line, 2);
  EXPECT_TRUE(contains(r.warnings[0].message, "nothing to write")) << r.warnings[0].message;
}

TEST(DatabaseHistoryElement, ElementsWithoutEloutAreKeptButNotWritten) {
  const ReadResult r = read_ok("*DATABASE_HISTORY_SHELL\n1,2\n*DATABASE_HISTORY_SOLID\n3\n");
  ASSERT_EQ(r.warnings.size(), 2u) << warnings_of(r);
  EXPECT_EQ(r.warnings[0].keyword, "*DATABASE_HISTORY_SHELL");
  EXPECT_EQ(r.warnings[0].where.line, 1);
  EXPECT_TRUE(contains(r.warnings[0].message,
                       "2 elements kept, but no elout.csv is written without *DATABASE_ELOUT"))
      << r.warnings[0].message;
  EXPECT_EQ(r.warnings[1].keyword, "*DATABASE_HISTORY_SOLID");
  EXPECT_EQ(r.model.history_elements.size(), 2u);
}

}  // namespace
}  // namespace plyform::keyword
