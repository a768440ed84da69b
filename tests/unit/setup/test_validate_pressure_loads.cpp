// The pressure loads as read and validated: *LOAD_SEGMENT(_ID), *LOAD_SEGMENT_SET,
// *LOAD_SHELL_ELEMENT, *LOAD_SHELL_SET and the *SET_SHELL forms they name; every bad reference
// a located error naming the field.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"

namespace plyform::setup {
namespace {

using keyword::Diagnostic;

std::string all(const std::vector<Diagnostic>& errors) {
  std::string s;
  for (const Diagnostic& d : errors)
    s += d.to_string() + "\n";
  return s;
}

// Lines 1-22: a 2 x 1 plate of shells 1 and 2, curve 7.
const std::string kPlate =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,2,0,0\n4,0,1,0\n5,1,1,0\n6,2,1,0\n"
    "*PART\nsheet\n1,1,1\n*SECTION_SHELL\n1\n0.1\n*MAT_ELASTIC\n1,1e-9,100.0,0.3\n"
    "*ELEMENT_SHELL\n1,1,1,2,5,4\n2,1,2,3,6,5\n*DEFINE_CURVE\n7\n0,1\n1,1\n";

TEST(PressureLoadKeywords, EachFormIsReadAndBuiltIntoSegments) {
  const std::string deck = kPlate +
                           "*LOAD_SEGMENT_ID\n"
                           "3,under the first\n"
                           "7,2.0,0.5,1,2,5,4\n"
                           "4,a triangle (N4 blank)\n"
                           "7,1.0,0.0,2,3,6\n"
                           "*SET_SEGMENT\n4\n1,2,5,4\n2,3,6,5\n"
                           "*LOAD_SEGMENT_SET\n4,7,-1.5\n"
                           "*SET_SHELL_LIST_TITLE\nboth\n5\n1,2\n"
                           "*LOAD_SHELL_SET\n5,7\n"
                           "*LOAD_SHELL_ELEMENT\n2,7,3.0\n"
                           "*CONTROL_TERMINATION\n1.0\n";
  const keyword::ReadResult read = keyword::read_deck_text(deck, "deck.k");
  ASSERT_TRUE(read.ok()) << all(read.errors);
  const auto& loads = read.model.pressure_loads;
  ASSERT_EQ(loads.size(), 5u);
  EXPECT_EQ(loads[0].id, 3);
  EXPECT_EQ(loads[0].heading, "under the first");
  EXPECT_DOUBLE_EQ(loads[0].scale, 2.0);
  EXPECT_DOUBLE_EQ(loads[0].arrival, 0.5);
  EXPECT_EQ(loads[1].id, 4);
  EXPECT_EQ(loads[1].nodes, (std::array<int, 4>{2, 3, 6, 6}));
  EXPECT_EQ(loads[2].target, model::PressureTarget::kSegmentSet);
  EXPECT_DOUBLE_EQ(loads[2].scale, -1.5);
  EXPECT_EQ(loads[3].target, model::PressureTarget::kShellSet);
  EXPECT_DOUBLE_EQ(loads[3].scale, 1.0);  // SF blank: 1
  EXPECT_EQ(loads[4].target, model::PressureTarget::kShell);
  ASSERT_EQ(read.model.shell_sets.size(), 1u);
  EXPECT_EQ(read.model.shell_sets[0].title, "both");
  const std::vector<Diagnostic> errors = validate(read.model);
  ASSERT_TRUE(errors.empty()) << all(errors);
  const BuildResult built = build(read.model);
  ASSERT_TRUE(built.errors.empty()) << all(built.errors);
  const core::Model& m = *built.model;
  ASSERT_EQ(m.pressure_loads.size(), 5u);
  // 1 + 1 + 2 + 2 + 1 segments, in load order; the triangle repeats N3.
  ASSERT_EQ(m.pressure_segments.size(), 7u);
  EXPECT_EQ(m.pressure_loads[1].first, 1u);
  EXPECT_EQ(m.pressure_segments[1][2], m.pressure_segments[1][3]);
  EXPECT_EQ(m.pressure_loads[3].first, 4u);
  EXPECT_EQ(m.pressure_loads[3].count, 2u);
  EXPECT_EQ(m.node_id[static_cast<std::size_t>(m.pressure_segments[6][0])], 2);  // shell 2's N1
}

TEST(PressureLoadKeywords, GeneratedShellSetsHoldTheShellsInTheirRanges) {
  const keyword::ReadResult read = keyword::read_deck_text(
      kPlate + "*SET_SHELL_GENERATE\n5\n1,10\n*LOAD_SHELL_SET\n5,7\n", "deck.k");
  ASSERT_TRUE(read.ok()) << all(read.errors);
  ASSERT_EQ(read.model.shell_sets.size(), 1u);
  EXPECT_EQ(read.model.shell_sets[0].ids, (std::vector<int>{1, 2}));
}

struct BadCase {
  std::string cards;
  int line;
  std::string keyword, field, part;
};

TEST(PressureLoadKeywords, EveryBadReferenceIsALocatedError) {
  // kPlate has 22 lines: each keyword below is on line 23, its first card on line 24.
  const std::vector<BadCase> cases = {
      {"*LOAD_SEGMENT\n8,1.0,0.0,1,2,5,4\n", 24, "*LOAD_SEGMENT", "LCID", "curve 8"},
      {"*LOAD_SEGMENT\n7,1.0,0.0,1,2,5,9\n", 24, "*LOAD_SEGMENT", "N4", "node 9"},
      {"*LOAD_SEGMENT\n7,1.0,0.0,1,2,1,4\n", 24, "*LOAD_SEGMENT", "N1", "distinct"},
      {"*LOAD_SEGMENT_SET\n4,7\n", 24, "*LOAD_SEGMENT_SET", "SSID", "segment set 4"},
      {"*LOAD_SHELL_ELEMENT\n3,7\n", 24, "*LOAD_SHELL_ELEMENT", "EID", "shell element 3"},
      {"*LOAD_SHELL_SET\n5,7\n", 24, "*LOAD_SHELL_SET", "ESID", "shell set 5"},
      {"*SET_SHELL\n5\n1,3\n*LOAD_SHELL_SET\n5,7\n", 25, "*SET_SHELL", "EID2", "shell element 3"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.cards);
    const keyword::ReadResult read = keyword::read_deck_text(kPlate + c.cards, "deck.k");
    ASSERT_TRUE(read.ok()) << all(read.errors);
    const std::vector<Diagnostic> errors = validate(read.model);
    ASSERT_EQ(errors.size(), 1u) << all(errors);
    EXPECT_EQ(errors[0].where.line, c.line);
    EXPECT_EQ(errors[0].keyword, c.keyword);
    EXPECT_EQ(errors[0].field, c.field);
    EXPECT_NE(errors[0].message.find(c.part), std::string::npos) << errors[0].to_string();
  }
}

TEST(PressureLoadKeywords, AQuadraticSegmentIsRejectedByName) {
  const keyword::ReadResult read =
      keyword::read_deck_text(kPlate + "*LOAD_SEGMENT\n7,1.0,0.0,1,2,5,4,3\n", "deck.k");
  ASSERT_EQ(read.errors.size(), 1u);
  EXPECT_EQ(read.errors[0].where.line, 24);
  EXPECT_EQ(read.errors[0].field, "N5");
  EXPECT_NE(read.errors[0].message.find("quadratic"), std::string::npos);
}

}  // namespace
}  // namespace plyform::setup
