// `plyform check --ranks N` prints the model's split over N ranks (domain/decomposition.hpp):
// a row per domain, the imbalance, the interface edges it cuts; and refuses, with the deck and the
// reason, a count the model cannot honour. (The split's guarantees are tested in
// tests/unit/domain against brute force.) `plyform run --rebalance` on one rank says it has
// nothing to do.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace {

// Two layers of 8 x 8 shells of 1 mm, 1 mm apart, the upper the slave of a one-way contact
// against the lower: 128 deformable elements.
std::string deck() {
  std::ostringstream d;
  d << "*KEYWORD\n*CONTROL_TERMINATION\n1.0e-3\n*NODE\n";
  for (int l = 0; l < 2; ++l)
    for (int j = 0; j <= 8; ++j)
      for (int i = 0; i <= 8; ++i)
        d << 1 + 100 * l + 9 * j + i << "," << i << "," << j << "," << l << "\n";
  d << "*ELEMENT_SHELL\n";
  for (int l = 0; l < 2; ++l)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        const int a = 1 + 100 * l + 9 * j + i;
        d << 1 + 100 * l + 8 * j + i << "," << l + 1 << "," << a << "," << a + 1 << "," << a + 10
          << "," << a + 9 << "\n";
      }
  d << "*PART\nlower\n1,1,1\n*PART\nupper\n2,1,1\n*SECTION_SHELL\n1,2,0.8333,5\n"
    << "1.0,1.0,1.0,1.0\n*MAT_ELASTIC\n1,7.85e-9,2.1e5,0.3\n"
    << "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE\n2,1,3,3\n0.0\n1.0,1.0\n*END\n";
  return d.str();
}

TEST(CheckRanks, PrintsEachDomainAndTheSplitsFigures) {
  test::TempDir dir;
  std::ostringstream out, err;
  ASSERT_EQ(run_check(dir.write("layers.k", deck()), out, err, 2), 0) << err.str();
  const std::string text = out.str();
  EXPECT_NE(text.find("decomposition: 2 domains (METIS k-way over 128 deformable elements"),
            std::string::npos)
      << text;
  for (const char* row : {"\n         0 ", "\n         1 ", "\n     least ", "\n      mean ",
                          "\n   largest ", "imbalance: ", "layers held together: "})
    EXPECT_NE(text.find(row), std::string::npos) << row << " missing in\n" << text;
  EXPECT_NE(text.find("\n      mean         64 "), std::string::npos) << text;
  EXPECT_NE(text.find("contact slave nodes: 81 over 1 interface\n"), std::string::npos) << text;
  EXPECT_NE(text.find("run it so: mpirun -np 2 plyform run DECK -o OUTDIR"), std::string::npos)
      << text;
  EXPECT_NE(text.find("nodes: every rank moves every node (the contact's search reads them all)"),
            std::string::npos)
      << text;
}

TEST(CheckRanks, SaysEachRankMovesItsOwnNodesWithoutContact) {
  test::TempDir dir;
  std::string plain = deck();
  plain.erase(plain.find("*CONTACT_ONE_WAY"), plain.find("*END") - plain.find("*CONTACT_ONE_WAY"));
  std::ostringstream out, err;
  ASSERT_EQ(run_check(dir.write("layers.k", plain), out, err, 2), 0) << err.str();
  EXPECT_NE(out.str().find("nodes: each rank moves its own and its neighbours' around them"),
            std::string::npos)
      << out.str();
}

TEST(RunRanks, RebalanceOnOneRankIsSaidToDoNothing) {
  for (const long every : {-1L, 50L, 0L}) {
    test::TempDir dir;
    RunOptions o;
    o.deck = dir.write("layers.k", deck());
    o.output = dir.path() / "out";
    o.progress = false;
    o.end_time = 1e-5;
    o.rebalance_every = every;  // off, every 50 cycles, auto (the default: no word)
    std::ostringstream out, err;
    ASSERT_EQ(run_deck(o, out, err), 0) << err.str();
    EXPECT_EQ(err.str().find("--rebalance has nothing to do on one rank") != std::string::npos,
              every != 0)
        << err.str();
  }
}

TEST(CheckRanks, WithoutRanksItPrintsNoSplit) {
  test::TempDir dir;
  std::ostringstream out, err;
  ASSERT_EQ(run_check(dir.write("layers.k", deck()), out, err), 0) << err.str();
  EXPECT_EQ(out.str().find("decomposition:"), std::string::npos);
}

TEST(CheckRanks, RefusesMoreDomainsThanElements) {
  test::TempDir dir;
  std::ostringstream out, err;
  const auto path = dir.write("layers.k", deck());
  EXPECT_EQ(run_check(path, out, err, 200), 1);
  EXPECT_NE(err.str().find("layers.k: --ranks 200: 200 domains for 128 deformable elements"),
            std::string::npos)
      << err.str();
}

}  // namespace
}  // namespace plyform::app
