// *RIGIDWALL_PLANAR and its options as read, validated and built: the cards of each option in
// LS-DYNA's order, the wall's frame, its slave nodes (and the nodes left out, with the warnings
// that count them); every bad value or reference a located error naming the field.
#include <cmath>
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

// Lines 1-25: one hexahedron of nodes 1-8 on z = 0..1, node 9 of no element, node set 1 = the
// bottom face, node set 2 = node 1.
const std::string kCube =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n9,0,0,5\n"
    "*PART\ncube\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1e-9,100.0,0.3\n"
    "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n*SET_NODE_LIST\n1\n1,2,3,4\n*SET_NODE_LIST\n2\n1\n";

TEST(RigidWallKeywords, EveryOptionIsReadAndBuiltIntoAWall) {
  const std::string deck = kCube +
                           "*RIGIDWALL_PLANAR_FINITE_MOVING_FORCES_ID\n"
                           "4,press\n"
                           "1,2,0,0.0,0.5,3.0,1.0\n"
                           "0,0,-0.5,0,0,2.5,0.2\n"
                           "1,0,-0.5,2,3\n"
                           "1e-3,-2.0\n"
                           "0,0,9\n"
                           "*RIGIDWALL_PLANAR\n0\n0,0,0,0,0,1\n"
                           "*DATABASE_RWFORC\n0.1\n*CONTROL_TERMINATION\n1.0\n";
  const keyword::ReadResult read = keyword::read_deck_text(deck, "deck.k");
  ASSERT_TRUE(read.ok()) << all(read.errors);
  const auto& walls = read.model.rigid_walls;
  ASSERT_EQ(walls.size(), 2u);
  EXPECT_EQ(walls[0].id, 4);
  EXPECT_EQ(walls[0].heading, "press");
  EXPECT_TRUE(walls[0].finite && walls[0].moving && walls[0].forces);
  EXPECT_EQ(walls[0].nsid, 1);
  EXPECT_EQ(walls[0].nsidex, 2);
  EXPECT_DOUBLE_EQ(walls[0].birth, 0.5);
  EXPECT_DOUBLE_EQ(walls[0].death, 3.0);
  EXPECT_DOUBLE_EQ(walls[0].fric, 0.2);
  EXPECT_DOUBLE_EQ(walls[0].length_l, 2.0);
  EXPECT_DOUBLE_EQ(walls[0].mass, 1e-3);
  EXPECT_DOUBLE_EQ(walls[0].v0, -2.0);
  EXPECT_EQ(walls[0].display[0], 9);
  EXPECT_FALSE(walls[1].finite || walls[1].moving || walls[1].forces);
  EXPECT_DOUBLE_EQ(walls[1].death, 1e20);  // blank: never
  ASSERT_TRUE(validate(read.model).empty()) << all(validate(read.model));
  const BuildResult built = build(read.model);
  ASSERT_TRUE(built.errors.empty()) << all(built.errors);
  const core::Model& m = *built.model;
  EXPECT_DOUBLE_EQ(m.output.rwforc_dt, 0.1);
  ASSERT_EQ(m.rigid_walls.size(), 2u);
  const core::RigidWall& w = m.rigid_walls[0];
  EXPECT_EQ(w.id, 4);
  EXPECT_DOUBLE_EQ(w.normal[2], 1.0);
  EXPECT_DOUBLE_EQ(w.edge_l[0], 1.0);
  EXPECT_NEAR(w.edge_m[1], 1.0, 1e-15);  // m = n x l
  // NSID 1 (the bottom face) less NSIDEX 2 (node 1).
  ASSERT_EQ(w.nodes.size(), 3u);
  EXPECT_EQ(m.node_id[static_cast<std::size_t>(w.nodes[0])], 2);
  ASSERT_EQ(w.display_nodes.size(), 1u);
  EXPECT_EQ(m.node_id[static_cast<std::size_t>(w.display_nodes[0])], 9);
  // The second wall: every node of an element (not node 9), id its place among the walls.
  EXPECT_EQ(m.rigid_walls[1].id, 2);
  EXPECT_EQ(m.rigid_walls[1].nodes.size(), 8u);
  EXPECT_EQ(m.rigid_walls[1].mass, 0.0);
}

TEST(RigidWallKeywords, NodesBehindTheWallOrHeldAreLeftOutWithAWarning) {
  // The wall z = 0.5 with its normal up: the bottom face lies behind it; node 5 is held by an
  // SPC.
  const std::string deck = kCube +
                           "*BOUNDARY_SPC_NODE\n5,0,1,1,1\n"
                           "*RIGIDWALL_PLANAR\n0\n0,0,0.5,0,0,1\n*CONTROL_TERMINATION\n1.0\n";
  const keyword::ReadResult read = keyword::read_deck_text(deck, "deck.k");
  ASSERT_TRUE(read.ok()) << all(read.errors);
  ASSERT_TRUE(validate(read.model).empty());
  const BuildResult built = build(read.model);
  ASSERT_TRUE(built.errors.empty()) << all(built.errors);
  EXPECT_EQ(built.model->rigid_walls[0].nodes.size(), 3u);  // 6, 7, 8
  const std::string warnings = all(built.warnings);
  EXPECT_NE(warnings.find("4 slave nodes lie behind the wall"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("1 slave nodes are held"), std::string::npos) << warnings;
}

struct BadCase {
  std::string cards;
  int line;
  std::string field, part;
};

TEST(RigidWallKeywords, EveryBadValueIsALocatedError) {
  // kCube has 25 lines: each keyword below is on line 26, its cards from line 27.
  const std::vector<BadCase> read_errors = {
      {"*RIGIDWALL_PLANAR_MOVING\n0\n0,0,0,0,0,1\n0.0,1.0\n", 29, "MASS", "positive mass"},
      {"*RIGIDWALL_PLANAR\n0\n0,0,0,0,0,1,2.0\n", 28, "FRIC", "out of range"},
      {"*RIGIDWALL_PLANAR_FINITE\n0\n0,0,0,0,0,1\n1,0,0,0,1\n", 29, "LENL", "LENL > 0"},
      {"*RIGIDWALL_PLANAR\n0,0,3\n0,0,0,0,0,1\n", 27, "BOXID", "not supported"},
      {"*RIGIDWALL_PLANAR\n0,0,0,0,2.0,1.0\n0,0,0,0,0,1\n", 27, "DEATH", "not after BIRTH"},
      {"*RIGIDWALL_PLANAR_FORCES\n0\n0,0,0,0,0,1\n2\n", 29, "SOFT", "not supported"},
      {"*RIGIDWALL_PLANAR\n0\n0,0,0,0,0,1\n5,5\n", 29, "", "_ORTHO is not supported"},
  };
  for (const BadCase& c : read_errors) {
    SCOPED_TRACE(c.cards);
    const keyword::ReadResult read = keyword::read_deck_text(kCube + c.cards, "deck.k");
    ASSERT_EQ(read.errors.size(), 1u) << all(read.errors);
    EXPECT_EQ(read.errors[0].where.line, c.line);
    EXPECT_EQ(read.errors[0].field, c.field);
    EXPECT_NE(read.errors[0].message.find(c.part), std::string::npos) << all(read.errors);
  }
  const std::vector<BadCase> cross_errors = {
      {"*RIGIDWALL_PLANAR\n3\n0,0,0,0,0,1\n", 27, "NSID", "node set 3"},
      {"*RIGIDWALL_PLANAR\n0,4\n0,0,0,0,0,1\n", 27, "NSIDEX", "node set 4"},
      {"*RIGIDWALL_PLANAR\n0\n1,1,1,1,1,1\n", 28, "XH", "is its tail"},
      {"*RIGIDWALL_PLANAR_FINITE\n0\n0,0,0,0,0,1\n0,0,3,1,1\n", 26, "XHEV", "along the normal"},
      {"*RIGIDWALL_PLANAR_FORCES\n0\n0,0,0,0,0,1\n0,0,5\n", 29, "N1", "belongs to an element"},
      {"*RIGIDWALL_PLANAR_FORCES\n0\n0,0,0,0,0,1\n0,0,0,77\n", 29, "N2", "node 77"},
  };
  for (const BadCase& c : cross_errors) {
    SCOPED_TRACE(c.cards);
    const keyword::ReadResult read = keyword::read_deck_text(kCube + c.cards, "deck.k");
    ASSERT_TRUE(read.ok()) << all(read.errors);
    const std::vector<Diagnostic> errors = validate(read.model);
    ASSERT_EQ(errors.size(), 1u) << all(errors);
    EXPECT_EQ(errors[0].where.line, c.line);
    EXPECT_EQ(errors[0].keyword.rfind("*RIGIDWALL_PLANAR", 0), 0u);
    EXPECT_EQ(errors[0].field, c.field);
    EXPECT_NE(errors[0].message.find(c.part), std::string::npos) << errors[0].to_string();
  }
  // LS-DYNA's _ORTHO (orthotropic friction) is an option plyform names as unsupported.
  const keyword::ReadResult ortho =
      keyword::read_deck_text(kCube + "*RIGIDWALL_PLANAR_ORTHO\n0\n0,0,0,0,0,1\n", "deck.k");
  ASSERT_EQ(ortho.errors.size(), 1u);
  EXPECT_NE(ortho.errors[0].message.find("unsupported option _ORTHO"), std::string::npos);
}

}  // namespace
}  // namespace plyform::setup
