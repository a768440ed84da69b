// The reader's side of issue 14's boundary features: card 2 of *BOUNDARY_PRESCRIBED_MOTION
// (DOF 9-11, with parameters as LS-PrePost writes it), *DEFINE_COORDINATE_SYSTEM / _VECTOR and
// *SET_NODE_GENERATE / *SET_PART_GENERATE; every bad value a located error.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, single_error, expect_error, ...

TEST(PrescribedRotationKeywords, Card2IsReadForDof9To11Only) {
  // As in foldingbox/Boundary_v5.K: _SET_ID, fixed format, offsets by parameter (one negated).
  const ReadResult r = read_ok(
      "*PARAMETER\n"
      "rcreasew2 1.0\n"
      "rcre2panw 21.0\n"
      "*BOUNDARY_PRESCRIBED_MOTION_SET_ID\n"
      "$#      id                                                               heading\n"
      "         1folding left plate\n"
      "$#    nsid       dof       vad      lcid        sf       vid     death     birth\n"
      "         1        10         2         1       1.0         0       2.1       0.0\n"
      "$# offset1   offset2       mrb     node1     node2\n"
      "&creasew2 -&creasew2         0         0         0\n"
      "         2Initial folding setp of right side\n"
      "         9         9         0         1      -1.0         0       2.1       0.5\n"
      "&creasew2 &cre2panw          0         0         0\n"
      "        11Box kompression\n"
      "        18         2         2         3      -1.0         0      10.0       0.0\n"
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n"
      "7,11,1,4\n"
      "\n"  // a blank card 2: the axis through the origin
      "8,3,0,4\n");
  const auto& m = r.model.prescribed_motions;
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[0].id, 1);
  EXPECT_EQ(m[0].heading, "folding left plate");
  EXPECT_EQ(m[0].dof, 10);
  EXPECT_EQ(m[0].vad, 2);
  EXPECT_DOUBLE_EQ(m[0].death, 2.1);
  EXPECT_DOUBLE_EQ(m[0].offset1, 1.0);
  EXPECT_DOUBLE_EQ(m[0].offset2, -1.0);
  EXPECT_EQ(m[0].where.line, 8);  // card 1
  EXPECT_EQ(m[1].dof, 9);
  EXPECT_EQ(m[1].vad, 0);
  EXPECT_DOUBLE_EQ(m[1].scale, -1.0);
  EXPECT_DOUBLE_EQ(m[1].birth, 0.5);
  EXPECT_DOUBLE_EQ(m[1].offset1, 1.0);
  EXPECT_DOUBLE_EQ(m[1].offset2, 21.0);
  // DOF 2 takes no card 2: the next line is the next motion's ID card.
  EXPECT_EQ(m[2].id, 11);
  EXPECT_EQ(m[2].dof, 2);
  EXPECT_DOUBLE_EQ(m[2].offset1, 0.0);
  EXPECT_EQ(m[3].target, model::NodeTarget::kNode);
  EXPECT_EQ(m[3].dof, 11);
  EXPECT_EQ(m[3].vad, 1);
  EXPECT_DOUBLE_EQ(m[3].offset1, 0.0);
  EXPECT_DOUBLE_EQ(m[3].offset2, 0.0);
  EXPECT_EQ(m[4].target_id, 8);
  EXPECT_EQ(m[4].dof, 3);
}

TEST(PrescribedRotationKeywords, BadValuesAreLocated) {
  constexpr std::string_view kNode = "*BOUNDARY_PRESCRIBED_MOTION_NODE";
  constexpr std::string_view kSet = "*BOUNDARY_PRESCRIBED_MOTION_SET_ID";
  // Card 2 missing at the end of the block: on card 1, naming what is missing and why.
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,9,2,1\n", 2, kNode, "OFFSET1",
               "missing card 2 (OFFSET1 OFFSET2 MRB NODE1 NODE2): DOF 9 turns");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_SET_ID\n1\n1,10,2,1\n", 3, kSet, "OFFSET1",
               "missing card 2");
  // A relative motion on card 2 is rejected by name, on card 2's line.
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,11,2,1\n0.0,0.0,5\n", 3, kNode, "MRB",
               "MRB = 5 (a motion relative to a body) is not supported yet");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,11,2,1\n0.0,0.0,0,0,3\n", 3, kNode, "NODE2",
               "not supported yet");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,9,2,1\nabc,1.0\n", 3, kNode, "OFFSET1",
               "expected a real number, got 'abc'");
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,9,2,1\n&nothing,1.0\n", 3, kNode, "OFFSET1",
               "nothing");
  // Turning with free radial motion, about a vector, and nodal rotations stay rejected.
  for (const char* dof : {"-9", "-11", "8", "12", "6"}) {
    SCOPED_TRACE(dof);
    expect_error(std::string("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,") + dof + ",2,1\n", 2, kNode,
                 "DOF", "must be one of 1, 2, 3, 9, 10, 11");
  }
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,10,2,1,1.0,0,1.0,2.0\n0,0\n", 2, kNode, "DEATH",
               "DEATH = 1 is not after BIRTH = 2");
  // A rigid body turning about an offset axis is not supported (its card 2 is never read).
  expect_error("*BOUNDARY_PRESCRIBED_MOTION_RIGID\n1,10,2,1\n", 2,
               "*BOUNDARY_PRESCRIBED_MOTION_RIGID", "DOF", "turning about an offset axis (9-11)");
}

TEST(CoordinateSystemKeywords, SystemsAndVectorsAreReadWithTheirAxes) {
  // The system of ryanlee/W7_3P_BendTest_explicit.k: x along -z, the x-y point along +y.
  const ReadResult r = read_ok(
      "*DEFINE_COORDINATE_SYSTEM\n"
      "$#     cid        xo        yo        zo        xl        yl        zl      cidl\n"
      "         3 -0.119915     0.062      0.44 -0.119915     0.062     -0.56         0\n"
      "$#      xp        yp        zp\n"
      " -0.119915     1.062      0.44\n"
      "*DEFINE_COORDINATE_SYSTEM_TITLE\n"
      "tilted\n"
      "4,1,1,1,2,2,1\n"
      "1,2,1\n"
      "*DEFINE_COORDINATE_VECTOR\n"
      "5,0,0,2,1,0,0\n"
      "6,1,1,0,-1,1,0,0\n");
  const auto& c = r.model.coordinate_systems;
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0].id, 3);
  EXPECT_EQ(c[0].where.line, 3);
  EXPECT_FALSE(c[0].from_vectors);
  const auto axes = model::coordinate_axes(c[0]);
  ASSERT_TRUE(axes);
  const std::array<std::array<double, 3>, 3> expected{
      {{0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}}};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      EXPECT_NEAR((*axes)[i][j], expected[i][j], 1e-15) << i << " " << j;
  EXPECT_EQ(c[1].id, 4);
  EXPECT_EQ(c[1].title, "tilted");
  // x along (1, 1, 0)/sqrt 2, the x-y point (1, 2, 1) - (1, 1, 1) = (0, 1, 0): z = +z.
  const auto tilted = model::coordinate_axes(c[1]);
  ASSERT_TRUE(tilted);
  const double h = std::sqrt(0.5);
  EXPECT_NEAR((*tilted)[0][0], h, 1e-15);
  EXPECT_NEAR((*tilted)[0][1], h, 1e-15);
  EXPECT_NEAR((*tilted)[1][0], -h, 1e-15);
  EXPECT_NEAR((*tilted)[1][1], h, 1e-15);
  EXPECT_NEAR((*tilted)[2][2], 1.0, 1e-15);
  EXPECT_TRUE(c[2].from_vectors);
  EXPECT_EQ(c[2].id, 5);
  // x along +z, the x-y vector +x: y = +x, z = x cross y = +y.
  const auto fromv = model::coordinate_axes(c[2]);
  ASSERT_TRUE(fromv);
  EXPECT_NEAR((*fromv)[0][2], 1.0, 1e-15);
  EXPECT_NEAR((*fromv)[1][0], 1.0, 1e-15);
  EXPECT_NEAR((*fromv)[2][1], 1.0, 1e-15);
  EXPECT_EQ(c[3].id, 6);
  EXPECT_EQ(c[3].where.line, 12);
}

TEST(CoordinateSystemKeywords, BadValuesAreLocated) {
  constexpr std::string_view kSystem = "*DEFINE_COORDINATE_SYSTEM";
  expect_error("*DEFINE_COORDINATE_SYSTEM\n1,0,0,0,1,0,0,2\n0,1,0\n", 2, kSystem, "CIDL",
               "CIDL = 2 (points given in another local system) is not supported yet");
  expect_error("*DEFINE_COORDINATE_SYSTEM\n1,0,0,0,1,0,0\n", 2, kSystem, "XP",
               "missing card 2 (XP YP ZP)");
  expect_error("*DEFINE_COORDINATE_SYSTEM\n", 1, kSystem, "", "missing card 1");
  // The x-y point on the x axis, and an x axis of no length.
  expect_error("*DEFINE_COORDINATE_SYSTEM\n7,0,0,0,1,0,0\n3,0,0\n", 2, kSystem, "",
               "coordinate system 7: the origin, the x point and the x-y point do not span a "
               "plane");
  expect_error("*DEFINE_COORDINATE_SYSTEM\n7,1,1,1,1,1,1\n3,0,0\n", 2, kSystem, "",
               "do not span a plane");
  expect_error("*DEFINE_COORDINATE_SYSTEM\n0,0,0,0,1,0,0\n0,1,0\n", 2, kSystem, "CID",
               "out of range");
  constexpr std::string_view kVector = "*DEFINE_COORDINATE_VECTOR";
  expect_error("*DEFINE_COORDINATE_VECTOR\n2,1,0,0,0,1,0,9\n", 2, kVector, "NID",
               "NID = 9 (a system turning with a node) is not supported yet");
  expect_error("*DEFINE_COORDINATE_VECTOR\n2,1,0,0,2,0,0\n", 2, kVector, "",
               "the two vectors do not span a plane");
}

TEST(GeneratedSetKeywords, RangesBecomeTheDefinedIds) {
  // Nodes 1-5 and 10-12; the set comes first and names gaps (6-9) and ids past the end.
  const ReadResult r = read_ok(
      "*SET_NODE_GENERATE\n"
      "$#     sid       da1       da2       da3       da4    solver\n"
      "       100\n"
      "$#   b1beg     b1end     b2beg     b2end     b3beg     b3end     b4beg     b4end\n"
      "         2         4         0         0        11        99\n"
      "         1         1\n"
      "*SET_NODE_LIST_GENERATE_TITLE\n"
      "all\n"
      "101\n"
      "1,5,3,11\n"
      "*SET_PART_LIST_GENERATE\n"
      "   6600000       0.0       0.0       0.0       0.0MECH\n"
      "         1   6599999   6600001  99999999         0         0         0         0\n"
      "*SET_PART_GENERATE_TITLE\n"
      "second\n"
      "7\n"
      "2,2\n"
      "*NODE\n"
      "1,0,0,0\n2,1,0,0\n3,2,0,0\n4,3,0,0\n5,4,0,0\n10,0,1,0\n11,1,1,0\n12,2,1,0\n"
      "*PART\np1\n1,1,1\n*PART\np2\n2,1,1\n*PART\np4\n4,1,1\n");
  const auto& n = r.model.node_sets;
  ASSERT_EQ(n.size(), 2u);
  EXPECT_EQ(n[0].id, 100);
  EXPECT_EQ(n[0].ids, (std::vector<int>{2, 3, 4, 11, 12, 1}));
  ASSERT_EQ(n[0].ranges.size(), 3u);
  EXPECT_EQ(n[0].ranges[2].first, 1);
  EXPECT_EQ(n[0].ids_where[5].line, 6);  // node 1 from the second range card
  EXPECT_EQ(n[0].keyword, "*SET_NODE_GENERATE");
  EXPECT_EQ(n[1].title, "all");
  EXPECT_EQ(n[1].ids, (std::vector<int>{1, 2, 3, 4, 5, 10, 11}));  // overlapping ranges: once
  const auto& p = r.model.part_sets;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].id, 6600000);
  EXPECT_EQ(p[0].ids, (std::vector<int>{1, 2, 4}));  // the second range holds no part
  EXPECT_EQ(p[1].title, "second");
  EXPECT_EQ(p[1].ids, (std::vector<int>{2}));
}

TEST(GeneratedSetKeywords, BadRangesAreLocated) {
  constexpr std::string_view kNode = "*SET_NODE_GENERATE";
  expect_error("*NODE\n1,0,0,0\n*SET_NODE_GENERATE\n1\n1,5,9,3\n", 5, kNode, "B2END",
               "range 2 is reversed: B2END = 3 is below B2BEG = 9");
  expect_error("*NODE\n1,0,0,0\n*SET_NODE_GENERATE\n1\n1,5\n7,0\n", 6, kNode, "B5END",
               "range 5 has only one end (7 to 0)");
  expect_error("*NODE\n1,0,0,0\n*SET_NODE_GENERATE\n1\n0,5\n", 5, kNode, "B1BEG",
               "range 1 has only one end");
  expect_error("*SET_NODE_GENERATE\n1\n", 2, kNode, "B1BEG", "no range given");
  expect_error("*SET_NODE_GENERATE\n1\n,,,\n", 2, kNode, "B1BEG", "no range given");
  expect_error("*SET_NODE_GENERATE\n1\n-1,5\n", 3, kNode, "B1BEG", "out of range");
  // A set whose ranges hold nothing the deck defines, found once the deck is read.
  expect_error("*SET_PART_LIST_GENERATE\n8\n10,20\n*PART\np\n1,1,1\n", 2, "*SET_PART_LIST_GENERATE",
               "B1BEG", "set 8: its ranges hold no part defined in the deck");
  expect_error("*SET_NODE_GENERATE_TITLE\nt\n9\n10,20\n*NODE\n1,0,0,0\n", 3,
               "*SET_NODE_GENERATE_TITLE", "B1BEG", "set 9: its ranges hold no node");
}

}  // namespace
}  // namespace plyform::keyword
