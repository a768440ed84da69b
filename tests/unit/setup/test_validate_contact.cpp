// setup::validate_contact: contact ids and sides, segment sets, the contact a
// *USER_INTERFACE_FRICTION names, temperature references and single prescriptions; every error
// located by file, line, keyword and field.
#include <string>

#include <gtest/gtest.h>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/validate.hpp"
#include "plyform/setup/validate_contact.hpp"

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

keyword::ReadResult read(std::string_view text) {
  keyword::ReadResult read = keyword::read_deck_text(text, "deck.k");
  EXPECT_TRUE(read.ok()) << all(read.errors);
  return read;
}

std::vector<Diagnostic> validate_text(std::string_view text) {
  return validate_contact(read(text).model);
}

// Two parts of one shell each, a node set, a part set and a segment set.
constexpr std::string_view kMesh =
    "*NODE\n"
    "1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"  // lines 2-9
    "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,2,5,6,7,8\n"                                // 10-12
    "*PART\nlower\n1,1,1\n*PART\nupper\n2,1,1\n"                                // 13-18
    "*SECTION_SHELL\n1\n0.1\n*MAT_ELASTIC\n1,1e-9,100.0,0.3\n"                  // 19-23
    "*SET_NODE_LIST\n10\n5,6,7,8\n"                                             // 24-26
    "*SET_PART_LIST\n20\n1,2\n"                                                 // 27-29
    "*SET_SEGMENT\n30\n1,2,3,4\n5,6,7\n"                                        // 30-33
    "*DEFINE_CURVE\n40\n0,300\n1,400\n";                                        // 34-37

std::string deck(std::string_view more) {
  return std::string(kMesh) + std::string(more);
}

TEST(ValidateContact, GoodDeckHasNoErrors) {
  const std::vector<Diagnostic> errors = validate_text(
      deck("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n1\n10,30,4,0\n"
           "*CONTACT_SURFACE_TO_SURFACE\n1,2,3,3\n"
           "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID\n2\n20,2,2,3\n"
           "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n30,20,0,2\n"
           "*INITIAL_TEMPERATURE_NODE\n1,300\n*INITIAL_TEMPERATURE_SET\n10,350\n"
           "*BOUNDARY_TEMPERATURE_SET\n10,40\n*BOUNDARY_TEMPERATURE_NODE\n1,0,300\n2,40,1.0\n"));
  EXPECT_TRUE(errors.empty()) << all(errors);
}

TEST(ValidateContact, ContactIdsAndSides) {
  const std::vector<Diagnostic> errors = validate_text(
      deck("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n5\n1,2,3,3\n"    // 38-40
           "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID\n5\n0,0,3,3\n"  // 41-43: CID, SSID, MSID
           "*CONTACT_SURFACE_TO_SURFACE\n9,31,3,0\n"                 // 44-45: SSID, MSID
           "*CONTACT_SURFACE_TO_SURFACE\n30,10,2,2\n"                // 46-47: SSID, MSID
           "*CONTACT_SURFACE_TO_SURFACE_ID\n0\n11,2,4,3\n*CONTACT_SURFACE_TO_SURFACE_ID\n0\n10,2,4,"
           "3\n"
           "*USER_INTERFACE_FRICTION\n5,0\n"));  // names contact 5: it must be unique
  ASSERT_EQ(errors.size(), 8u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:41: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID: field CID: contact 5 is already "
            "defined at deck.k:38");
  EXPECT_EQ(errors[1].where.line, 43);
  EXPECT_EQ(errors[1].field, "SSID");
  EXPECT_NE(errors[1].message.find("SSID = 0 (every part) is not supported"), std::string::npos);
  EXPECT_EQ(errors[2].field, "MSID");
  EXPECT_NE(errors[2].message.find("segment set, part set or part"), std::string::npos);
  EXPECT_EQ(errors[3].to_string(),
            "deck.k:45: *CONTACT_SURFACE_TO_SURFACE: field SSID: part 9 is not defined (no "
            "*PART with this id; SSTYP = 3)");
  EXPECT_EQ(errors[4].to_string(),
            "deck.k:45: *CONTACT_SURFACE_TO_SURFACE: field MSID: segment set 31 is not defined "
            "(no *SET_SEGMENT with this id; MSTYP = 0)");
  EXPECT_EQ(errors[5].field, "SSID");  // part set 30 (a segment set id)
  EXPECT_NE(errors[5].message.find("part set 30"), std::string::npos);
  EXPECT_EQ(errors[6].field, "MSID");   // part set 10 (a node set id)
  EXPECT_EQ(errors[7].where.line, 50);  // node set 11; CID 0 twice is no duplicate
  EXPECT_NE(errors[7].message.find("node set 11 is not defined"), std::string::npos);
}

// LS-PrePost writes copies of a contact with the same CID: that is no error unless a
// *USER_INTERFACE_FRICTION names the id (build_contacts warns about the repeat).
TEST(ValidateContact, RepeatedContactIdsAreAcceptedUnlessALawNamesThem) {
  const std::vector<Diagnostic> errors =
      validate_text(deck("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID\n5\n1,2,3,3\n"
                         "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID\n5\n2,1,3,3\n"));
  EXPECT_TRUE(errors.empty()) << all(errors);
}

TEST(ValidateContact, SegmentSets) {
  const std::vector<Diagnostic> errors =
      validate_text(deck("*SET_SEGMENT_TITLE\nagain\n30\n1,2,3\n"  // 38-41: SID
                         "*SET_SEGMENT\n31\n1,2,99,4\n"            // 42-44: N3
                         "1,2,3,98\n"                              // 45: N4
                         "1,2,2,4\n"                               // 46: N3 repeats N2
                         "1,2,3,1\n"));                            // 47: N4 repeats N1
  ASSERT_EQ(errors.size(), 5u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:40: *SET_SEGMENT: field SID: segment set 30 is already defined at deck.k:31");
  EXPECT_EQ(errors[1].to_string(),
            "deck.k:44: *SET_SEGMENT: field N3: segment set 31, segment 1: node 99 is not "
            "defined (no *NODE with this id)");
  EXPECT_EQ(errors[2].where.line, 45);
  EXPECT_EQ(errors[2].field, "N4");
  EXPECT_EQ(errors[3].where.line, 46);
  EXPECT_EQ(errors[3].field, "N3");
  EXPECT_NE(errors[3].message.find("N3 repeats node 2 of N2"), std::string::npos);
  EXPECT_EQ(errors[4].where.line, 47);
  EXPECT_EQ(errors[4].field, "N4");
}

TEST(ValidateContact, UserInterfaceFrictionNamesAContact) {
  const std::vector<Diagnostic> errors =
      validate_text(deck("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n3\n1,2,3,3\n"  // 38-40
                         "*USER_INTERFACE_FRICTION\n3,0\n"                       // 41-42
                         "*USER_INTERFACE_FRICTION\n4,0\n"));                    // 43-44
  ASSERT_EQ(errors.size(), 1u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:43: *USER_INTERFACE_FRICTION: field NOSID: no *CONTACT_..._ID with CID 4: the "
            "law must name the contact it applies to");
  // The law alone (no mesh, no contact), as `plyform law` reads it, names no contact.
  EXPECT_TRUE(validate_text("*USER_INTERFACE_FRICTION\n4,0\n").empty());
}

TEST(ValidateContact, TemperatureReferences) {
  const std::vector<Diagnostic> errors =
      validate_text(deck("*INITIAL_TEMPERATURE_NODE\n99,300\n"         // 38-39
                         "*INITIAL_TEMPERATURE_SET\n11,300\n"          // 40-41
                         "*BOUNDARY_TEMPERATURE_NODE\n98,41\n"         // 42-43: NID, LCID
                         "*BOUNDARY_TEMPERATURE_SET\n12,0,300.0\n"));  // 44-45: NSID
  ASSERT_EQ(errors.size(), 5u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:39: *INITIAL_TEMPERATURE_NODE: field NID: node 99 is not defined (no *NODE "
            "with this id)");
  EXPECT_EQ(errors[1].to_string(),
            "deck.k:41: *INITIAL_TEMPERATURE_SET: field NSID: node set 11 is not defined (no "
            "*SET_NODE_LIST with this id)");
  EXPECT_EQ(errors[2].field, "NID");
  EXPECT_EQ(errors[2].keyword, "*BOUNDARY_TEMPERATURE_NODE");
  EXPECT_EQ(errors[3].to_string(),
            "deck.k:43: *BOUNDARY_TEMPERATURE_NODE: field LCID: curve 41 is not defined (no "
            "*DEFINE_CURVE with this id)");
  EXPECT_EQ(errors[4].where.line, 45);
  EXPECT_EQ(errors[4].field, "NSID");
}

TEST(ValidateContact, ANodeTakesOneBoundaryTemperature) {
  const std::vector<Diagnostic> errors = validate_text(
      deck("*BOUNDARY_TEMPERATURE_SET\n10,40\n"               // 38-39: nodes 5-8
           "*BOUNDARY_TEMPERATURE_NODE\n1,40\n6,40\n1,0,3\n"  // 40-43: 6 and 1 again
           "*SET_NODE_LIST\n11\n1,5,7,2\n"                    // 44-46
           "*BOUNDARY_TEMPERATURE_SET\n11,0,500.0\n"));       // 47-48: 1, 5, 7 again; 2 new
  ASSERT_EQ(errors.size(), 3u) << all(errors);
  EXPECT_EQ(errors[0].to_string(),
            "deck.k:42: *BOUNDARY_TEMPERATURE_NODE: field NID: node 6 already has a prescribed "
            "temperature (*BOUNDARY_TEMPERATURE_SET at deck.k:39); a node takes one "
            "*BOUNDARY_TEMPERATURE entry per face (LOC)");
  EXPECT_EQ(errors[1].where.line, 43);
  EXPECT_NE(errors[1].message.find("node 1 already has a prescribed temperature "
                                   "(*BOUNDARY_TEMPERATURE_NODE at deck.k:41)"),
            std::string::npos);
  EXPECT_EQ(errors[2].where.line, 48);
  EXPECT_EQ(errors[2].field, "NSID");
  EXPECT_NE(errors[2].message.find("node 1 already has"), std::string::npos);
  EXPECT_NE(errors[2].message.find("and so have 2 more nodes of the set"), std::string::npos);
}

TEST(ValidateContact, ReachedThroughValidate) {
  const keyword::ReadResult r =
      read(deck("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,7,3,3\n*INITIAL_TEMPERATURE_NODE\n9,1\n"));
  const std::vector<Diagnostic> errors = validate(r.model);
  ASSERT_EQ(errors.size(), 2u) << all(errors);
  EXPECT_EQ(errors[0].field, "MSID");
  EXPECT_EQ(errors[1].field, "NID");
}

// A tied contact is a constraint: the friction and penalty fields it reads are warned about by
// name (not passed over in silence); its defaults draw no warning.
TEST(TiedContactCards, FieldsATieCannotUseAreWarnedAboutByName) {
  const std::string mesh =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0.5,0.5,0.1\n*SET_NODE_LIST\n1\n5\n";
  const keyword::ReadResult plain =
      keyword::read_deck_text(mesh + "*CONTACT_TIED_NODES_TO_SURFACE_OFFSET\n1,1,4,3\n", "deck.k");
  ASSERT_TRUE(plain.ok());
  EXPECT_TRUE(plain.warnings.empty());
  ASSERT_EQ(plain.model.contacts.size(), 1u);
  EXPECT_TRUE(plain.model.contacts[0].offset);
  const keyword::ReadResult given = keyword::read_deck_text(
      mesh + "*CONTACT_TIED_NODES_TO_SURFACE\n1,1,4,3\n0.3,0.2\n2.0\n", "deck.k");
  ASSERT_TRUE(given.ok());
  std::string fields;
  for (const auto& w : given.warnings)
    fields += w.field + " ";
  EXPECT_EQ(fields, "FS FD SFS ");
}

}  // namespace
}  // namespace plyform::setup
