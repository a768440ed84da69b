// `plyform check`'s mesh summary: the shell formulations it names, and the stable step and cycle
// count it announces with mass scaling (*CONTROL_TIMESTEP DT2MS) applied as the run applies it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace test_check_step {

// A free 2 x 2 plate of 1 mm shells, 1 mm thick, steel in mm, t, s; plate() fills in the
// @ fields.
constexpr const char* kPlate = R"(*KEYWORD
*CONTROL_TERMINATION
4.0e-3
@TIMESTEP
@PARTS
*SECTION_SHELL
1,@ELFORM,0.8333,3
1.0,1.0,1.0,1.0
*SECTION_SHELL
2,16,0.8333,3
1.0,1.0,1.0,1.0
*MAT_ELASTIC
1,7.85e-9,2.1e5,0.3
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
*ELEMENT_SHELL
1,1,1,2,5,4
2,1,2,3,6,5
3,@PART,4,5,8,7
4,@PART,5,6,9,8
*END
)";

constexpr double kRho = 7.85e-9, kE = 2.1e5, kNu = 0.3, kEndTime = 4.0e-3, kTssfac = 0.9;

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// elform: section 1's ELFORM; upper_part: the part of elements 3 and 4 (part 2 is section 2,
// ELFORM 16); timestep: the *CONTROL_TIMESTEP block or "".
std::string plate(int elform, int upper_part, const std::string& timestep) {
  std::string text = replace_all(kPlate, "@ELFORM", std::to_string(elform));
  text = replace_all(text, "@PART,", std::to_string(upper_part) + ",");
  text = replace_all(text, "@TIMESTEP\n", timestep);
  const std::string parts =
      upper_part == 2 ? "*PART\nsheet\n1,1,1\n*PART\nfull\n2,2,1\n" : "*PART\nsheet\n1,1,1\n";
  return replace_all(text, "@PARTS\n", parts);
}

struct CheckRun {
  int status;
  std::string out, err;
};

CheckRun check(const std::filesystem::path& deck) {
  std::ostringstream out, err;
  const int status = run_check(deck, out, err);
  return {status, out.str(), err.str()};
}

// The number after `key` on check's output (0 and a failure when absent).
double number_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos) << key << " in\n" << text;
  return at == std::string::npos ? 0.0 : std::stod(text.substr(at + key.size()));
}

// Runs `deck` with `plyform run` into `outdir` and reads back its summary.json.
void run_summary(const std::filesystem::path& deck, const std::filesystem::path& outdir,
                 std::string& json) {
  RunOptions o;
  o.deck = deck;
  o.output = outdir;
  o.progress = false;
  std::ostringstream out, err;
  ASSERT_EQ(run_deck(o, out, err), 0) << err.str();
  std::ifstream in(outdir / "summary.json");
  json.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(CheckShells, NamesTheBelytschkoTsayShells) {
  test::TempDir dir;
  const CheckRun r = check(dir.write("bt.k", plate(2, 1, "")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("shell elements: 4 (Belytschko-Tsay; 0 triangles)\n"), std::string::npos)
      << r.out;
}

TEST(CheckShells, NamesFullyIntegratedShells) {
  test::TempDir dir;
  const CheckRun r = check(dir.write("full.k", plate(16, 1, "")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("shell elements: 4 (ELFORM 16 fully integrated; 0 triangles)\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("Belytschko-Tsay"), std::string::npos) << r.out;
}

TEST(CheckShells, CountsEachFormulationWhenMixed) {
  test::TempDir dir;
  const CheckRun r = check(dir.write("mixed.k", plate(2, 2, "")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("shell elements: 4 (Belytschko-Tsay: 2, ELFORM 16 fully integrated: 2; 0 "
                       "triangles)\n"),
            std::string::npos)
      << r.out;
}

// Without mass scaling: the step of a 1 mm square Belytschko-Tsay shell is its side over the
// plate wave speed sqrt(E / (rho (1 - nu^2))), times TSSFAC.
TEST(CheckStep, UnscaledStepIsTheSquaresSideOverThePlateWaveSpeed) {
  test::TempDir dir;
  const CheckRun r = check(dir.write("plain.k", plate(2, 1, "")));
  ASSERT_EQ(r.status, 0) << r.err;
  const double c = std::sqrt(kE / (kRho * (1.0 - kNu * kNu)));
  const double dt = kTssfac * 1.0 / c;
  EXPECT_NEAR(number_after(r.out, "stable time step estimate: "), dt, 1e-5 * dt) << r.out;
  EXPECT_NEAR(number_after(r.out, "about "), kEndTime / dt, 1e-5 * kEndTime / dt) << r.out;
  EXPECT_EQ(r.out.find("mass scaling"), std::string::npos) << r.out;
}

// DT2MS -4e-5 (and +4e-5: plyform adds mass for either sign): every element's step is below
// 4e-5, so each is made heavier by (4e-5 / dt_e)^2 and the run steps at TSSFAC |DT2MS|: the
// announced cycle count is the end time over that step (plyform check used to announce the
// unscaled 2.4e4 cycles), and the added mass is (f - 1) times the plate's mass.
TEST(CheckStep, MassScaledStepAndAddedMassShare) {
  for (const char* dt2ms : {"-4.0e-5", "4.0e-5"}) {
    SCOPED_TRACE(dt2ms);
    test::TempDir dir;
    const std::string timestep = std::string("*CONTROL_TIMESTEP\n0.0,0.9,0,0.0,") + dt2ms + "\n";
    const CheckRun r = check(dir.write("scaled.k", plate(2, 1, timestep)));
    ASSERT_EQ(r.status, 0) << r.err;
    const double dt = kTssfac * 4.0e-5;
    EXPECT_NEAR(number_after(r.out, "stable time step estimate: "), dt, 1e-9 * dt) << r.out;
    EXPECT_NEAR(number_after(r.out, "about "), kEndTime / dt, 1e-3) << r.out;  // 111.111
    const double c = std::sqrt(kE / (kRho * (1.0 - kNu * kNu)));
    const double f = std::pow(4.0e-5 * c, 2);  // the square's step is 1 / c
    const double mass = 4.0 * kRho * 1.0 * 1.0;
    EXPECT_NEAR(number_after(r.out, "made heavier, adding "), (f - 1.0) * mass,
                2e-5 * (f - 1.0) * mass)
        << r.out;
    const std::string scaling = r.out.substr(r.out.find("mass scaling (DT2MS"));
    EXPECT_NEAR(number_after(scaling.substr(scaling.find("adding ")), " ("), 100.0 * (f - 1.0),
                2e-3 * 100.0 * (f - 1.0))
        << r.out;  // per cent of the plate's mass, to the 3 digits printed
    EXPECT_NE(r.out.find("4 elements below the step 3.6e-05"), std::string::npos) << r.out;
  }
}

// The run takes as many cycles as check announced (within one: the last step reaches the end
// time).
TEST(CheckStep, AnnouncedCyclesAreTheRunsWithMassScaling) {
  test::TempDir dir;
  const auto deck =
      dir.write("scaled.k", plate(2, 1, "*CONTROL_TIMESTEP\n0.0,0.9,0,0.0,-4.0e-5\n"));
  const CheckRun r = check(deck);
  ASSERT_EQ(r.status, 0) << r.err;
  const double announced = number_after(r.out, "about ");
  std::string json;
  ASSERT_NO_FATAL_FAILURE(run_summary(deck, dir.path() / "out", json));
  EXPECT_NEAR(number_after(json, "\"cycles\":"), announced, 1.0) << json;
}

// LCTM: a curve that caps the step at a quarter of the stable one for the first half of the
// run and leaves it free after: check announces 4 x 1/2 + 1/2 = 2.5 times the uncapped cycles,
// and the run takes them.
TEST(CheckStep, AStepCurveCapsTheAnnouncedAndTheRunsCycles) {
  test::TempDir dir;
  const double c = std::sqrt(kE / (kRho * (1.0 - kNu * kNu)));
  const double dt = kTssfac * 1.0 / c;
  std::ostringstream timestep;
  timestep.precision(17);
  timestep << "*CONTROL_TIMESTEP\n0.0,0.9,0,0.0,0.0,5\n*DEFINE_CURVE\n5\n0.0," << 0.25 * dt << "\n"
           << 0.5 * kEndTime << "," << 0.25 * dt << "\n"
           << 0.5 * kEndTime * (1 + 1e-9) << ",1.0\n1.0,1.0\n";
  const auto deck = dir.write("capped.k", plate(2, 1, timestep.str()));
  const CheckRun r = check(deck);
  ASSERT_EQ(r.status, 0) << r.err;
  const double announced = number_after(r.out, "about ");
  EXPECT_NEAR(announced, 2.5 * kEndTime / dt, 1e-2 * kEndTime / dt) << r.out;
  EXPECT_NE(r.out.find("with the largest step of the curve LCTM"), std::string::npos) << r.out;
  std::string json;
  ASSERT_NO_FATAL_FAILURE(run_summary(deck, dir.path() / "out", json));
  EXPECT_NEAR(number_after(json, "\"cycles\":"), announced, 0.01 * announced) << json;
}

// *CONTROL_PARALLEL: check says how many threads a run takes without --threads, and that the
// consistency a negative NCPU asks LS-DYNA for is always there (no warning).
TEST(CheckParallel, SaysTheThreadsAndThatConsistencyIsMet) {
  test::TempDir dir;
  const CheckRun r = check(dir.write("ncpu.k", plate(2, 1, "*CONTROL_PARALLEL\n-3\n")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("threads (*CONTROL_PARALLEL NCPU -3): 3 for `plyform run` without "
                       "--threads; the consistency it asks for is always met"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

}  // namespace test_check_step
}  // namespace plyform::app
