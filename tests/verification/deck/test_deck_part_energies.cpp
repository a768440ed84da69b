// *DATABASE_MATSUM: each part's books against closed forms. Two elastic shell parts that share
// a row of nodes and a rigid shell part fly free at uniform velocities: each deformable part's
// kinetic energy and momentum are those of its own mass, rho t A (1/2 v^2 and v), the rigid
// part's those of its body, and the parts' kinetic energies add up to glstat's.
#include <gtest/gtest.h>

#include <sstream>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace {

constexpr double kRho = 7.85e-9, kT = 0.5, kRigidRho = 2.0e-9, kRigidT = 2.0;

// Plate A: 3 x 1 elements of 1 mm at z = 0, elements 1-2 part 1, element 3 part 2 (they share
// the nodes at x = 2). Plate B: one rigid 2 x 2 mm element at z = 5, part 3.
std::string deck() {
  std::ostringstream os;
  os << "*KEYWORD\n*CONTROL_TERMINATION\n1.0e-5\n*DATABASE_GLSTAT\n2.0e-6\n"
     << "*DATABASE_MATSUM\n2.0e-6\n"
     << "*PART\nleft\n1,1,1\n*PART\nright\n2,1,1\n*PART\ntool\n3,2,2\n"
     << "*SECTION_SHELL\n1,2,0.8333,3\n"
     << kT << "," << kT << "," << kT << "," << kT << "\n"
     << "*SECTION_SHELL\n2,2,0.8333,2\n"
     << kRigidT << "," << kRigidT << "," << kRigidT << "," << kRigidT << "\n"
     << "*MAT_ELASTIC\n1," << kRho << ",210000.0,0.3\n"
     << "*MAT_RIGID\n2," << kRigidRho << ",210000.0,0.3\n0.0,0,0\n"
     << "*NODE\n";
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 3; ++i)
      os << 1 + i + 4 * j << "," << i << "," << j << ",0\n";
  os << "101,0,0,5\n102,2,0,5\n103,2,2,5\n104,0,2,5\n"
     << "*ELEMENT_SHELL\n1,1,1,2,6,5\n2,1,2,3,7,6\n3,2,3,4,8,7\n4,3,101,102,103,104\n"
     << "*INITIAL_VELOCITY_GENERATION\n1,2,0.0,100.0,-40.0,20.0\n"
     << "*INITIAL_VELOCITY_GENERATION\n2,2,0.0,100.0,-40.0,20.0\n"
     << "*INITIAL_VELOCITY_GENERATION\n3,2,0.0,0.0,30.0,-50.0\n*END\n";
  return os.str();
}

struct PartRecorder : test::RecordingSink {
  std::vector<std::pair<double, std::vector<engine::PartEnergies>>> parts;
  void part_energies(double time, const std::vector<engine::PartEnergies>& p) override {
    parts.emplace_back(time, p);
  }
};

TEST(DeckPartEnergies, FreeFlyingPartsCarryTheirOwnKineticEnergyAndMomentum) {
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("parts.k", deck()));
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  ASSERT_TRUE(setup::validate(read.model).empty());
  auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  PartRecorder sink;
  const engine::RunResult r = engine::run(*built.model, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(sink.parts.size(), sink.energies.size());
  const double v2 = 100.0 * 100.0 + 40.0 * 40.0 + 20.0 * 20.0;
  const double m1 = kRho * kT * 2.0, m2 = kRho * kT * 1.0, m3 = kRigidRho * kRigidT * 4.0;
  for (std::size_t k = 0; k < sink.parts.size(); ++k) {
    const auto& [time, parts] = sink.parts[k];
    ASSERT_EQ(parts.size(), 3u);
    EXPECT_EQ(parts[0].part, 1);
    EXPECT_EQ(parts[2].part, 3);
    EXPECT_FALSE(parts[0].rigid);
    EXPECT_TRUE(parts[2].rigid);
    EXPECT_NEAR(parts[0].kinetic, 0.5 * m1 * v2, 1e-12 * m1 * v2) << "t = " << time;
    EXPECT_NEAR(parts[1].kinetic, 0.5 * m2 * v2, 1e-12 * m2 * v2) << "t = " << time;
    EXPECT_NEAR(parts[2].kinetic, 0.5 * m3 * (30.0 * 30.0 + 50.0 * 50.0), 1e-9 * m3 * 3400.0);
    EXPECT_NEAR(parts[0].momentum[0], m1 * 100.0, 1e-12 * m1 * 100.0);
    EXPECT_NEAR(parts[1].momentum[1], -m2 * 40.0, 1e-12 * m2 * 40.0);
    EXPECT_NEAR(parts[2].momentum[2], -m3 * 50.0, 1e-9 * m3 * 50.0);
    // The parts' books are glstat's, split.
    const engine::Energies& g = sink.energies[k];
    double kinetic = 0.0, internal = 0.0;
    for (const engine::PartEnergies& p : parts) {
      kinetic += p.kinetic;
      internal += p.internal;
    }
    EXPECT_NEAR(kinetic, g.kinetic, 1e-12 * g.kinetic);
    EXPECT_NEAR(internal, g.internal, 1e-12 * g.kinetic);
  }
}

}  // namespace
}  // namespace plyform

namespace plyform {
namespace {

// *INITIAL_VELOCITY_NODE replaces a generated velocity node by node; angular velocities reach
// the nodes of shells, and one on a node without rotations is an error naming it.
TEST(DeckInitialVelocityNode, ReplacesTheGeneratedVelocityAndGivesShellNodesTheirSpin) {
  test::TempDir dir;
  std::string text = deck();
  const std::string node_cards =
      "*INITIAL_VELOCITY_NODE\n2,1.0,2.0,3.0\n6,0,0,0,0.5,0.0,-0.5\n*END\n";
  text.replace(text.find("*END\n"), 5, node_cards);
  const auto read = keyword::read_deck(dir.write("nodes.k", text));
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  const core::Model& m = *built.model;
  const auto at = [&](core::GlobalId id) {
    for (std::size_t i = 0; i < m.node_count(); ++i)
      if (m.node_id[i] == id)
        return i;
    return m.node_count();
  };
  EXPECT_DOUBLE_EQ(m.v0x[at(2)], 1.0);
  EXPECT_DOUBLE_EQ(m.v0z[at(2)], 3.0);
  EXPECT_DOUBLE_EQ(m.v0x[at(3)], 100.0);  // generated, untouched
  EXPECT_DOUBLE_EQ(m.v0x[at(6)], 0.0);
  ASSERT_FALSE(m.w0x.empty());
  EXPECT_DOUBLE_EQ(m.w0x[at(6)], 0.5);
  EXPECT_DOUBLE_EQ(m.w0z[at(6)], -0.5);
  EXPECT_DOUBLE_EQ(m.w0x[at(2)], 0.0);
}

}  // namespace
}  // namespace plyform

namespace plyform {
namespace {

// *DATABASE_HISTORY_NODE_SET: every node of the sets becomes a history node (nodout.csv); an
// undefined set is an error with its line.
TEST(DeckHistoryNodeSet, TheSetsNodesAreHistoryNodes) {
  test::TempDir dir;
  std::string text = deck();
  text.replace(text.find("*END\n"), 5,
               "*SET_NODE_LIST\n9\n5,6,7\n*DATABASE_HISTORY_NODE_SET\n9\n"
               "*DATABASE_HISTORY_NODE\n101\n*END\n");
  const auto read = keyword::read_deck(dir.write("history.k", text));
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  ASSERT_TRUE(setup::validate(read.model).empty());
  auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  std::vector<core::GlobalId> ids;
  for (core::Index i : built.model->output.history_nodes)
    ids.push_back(built.model->node_id[static_cast<std::size_t>(i)]);
  EXPECT_EQ(ids, (std::vector<core::GlobalId>{5, 6, 7, 101}));
  std::string bad = deck();
  bad.replace(bad.find("*END\n"), 5, "*DATABASE_HISTORY_NODE_SET\n8\n*END\n");
  const auto read_bad = keyword::read_deck(dir.write("bad.k", bad));
  ASSERT_TRUE(read_bad.ok());
  const auto errors = setup::validate(read_bad.model);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].keyword, "*DATABASE_HISTORY_NODE_SET");
}

}  // namespace
}  // namespace plyform
