// `plyform run`'s summary.json on a shell deck with a rigid tool: it counts every element, and
// its rate is the integrated (deformable) element-cycles over the wall time it reports.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace {

// A 2 x 2 elastic sheet (part 1, 4 shells) under a rigid plate of 1 shell (part 2), apart.
constexpr const char* kDeck = R"(*KEYWORD
*CONTROL_TERMINATION
1.0e-5
*PART
sheet
1,1,1
*PART
tool
2,1,2
*SECTION_SHELL
1,2,0.8333,3
0.5,0.5,0.5,0.5
*MAT_ELASTIC
1,7.85e-9,2.1e5,0.3
*MAT_RIGID
2,7.85e-9,2.1e5,0.3
*NODE
1,0,0,0
2,1,0,0
3,2,0,0
4,0,1,0
5,1,1,0
6,2,1,0
7,0,2,0
8,1,2,0
9,2,2,0
11,0,0,1
12,2,0,1
13,2,2,1
14,0,2,1
*ELEMENT_SHELL
1,1,1,2,5,4
2,1,2,3,6,5
3,1,4,5,8,7
4,1,5,6,9,8
5,2,11,12,13,14
*INITIAL_VELOCITY_GENERATION
1,2,0,0,0,10
*END
)";

// The number after "key": in a flat JSON object (enough for summary.json's scalars).
double number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  EXPECT_NE(at, std::string::npos) << key;
  return at == std::string::npos ? 0.0 : std::stod(json.substr(at + key.size() + 3));
}

TEST(RunSummary, CountsShellsAndRatesTheDeformableElements) {
  test::TempDir dir;
  RunOptions o;
  o.deck = dir.write("sheet_tool.k", kDeck);
  o.output = dir.path() / "out";
  o.progress = false;
  std::ostringstream out, err;
  ASSERT_EQ(run_deck(o, out, err), 0) << err.str();
  std::ifstream in(*o.output / "summary.json");
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(number(json, "elements"), 5.0) << json;
  EXPECT_EQ(number(json, "deformable_elements"), 4.0) << json;
  const double cycles = number(json, "cycles"), wall = number(json, "wall_seconds");
  ASSERT_GT(cycles, 0.0);
  ASSERT_GT(wall, 0.0);
  EXPECT_NEAR(number(json, "element_cycles_per_second"), 4.0 * cycles / wall,
              1e-9 * 4.0 * cycles / wall)
      << json;
}

// The run's thread count (summary.json "threads"): the deck's *CONTROL_PARALLEL NCPU (its
// magnitude: a negative one asks for consistency, which plyform always has) when --threads is
// not given, --threads when it is, 1 when neither says.
double threads_of_run(const std::string& deck_text, int threads) {
  test::TempDir dir;
  RunOptions o;
  o.deck = dir.write("threads.k", deck_text);
  o.output = dir.path() / "out";
  o.progress = false;
  o.threads = threads;
  std::ostringstream out, err;
  EXPECT_EQ(run_deck(o, out, err), 0) << err.str();
  std::ifstream in(*o.output / "summary.json");
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return number(json, "threads");
}

std::string with_parallel_card(const std::string& card) {
  std::string text = kDeck;
  text.insert(text.find("*PART"), "*CONTROL_PARALLEL\n" + card + "\n");
  return text;
}

TEST(RunSummary, ThreadsFromTheDeckWhenTheCommandLineGivesNone) {
  EXPECT_EQ(threads_of_run(with_parallel_card("         2"), 0), 2.0);
  EXPECT_EQ(threads_of_run(with_parallel_card("        -2         0         1"), 0), 2.0);
  EXPECT_EQ(threads_of_run(kDeck, 0), 1.0);
}

TEST(RunSummary, CommandLineThreadsWinOverTheDeck) {
  EXPECT_EQ(threads_of_run(with_parallel_card("         2"), 1), 1.0);
}

}  // namespace
}  // namespace plyform::app
