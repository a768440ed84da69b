// `plyform law` end to end: deck -> law -> CSV, checked against the closed forms of a
// quasi-static opening (peak sigma_max at g_c, work omega) and for its input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace {

// sigma_max 0.3 MPa, C_N 30 MPa/mm: g_c = 0.01 mm, omega = 0.003 N/mm. Eta tiny: quasi-static.
constexpr const char* kDeck = R"(*KEYWORD
*USER_INTERFACE_FRICTION
         1        11         0
         1      30.0       0.3       0.3     300.0     500.0   1.0E-12       0.0
       0.0       1.0    1.0E-6
*END
)";

std::string opening_path(int n, double g_end) {
  std::ostringstream os;
  os << "time,gap,slip_x,slip_y,temperature\n";
  os.precision(17);
  for (int i = 0; i <= n; ++i)
    os << i * 1e-3 << "," << g_end * i / n << ",0,0,300\n";
  return os.str();
}

struct Row {
  double gap, pressure, beta;
  std::string state;
};

std::vector<Row> parse(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time,gap,slip_x,slip_y,temperature,pressure,tau_x,tau_y,beta,state,dissipated");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ','))
      f.push_back(cell);
    EXPECT_EQ(f.size(), 11u);
    rows.push_back({std::stod(f[1]), std::stod(f[5]), std::stod(f[8]), f[9]});
  }
  return rows;
}

TEST(LawCommand, QuasiStaticOpeningMatchesTheClosedForms) {
  test::TempDir dir;
  LawOptions o;
  o.deck = dir.write("law.k", kDeck);
  o.path_csv = dir.write("path.csv", opening_path(8000, 0.4));  // to 40 g_c, 200 steps per g_c
  o.output = dir.path() / "out.csv";
  std::ostringstream out, err;
  ASSERT_EQ(run_law(o, out, err), 0) << err.str();
  std::ifstream file(*o.output);
  const auto rows = parse(std::string(std::istreambuf_iterator<char>(file), {}));
  ASSERT_EQ(rows.size(), 8001u);
  double peak = 0, g_peak = 0, work = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (-rows[i].pressure > peak) {
      peak = -rows[i].pressure;
      g_peak = rows[i].gap;
    }
    if (i > 0) {
      work += -0.5 * (rows[i].pressure + rows[i - 1].pressure) * (rows[i].gap - rows[i - 1].gap);
    }
  }
  EXPECT_NEAR(peak, 0.3, 0.005 * 0.3);
  EXPECT_NEAR(g_peak, 0.01, 0.01 * 0.01);
  EXPECT_NEAR(work, 0.003, 0.01 * 0.003);
  EXPECT_EQ(rows.front().state, "CONTACT");  // bonded at g = 0
  EXPECT_EQ(rows[100].state, "SEPARATING");
  EXPECT_EQ(rows.back().state, "DETACHED");
  EXPECT_EQ(rows.back().beta, 0.0);
}

TEST(LawCommand, PenaltyOptionSetsTheContactStiffness) {
  test::TempDir dir;
  LawOptions o;
  o.deck = dir.write("law.k", kDeck);
  o.path_csv =
      dir.write("path.csv", "time,gap,slip_x,slip_y,temperature\n0,0,0,0,300\n1,-0.01,0,0,300\n");
  o.penalty = 500.0;
  std::ostringstream out, err;
  ASSERT_EQ(run_law(o, out, err), 0) << err.str();
  const auto rows = parse(out.str());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_DOUBLE_EQ(rows[1].pressure, 5.0);
  EXPECT_EQ(rows[1].state, "CONTACT");
}

struct BadPath {
  const char* text;
  const char* message;
};

class LawPathErrors : public ::testing::TestWithParam<BadPath> {};

TEST_P(LawPathErrors, NameTheFileLineAndColumn) {
  test::TempDir dir;
  LawOptions o;
  o.deck = dir.write("law.k", kDeck);
  o.path_csv = dir.write("path.csv", GetParam().text);
  std::ostringstream out, err;
  EXPECT_EQ(run_law(o, out, err), 1);
  EXPECT_NE(err.str().find(GetParam().message), std::string::npos) << err.str();
}

INSTANTIATE_TEST_SUITE_P(
    EveryClass, LawPathErrors,
    ::testing::Values(BadPath{"time,gap,slip_x,temperature\n0,0,0,300\n1,0,0,300\n",
                              "path.csv:1: missing column 'slip_y'"},
                      BadPath{"time,gap,slip_x,slip_y,temp\n", "path.csv:1: unknown column 'temp'"},
                      BadPath{"time,gap,slip_x,slip_y,temperature\n0,0,0,0,300\n1,abc,0,0,300\n",
                              "path.csv:3: column gap: expected a finite number, got 'abc'"},
                      BadPath{"time,gap,slip_x,slip_y,temperature\n0,0,0,0,300\n0,0,0,0,300\n",
                              "path.csv:3: column time: must increase"},
                      BadPath{"time,gap,slip_x,slip_y,temperature\n0,0,0,0,300\n1,0,0,300\n",
                              "path.csv:3: expected 5 values, found 4"},
                      BadPath{"time,gap,slip_x,slip_y,temperature\n0,0,0,0,300\n",
                              "the path needs at least two rows"}));

TEST(LawCommand, DeckWithoutALawOrWithSeveral) {
  test::TempDir dir;
  LawOptions o;
  o.path_csv = dir.write("path.csv", opening_path(2, 0.01));
  std::ostringstream out, err;
  o.deck = dir.write("none.k", "*KEYWORD\n*END\n");
  EXPECT_EQ(run_law(o, out, err), 1);
  EXPECT_NE(err.str().find("no *USER_INTERFACE_FRICTION"), std::string::npos);

  std::string two = kDeck;
  const std::string uif = two.substr(two.find("*USER"), two.find("*END") - two.find("*USER"));
  std::string second = uif;
  second.replace(second.find("         1        11"), 20, "         2        11");
  two.insert(two.find("*END"), second);
  o.deck = dir.write("two.k", two);
  std::ostringstream err2;
  EXPECT_EQ(run_law(o, out, err2), 1);
  EXPECT_NE(err2.str().find("--interface NOSID"), std::string::npos);
  o.interface_id = 2;
  std::ostringstream out3, err3;
  EXPECT_EQ(run_law(o, out3, err3), 0) << err3.str();
  o.interface_id = 5;
  EXPECT_EQ(run_law(o, out3, err3), 1);
}

}  // namespace
}  // namespace plyform::app
