// Errors of the solver-core keywords: each names file, line, keyword and field.
#include <string>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, single_error, expect_error, ...

TEST(SolverKeywordErrors, BadNumberInNode) {
  const Diagnostic d = single_error("*KEYWORD\n*NODE\n       1             abc\n");
  EXPECT_EQ(d.to_string(), "deck.k:3: *NODE: field X: expected a real number, got 'abc'");
}

TEST(SolverKeywordErrors, MissingCards) {
  Diagnostic d = single_error("*PART\nheading only\n");
  EXPECT_EQ(d.where.line, 2);
  EXPECT_EQ(d.keyword, "*PART");
  EXPECT_TRUE(contains(d.message, "missing card 1")) << d.message;
  d = single_error("*MAT_ELASTIC_TITLE\nsteel\n");
  EXPECT_EQ(d.where.line, 1);
  EXPECT_TRUE(contains(d.message, "missing card 1 (MID RO E PR DA DB K)")) << d.message;
  d = single_error("*ELEMENT_SOLID\n       1       1\n");
  EXPECT_EQ(d.where.line, 2);
  EXPECT_TRUE(contains(d.message, "missing node card")) << d.message;
  d = single_error("*BOUNDARY_SPC_SET_ID\n        10fixed\n");
  EXPECT_EQ(d.where.line, 2);
  EXPECT_TRUE(contains(d.message, "missing card 1 after the ID card")) << d.message;
  d = single_error("*CONTROL_TERMINATION\n");
  EXPECT_EQ(d.keyword, "*CONTROL_TERMINATION");
  EXPECT_TRUE(contains(d.message, "missing card 1")) << d.message;
}

TEST(SolverKeywordErrors, OutOfRangeAndUnsupportedValues) {
  Diagnostic d = single_error("*MAT_ELASTIC\n1,1e-9,100.0,0.5\n");
  EXPECT_EQ(d.to_string(),
            "deck.k:2: *MAT_ELASTIC: field PR: value 0.5 is out of range: must be in [-1, 0.5)");
  d = single_error("*SECTION_SOLID_TITLE\ntet\n         1        10\n");
  EXPECT_EQ(d.where.line, 3);
  EXPECT_EQ(d.field, "ELFORM");
  EXPECT_EQ(d.message,
            "value 10 is not supported: must be one of 0, 1, 2; plyform has ELFORM 1 and 2 "
            "solids only for now");
  d = single_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,5,0,1\n");
  EXPECT_EQ(d.field, "DOF");
  EXPECT_TRUE(contains(d.message, "value 5 is not supported: must be one of 1, 2, 3, 9, 10, 11"))
      << d.message;
  d = single_error("*BOUNDARY_PRESCRIBED_MOTION_SET\n1,-1,0,1\n");
  EXPECT_EQ(d.field, "DOF");
  d = single_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,1,3,1\n");
  EXPECT_EQ(d.field, "VAD");
  d = single_error("*BOUNDARY_SPC_NODE\n1,0,2\n");
  EXPECT_EQ(d.field, "DOFX");
  EXPECT_EQ(d.message, "value 2 is out of range: must be in [0, 1]");
  d = single_error("*NODE\n       1     0.0     0.0     0.0       8\n");
  d = single_error("*NODE\n1,0,0,0,8\n");
  EXPECT_EQ(d.field, "TC");
  d = single_error("*MAT_MOONEY-RIVLIN_RUBBER\n1,1e-9,0.5,0.4,0.1\n");
  EXPECT_EQ(d.field, "PR");
}

TEST(SolverKeywordErrors, NotSupportedYetNamesTheField) {
  Diagnostic d = single_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,1,0,1,1.0,3\n");
  EXPECT_EQ(d.to_string(),
            "deck.k:2: *BOUNDARY_PRESCRIBED_MOTION_NODE: field VID: VID = 3 (a motion along a "
            "vector) is not supported yet; leave it blank or 0");
  d = single_error("*LOAD_NODE_POINT\n1,1,1,1.0,2\n");
  EXPECT_EQ(d.field, "CID");
  d = single_error("*INITIAL_VELOCITY_GENERATION\n1,2,0,1,0,0,0,4\n");
  EXPECT_EQ(d.field, "ICID");
  d = single_error("*MAT_MOONEY-RIVLIN_RUBBER\n1,1e-9,0.49,0.4,0.1\n0,0,0,7\n");
  EXPECT_EQ(d.where.line, 3);
  EXPECT_EQ(d.field, "LCID1");
  EXPECT_TRUE(contains(d.message, "not supported yet")) << d.message;
  d = single_error("*MAT_MOONEY-RIVLIN_RUBBER\n1,1e-9,0.49,0.4,0.1,1.0\n");
  EXPECT_EQ(d.field, "REF");
  d = single_error("*MAT_027\n1,1e-9,0.49\n10.0,1.0,1.0,7\n");
  EXPECT_EQ(d.field, "LCID1");
  d = single_error("*MAT_027\n1,1e-9,0.49\n");
  EXPECT_EQ(d.field, "A");
  EXPECT_TRUE(contains(d.message, "fit")) << d.message;
  d = single_error("*DATABASE_GLSTAT\n1e-4,0,5\n");
  EXPECT_EQ(d.field, "LCUR");
  d = single_error("*SET_NODE_LIST\n1,,,,,THERMAL\n1\n");
  EXPECT_EQ(d.field, "SOLVER");
}

TEST(SolverKeywordErrors, UnsupportedOptionsAndKeywords) {
  Diagnostic d = single_error("*SET_NODE_ADD\n1\n1,10\n");
  EXPECT_TRUE(contains(d.message, "unsupported option _ADD of *SET_NODE")) << d.message;
  d = single_error("*BOUNDARY_SPC_SET_BIRTH_DEATH\n1\n");
  EXPECT_TRUE(contains(d.message, "unsupported option _BIRTH_DEATH")) << d.message;
  d = single_error("*MAT_ELASTIC_FLUID\n1\n");
  EXPECT_TRUE(contains(d.message, "unsupported option _FLUID")) << d.message;
  d = single_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID_LOCAL\n1,1,0,1\n");
  EXPECT_TRUE(contains(d.message, "unsupported option _LOCAL of *BOUNDARY_PRESCRIBED_MOTION_RIGID"))
      << d.message;
  d = single_error("*ELEMENT_SHELL_OFFSET\n1,1,1,2,3,4\n0.5\n");
  EXPECT_TRUE(contains(d.message, "unsupported option _OFFSET of *ELEMENT_SHELL")) << d.message;
  d = single_error("*MAT_RIGID_DISCRETE\n1,1e-9,1e5,0.3\n");
  EXPECT_TRUE(contains(d.message, "unsupported option _DISCRETE of *MAT_RIGID")) << d.message;
  d = single_error("*PART_INERTIA\np\n1,1,1\n");
  EXPECT_TRUE(contains(d.message, "unsupported option _INERTIA of *PART")) << d.message;
}

TEST(SolverKeywordErrors, ElementWithTooFewNodes) {
  const Diagnostic d =
      single_error("*ELEMENT_SOLID\n       1       1       1       2       3       4\n");
  EXPECT_EQ(d.where.line, 2);
  EXPECT_EQ(d.field, "N5");
  EXPECT_TRUE(contains(d.message, "8 node ids")) << d.message;
}

TEST(SolverKeywordErrors, RequiredIdBlank) {
  const Diagnostic d = single_error("*NODE\n                 1.0\n");
  EXPECT_EQ(d.field, "NID");
  EXPECT_EQ(d.message, "a value is required");
}

}  // namespace
}  // namespace plyform::keyword
