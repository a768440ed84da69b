// Loads and initial conditions read from a deck, checked against conservation laws: a constant
// nodal force on a free body moves its centre of mass by F t^2 / (2 M) whatever the body's
// deformation; *INITIAL_VELOCITY_GENERATION gives v = v_t + omega n x (x - x_c) at t = 0, and
// the momentum of a free body stays constant.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace {

// A 4 x 2 x 2 mm steel bar of 4 x 2 x 2 hexahedra (nodes 1..45), with `extra` cards.
std::string deck(const std::string& extra) {
  std::ostringstream os;
  os << "*KEYWORD\n*CONTROL_TERMINATION\n   2.0E-05\n*DATABASE_BINARY_D3PLOT\n   1.0E-06\n";
  os << "*PART\nbar\n         1         1         1\n*SECTION_SOLID\n         1         1\n";
  os << "*MAT_ELASTIC\n         1   7.85E-9  210000.0       0.3\n*NODE\n";
  const auto id = [](int i, int j, int k) { return (k * 3 + j) * 5 + i + 1; };
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 4; ++i)
        os << id(i, j, k) << "," << i << "," << j << "," << k << "\n";
  os << "*ELEMENT_SOLID\n";
  int e = 1;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i) {
        os << e++ << ",1," << id(i, j, k) << "," << id(i + 1, j, k) << "," << id(i + 1, j + 1, k)
           << "," << id(i, j + 1, k) << "," << id(i, j, k + 1) << "," << id(i + 1, j, k + 1) << ","
           << id(i + 1, j + 1, k + 1) << "," << id(i, j + 1, k + 1) << "\n";
      }
  os << extra << "*END\n";
  return os.str();
}

core::Model build(const std::string& text) {
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("bar.k", text));
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().to_string());
  EXPECT_TRUE(setup::validate(read.model).empty());
  auto built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  return *built.model;
}

TEST(DeckLoads, ConstantNodalForceMovesTheCentreOfMassByFt2Over2M) {
  // 100 N in x on node 1 (a corner): the bar also spins and vibrates, its centre does not care.
  const core::Model m =
      build(deck("*LOAD_NODE_POINT\n         1         1         1     100.0\n"
                 "*DEFINE_CURVE\n         1\n               0.0               1.0\n"
                 "               1.0               1.0\n"));
  test::RecordingSink sink;
  double mass = 0.0;
  std::vector<std::pair<double, double>> centre;  // (t, x_cm displacement)
  sink.on_state = [&](const engine::Snapshot& s) {
    double mx = 0.0, mm = 0.0;
    for (std::size_t i = 0; i < s.nodes->size(); ++i) {
      mx += s.nodes->mass[i] * s.nodes->ux[i];
      mm += s.nodes->mass[i];
    }
    mass = mm;
    centre.emplace_back(s.time, mx / mm);
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NEAR(mass, 7.85e-9 * 16.0, 1e-12 * mass);
  ASSERT_GT(centre.size(), 10u);
  for (const auto& [t, x] : centre) {
    if (t == 0.0)
      continue;
    const double expected = 100.0 * t * t / (2.0 * mass);
    EXPECT_NEAR(x, expected, 1e-6 * expected) << "t = " << t;
  }
}

TEST(DeckLoads, InitialVelocityGenerationAndMomentum) {
  // Spin about the bar's axis through (2, 1, 1) plus a translation, on part 1.
  const core::Model m = build(deck(
      "*INITIAL_VELOCITY_GENERATION\n         1         2     500.0      10.0      20.0     -30.0\n"
      "       2.0       1.0       1.0       1.0       0.0       0.0\n"));
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const double ry = m.y0[i] - 1.0, rz = m.z0[i] - 1.0;
    EXPECT_DOUBLE_EQ(m.v0x[i], 10.0);
    EXPECT_NEAR(m.v0y[i], 20.0 - 500.0 * rz, 1e-12);
    EXPECT_NEAR(m.v0z[i], -30.0 + 500.0 * ry, 1e-12);
  }
  test::RecordingSink sink;
  std::vector<std::array<double, 3>> momentum;
  sink.on_state = [&](const engine::Snapshot& s) {
    std::array<double, 3> p{0, 0, 0};
    for (std::size_t i = 0; i < s.nodes->size(); ++i) {
      p[0] += s.nodes->mass[i] * s.nodes->vnx[i];
      p[1] += s.nodes->mass[i] * s.nodes->vny[i];
      p[2] += s.nodes->mass[i] * s.nodes->vnz[i];
    }
    momentum.push_back(p);
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  const double mass = 7.85e-9 * 16.0;
  for (const auto& p : momentum) {
    EXPECT_NEAR(p[0], 10.0 * mass, 1e-9 * mass);
    EXPECT_NEAR(p[1], 20.0 * mass, 1e-9 * mass);
    EXPECT_NEAR(p[2], -30.0 * mass, 1e-9 * mass);
  }
}

// A shell plate (part 1, listed first) beside the bar, the bar then part 2: STYP 2 on either
// part moves that part's nodes only. The bar's momentum is then its own mass times v, the
// plate's stays zero (and the other way round).
std::string plate_and_bar(int moving_part) {
  std::string bar = deck("");
  bar = bar.substr(0, bar.rfind("*END"));
  // The bar's part becomes 2 (its *PART card and its elements' PID).
  std::string out;
  std::istringstream in(bar);
  std::string line, section;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '*')
      section = line;
    if (section == "*PART" && line == "         1         1         1")
      line = "         2         1         1";
    if (section == "*ELEMENT_SOLID" && line[0] != '*')
      line.replace(line.find(','), 3, ",2,");
    out += line + "\n";
  }
  std::ostringstream os;
  os << out << "*PART\nplate\n         1         2         1\n";
  os << "*SECTION_SHELL\n         2         2    0.8333         2\n       0.5       0.5       0.5"
        "       0.5\n";
  os << "*NODE\n101,0,0,5\n102,4,0,5\n103,4,2,5\n104,0,2,5\n";
  os << "*ELEMENT_SHELL\n1,1,101,102,103,104\n";
  os << "*INITIAL_VELOCITY_GENERATION\n         " << moving_part
     << "         2       0.0       0.0       0.0       7.0\n       0.0       0.0       0.0"
        "       0.0       0.0       1.0\n";
  os << "*END\n";
  return os.str();
}

TEST(DeckLoads, InitialVelocityGenerationOnAPartAfterAShellPart) {
  for (int part : {1, 2}) {
    const core::Model m = build(plate_and_bar(part));
    for (std::size_t i = 0; i < m.node_count(); ++i) {
      const bool plate = m.node_id[i] > 100;
      const double expected = (plate == (part == 1)) ? 7.0 : 0.0;
      EXPECT_EQ(m.v0z[i], expected) << "part " << part << ", node " << m.node_id[i];
      EXPECT_EQ(m.v0x[i], 0.0);
      EXPECT_EQ(m.v0y[i], 0.0);
    }
  }
}

}  // namespace
}  // namespace plyform
