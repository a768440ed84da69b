// setup::validate_mesh: duplicate ids, undefined references, repeated element nodes, element
// and section kinds; every error located.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "plyform/setup/validate_mesh.hpp"

namespace plyform::setup {
namespace {

using keyword::Diagnostic;

std::string all(const std::vector<Diagnostic>& errors) {
  std::string out;
  for (const Diagnostic& d : errors) {
    out += d.to_string() + "\n";
  }
  return out;
}

/// Reads a deck that must read without error and validates it.
std::vector<Diagnostic> validate_text(std::string_view text) {
  const keyword::ReadResult read = keyword::read_deck_text(text, "deck.k");
  EXPECT_TRUE(read.ok()) << all(read.errors);
  return validate_mesh(read.model);
}

constexpr std::string_view kGoodDeck =
    "*NODE\n"
    "1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"  // lines 2-9
    "*ELEMENT_SOLID\n"
    "1,1,1,2,3,4,5,6,7,8\n"  // 11: hexahedron
    "2,1,1,2,3,4,5,5,6,6\n"  // 12: pentahedron
    "3,1,1,2,3,4,4,4,4,4\n"  // 13: tetrahedron
    "4,1,1,2,3,3,5,5,5,5\n"  // 14: tetrahedron, collapsed hex
    "5,1,1,2,3,4,5,5,5,5\n"  // 15: pyramid
    "6,1,1,2,3,3,5,6,7,7\n"  // 16: pentahedron, collapsed face
    "*PART\nblock\n1,1,1,0,1\n"
    "*SECTION_SOLID\n1,1\n"
    "*MAT_ELASTIC\n1,1e-9,100.0,0.3\n"
    "*HOURGLASS\n1,4\n"
    "*SET_NODE_LIST\n1\n1,2,3,4\n"
    "*SET_PART_LIST\n2\n1\n"
    "*DEFINE_CURVE\n1\n0,0\n1,1\n"
    "*BOUNDARY_SPC_SET\n1,0,1,1,1\n"
    "*BOUNDARY_PRESCRIBED_MOTION_NODE\n5,3,2,1\n"
    "*LOAD_NODE_POINT\n6,3,1\n"
    "*INITIAL_VELOCITY_GENERATION\n2,1,0,1.0\n"
    "*DATABASE_BINARY_D3PLOT\n1e-3,0,0,0,2\n"
    "*DATABASE_HISTORY_NODE\n5,6\n";

TEST(ValidateMesh, GoodDeckWithDegenerateSolidsHasNoErrors) {
  const std::vector<Diagnostic> errors = validate_text(kGoodDeck);
  EXPECT_TRUE(errors.empty()) << all(errors);
}

TEST(ValidateMesh, DuplicateIdsNameBothPlaces) {
  const std::vector<Diagnostic> errors = validate_text(
      "*NODE\n1,0,0,0\n1,1,0,0\n"
      "*PART\na\n3,1,1\n*PART\nb\n3,1,1\n"
      "*SECTION_SOLID\n1\n1\n"
      "*MAT_ELASTIC\n1,1,1\n*MAT_MOONEY-RIVLIN_RUBBER\n1,1,0.49,1\n"
      "*SET_NODE_LIST\n4\n1\n*SET_NODE_LIST\n4\n1\n");
  ASSERT_EQ(errors.size(), 5u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:3: *NODE: field NID: node 1 is already defined at deck.k:2");
  EXPECT_EQ(errors[1].keyword, "*PART");
  EXPECT_EQ(errors[1].where.line, 9);
  EXPECT_EQ(errors[2].keyword, "*SECTION_SOLID");
  EXPECT_EQ(errors[2].where.line, 12);
  EXPECT_EQ(errors[3].keyword, "*MAT_MOONEY-RIVLIN_RUBBER");
  EXPECT_EQ(errors[3].field, "MID");
  EXPECT_EQ(errors[4].keyword, "*SET_NODE_LIST");
  EXPECT_EQ(errors[4].field, "SID");
}

TEST(ValidateMesh, UndefinedReferencesAreAllReported) {
  const std::vector<Diagnostic> errors = validate_text(
      "*NODE\n1,0,0,0\n"                             // 2
      "*ELEMENT_SOLID\n1,9,1,2,3,4,5,6,7,8\n"        // 4: part 9, nodes 2..8
      "*PART\np\n1,2,3,0,4\n"                        // 7: section 2, material 3, hourglass 4
      "*SET_NODE_LIST\n1\n1,77\n"                    // 10: node 77
      "*SET_PART_LIST\n2\n5\n"                       // 13: part 5
      "*BOUNDARY_SPC_SET\n3\n"                       // 15: node set 3
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n1,1,0,6\n"  // 17: curve 6
      "*LOAD_NODE_SET\n8,1,1\n"                      // 19: node set 8, curve 1
      "*INITIAL_VELOCITY_GENERATION\n4,3\n"          // 21: node set 4
      "*DATABASE_HISTORY_NODE\n1,99\n");             // 23: node 99
  const std::string text = all(errors);
  for (const char* expected :
       {"deck.k:7: *PART: field SECID: section 2 is not defined (no *SECTION_ keyword with this "
        "id)",
        "deck.k:7: *PART: field MID: material 3 is not defined",
        "deck.k:7: *PART: field HGID: hourglass 4 is not defined",
        "deck.k:4: *ELEMENT_SOLID: field PID: part 9 is not defined (no *PART with this id)",
        "deck.k:4: *ELEMENT_SOLID: field N2: element 1: node 2 is not defined",
        "deck.k:4: *ELEMENT_SOLID: field N8: element 1: node 8 is not defined",
        "deck.k:10: *SET_NODE_LIST: field NID2: node set 1: node 77 is not defined",
        "deck.k:13: *SET_PART_LIST: field PID1: part set 2: part 5 is not defined",
        "deck.k:15: *BOUNDARY_SPC_SET: field NSID: node set 3 is not defined",
        "deck.k:17: *BOUNDARY_PRESCRIBED_MOTION_NODE: field LCID: curve 6 is not defined",
        "deck.k:19: *LOAD_NODE_SET: field NSID: node set 8 is not defined",
        "deck.k:19: *LOAD_NODE_SET: field LCID: curve 1 is not defined",
        "deck.k:21: *INITIAL_VELOCITY_GENERATION: field ID: node set 4 is not defined",
        "deck.k:23: *DATABASE_HISTORY_NODE: field NID2: node 99 is not defined"}) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\nin:\n" << text;
  }
  EXPECT_EQ(errors.size(), 19u) << text;  // 7 undefined element nodes among them
}

TEST(ValidateMesh, CoordinateSystemsOfSpcs) {
  const std::vector<Diagnostic> errors = validate_text(
      "*NODE\n1,0,0,0\n"                                   // 2
      "*DEFINE_COORDINATE_SYSTEM\n5,0,0,0,1,0,0\n0,1,0\n"  // 4
      "*DEFINE_COORDINATE_VECTOR\n5,1,0,0,0,1,0\n"         // 7: 5 again
      "*DEFINE_COORDINATE_VECTOR\n6,1,0,0,0,1,0\n"         // 9: named by nothing, kept
      "*BOUNDARY_SPC_NODE\n1,5,1\n1,8,0,1\n");             // 11, 12: system 8 undefined
  const std::string text = all(errors);
  ASSERT_EQ(errors.size(), 2u) << text;
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:7: *DEFINE_COORDINATE_VECTOR: field CID: coordinate system 5 is already "
            "defined at deck.k:4");
  EXPECT_EQ(errors[1].to_string(),
            "deck.k:12: *BOUNDARY_SPC_NODE: field CID: coordinate system 8 is not defined (no "
            "*DEFINE_COORDINATE_SYSTEM or _VECTOR with this id)");
}

TEST(ValidateMesh, RepeatedNodeOutsideTheDegeneratePatterns) {
  std::string deck(kGoodDeck);
  deck += "*ELEMENT_SOLID\n7,1,1,2,3,4,5,6,2,8\n8,1,1,1,3,4,5,6,7,8\n9,1,1,2,3,4,5,5,6,7\n";
  const std::vector<Diagnostic> errors = validate_text(deck);
  ASSERT_EQ(errors.size(), 3u) << all(errors);
  EXPECT_EQ(errors[0].keyword, "*ELEMENT_SOLID");
  EXPECT_EQ(errors[0].field, "N7");
  EXPECT_NE(errors[0].message.find("element 7: N7 repeats node 2 of N2"), std::string::npos)
      << errors[0].message;
  EXPECT_EQ(errors[1].field, "N2");
  EXPECT_EQ(errors[2].field, "N6");  // a b c d e e f g: not a pentahedron
  const int last_line = errors[2].where.line;
  EXPECT_EQ(errors[0].where.line, last_line - 2);
}

TEST(ValidateMesh, SolidElementNeedsASolidSection) {
  std::string deck(kGoodDeck);
  deck += "*SECTION_SHELL\n5,2\n1.0\n*PART\nshell section\n2,5,1\n*ELEMENT_SOLID\n";
  deck += "7,2,1,2,3,4,5,6,7,8\n8,2,1,2,3,4,5,6,7,8\n";
  const std::vector<Diagnostic> errors = validate_text(deck);
  ASSERT_EQ(errors.size(), 1u) << all(errors);  // the first element of the part only
  EXPECT_EQ(errors[0].keyword, "*ELEMENT_SOLID");
  EXPECT_EQ(errors[0].field, "PID");
  EXPECT_NE(errors[0].message.find("element 7: part 2 has section 5, which is not a "
                                   "*SECTION_SOLID"),
            std::string::npos)
      << errors[0].message;
}

// A blank (shells, part 1) drawn by a rigid punch (part 2) with a rigid die (part 3).
constexpr std::string_view kSheetDeck =
    "*NODE\n"
    "1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,2,0,0\n6,2,1,0\n"  // lines 2-7
    "*ELEMENT_SHELL\n"
    "1,1,1,2,3,4\n"  // 9: quad
    "2,1,2,5,6,6\n"  // 10: triangle, N4 = N3
    "*ELEMENT_SHELL_THICKNESS\n"
    "3,2,11,12,13,14\n"  // 12: punch (each rigid body on its own nodes, at the end)
    "0.5,0.5,0.5,0.5\n"
    "*ELEMENT_SHELL\n"
    "4,3,21,22,23,24\n"  // 15: die
    "*PART\nblank\n1,1,1\n"
    "*PART\npunch\n2,2,2\n"
    "*PART\ndie\n3,1,3\n"
    "*SECTION_SHELL\n1,2,0.8333,5\n1.0\n"
    "*SECTION_SHELL\n2,2\n0.0\n"  // no thickness: the punch's elements give it
    "*MAT_PIECEWISE_LINEAR_PLASTICITY\n1,7.8e-9,2.1e5,0.3\n0,0,7\n"
    "*MAT_RIGID\n2,7.8e-9,2.1e5,0.3\n1.0,4,7\n"
    "*MAT_020\n3,7.8e-9,2.1e5,0.3\n1.0,7,7\n"
    "*DEFINE_CURVE\n7\n0,200\n1,400\n"
    "*DEFINE_CURVE\n8\n0,0\n1,1\n"
    "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n2,3,2,8,-10.0\n2,7,0,8\n"
    "*LOAD_RIGID_BODY\n3,3,8,-100.0\n"
    "*NODE\n11,0,0,1\n12,1,0,1\n13,1,1,1\n14,0,1,1\n21,0,0,-1\n22,2,0,-1\n23,2,1,-1\n"
    "24,0,1,-1\n";

/// The line number of the k-th line (1-based) appended after kSheetDeck.
int after_sheet_deck(int k) {
  return static_cast<int>(std::count(kSheetDeck.begin(), kSheetDeck.end(), '\n')) + k;
}

TEST(ValidateMesh, SheetFormingDeckHasNoErrors) {
  const std::vector<Diagnostic> errors = validate_text(kSheetDeck);
  EXPECT_TRUE(errors.empty()) << all(errors);
}

TEST(ValidateMesh, ShellIdsAndReferences) {
  std::string deck(kSheetDeck);
  deck +=
      "*ELEMENT_SHELL\n"
      "1,1,1,2,3,4\n"                                          // duplicate shell id
      "9,8,1,2,3,4\n"                                          // part 8
      "10,1,1,2,3,44\n"                                        // node 44
      "*ELEMENT_SOLID\n1,4,1,2,3,5,5,5,5,5\n"                  // a solid may share a shell's id
      "*SECTION_SHELL\n1,2\n1.0\n"                             // duplicate section id
      "*MAT_POWER_LAW_PLASTICITY\n2,7.8e-9,2e5,0.3,500,0.2\n"  // duplicate material id
      "*MAT_024\n5,7.8e-9,2e5,0.3\n0,0,99\n"                   // curve 99
      "*PART\nsolid on a shell section\n4,1,1\n";
  const std::vector<Diagnostic> errors = validate_text(deck);
  const std::string text = all(errors);
  for (const char* expected :
       {"*ELEMENT_SHELL: field EID: shell element 1 is already defined at deck.k:9",
        "*ELEMENT_SHELL: field PID: part 8 is not defined (no *PART with this id)",
        "*ELEMENT_SHELL: field N4: shell element 10: node 44 is not defined",
        "*SECTION_SHELL: field SECID: section 1 is already defined at deck.k:",
        "*MAT_POWER_LAW_PLASTICITY: field MID: material 2 is already defined at deck.k:",
        "*MAT_PIECEWISE_LINEAR_PLASTICITY: field LCSS: material 5: curve 99 is not defined (no "
        "*DEFINE_CURVE or *DEFINE_TABLE with this id)",
        "*ELEMENT_SOLID: field PID: element 1: part 4 has section 1, which is not a "
        "*SECTION_SOLID"}) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\nin:\n" << text;
  }
  EXPECT_EQ(errors.size(), 7u) << text;
}

TEST(ValidateMesh, ShellElementNeedsAShellSectionAndAThickness) {
  std::string deck(kSheetDeck);
  deck +=
      "*ELEMENT_SHELL\n"
      "20,5,1,2,3,4\n"  // part 5 has a solid section
      "21,5,1,2,3,4\n"  // the same part: reported once
      "22,2,1,2,3,4\n"  // part 2's section has T1 = 0 and no _THICKNESS card
      "*ELEMENT_SHELL_THICKNESS\n"
      "23,6,1,2,3,3\n0.5,0.5,0.5\n"      // triangle: THIC1..3 are enough
      "24,7,1,2,3,4\n0.5,0.5,0.5,0.0\n"  // quad: THIC4 missing
      "*PART\nsolid section\n5,9,1\n"
      "*PART\ntriangles\n6,2,1\n"
      "*PART\nquads\n7,2,1\n"
      "*SECTION_SOLID\n9,1\n";
  const std::vector<Diagnostic> errors = validate_text(deck);
  ASSERT_EQ(errors.size(), 3u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:" + std::to_string(after_sheet_deck(2)) +
                ": *ELEMENT_SHELL: field PID: shell element 20: part 5 has section 9, which is "
                "not a *SECTION_SHELL (the first such element is reported)");
  EXPECT_EQ(errors[1].where.line, after_sheet_deck(4));
  EXPECT_EQ(errors[1].field, "PID");
  EXPECT_NE(errors[1].message.find("shell element 22: no thickness: section 2 has T1 = 0"),
            std::string::npos)
      << errors[1].message;
  EXPECT_EQ(errors[2].where.line, after_sheet_deck(8));
  EXPECT_NE(errors[2].message.find("shell element 24: no thickness"), std::string::npos)
      << errors[2].message;
}

TEST(ValidateMesh, ShellNodeRepeats) {
  std::string deck(kSheetDeck);
  deck +=
      "*ELEMENT_SHELL\n"
      "30,1,1,2,3,3\n"   // triangle: fine
      "31,1,1,1,3,4\n"   // N2 = N1
      "32,1,1,2,2,4\n"   // N3 = N2
      "33,1,1,2,3,1\n"   // N4 = N1
      "34,1,1,2,1,1\n";  // N3 = N1 (also N4 = N3, but the first repeat is reported)
  const std::vector<Diagnostic> errors = validate_text(deck);
  ASSERT_EQ(errors.size(), 4u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:" + std::to_string(after_sheet_deck(3)) +
                ": *ELEMENT_SHELL: field N2: shell element 31: N2 repeats node 1 of N1; the only "
                "repeat accepted is N4 = N3 (a triangle)");
  EXPECT_EQ(errors[1].field, "N3");
  EXPECT_EQ(errors[2].field, "N4");
  EXPECT_EQ(errors[3].field, "N3");
  EXPECT_EQ(errors[3].where.line, after_sheet_deck(6));
}

TEST(ValidateMesh, RigidMotionsAndLoadsNeedARigidPart) {
  std::string deck(kSheetDeck);
  deck +=
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID_ID\n"
      "5,blank moved\n"
      "1,3,0,8\n"  // 32: part 1 is not rigid
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n"
      "9,1,0,8\n"   // 5: part 9 undefined
      "2,1,0,77\n"  // 6: curve 77
      "*LOAD_RIGID_BODY\n"
      "1,1,8\n"    // 37: part 1 is not rigid
      "12,1,8\n"   // 38: part 12 undefined
      "3,5,78\n";  // 39: curve 78
  const std::vector<Diagnostic> errors = validate_text(deck);
  ASSERT_EQ(errors.size(), 6u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:" + std::to_string(after_sheet_deck(3)) +
                ": *BOUNDARY_PRESCRIBED_MOTION_RIGID: field PID: part 1 has material 1, which is "
                "not a *MAT_RIGID: only rigid bodies take this keyword");
  EXPECT_EQ(errors[1].to_string(),
            "deck.k:" + std::to_string(after_sheet_deck(5)) +
                ": *BOUNDARY_PRESCRIBED_MOTION_RIGID: field PID: part 9 is not defined (no *PART "
                "with this id)");
  EXPECT_EQ(errors[2].to_string(),
            "deck.k:" + std::to_string(after_sheet_deck(6)) +
                ": *BOUNDARY_PRESCRIBED_MOTION_RIGID: field LCID: curve 77 is not defined (no "
                "*DEFINE_CURVE with this id)");
  EXPECT_EQ(errors[3].keyword, "*LOAD_RIGID_BODY");
  EXPECT_EQ(errors[3].where.line, after_sheet_deck(8));
  EXPECT_EQ(errors[3].field, "PID");
  EXPECT_EQ(errors[4].where.line, after_sheet_deck(9));
  EXPECT_EQ(errors[5].where.line, after_sheet_deck(10));
  EXPECT_EQ(errors[5].field, "LCID");
}

TEST(ValidateMesh, TheStepCurveMustExist) {
  std::string deck(kSheetDeck);
  deck +=
      "*CONTROL_TIMESTEP\n"
      ",0.9,,,,79\n";  // 2: curve 79
  const std::vector<Diagnostic> errors = validate_text(deck);
  ASSERT_EQ(errors.size(), 1u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:" + std::to_string(after_sheet_deck(2)) +
                ": *CONTROL_TIMESTEP: field LCTM: curve 79 is not defined (no *DEFINE_CURVE with "
                "this id)");
}

// A node shared by two rigid bodies and a rigid part without elements: found with their cards
// (the engine would stop at the start of the run without either).
TEST(ValidateMesh, RigidBodiesOwnTheirNodesAndHaveElements) {
  std::string deck(kSheetDeck);
  deck +=
      "*ELEMENT_SHELL\n"
      "40,3,21,22,13,24\n"           // 2: the die's element on the punch's node 13
      "41,3,21,22,12,24\n"           // 3: the same pair of bodies: reported once
      "42,1,1,2,11,4\n"              // 4: a deformable part on the punch's node: fine
      "*PART\nempty tool\n8,2,2\n";  // 7: rigid, no element
  const std::vector<Diagnostic> errors = validate_text(deck);
  ASSERT_EQ(errors.size(), 2u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:" + std::to_string(after_sheet_deck(2)) +
                ": *ELEMENT_SHELL: field N3: element 40 of rigid part 3 uses node 13, which rigid "
                "part 2 uses too: merging rigid bodies is not supported (give each body its own "
                "nodes; the first shared node of each pair of parts is reported)");
  EXPECT_EQ(errors[1].to_string(),
            "deck.k:" + std::to_string(after_sheet_deck(7)) +
                ": *PART: field PID: part 8 is rigid (*MAT_RIGID 2) but has no elements: a rigid "
                "body takes its mass and inertia from its elements");
}

}  // namespace
}  // namespace plyform::setup

namespace plyform::setup {
namespace {

// setup::validate keeps three of the errors that repeat one mistake on many cards and counts
// the rest in a fourth that names their lines.
TEST(ValidateMesh, RepeatedErrorsAreCountedNotListed) {
  std::string deck =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
      "*ELEMENT_SOLID\n";  // lines 1-10; the elements from line 11
  for (int e = 1; e <= 10; ++e)
    deck += std::to_string(e) + ",7,1,2,3,4,5,6,7,8\n";
  const keyword::ReadResult read = keyword::read_deck_text(deck, "deck.k");
  ASSERT_TRUE(read.ok()) << all(read.errors);
  const std::vector<Diagnostic> errors = validate(read.model);
  ASSERT_EQ(errors.size(), 4u) << all(errors);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(errors[static_cast<std::size_t>(i)].where.line, 11 + i);
    EXPECT_EQ(errors[static_cast<std::size_t>(i)].field, "PID");
  }
  EXPECT_EQ(errors[3].where.line, 20);
  EXPECT_NE(errors[3].message.find("part 7 is not defined"), std::string::npos);
  EXPECT_NE(errors[3].message.find("the same on 7 more lines, 14 to 20"), std::string::npos)
      << errors[3].message;
}

// *CONTROL_SHELL ESORT 1 or 2 sorts triangles into a formulation plyform does not have: an
// error naming how many there are and the first; without triangles the deck is fine.
TEST(ValidateMesh, EsortWithTrianglesIsAnError) {
  const std::string mesh =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n*PART\nsheet\n1,1,1\n"
      "*SECTION_SHELL\n1\n0.1\n*MAT_ELASTIC\n1,1e-9,100.0,0.3\n"
      "*CONTROL_SHELL\n20.0,1\n";  // line 15: card 1
  EXPECT_TRUE(validate_text(mesh + "*ELEMENT_SHELL\n1,1,1,2,3,4\n").empty());
  const std::vector<Diagnostic> errors =
      validate_text(mesh + "*ELEMENT_SHELL\n1,1,1,2,3,3\n2,1,1,3,4,4\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].keyword, "*CONTROL_SHELL");
  EXPECT_EQ(errors[0].field, "ESORT");
  EXPECT_EQ(errors[0].where.line, 15);
  EXPECT_NE(errors[0].message.find("2 triangular shells (the first: element 1"), std::string::npos)
      << errors[0].message;
}

}  // namespace
}  // namespace plyform::setup

namespace plyform::setup {
namespace {

// Two shells and a hexahedron sharing nothing: shells 1-2 of part 1, rigid shell 3 of part 2,
// solid 10 of part 3 (lines 1-43); the history keywords follow.
std::string elout_deck(const std::string& histories) {
  return "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,2,0,0\n6,2,1,0\n"
         "11,0,0,5\n12,1,0,5\n13,1,1,5\n14,0,1,5\n15,0,0,6\n16,1,0,6\n17,1,1,6\n18,0,1,6\n"
         "*PART\nsheet\n1,1,1\n*PART\ntool\n2,1,2\n*PART\nblock\n3,2,1\n"
         "*SECTION_SHELL\n1,2,0.8333,5\n0.1\n*SECTION_SOLID\n2,1\n"
         "*MAT_ELASTIC\n1,1e-9,100.0,0.3\n*MAT_RIGID\n2,1e-9,100.0,0.3\n"
         "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,1,2,5,6,3\n3,2,1,2,3,4\n"
         "*ELEMENT_SOLID\n10,3,11,12,13,14,15,16,17,18\n*CONTROL_TERMINATION\n1.0\n"
         "*DATABASE_ELOUT\n0.1\n" +
         histories;
}

// An element the history keywords name must exist, in its own id range (a shell id is no
// solid id): a located error naming the kind and the id.
TEST(ValidateMesh, HistoryElementsMustBeDefined) {
  const keyword::ReadResult read = keyword::read_deck_text(
      elout_deck("*DATABASE_HISTORY_SHELL\n2,12\n*DATABASE_HISTORY_SOLID_ID\n1,a shell id\n"),
      "deck.k");
  ASSERT_TRUE(read.ok()) << all(read.errors);
  const std::vector<Diagnostic> errors = validate(read.model);
  ASSERT_EQ(errors.size(), 2u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:45: *DATABASE_HISTORY_SHELL: field EID: shell element 12 is not defined (no "
            "*ELEMENT_SHELL with this id)");
  EXPECT_EQ(errors[1].to_string(),
            "deck.k:47: *DATABASE_HISTORY_SOLID: field ID: solid element 1 is not defined (no "
            "*ELEMENT_SOLID with this id)");
}

// The build finds each history element in its block (after colouring), keeps each once, in
// deck order, and leaves out a rigid part's element with a warning.
TEST(ValidateMesh, HistoryElementsAreFoundInTheirBlocks) {
  const keyword::ReadResult read = keyword::read_deck_text(
      elout_deck("*DATABASE_HISTORY_SHELL\n2,1,3,2\n*DATABASE_HISTORY_SOLID\n10\n"), "deck.k");
  ASSERT_TRUE(read.ok()) << all(read.errors);
  ASSERT_TRUE(validate(read.model).empty()) << all(validate(read.model));
  const BuildResult built = build(read.model);
  ASSERT_TRUE(built.model) << all(built.errors);
  const core::Model& m = *built.model;
  EXPECT_DOUBLE_EQ(m.output.elout_dt, 0.1);
  ASSERT_EQ(m.output.history_shells.size(), 2u);
  const auto id_of = [&](const core::BlockElement& h) {
    return m.shell_blocks[static_cast<std::size_t>(h.block)]
        .element_id[static_cast<std::size_t>(h.element)];
  };
  EXPECT_EQ(id_of(m.output.history_shells[0]), 2);
  EXPECT_EQ(id_of(m.output.history_shells[1]), 1);
  ASSERT_EQ(m.output.history_solids.size(), 1u);
  const core::BlockElement& solid = m.output.history_solids[0];
  EXPECT_EQ(m.solid_blocks[static_cast<std::size_t>(solid.block)]
                .element_id[static_cast<std::size_t>(solid.element)],
            10);
  ASSERT_EQ(built.warnings.size(), 1u) << all(built.warnings);
  EXPECT_EQ(built.warnings[0].to_string(),
            "deck.k:45: *DATABASE_HISTORY_SHELL: element 3 is in rigid part 2: it has no "
            "stresses, so it is not in elout.csv");
}

// *MAT_024's LCSS may name a curve or a *DEFINE_TABLE of curves by rate; with a table the
// Cowper-Symonds constants, which LS-DYNA would ignore, are an error naming C; an id that is
// neither is an error on LCSS.
TEST(ValidateMesh, RateTableOfMat024) {
  const std::string head = "*MAT_024\n1,7.8e-9,2e5,0.3\n";
  const std::string table =
      "*DEFINE_TABLE\n10\n1.0,11\n100.0,12\n*DEFINE_CURVE\n11\n0,200\n1,300\n"
      "*DEFINE_CURVE\n12\n0,250\n1,350\n";
  const auto errors_of = [](const std::string& deck) {
    const keyword::ReadResult read = keyword::read_deck_text(deck, "deck.k");
    EXPECT_TRUE(read.ok()) << all(read.errors);
    return validate(read.model);
  };
  EXPECT_TRUE(errors_of(head + "0,0,10\n" + table).empty());
  const std::vector<Diagnostic> rates = errors_of(head + "40,5,10\n" + table);
  ASSERT_EQ(rates.size(), 1u) << all(rates);
  EXPECT_EQ(rates[0].field, "C");
  EXPECT_NE(rates[0].message.find("would be ignored"), std::string::npos) << rates[0].message;
  const std::vector<Diagnostic> missing = errors_of(head + "0,0,9\n" + table);
  ASSERT_EQ(missing.size(), 1u) << all(missing);
  EXPECT_EQ(missing[0].field, "LCSS");
  EXPECT_NE(missing[0].message.find("no *DEFINE_CURVE or *DEFINE_TABLE"), std::string::npos);
}

}  // namespace
}  // namespace plyform::setup
