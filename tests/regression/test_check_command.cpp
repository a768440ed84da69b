// `plyform check`: valid decks summarised with the law's constants by name and unit; every
// error located by file, line and keyword; non-zero exit; third-party decks never crash it.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace {

constexpr const char* kValid = R"(*KEYWORD
*TITLE
probe
*PARAMETER
R   smax       0.3
*DEFINE_CURVE
         7
             300.0               0.3
             500.0               0.1
*USER_INTERFACE_FRICTION
         1        13         0
         1      30.0     &smax               300.0     500.0    3.0E-5       0.0
                 1.0    1.0E-6         0        -7
*END
)";

struct CheckRun {
  int status;
  std::string out, err;
};

CheckRun check(const std::filesystem::path& deck) {
  std::ostringstream out, err;
  const int status = run_check(deck, out, err);
  return {status, out.str(), err.str()};
}

TEST(CheckCommand, ValidDeckPrintsTheLawByName) {
  test::TempDir dir;
  const CheckRun r = check(dir.write("probe.k", kValid));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("valid"), std::string::npos);
  EXPECT_NE(r.out.find("SMAX_LO"), std::string::npos);
  EXPECT_NE(r.out.find("[stress/length]"), std::string::npos);
  EXPECT_NE(r.out.find("load curve 7"), std::string::npos);
  EXPECT_NE(r.out.find("= SMAX_LO (default)"), std::string::npos);
  // Derived quantities against their closed forms: omega = 0.3^2/30, g_c = 0.3/30.
  EXPECT_NE(r.out.find("omega = sigma_max^2 / C_N = 0.003"), std::string::npos);
  EXPECT_NE(r.out.find("g_c = sigma_max / C_N = 0.01"), std::string::npos);
}

struct BadDeck {
  const char* what;
  const char* from;  // text of kValid to replace
  const char* to;
  const char* message;  // expected part of stderr
};

class CheckErrors : public ::testing::TestWithParam<BadDeck> {};

TEST_P(CheckErrors, AreLocatedAndExitNonZero) {
  const BadDeck& c = GetParam();
  std::string text = kValid;
  const auto at = text.find(c.from);
  ASSERT_NE(at, std::string::npos) << c.from;
  text.replace(at, std::string(c.from).size(), c.to);
  test::TempDir dir;
  const CheckRun r = check(dir.write("deck.k", text));
  EXPECT_NE(r.status, 0) << c.what;
  EXPECT_NE(r.err.find(c.message), std::string::npos) << c.what << "\n" << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    EveryClass, CheckErrors,
    ::testing::Values(
        BadDeck{"out-of-range constant", "    1.0E-6         0", "    1.0E-6         5",
                "deck.k:13: *USER_INTERFACE_FRICTION: field UC12 (FRIC): constant UC12 FRIC = 5"},
        BadDeck{"undefined curve", "        -7", "        -8",
                "deck.k:13: *USER_INTERFACE_FRICTION: field UC13 (MU_LO): constant UC13 MU_LO = "
                "-8: refers to load curve 8, which is not defined"},
        BadDeck{"missing required constant", "    3.0E-5", "          ",
                "deck.k:12: *USER_INTERFACE_FRICTION: field UC7 (ETA): constant UC7 ETA is "
                "required"},
        BadDeck{"unsupported keyword", "*DEFINE_CURVE\n", "*ELEMENT_BEAM\n",
                "deck.k:6: *ELEMENT_BEAM"},
        BadDeck{"bad number", "     &smax", "      0.3x", "deck.k:12: *USER_INTERFACE_FRICTION"},
        BadDeck{"undefined parameter", "     &smax", "     &smox", "deck.k:12"},
        BadDeck{"duplicate curve id", "*USER_INTERFACE_FRICTION\n",
                "*DEFINE_CURVE\n         7\n0.0,1.0\n1.0,2.0\n*USER_INTERFACE_FRICTION\n",
                "*DEFINE_CURVE: field LCID: curve id 7 is already defined at"}));

// "error: FILE:LINE: *KEYWORD...": a file, a line number, then the keyword.
bool located(const std::string& e) {
  const std::string head = "error: ";
  if (e.rfind(head, 0) != 0)
    return false;
  const auto keyword = e.find(": *", head.size());
  if (keyword == std::string::npos)
    return false;
  const auto colon = e.rfind(':', keyword - 1);
  if (colon == std::string::npos || colon <= head.size() || colon + 1 >= keyword)
    return false;
  for (auto i = colon + 1; i < keyword; ++i) {
    if (e[i] < '0' || e[i] > '9')
      return false;
  }
  return true;
}

TEST(CheckCommand, MissingDeckIsAnError) {
  const CheckRun r = check("/nonexistent/deck.k");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("deck.k"), std::string::npos);
}

// Two shell plates and the contacts between them: one line per contact with its id, keyword,
// sides and, when a *USER_INTERFACE_FRICTION names it, the cohesive law.
constexpr const char* kContacts = R"(*KEYWORD
*NODE
1,0,0,0
2,1,0,0
3,1,1,0
4,0,1,0
5,0,0,0.1
6,1,0,0.1
7,1,1,0.1
8,0,1,0.1
*ELEMENT_SHELL
1,1,1,2,3,4
2,2,5,6,7,8
*PART
lower
1,1,1
*PART
upper
2,1,1
*SECTION_SHELL
1
0.1
*MAT_ELASTIC
1,1e-9,100.0,0.3
*SET_PART_LIST
2
2
*SET_SEGMENT
5
5,6,7,8
*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID
3,layers
1,2,3,2
*CONTACT_SURFACE_TO_SURFACE
1,5,3,0
*CONTROL_TERMINATION
1.0
*USER_INTERFACE_FRICTION
         3        13         0
         1      30.0       0.3               300.0     500.0    3.0E-5       0.0
                 1.0    1.0E-6         0       0.1
*END
)";

TEST(CheckCommand, ListsTheContacts) {
  test::TempDir dir;
  const CheckRun r = check(dir.write("contacts.k", kContacts));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("contacts: 2\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  contact 3 'layers' *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID: "
                       "slave part 1, master part set 2, cohesive law (UIF)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  contact (no CID) *CONTACT_SURFACE_TO_SURFACE: slave part 1, master "
                       "segment set 5\n"),
            std::string::npos)
      << r.out;
}

// *DATABASE_BINARY_D3DUMP: check says where and how often the checkpoints go; the fields plyform
// does not implement (NR: several files) are rejected by name.
TEST(CheckCommand, ShowsTheCheckpointsAndRejectsSeveralFiles) {
  const std::string term = "*CONTROL_TERMINATION\n1.0\n";
  std::string text = kContacts;
  text.insert(text.find(term), "*DATABASE_BINARY_D3DUMP\n       500\n");
  test::TempDir dir;
  const CheckRun r = check(dir.write("dump.k", text));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("checkpoints: OUTDIR/d3dump every 500 cycles and at the end"),
            std::string::npos)
      << r.out;
  std::string several = kContacts;
  several.insert(several.find(term), "*DATABASE_BINARY_D3DUMP\n       500         3\n");
  const CheckRun bad = check(dir.write("dump_nr.k", several));
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("*DATABASE_BINARY_D3DUMP: field NR"), std::string::npos) << bad.err;
}

// A deck is valid or not: without *CONTROL_TERMINATION the build fails, and check must not
// first call it valid and summarise it.
TEST(CheckCommand, ADeckThatDoesNotBuildIsNeverCalledValid) {
  std::string text = kContacts;
  const std::string term = "*CONTROL_TERMINATION\n1.0\n";
  text.erase(text.find(term), term.size());
  test::TempDir dir;
  const CheckRun r = check(dir.write("no_end.k", text));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out.find("valid"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("contacts:"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("*CONTROL_TERMINATION"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no_end.k: 1 error"), std::string::npos) << r.err;
}

// The shipped fundamental model: the build's view of its cohesive contact. 25 slave nodes (the
// 4 x 4 upper plate) against 36 segments (the 6 x 6 lower plate), half of 1 mm on both sides,
// following the thickness (a cohesive interface); interior slave nodes carry 0.1 K A / d of a
// 2.5 mm shell over its area: 0.1 * 166667 / 3.5355 = 4714 per length; the 2 mm master segments
// 0.1 * 166667 / 2.8284 = 5893; the deck leaves PENOPT blank, so the cohesive interface takes
// the layer rule (the stiffer side within the step). Its guard, pass 2, puts the 49 nodes of
// the lower plate against the 16 segments of the upper one.
TEST(CheckCommand, ShowsTheContactAsBuilt) {
  const CheckRun r = check(std::filesystem::path(PLYFORM_SOURCE_DIR) / "examples" / "fundamental" /
                           "fundamental.k");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("  contact 1 pass 1: 25 slave nodes against 36 segments; offsets slave "
                       "0.5, master 0.5 (following the thickness); penalty per area slave 4714, "
                       "master 5893, PENOPT 0: a layer interface's: the stiffer side, at most "
                       "m* / (4 dt0^2) (SOFT 0)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("  contact 1 pass 2: 49 slave nodes against 16 segments; offsets slave "
                       "0.5, master 0.5 (following the thickness); penalty per area slave 5893, "
                       "master 4714, PENOPT 0: a layer interface's: the stiffer side, at most "
                       "m* / (4 dt0^2); the guard: the master's nodes against the slave's "
                       "segments, pressure only, beyond a tenth of the offsets (SOFT 0)\n"),
            std::string::npos)
      << r.out;
}

// A soft layer against a stiff one under PENOPT 1: the smaller penalty is the soft side's, and
// check says so, naming the contact, the field and the remedies. Both plates 1 x 1 mm, 0.1 mm
// thick (offsets 0.05), 0.1 K A / d per area: lower (master) E 100, upper (slave) E 1e5, so the
// master's is 1/1000 of the slave's. With PENOPT 3 the slave's is used and nothing is said.
TEST(CheckCommand, WarnsWhenPenopt1TakesAFarSofterSide) {
  constexpr const char* kSoftMaster = R"(*KEYWORD
*CONTROL_TERMINATION
1e-3
*NODE
1,0,0,0
2,1,0,0
3,1,1,0
4,0,1,0
5,0,0,0.1
6,1,0,0.1
7,1,1,0.1
8,0,1,0.1
*ELEMENT_SHELL
1,1,1,2,3,4
2,2,5,6,7,8
*PART
lower
1,1,1
*PART
upper
2,1,2
*SECTION_SHELL
1
0.1
*MAT_ELASTIC
1,1e-9,100.0,0.3
*MAT_ELASTIC
2,1e-9,1.0e5,0.3
*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID
4
2,1,3,3
*END
)";
  test::TempDir dir;
  const CheckRun r = check(dir.write("soft.k", kSoftMaster));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("field SFM: contact 4: PENOPT 1 takes the smaller penalty, the master "
                       "side's"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1/1000 of the slave side's"), std::string::npos) << r.err;
  std::string stiff = kSoftMaster;
  stiff.replace(stiff.find("*CONTACT"), 0, "*CONTROL_CONTACT\n0.1,0,0,0,3\n");
  const CheckRun r3 = check(dir.write("penopt3.k", stiff));
  EXPECT_EQ(r3.status, 0) << r3.err;
  EXPECT_EQ(r3.err.find("PENOPT 1 takes"), std::string::npos) << r3.err;
}

TEST(CheckCommand, UserInterfaceFrictionWithoutItsContactIsAnError) {
  std::string text = kContacts;
  text.replace(text.find("3,layers"), 8, "4,layers");
  test::TempDir dir;
  const CheckRun r = check(dir.write("contacts.k", text));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("contacts.k:38: *USER_INTERFACE_FRICTION: field NOSID: no "
                       "*CONTACT_..._ID with CID 3"),
            std::string::npos)
      << r.err;
}

// The third-party decks of ../shared/decks/real: `check` either accepts each or stops with
// errors that all name a file and a line; never a crash.
TEST(CheckCommand, RealDecksAreAcceptedOrRejectedWithLocatedErrors) {
  const std::filesystem::path root =
      std::filesystem::path(PLYFORM_SOURCE_DIR) / ".." / "shared" / "decks" / "real";
  std::ifstream manifest(root / "MANIFEST.tsv");
  if (!manifest)
    GTEST_SKIP() << "no ../shared/decks/real here";
  std::string line;
  std::getline(manifest, line);  // header
  int decks = 0;
  while (std::getline(manifest, line)) {
    std::istringstream row(line);
    std::string path, repo, src, commit, bytes, sha, role;
    std::getline(row, path, '\t');
    for (std::string* f : {&repo, &src, &commit, &bytes, &sha, &role})
      std::getline(row, *f, '\t');
    if (role != "deck")
      continue;
    ++decks;
    const CheckRun r = check(root / path);
    if (r.status == 0)
      continue;
    std::istringstream lines(r.err);
    std::string e;
    int errors = 0;
    while (std::getline(lines, e)) {
      if (e.rfind("error: ", 0) != 0)
        continue;
      ++errors;
      // "error: FILE:LINE: *KEYWORD..." (a file that cannot be opened has no line).
      EXPECT_TRUE(located(e) || e.find("cannot open") != std::string::npos) << path << ": " << e;
    }
    EXPECT_GT(errors, 0) << path;
  }
  // The manifest grows as decks are added (its README counts them); at least the 29 the suite
  // was written against are there.
  EXPECT_GE(decks, 29);
}

}  // namespace
}  // namespace plyform::app
