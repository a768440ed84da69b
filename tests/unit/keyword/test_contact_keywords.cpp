// The contact keywords and the temperatures: *CONTACT_..._SURFACE_TO_SURFACE(_ID), *SET_SEGMENT,
// *CONTROL_CONTACT, *DATABASE_RCFORC, *INITIAL_TEMPERATURE_NODE/_SET and
// *BOUNDARY_TEMPERATURE_NODE/_SET. Fixed and free format, defaults, and every error with its
// file, line, keyword and field.
#include <string>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, single_error, expect_error, ...

using model::ContactKind;
using model::ContactSideType;

// --- *CONTACT_

TEST(Contact, FixedFormatWithIdAndEveryCard) {
  const ReadResult r = read_ok(
      "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID\n"
      "$#     cid                                                                 title\n"
      "        12blank to die\n"
      "$#    ssid      msid     sstyp     mstyp    sboxid    mboxid       spr       mpr\n"
      "         1         2         3         2         0         0         1         2\n"
      "$#      fs        fd        dc        vc       vdc    penchk        bt        dt\n"
      "     0.125      0.09       2.5      10.0      20.0         0       0.1       5.0\n"
      "$#     sfs       sfm       sst       mst      sfst      sfmt       fsf       vsf\n"
      "       2.0       3.0      0.01      0.02       1.1       1.2       0.5       0.6\n"
      "$#    soft    sofscl    lcidab    maxpar     sbopt     depth     bsort    frcfrq\n"
      "         1       0.2         0      1.05         2         2       100         1\n");
  ASSERT_EQ(r.model.contacts.size(), 1u);
  const model::ContactDesc& c = r.model.contacts[0];
  EXPECT_EQ(c.kind, ContactKind::forming_one_way_surface_to_surface);
  EXPECT_EQ(c.keyword, "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID");
  EXPECT_EQ(c.id, 12);
  EXPECT_EQ(c.heading, "blank to die");
  EXPECT_EQ(c.ssid, 1);
  EXPECT_EQ(c.msid, 2);
  EXPECT_EQ(c.sstyp, ContactSideType::part);
  EXPECT_EQ(c.mstyp, ContactSideType::part_set);
  EXPECT_EQ(c.spr, 1);
  EXPECT_EQ(c.mpr, 2);
  EXPECT_DOUBLE_EQ(c.fs, 0.125);
  EXPECT_DOUBLE_EQ(c.fd, 0.09);
  EXPECT_DOUBLE_EQ(c.dc, 2.5);
  EXPECT_DOUBLE_EQ(c.vc, 10.0);
  EXPECT_DOUBLE_EQ(c.vdc, 20.0);
  EXPECT_DOUBLE_EQ(c.birth, 0.1);
  EXPECT_DOUBLE_EQ(c.death, 5.0);
  EXPECT_DOUBLE_EQ(c.sfs, 2.0);
  EXPECT_DOUBLE_EQ(c.sfm, 3.0);
  EXPECT_DOUBLE_EQ(c.sst, 0.01);
  EXPECT_DOUBLE_EQ(c.mst, 0.02);
  EXPECT_DOUBLE_EQ(c.sfst, 1.1);
  EXPECT_DOUBLE_EQ(c.sfmt, 1.2);
  EXPECT_DOUBLE_EQ(c.fsf, 0.5);
  EXPECT_DOUBLE_EQ(c.vsf, 0.6);
  EXPECT_EQ(c.soft, 1);
  EXPECT_DOUBLE_EQ(c.sofscl, 0.2);
  EXPECT_DOUBLE_EQ(c.maxpar, 1.05);
  EXPECT_EQ(c.bsort, 100);
  EXPECT_EQ(c.where.line, 1);
  EXPECT_EQ(c.card1.line, 5);
  EXPECT_EQ(c.card1.file, "deck.k");
}

TEST(Contact, FreeFormatZerosAndOmittedCardsTakeLsDynaDefaults) {
  const ReadResult r = read_ok(
      "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n"
      "5,6,0,0\n"
      "*CONTACT_SURFACE_TO_SURFACE\n"
      "5,6,4,3\n"
      "0.2,0.1,0,0,0,0,0,0\n"
      "0,0,0,0,0,0,0,0\n"
      "0,0,0,0,0,0,0,0\n"
      "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TITLE\n"
      "7,sheets\n"
      "1,2,2,2\n"
      "\n"
      "\n"
      "\n");
  ASSERT_EQ(r.model.contacts.size(), 3u);
  for (const model::ContactDesc& c : r.model.contacts) {
    EXPECT_DOUBLE_EQ(c.death, 1e20);
    EXPECT_DOUBLE_EQ(c.sfs, 1.0);
    EXPECT_DOUBLE_EQ(c.sfm, 1.0);
    EXPECT_DOUBLE_EQ(c.sfst, 1.0);
    EXPECT_DOUBLE_EQ(c.sfmt, 1.0);
    EXPECT_DOUBLE_EQ(c.fsf, 1.0);
    EXPECT_DOUBLE_EQ(c.vsf, 1.0);
    EXPECT_EQ(c.soft, 0);
    EXPECT_DOUBLE_EQ(c.sofscl, 0.1);
    EXPECT_DOUBLE_EQ(c.maxpar, 1.025);
    EXPECT_EQ(c.bsort, 0);
  }
  const auto& c = r.model.contacts;
  EXPECT_EQ(c[0].kind, ContactKind::one_way_surface_to_surface);
  EXPECT_EQ(c[0].id, 0);
  EXPECT_EQ(c[0].sstyp, ContactSideType::segment_set);
  EXPECT_EQ(c[0].mstyp, ContactSideType::segment_set);
  EXPECT_DOUBLE_EQ(c[0].fs, 0.0);
  EXPECT_EQ(c[1].kind, ContactKind::surface_to_surface);
  EXPECT_EQ(c[1].sstyp, ContactSideType::node_set);
  EXPECT_EQ(c[1].mstyp, ContactSideType::part);
  EXPECT_DOUBLE_EQ(c[1].fs, 0.2);
  EXPECT_DOUBLE_EQ(c[1].fd, 0.1);
  EXPECT_EQ(c[2].kind, ContactKind::automatic_surface_to_surface);
  EXPECT_EQ(c[2].id, 7);
  EXPECT_EQ(c[2].heading, "sheets");
  EXPECT_EQ(c[2].card1.line, 10);
}

TEST(Contact, FieldsPlyformDoesNotImplementAreNamed) {
  constexpr std::string_view kKw = "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE";
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,1,3\n", 2, kKw, "SSTYP",
               "must be one of 0, 2, 3, 4; shell element sets (1)");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,5,3\n", 2, kKw, "SSTYP", "all parts (5)");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,4\n", 2, kKw, "MSTYP",
               "must be one of 0, 2, 3");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,6\n", 2, kKw, "MSTYP", "exclusions");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3,4\n", 2, kKw, "SBOXID",
               "not supported");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3,0,4\n", 2, kKw, "MBOXID",
               "not supported");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n0,0,0,0,0,1\n", 3, kKw, "PENCHK",
               "not supported");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n-0.1\n", 3, kKw, "FS", ">= 0");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n0,-0.1\n", 3, kKw, "FD", ">= 0");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n0,0,0,0,-5\n", 3, kKw, "VDC",
               "out of range");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n0,0,0,0,0,0,2.0,1.0\n", 3, kKw, "DT",
               "DT = 1 is not after BT = 2");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n-1\n", 4, kKw, "SFS", ">= 0");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n2\n", 5, kKw, "SOFT",
               "segment-based contact (SOFT = 2)");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n0,0,5\n", 5, kKw, "LCIDAB",
               "not supported");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n0,0,0,0,1.0\n", 5, kKw, "SBOPT",
               "SOFT = 2");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n0,0,0,0,0,3\n", 5, kKw, "DEPTH",
               "SOFT = 2");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n0,0,0,0,0,0,0,2\n", 5, kKw,
               "FRCFRQ", "every cycle");
  // Optional cards B-D: read at LS-DYNA's defaults only, each other value named.
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n\n0.5,0,0\n", 6, kKw, "PENMAX",
               "maximum penetration distance");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n\n0,0,0,2\n", 6, kKw, "SNLOG",
               "only 0 and 1");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n\n\n1,3\n", 7, kKw, "IGNORE",
               "IGNORE takes 0, 1 or 2");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n\n\n\n0,0,0,0,0,0,0,1\n", 8, kKw,
               "SHLEDG", "shell edge");
  expect_error("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n\n\n\n\n1\n", 9, kKw, "",
               "optional cards E.. (SHAREC CPARM8 ...) are not supported");
  expect_error("*CONTACT_SURFACE_TO_SURFACE_ID\n3\n", 1, "*CONTACT_SURFACE_TO_SURFACE_ID", "",
               "missing card 1");
  expect_error("*CONTACT_SURFACE_TO_SURFACE_ID\n-3\n1,2,3,3\n", 2, "*CONTACT_SURFACE_TO_SURFACE_ID",
               "CID", ">= 0");
}

TEST(Contact, OtherContactOptionsAreUnsupportedKeywords) {
  const ReadResult r =
      read_deck_text("*CONTACT_SURFACE_TO_SURFACE_TIEBREAK_ID\n1\n1,2,3,3\n", "deck.k");
  ASSERT_EQ(r.errors.size(), 1u) << all_errors(r);
  EXPECT_EQ(r.errors[0].where.line, 1);
  EXPECT_NE(r.errors[0].message.find("unsupported option _TIEBREAK_ID"), std::string::npos);
}

// --- _MPP: the MPP cards after the ID card

TEST(Contact, MppCardsAreReadAfterTheIdCard) {
  const ReadResult r = read_ok(
      "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID_MPP\n"
      "         4blank to die\n"
      "$#  ignore      bckt    lcbckt    ns2trk   inititr    parmax    unused   chksegs\n"
      "         1       200         0         3         2    1.0005                   0\n"
      "&         0\n"
      "         1         2         3         3\n"
      "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_MPP\n0,200\n3,4,3,3\n");
  ASSERT_EQ(r.model.contacts.size(), 2u);
  EXPECT_EQ(r.model.contacts[0].id, 4);
  EXPECT_EQ(r.model.contacts[0].ignore, 1);  // the MPP card's IGNORE
  EXPECT_EQ(r.model.contacts[0].ssid, 1);    // the '&' card passed over, with a warning
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].where.line, 5);
  EXPECT_NE(r.warnings[0].message.find("MPP card 2 passed over"), std::string::npos);
  EXPECT_EQ(r.model.contacts[1].ssid, 3);
  EXPECT_EQ(r.model.contacts[1].ignore, 0);
  expect_error("*CONTACT_SURFACE_TO_SURFACE_MPP\n3\n1,2,3,3\n", 2,
               "*CONTACT_SURFACE_TO_SURFACE_MPP", "IGNORE", "IGNORE takes 0, 1 or 2");
}

// --- _TIEBREAK of the automatic contacts

TEST(ContactTiebreak, TheCardAfterCard3IsRead) {
  const ReadResult r = read_ok(
      "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK_ID\n"
      "         4tiebreak contact\n"
      "        13        11         3         3         0         0         0         0\n"
      "       0.2       0.1       0.0       0.0       0.0         0       0.01.00000E20\n"
      "       1.0       1.0       0.0       0.0       1.0       1.0       1.0       1.0\n"
      "         2      25.0      40.0       0.0       0.0       0.0       0.0       0.0\n"
      "*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK\n"
      "1,2,3,3\n\n\n4,12.5,3.0,1.0\n"
      "*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_ID\n5\n1,2,3,3\n");
  ASSERT_EQ(r.model.contacts.size(), 3u);
  const model::ContactDesc& a = r.model.contacts[0];
  EXPECT_EQ(a.kind, ContactKind::automatic_surface_to_surface);
  EXPECT_TRUE(a.tiebreak);
  EXPECT_EQ(a.tiebreak_option, 2);
  EXPECT_DOUBLE_EQ(a.nfls, 25.0);
  EXPECT_DOUBLE_EQ(a.sfls, 40.0);
  EXPECT_DOUBLE_EQ(a.fs, 0.2);
  EXPECT_EQ(a.tiebreak_card.line, 6);
  const model::ContactDesc& b = r.model.contacts[1];
  EXPECT_EQ(b.kind, ContactKind::automatic_one_way_surface_to_surface);
  EXPECT_EQ(b.tiebreak_option, 4);
  EXPECT_DOUBLE_EQ(b.param, 1.0);
  EXPECT_FALSE(r.model.contacts[2].tiebreak);
  EXPECT_EQ(r.model.contacts[2].id, 5);
}

TEST(ContactTiebreak, ThermalFollowsTheTiebreakCard) {
  // LS-DYNA's order: the contact type (with TIEBREAK), then THERMAL, then ID; the thermal card
  // comes after the tiebreak card.
  const ReadResult r = read_ok(
      "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK_THERMAL_ID\n"
      "4\n1,2,3,3\n0.2,0.2\n1.0,1.0\n2,0.5,0.5\n0.0,0.0,10.0,0.01,0.1,0.5,0,0\n");
  ASSERT_EQ(r.model.contacts.size(), 1u);
  const model::ContactDesc& a = r.model.contacts[0];
  EXPECT_EQ(a.id, 4);
  EXPECT_TRUE(a.tiebreak);
  EXPECT_TRUE(a.thermal);
  EXPECT_EQ(a.tiebreak_option, 2);
  EXPECT_DOUBLE_EQ(a.nfls, 0.5);
  EXPECT_DOUBLE_EQ(a.h0, 10.0);
  EXPECT_DOUBLE_EQ(a.lmin, 0.01);
  EXPECT_DOUBLE_EQ(a.lmax, 0.1);
  expect_error("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK_THERMAL\n1,2,3,3\n\n\n2,1,1\n", 1,
               "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK_THERMAL", "",
               "_THERMAL needs its thermal card");
}

TEST(ContactTiebreak, OptionsAndFieldsPlyformDoesNotImplementAreNamed) {
  constexpr std::string_view kKw = "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK";
  const std::string head = std::string(kKw) + "\n1,2,3,3\n\n\n";
  expect_error(head + "6,10,10,0.5\n", 5, kKw, "OPTION", "damage (5, 6, 8, 13, 14)");
  expect_error(head + "9,10,10\n", 5, kKw, "OPTION", "discrete-crack");
  expect_error(head + "-1,10,10\n", 5, kKw, "OPTION", "moment-transferring");
  expect_error(head + "2,0,10\n", 5, kKw, "NFLS", "give NFLS > 0");
  expect_error(head + "3,10\n", 5, kKw, "SFLS", "give SFLS > 0");
  expect_error(head + "4,10,0,1\n", 5, kKw, "SFLS", "friction limit SFLS > 0");
  expect_error(head + "4,10,0,2\n", 5, kKw, "PARAM", "OPTION 4 takes 0");
  expect_error(head + "2,10,10,1\n", 5, kKw, "PARAM", "shell offsets ignored");
  expect_error(head + "2,10,10,0,1.0\n", 5, kKw, "ERATEN", "discrete-crack");
  expect_error(std::string(kKw) + "\n1,2,3,3\n", 1, kKw, "", "_TIEBREAK needs its card");
}

// --- *SET_SEGMENT

TEST(SetSegment, QuadsTrianglesTitleAndFreeFormat) {
  const ReadResult r = read_ok(
      "*SET_SEGMENT\n"
      "$#     sid       da1       da2       da3       da4    solver\n"
      "         1     0.000     0.000     0.000     0.000      MECH\n"
      "$#      n1        n2        n3        n4        a1        a2        a3        a4\n"
      "      2842       626      3232      3242     0.000     0.000     0.000     0.000\n"
      "        11        12        13\n"
      "        21        22        23         0\n"
      "*SET_SEGMENT_TITLE\n"
      "upper face\n"
      "4\n"
      "1,2,3,4\n"
      "5,6,7,7\n");
  ASSERT_EQ(r.model.segment_sets.size(), 2u);
  const model::SetSegmentDesc& s = r.model.segment_sets[0];
  EXPECT_EQ(s.id, 1);
  EXPECT_EQ(s.where.line, 3);
  ASSERT_EQ(s.segments.size(), 3u);
  EXPECT_EQ(s.segments[0], (std::array<int, 4>{2842, 626, 3232, 3242}));
  EXPECT_EQ(s.segments[1], (std::array<int, 4>{11, 12, 13, 13}));  // N4 blank: a triangle
  EXPECT_EQ(s.segments[2], (std::array<int, 4>{21, 22, 23, 23}));  // N4 0: a triangle
  ASSERT_EQ(s.segments_where.size(), 3u);
  EXPECT_EQ(s.segments_where[2].line, 7);
  const model::SetSegmentDesc& t = r.model.segment_sets[1];
  EXPECT_EQ(t.id, 4);
  EXPECT_EQ(t.title, "upper face");
  EXPECT_EQ(t.segments[0], (std::array<int, 4>{1, 2, 3, 4}));
  EXPECT_EQ(t.segments[1], (std::array<int, 4>{5, 6, 7, 7}));
}

TEST(SetSegment, Errors) {
  expect_error("*SET_SEGMENT\n1\n1,2\n", 3, "*SET_SEGMENT", "N3", "required");
  expect_error("*SET_SEGMENT\n1\n1,2,3,-4\n", 3, "*SET_SEGMENT", "N4", ">= 0");
  expect_error("*SET_SEGMENT\n1,0,0,0,0,THERMAL\n1,2,3\n", 2, "*SET_SEGMENT", "SOLVER",
               "not supported");
  expect_error("*SET_SEGMENT\n0\n1,2,3\n", 2, "*SET_SEGMENT", "SID", "");
}

TEST(Contact, OptionalCardsBToDAtTheirDefaultsAreRead) {
  const ReadResult r = read_ok(
      "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE\n"
      "         1         2         3         3         0         0         1         1\n"
      "     0.125       0.0       0.0       0.0      20.0         0       0.0       0.0\n"
      "       1.0       1.0       0.0       0.0       1.0       1.0       1.0       1.0\n"
      "         0       0.1         0     1.025         2         2       100         1\n"
      "       0.0         0         0         1         0         0       0.0       0.0\n"
      "         1         0       0.0       0.0       0.0                 0.0         0\n"
      "         0       0.0       0.0       0.0       0.0         0         0         0\n");
  ASSERT_EQ(r.model.contacts.size(), 1u);
  EXPECT_EQ(r.model.contacts[0].bsort, 100);
  EXPECT_DOUBLE_EQ(r.model.contacts[0].fs, 0.125);
}

TEST(Contact, InterfaceForceFileRequestIsWarnedAbout) {
  const ReadResult r = read_ok("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n1,2,3,3,0,0,1,0\n");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].field, "SPR");
  EXPECT_EQ(r.warnings[0].where.line, 2);
  EXPECT_NE(r.warnings[0].message.find("rcforc.csv"), std::string::npos);
}

// --- *CONTROL_CONTACT

TEST(ControlContact, ValuesDefaultsAndFieldsThatChangeNothing) {
  const ReadResult r = read_ok(
      "*CONTROL_CONTACT\n"
      "$#  slsfac    rwpnal    islchk    shlthk    penopt    thkchg     orien    enmass\n"
      "      0.05       1.0         2         2         3         1         4         2\n"
      "$#  usrstr    usrfrc     nsbcs    interm     xpene     ssthk      ecdt   tiedprj\n"
      "         0        32        10         0       1.0         1         1         1\n"
      "$#   sfric     dfric       edc       vfc        th     th_sf    pen_sf     ptscl\n"
      "       0.2       0.1       3.0       5.0       0.0       0.0       0.0       1.0\n"
      "$#  ignore    frceng   skiprwg    outseg   spotstp   spotdel   spothin   dir_tie\n"
      "         0         1         1         1         2         1       0.1         1\n");
  ASSERT_TRUE(r.model.control_contact.has_value());
  const model::ControlContactDesc& c = *r.model.control_contact;
  EXPECT_DOUBLE_EQ(c.slsfac, 0.05);
  EXPECT_EQ(c.shlthk, 2);
  EXPECT_EQ(c.penopt, 3);
  EXPECT_EQ(c.thkchg, 1);
  EXPECT_EQ(c.nsbcs, 10);
  EXPECT_DOUBLE_EQ(c.sfric, 0.2);
  EXPECT_DOUBLE_EQ(c.dfric, 0.1);
  EXPECT_DOUBLE_EQ(c.edc, 3.0);
  EXPECT_DOUBLE_EQ(c.vfc, 5.0);
  EXPECT_EQ(c.where.line, 3);

  // Blank and 0: LS-DYNA's defaults (SLSFAC 0.1); PENOPT 0 stays "not given" (a plain contact
  // then takes 1, a cohesive interface its layer rule: setup); cards 2-4 optional.
  const ReadResult d = read_ok("*CONTROL_CONTACT\n0.0,0,0,0,0\n");
  ASSERT_TRUE(d.model.control_contact.has_value());
  EXPECT_DOUBLE_EQ(d.model.control_contact->slsfac, 0.1);
  EXPECT_EQ(d.model.control_contact->penopt, 0);
  EXPECT_EQ(d.model.control_contact->shlthk, 0);
  EXPECT_EQ(d.model.control_contact->thkchg, 0);
  EXPECT_EQ(d.model.control_contact->nsbcs, 0);
  EXPECT_DOUBLE_EQ(d.model.control_contact->sfric, 0.0);
}

TEST(ControlContact, GivenTwiceTheLastWinsWithAWarning) {
  const ReadResult r =
      read_ok("*CONTROL_CONTACT\n0.2\n*CONTROL_CONTACT\n0.3,0,0,0,2\n*CONTROL_CONTACT\n\n");
  ASSERT_TRUE(r.model.control_contact.has_value());
  EXPECT_DOUBLE_EQ(r.model.control_contact->slsfac, 0.1);
  EXPECT_EQ(r.model.control_contact->penopt, 0);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[0].where.line, 3);
  EXPECT_EQ(r.warnings[0].keyword, "*CONTROL_CONTACT");
  EXPECT_NE(r.warnings[0].message.find("replaces the one at deck.k:2"), std::string::npos);
}

TEST(ControlContact, FieldsPlyformDoesNotImplementAreNamed) {
  constexpr std::string_view kKw = "*CONTROL_CONTACT";
  expect_error("*CONTROL_CONTACT\n0.1,0,0,0,5\n", 2, kKw, "PENOPT", "PENOPT 5");
  // PENOPT 4 (area-weighted slave stiffness) is plyform's slave stiffness: read as 3.
  EXPECT_EQ(read_ok("*CONTROL_CONTACT\n0.1,0,0,0,4\n").model.control_contact->penopt, 3);
  // IGNORE 1 and 2 are read (initial penetrations tracked).
  EXPECT_EQ(read_ok("*CONTROL_CONTACT\n0.1\n\n\n2\n").model.control_contact->ignore, 2);
  expect_error("*CONTROL_CONTACT\n-0.1\n", 2, kKw, "SLSFAC", ">= 0");
  expect_error("*CONTROL_CONTACT\n0.1,0,0,3\n", 2, kKw, "SHLTHK", "must be one of 0, 1, 2");
  expect_error("*CONTROL_CONTACT\n0.1,0,0,0,0,2\n", 2, kKw, "THKCHG", "must be one of 0, 1");
  expect_error("*CONTROL_CONTACT\n0.1\n0,0,0,1\n", 3, kKw, "INTERM", "intermittent");
  expect_error("*CONTROL_CONTACT\n0.1\n\n0,0,0,0,1.5\n", 4, kKw, "TH", "*PART_CONTACT");
  expect_error("*CONTROL_CONTACT\n0.1\n\n0,0,0,0,0,2\n", 4, kKw, "TH_SF", "*PART_CONTACT");
  expect_error("*CONTROL_CONTACT\n0.1\n\n0,0,0,0,0,0,3\n", 4, kKw, "PEN_SF", "*PART_CONTACT");
  expect_error("*CONTROL_CONTACT\n0.1\n\n0,0,0,0,0,0,0,2\n", 4, kKw, "PTSCL", "blank, 0 or 1");
  expect_error("*CONTROL_CONTACT\n0.1\n\n\n3\n", 5, kKw, "IGNORE", "IGNORE takes 0, 1 or 2");
  // Cards 5 and 6 as LS-PrePost writes them are read; what they could ask of the contacts is
  // rejected by name, and a seventh card is an error.
  const ReadResult six = read_ok(
      "*CONTROL_CONTACT\n0.1,0.0,2,2,1,0,2,0\n0,0,10,0,4.0,1,0,0\n0,0,0,0,0,0,0\n"
      "0,0,0,0,0,0,0.1\n0,0,1,0.0,1.0,0,0.0,0\n0,0,0,0,0,,0.0,0\n");
  EXPECT_TRUE(six.model.control_contact.has_value());
  expect_error("*CONTROL_CONTACT\n0.1\n\n\n\n1\n", 6, kKw, "ISYM", "symmetry-plane");
  expect_error("*CONTROL_CONTACT\n0.1\n\n\n\n\n0,1\n", 7, kKw, "PSTIFF", "PSTIFF 1");
  expect_error("*CONTROL_CONTACT\n0.1\n\n\n\n\n\n1\n", 8, kKw, "", "cards 7 and after");
}

// --- *DATABASE_RCFORC

TEST(DatabaseRcforc, ReadsTheInterval) {
  const ReadResult r = read_ok(
      "*DATABASE_RCFORC\n"
      "2.50000E-4         1         0         1\n"
      "*DATABASE_GLSTAT\n1e-3\n");
  ASSERT_EQ(r.model.ascii_outputs.size(), 2u);
  EXPECT_EQ(r.model.ascii_outputs[0].name, "RCFORC");
  EXPECT_DOUBLE_EQ(r.model.ascii_outputs[0].dt, 2.5e-4);
  EXPECT_EQ(r.model.ascii_outputs[0].binary, 1);
  EXPECT_EQ(r.model.ascii_outputs[0].where.line, 2);
  EXPECT_EQ(r.model.ascii_outputs[1].name, "GLSTAT");
  expect_error("*DATABASE_RCFORC\n1e-3,1,7\n", 2, "*DATABASE_RCFORC", "LCUR", "not supported");
}

// --- *DATABASE_SPCFORC, _SLEOUT, _MATSUM; output requests plyform does not write

TEST(DatabaseOutputs, SpcforcSleoutMatsumReadTheirIntervals) {
  const ReadResult r =
      read_ok("*DATABASE_SPCFORC\n1e-4\n*DATABASE_SLEOUT\n2e-4,3\n*DATABASE_MATSUM\n3e-4\n");
  ASSERT_EQ(r.model.ascii_outputs.size(), 3u);
  EXPECT_EQ(r.model.ascii_outputs[0].name, "SPCFORC");
  EXPECT_DOUBLE_EQ(r.model.ascii_outputs[0].dt, 1e-4);
  EXPECT_EQ(r.model.ascii_outputs[1].name, "SLEOUT");
  EXPECT_EQ(r.model.ascii_outputs[1].binary, 3);
  EXPECT_EQ(r.model.ascii_outputs[2].name, "MATSUM");
  EXPECT_DOUBLE_EQ(r.model.ascii_outputs[2].dt, 3e-4);
  expect_error("*DATABASE_MATSUM\n1e-3,1,7\n", 2, "*DATABASE_MATSUM", "LCUR", "not supported");
}

TEST(DatabaseOutputs, OutputRequestsPlyformDoesNotWriteAreWarnedAboutNotRejected) {
  // Unknown output keywords (one with an option), with cards of their own.
  const ReadResult r = read_ok(
      "*DATABASE_SECFORC\n1e-4\n*DATABASE_ABSTAT\n1e-4,1\n0,0,0,0,0\n"
      "*DATABASE_HISTORY_SHELL_SET\n7\n*DATABASE_GLSTAT\n1e-3\n");
  ASSERT_EQ(r.warnings.size(), 3u);
  EXPECT_EQ(r.warnings[0].keyword, "*DATABASE_SECFORC");
  EXPECT_EQ(r.warnings[0].where.line, 1);
  EXPECT_NE(r.warnings[0].message.find("not written"), std::string::npos);
  EXPECT_EQ(r.warnings[1].keyword, "*DATABASE_ABSTAT");
  EXPECT_EQ(r.warnings[2].keyword, "*DATABASE_HISTORY_SHELL_SET");
  ASSERT_EQ(r.model.ascii_outputs.size(), 1u);  // the cards passed over are not read as others
  EXPECT_EQ(r.model.ascii_outputs[0].name, "GLSTAT");
  // Any other keyword plyform does not know stays an error.
  expect_error("*CONTROL_IMPLICIT_GENERAL\n1\n", 1, "*CONTROL_IMPLICIT_GENERAL", "",
               "unsupported keyword");
}

TEST(DatabaseExtentBinary, ReadsTheFlagsAndNamesWhatIsNotWritten) {
  // LS-PrePost's four cards, with requests plyform honours (STRFLG 1, SIGFLG 3, EPSFLG 2),
  // passes (IEVERP, DCOMP) and does not write (NEIPS, SHGE, STSSZ, NINTSLD, INTOUT).
  const ReadResult r = read_ok(
      "*DATABASE_EXTENT_BINARY\n"
      "$#   neiph     neips    maxint    strflg    sigflg    epsflg    rltflg    engflg\n"
      "         0         7         3         1         3         2         1         1\n"
      "         0         1         0         1         2         2         1         1\n"
      "         8         0       1.0         0         0         0ALL\n"
      "         0         0         0         0         0\n");
  ASSERT_TRUE(r.model.extent_binary.has_value());
  const model::DatabaseExtentBinaryDesc& x = *r.model.extent_binary;
  EXPECT_EQ(x.strflg, 1);
  EXPECT_EQ(x.sigflg, 3);
  EXPECT_EQ(x.epsflg, 2);
  EXPECT_EQ(x.ieverp, 1);
  EXPECT_EQ(x.nintsld, 8);
  EXPECT_EQ(x.intout, "ALL");
  std::vector<std::string> fields;
  for (const Diagnostic& w : r.warnings) {
    EXPECT_EQ(w.keyword, "*DATABASE_EXTENT_BINARY");
    fields.push_back(w.field);
  }
  EXPECT_EQ(fields, (std::vector<std::string>{"NEIPS", "SHGE", "STSSZ", "NINTSLD", "INTOUT"}));
  EXPECT_EQ(r.warnings[0].where.line, 3);
  // Blank cards are LS-DYNA's defaults: nothing to warn about.
  EXPECT_TRUE(read_ok("*DATABASE_EXTENT_BINARY\n\n                   1\n").warnings.empty());
  expect_error("*DATABASE_EXTENT_BINARY\n0,0,3,12\n", 2, "*DATABASE_EXTENT_BINARY", "STRFLG",
               "digits abc");
  expect_error("*DATABASE_EXTENT_BINARY\n0,0,3,0,4\n", 2, "*DATABASE_EXTENT_BINARY", "SIGFLG", "");
  expect_error("*DATABASE_EXTENT_BINARY\n\n\n\n\n1\n", 6, "*DATABASE_EXTENT_BINARY", "",
               "cards 5 and after");
}

TEST(DatabaseHistoryNodeSet, ReadsTheNodeSetIds) {
  const ReadResult r = read_ok("*DATABASE_HISTORY_NODE_SET\n3,0,4\n5\n");
  ASSERT_EQ(r.model.history_nodes.size(), 1u);
  EXPECT_EQ(r.model.history_nodes[0].set_ids, (std::vector<int>{3, 4, 5}));
  EXPECT_TRUE(r.model.history_nodes[0].node_ids.empty());
  EXPECT_EQ(r.model.history_nodes[0].sets_where[2].line, 3);
  expect_error("*DATABASE_HISTORY_NODE_SET\n-2\n", 2, "*DATABASE_HISTORY_NODE_SET", "NSID1",
               "range");
}

// --- *INITIAL_TEMPERATURE_NODE / _SET

TEST(InitialTemperature, NodesAndSets) {
  const ReadResult r = read_ok(
      "*INITIAL_TEMPERATURE_NODE\n"
      "$#     nid      temp       loc\n"
      "         1     293.0         0\n"
      "2,300.5\n"
      "*INITIAL_TEMPERATURE_SET\n"
      "         4     450.0\n");
  const auto& t = r.model.initial_temperatures;
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].target, model::NodeTarget::kNode);
  EXPECT_EQ(t[0].target_id, 1);
  EXPECT_DOUBLE_EQ(t[0].temperature, 293.0);
  EXPECT_EQ(t[0].where.line, 3);
  EXPECT_EQ(t[1].target_id, 2);
  EXPECT_DOUBLE_EQ(t[1].temperature, 300.5);
  EXPECT_EQ(t[1].loc, 0);
  EXPECT_EQ(t[2].target, model::NodeTarget::kSet);
  EXPECT_EQ(t[2].target_id, 4);
  EXPECT_DOUBLE_EQ(t[2].temperature, 450.0);
}

TEST(InitialTemperature, SetZeroIsEveryNode) {
  // NSID 0 (written or blank) is every node of the model: target_id stays 0 for setup.
  const ReadResult r = read_ok(
      "*INITIAL_TEMPERATURE_SET\n"
      "0,300.0\n"
      "\n"
      "         0     310.0\n");
  const auto& t = r.model.initial_temperatures;
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].target, model::NodeTarget::kSet);
  EXPECT_EQ(t[0].target_id, 0);
  EXPECT_DOUBLE_EQ(t[0].temperature, 300.0);
  EXPECT_EQ(t[0].where.line, 2);
  EXPECT_EQ(t[1].target_id, 0);
  EXPECT_DOUBLE_EQ(t[1].temperature, 310.0);
  EXPECT_EQ(t[1].where.line, 4);
}

TEST(InitialTemperature, Errors) {
  expect_error("*INITIAL_TEMPERATURE_SET\n-1,300.0\n", 2, "*INITIAL_TEMPERATURE_SET", "NSID",
               ">= 0");
  expect_error("*INITIAL_TEMPERATURE_NODE\n1,300.0,1\n", 2, "*INITIAL_TEMPERATURE_NODE", "LOC",
               "thermal shells");
  expect_error("*INITIAL_TEMPERATURE_NODE\n,300.0\n", 2, "*INITIAL_TEMPERATURE_NODE", "NID",
               "required");
}

// --- *BOUNDARY_TEMPERATURE_NODE / _SET

TEST(BoundaryTemperature, NodesAndSetsWithDefaults) {
  const ReadResult r = read_ok(
      "*BOUNDARY_TEMPERATURE_SET\n"
      "$#    nsid      lcid     cmult       loc    tdeath    tbirth\n"
      "         6        11\n"
      "         7         0     500.0         0       2.0       1.0\n"
      "*BOUNDARY_TEMPERATURE_NODE\n"
      "3,12,0.5,0,0,0.25\n");
  const auto& t = r.model.temperature_histories;
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].target, model::NodeTarget::kSet);
  EXPECT_EQ(t[0].target_id, 6);
  EXPECT_EQ(t[0].curve_id, 11);
  EXPECT_DOUBLE_EQ(t[0].cmult, 1.0);  // blank: 1
  EXPECT_DOUBLE_EQ(t[0].death, 1e20);
  EXPECT_DOUBLE_EQ(t[0].birth, 0.0);
  EXPECT_EQ(t[0].where.line, 3);
  EXPECT_EQ(t[1].curve_id, 0);
  EXPECT_DOUBLE_EQ(t[1].cmult, 500.0);
  EXPECT_DOUBLE_EQ(t[1].death, 2.0);
  EXPECT_DOUBLE_EQ(t[1].birth, 1.0);
  EXPECT_EQ(t[2].target, model::NodeTarget::kNode);
  EXPECT_EQ(t[2].target_id, 3);
  EXPECT_EQ(t[2].curve_id, 12);
  EXPECT_DOUBLE_EQ(t[2].cmult, 0.5);
  EXPECT_DOUBLE_EQ(t[2].death, 1e20);  // 0: 1e20
  EXPECT_DOUBLE_EQ(t[2].birth, 0.25);
}

TEST(BoundaryTemperature, Errors) {
  expect_error("*BOUNDARY_TEMPERATURE_SET\n6,11,1.0,3\n", 2, "*BOUNDARY_TEMPERATURE_SET", "LOC",
               "-1, 0, 1");
  expect_error("*BOUNDARY_TEMPERATURE_SET\n,0,1.0\n", 2, "*BOUNDARY_TEMPERATURE_SET", "NSID",
               "required");
  expect_error("*BOUNDARY_TEMPERATURE_NODE\n1,-2\n", 2, "*BOUNDARY_TEMPERATURE_NODE", "LCID",
               ">= 0");
  expect_error("*BOUNDARY_TEMPERATURE_NODE\n1,2,1.0,0,1.0,3.0\n", 2, "*BOUNDARY_TEMPERATURE_NODE",
               "TDEATH", "TDEATH = 1 is not after TBIRTH = 3");
}

}  // namespace
}  // namespace plyform::keyword
