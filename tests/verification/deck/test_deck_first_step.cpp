// The books of a velocity that jumps at t = 0, against the change of kinetic energy it makes:
// a block whose every node is driven at V from t = 0, a rigid body driven at V from t = 0 (both
// take 1/2 M V^2 of external work; the first half step once booked M V^2 for the nodes and
// nothing for the body), and a block given an initial velocity V whose every node is held by
// *BOUNDARY_SPC (the constraint takes -1/2 M V^2; it booked nothing). Nothing deforms, so the
// external work must equal the kinetic energy change to round-off at every glstat row.
// And at the end: a block and a rigid body driven by displacement curves that stop at the end
// time keep, in the final row, the velocity of the last step (the step beyond the end, which
// is never taken, once read the curve past its end and stopped them there: their kinetic
// energy vanished from the last row of the books).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace {

constexpr double kRho = 7.85e-9, kV = 100.0;

/// A unit cube of one hexahedron, part 1 (nodes 1-8), and optionally a rigid one, part 2
/// (nodes 11-18, 4 above it).
std::string cubes(const std::string& extra, bool rigid) {
  std::ostringstream os;
  os << "*KEYWORD\n*CONTROL_TERMINATION\n1e-5\n*DATABASE_GLSTAT\n1e-6\n"
     << "*PART\ncube\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1," << kRho << ",210000,0.3\n";
  if (rigid)
    os << "*PART\ntool\n2,2,2\n*SECTION_SOLID\n2,1\n*MAT_RIGID\n2," << kRho
       << ",210000,0.3\n0,0,0\n";
  os << "*NODE\n";
  for (int body = 0; body < (rigid ? 2 : 1); ++body) {
    for (int k = 0; k <= 1; ++k)
      for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i)
          os << 10 * body + 1 + i + 2 * j + 4 * k << "," << i << "," << j << "," << k + 5 * body
             << "\n";
  }
  os << "*ELEMENT_SOLID\n1,1,1,2,4,3,5,6,8,7\n";
  if (rigid)
    os << "2,2,11,12,14,13,15,16,18,17\n";
  os << "*DEFINE_CURVE\n1\n0,1\n1,1\n" << extra << "*END\n";
  return os.str();
}

struct Row {
  double time, kinetic, external_work, total, ratio;
};

std::vector<Row> glstat_of(const std::string& deck, std::string* summary = nullptr,
                           int exit_code = 0) {
  test::TempDir dir;
  app::RunOptions o;
  o.deck = dir.write("deck.k", deck);
  o.output = dir.path() / "out";
  o.progress = false;
  std::ostringstream out, err;
  EXPECT_EQ(app::run_deck(o, out, err), exit_code) << err.str();
  if (summary != nullptr) {
    std::ifstream json(*o.output / "summary.json");
    *summary = {std::istreambuf_iterator<char>(json), std::istreambuf_iterator<char>()};
  }
  std::ifstream in(*o.output / "glstat.csv");
  std::string line;
  std::getline(in, line);  // time,dt,kinetic,internal,hourglass,contact,external_work,total,ratio
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ','))
      v.push_back(std::stod(cell));
    rows.push_back({v[0], v[2], v[6], v[7], v[8]});
  }
  return rows;
}

std::string driven_nodes() {
  std::ostringstream os;
  os << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int n = 1; n <= 8; ++n)
    os << n << ",1,0,1," << kV << "\n";
  return os.str();
}

TEST(FirstStepBooks, NodesDrivenFromRestTakeHalfMVSquared) {
  const double half_mv2 = 0.5 * kRho * kV * kV;
  const auto rows = glstat_of(cubes(driven_nodes(), false));
  ASSERT_GT(rows.size(), 5u);
  for (const Row& r : rows) {
    if (r.time == 0.0)
      continue;
    EXPECT_NEAR(r.kinetic, half_mv2, 1e-12 * half_mv2) << r.time;
    EXPECT_NEAR(r.external_work, half_mv2, 1e-12 * half_mv2) << r.time;
    EXPECT_NEAR(r.ratio, 1.0, 1e-12) << r.time;
  }
}

TEST(FirstStepBooks, RigidBodyDrivenFromRestTakesHalfMVSquared) {
  const double half_mv2 = 0.5 * kRho * kV * kV;
  const auto rows = glstat_of(cubes(
      driven_nodes() + "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n2,1,0,1," + std::to_string(kV) + "\n",
      true));
  ASSERT_GT(rows.size(), 5u);
  for (const Row& r : rows) {
    if (r.time == 0.0)
      continue;
    EXPECT_NEAR(r.kinetic, 2.0 * half_mv2, 1e-12 * half_mv2) << r.time;
    EXPECT_NEAR(r.external_work, 2.0 * half_mv2, 1e-12 * half_mv2) << r.time;
  }
}

TEST(FirstStepBooks, MovingNodesHeldAtTheStartGiveTheirKineticEnergyToTheConstraint) {
  std::ostringstream extra;
  extra << "*INITIAL_VELOCITY_NODE\n";
  for (int n = 1; n <= 8; ++n)
    extra << n << "," << kV << ",0,0\n";
  extra << "*BOUNDARY_SPC_NODE\n";
  for (int n = 1; n <= 8; ++n)
    extra << n << ",0,1,0,0\n";
  const double half_mv2 = 0.5 * kRho * kV * kV;
  const auto rows = glstat_of(cubes(extra.str(), false));
  ASSERT_GT(rows.size(), 5u);
  EXPECT_NEAR(rows.front().kinetic, half_mv2, 1e-12 * half_mv2);
  for (const Row& r : rows) {
    if (r.time == 0.0)
      continue;
    EXPECT_NEAR(r.kinetic, 0.0, 1e-12 * half_mv2) << r.time;
    EXPECT_NEAR(r.external_work, -half_mv2, 1e-12 * half_mv2) << r.time;
    EXPECT_NEAR(r.ratio, 1.0, 1e-9) << r.time;
  }
}

TEST(BooksWarnings, HourglassEnergyAboveTheInternalIsNamed) {
  // One ELFORM 1 hexahedron whose bottom front edge is stopped at t = 0 while the rest moves
  // on: its hourglass modes take far more than its internal energy (a real case for the
  // warning, which must not be lost under the floor that keeps round-off energies quiet). The
  // run completes with its results not to be trusted (exit 5, docs/energy.md).
  std::ostringstream extra;
  extra << "*INITIAL_VELOCITY_NODE\n";
  for (int n = 1; n <= 8; ++n)
    extra << n << "," << kV << ",0,0\n";
  extra << "*BOUNDARY_SPC_NODE\n1,0,1,0,0\n2,0,1,0,0\n";
  std::string summary;
  const auto rows = glstat_of(cubes(extra.str(), false), &summary, 5);
  ASSERT_FALSE(rows.empty());
  EXPECT_NE(summary.find("hourglass energy"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"status\": \"completed, results not to be trusted\""), std::string::npos)
      << summary;
}

TEST(LastStepBooks, DisplacementsThatStopAtTheEndTimeKeepTheirLastVelocity) {
  // Curve 2: the displacement D in time T, then held. Nodes 1-8 and the rigid body along x.
  const double t_end = 1e-5, d = 1e-3, v = d / t_end;
  std::ostringstream extra;
  extra << "*DEFINE_CURVE\n2\n0,0\n"
        << t_end << "," << d << "\n"
        << 2 * t_end << "," << d << "\n*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int n = 1; n <= 8; ++n)
    extra << n << ",1,2,2,1.0\n";
  extra << "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n2,1,2,2,1.0\n";
  const auto rows = glstat_of(cubes(extra.str(), true));
  ASSERT_GT(rows.size(), 5u);
  const double both = 2.0 * 0.5 * kRho * v * v;  // the block and the body, at speed v
  const Row& last = rows.back();
  EXPECT_NEAR(last.time, t_end, 1e-9 * t_end);
  EXPECT_NEAR(last.kinetic, both, 1e-9 * both);
  EXPECT_NEAR(last.ratio, 1.0, 1e-9);
}

}  // namespace
}  // namespace plyform
