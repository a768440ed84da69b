// What `plyform run` says of a run whose books break (docs/energy.md): the clamped plate of
// tests/verification/engine/test_energy_books.cpp written as a deck. On one-point shells with
// the default viscous hourglass control it reaches its end with hourglass energy above 10 % of
// its largest internal energy: "completed, results not to be trusted", the reason and the time
// in summary.json, exit 5. With a step above the stability limit (TSSFAC 1.05) it stops with
// the diagnosis once its energy ratio leaves the band: exit 3. With stiffness hourglass
// control its books hold: normal termination, exit 0.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace {

// A 40 x 40 mm steel plate, 1 mm thick, 8 x 8 shells (NIP 3), every edge node clamped, the
// rest given 1 mm/ms out of plane; 1 ms; glstat every 10 us.
std::string plate_deck(const std::string& timestep, const std::string& hourglass) {
  std::ostringstream d;
  d << "*KEYWORD\n*CONTROL_TERMINATION\n1.0e-3\n";
  d << "*CONTROL_TIMESTEP\n" << timestep << "\n";
  d << "*DATABASE_GLSTAT\n1.0e-5\n";
  d << "*PART\nplate\n1,1,1,0," << hourglass << "\n";
  if (!hourglass.empty())
    d << "*HOURGLASS\n1,4,0.1\n";
  d << "*SECTION_SHELL\n1,2,0.8333,3\n1.0,1.0,1.0,1.0\n";
  d << "*MAT_ELASTIC\n1,7.85e-9,2.1e5,0.3\n*NODE\n";
  const int n = 8;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      d << j * (n + 1) + i + 1 << "," << 5.0 * i << "," << 5.0 * j << ",0\n";
  d << "*ELEMENT_SHELL\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i + 1;
      d << j * n + i + 1 << ",1," << a << "," << a + 1 << "," << a + n + 2 << "," << a + n + 1
        << "\n";
    }
  d << "*SET_NODE_LIST\n1\n";
  int column = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (i == 0 || j == 0 || i == n || j == n) {
        d << j * (n + 1) + i + 1 << ((++column % 8 == 0) ? "\n" : ",");
      }
  d << "\n*BOUNDARY_SPC_SET\n1,0,1,1,1,1,1,1\n";
  d << "*INITIAL_VELOCITY_GENERATION\n1,2,0,0,0,1000\n*END\n";
  return d.str();
}

struct Ran {
  int code = 0;
  std::string json, out, err;
};

Ran run(const std::string& deck) {
  test::TempDir dir;
  RunOptions o;
  o.deck = dir.write("plate.k", deck);
  o.output = dir.path() / "out";
  o.progress = false;
  std::ostringstream out, err;
  Ran r;
  r.code = run_deck(o, out, err);
  std::ifstream in(*o.output / "summary.json");
  r.json.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  r.out = out.str();
  r.err = err.str();
  return r;
}

TEST(RunBooks, HourglassAboveTenPercentIsCompletedNotToBeTrusted) {
  const Ran r = run(plate_deck("0,0.9", ""));
  EXPECT_EQ(r.code, 5) << r.out << r.err;
  EXPECT_NE(r.json.find("\"status\": \"completed, results not to be trusted\""), std::string::npos)
      << r.json;
  EXPECT_NE(r.json.find("\"distrust\": [\n    {\"reason\": \"hourglass energy"), std::string::npos)
      << r.json;
  EXPECT_NE(r.out.find("completed, results not to be trusted:"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("  from t = "), std::string::npos) << r.err;
}

TEST(RunBooks, StiffnessHourglassControlEndsNormally) {
  const Ran r = run(plate_deck("0,0.9", "1"));
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.json.find("\"status\": \"normal termination\""), std::string::npos) << r.json;
  EXPECT_NE(r.json.find("\"distrust\": []"), std::string::npos) << r.json;
}

TEST(RunBooks, AnUnstableStepStopsAtTheEnergyBand) {
  const Ran r = run(plate_deck("0,1.05", "1"));
  EXPECT_EQ(r.code, 3) << r.out << r.err;
  EXPECT_NE(r.json.find("\"status\": \"error: the energy ratio"), std::string::npos) << r.json;
  EXPECT_NE(r.err.find("left the band 1 +- 0.5 at t = "), std::string::npos) << r.err;
}

TEST(RunBooks, EndengNarrowsTheBand) {
  std::string deck = plate_deck("0,1.05", "1");
  deck.replace(deck.find("1.0e-3\n"), 7, "1.0e-3,0,0,5.0\n");  // ENDENG 5 %
  const Ran r = run(deck);
  EXPECT_EQ(r.code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("left the band 1 +- 0.05 (*CONTROL_TERMINATION ENDENG)"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace plyform::app
