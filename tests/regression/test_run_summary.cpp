// `plyform run`'s summary.json on a shell deck with a rigid tool: it counts every element, its
// rate is the integrated (deformable) element-cycles over the wall time it reports, and its
// per-pass timing accounts for the whole time loop.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

// `plyform run` on a deck's text: its exit code, stdout, stderr and summary.json.
struct RunOutput {
  int code = 0;
  std::string out, err, json;
};
RunOutput run_text(const std::string& deck_text, int threads = 0) {
  test::TempDir dir;
  RunOptions o;
  o.deck = dir.write("deck.k", deck_text);
  o.output = dir.path() / "out";
  o.progress = false;
  o.threads = threads;
  std::ostringstream out, err;
  RunOutput r;
  r.code = run_deck(o, out, err);
  r.out = out.str();
  r.err = err.str();
  std::ifstream in(*o.output / "summary.json");
  r.json.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return r;
}

TEST(RunSummary, CountsShellsAndRatesTheDeformableElements) {
  const RunOutput r = run_text(kDeck);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string& json = r.json;
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
  const RunOutput r = run_text(deck_text, threads);
  EXPECT_EQ(r.code, 0) << r.err;
  return number(r.json, "threads");
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

// Every number after "key": in the text, in order.
std::vector<double> numbers(const std::string& json, const std::string& key) {
  std::vector<double> out;
  const std::string tag = "\"" + key + "\": ";
  for (auto at = json.find(tag); at != std::string::npos; at = json.find(tag, at + 1))
    out.push_back(std::stod(json.substr(at + tag.size())));
  return out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

TEST(RunSummary, TimingAccountsForTheWholeLoopByKernelAndInterfaceStage) {
  // The sheet and tool with a contact between them (the sheet's part the slave).
  std::string text = kDeck;
  text.insert(text.find("*END"), "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n1,2,3,3\n");
  const RunOutput r = run_text(text);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string& json = r.json;
  const double loop = number(json, "loop_seconds"), wall = number(json, "wall_seconds");
  ASSERT_GT(loop, 0.0) << json;
  EXPECT_LE(loop, wall) << json;
  // The passes' seconds are never negative and sum to the loop's (the last line takes what no
  // pass took), their shares to one.
  const std::vector<double> seconds = numbers(json, "seconds"), shares = numbers(json, "share");
  ASSERT_EQ(seconds.size(), shares.size());
  double sum = 0.0, share_sum = 0.0;
  for (std::size_t i = 0; i < seconds.size(); ++i) {
    EXPECT_GE(seconds[i], 0.0) << json;
    sum += seconds[i];
    share_sum += shares[i];
  }
  EXPECT_NEAR(sum, loop, 1e-9 * loop) << json;
  EXPECT_NEAR(share_sum, 1.0, 1e-9) << json;
  // The one deformable block's kernel by formulation and law (the rigid tool has none), and
  // the interface's four stages.
  EXPECT_EQ(count(json, "\"group\": \"elements\""), 1u) << json;
  EXPECT_EQ(count(json, "\"pass\": \"shells ELFORM 2 (Belytschko-Tsay), *MAT_ELASTIC\""), 1u)
      << json;
  for (const char* stage : {"search", "projection and kinematics", "law", "forces"})
    EXPECT_EQ(count(json, std::string("\"pass\": \"contact 1: ") + stage + "\""), 1u) << json;
  EXPECT_NE(r.out.find("timing: the time loop's"), std::string::npos) << r.out;
}

TEST(RunSummary, CommandLineThreadsWinOverTheDeck) {
  EXPECT_EQ(threads_of_run(with_parallel_card("         2"), 1), 1.0);
}

}  // namespace
}  // namespace plyform::app
