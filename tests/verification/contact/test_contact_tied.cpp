// Tied contacts (*CONTACT_TIED_NODES_TO_SURFACE, *CONTACT_TIED_SHELL_EDGE_TO_SURFACE and their
// _OFFSET forms) against the uncut structure: a shell cantilever (steel, 100 x 10 x 2 mm,
// ELFORM 16) cut at mid-length into two meshes and tied along the cut
// - with the shell edge tied (rotations too), on a matching mesh, on a finer mesh across the
//   cut (3 shells against 2) and on a mesh offset by half the thickness, deflects as the uncut
//   cantilever under the same tip load within 1 % of its peak at every output (measured: to
//   round-off, 2e-4 and 1e-3): the tie carries the moment; the books close within 1e-5;
// - with the nodes tied alone (translations), the cut is a hinge: the tip falls 16 times
//   further.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "contact_decks.hpp"

namespace plyform::test {
namespace {

constexpr double kE = 210000.0, kRho = 7.85e-9, kLength = 100.0, kWidth = 10.0, kT = 2.0;

enum class Cut { none, edge, edge_finer, edge_offset, nodes_only };

// The tip deflection (mean uz of the tip nodes) at each state time, for a tip load P ramped
// smoothly over t_ramp (a half cosine) and held.
std::vector<double> cantilever(Cut cut, double& ratio_error) {
  const double p = 10.0, t_ramp = 6e-3, t_end = 9e-3;
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(t_end);
  w.kw("*DATABASE_GLSTAT").card(t_end / 30);
  w.kw("*DATABASE_BINARY_D3PLOT").card(t_end / 30);
  w.kw("*PART").card("left").card(1, 1, 1);
  w.kw("*PART").card("right").card(2, 1, 1);
  w.kw("*SECTION_SHELL").card(1, 16, 0.8333, 3).card(kT, kT, kT, kT);
  w.kw("*MAT_ELASTIC").card(1, kRho, kE, 0.3);
  std::vector<int> tip;
  if (cut == Cut::none) {
    const std::vector<int> nodes = w.plate(1, 1, 1, 0.0, kLength, 0.0, kWidth, 20, 2, 0.0);
    for (int j = 0; j <= 2; ++j)
      tip.push_back(nodes[static_cast<std::size_t>(j * 21 + 20)]);
  } else {
    w.plate(1, 1, 1, 0.0, 0.5 * kLength, 0.0, kWidth, 10, 2, 0.0);
    const int ny = cut == Cut::edge_finer ? 3 : 2;
    const double z = cut == Cut::edge_offset ? 0.5 * kT : 0.0;
    const std::vector<int> right =
        w.plate(2, 1001, 1001, 0.5 * kLength, kLength, 0.0, kWidth, 10, ny, z);
    std::vector<int> edge;
    for (int j = 0; j <= ny; ++j) {
      edge.push_back(right[static_cast<std::size_t>(j * 11)]);
      tip.push_back(right[static_cast<std::size_t>(j * 11 + 10)]);
    }
    w.kw("*SET_NODE_LIST").card(1).ids(edge);
    w.kw("*SET_PART_LIST").card(2).card(1);
    const std::string keyword = cut == Cut::nodes_only ? "*CONTACT_TIED_NODES_TO_SURFACE"
                                : cut == Cut::edge_offset
                                    ? "*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_OFFSET"
                                    : "*CONTACT_TIED_SHELL_EDGE_TO_SURFACE";
    w.kw(keyword).card(1, 1, 4, 3);
  }
  // Clamped at x = 0: the first node of each row of the left (or uncut) plate.
  const int row = cut == Cut::none ? 21 : 11;
  w.kw("*SET_NODE_LIST").card(3).ids({1, 1 + row, 1 + 2 * row});
  w.kw("*BOUNDARY_SPC_SET").card(3, 0, 1, 1, 1, 1, 1, 1);
  w.kw("*SET_NODE_LIST").card(4).ids(tip);
  w.kw("*DEFINE_CURVE").card(1);
  for (int k = 0; k <= 40; ++k) {
    const double t = t_ramp * k / 40;
    w.card(t, 0.5 * (1.0 - std::cos(std::numbers::pi * t / t_ramp)));
  }
  w.card(10.0, 1.0);
  w.kw("*LOAD_NODE_SET").card(4, 3, 1, -p / static_cast<double>(tip.size()));
  std::vector<double> deflection;
  DeckRun run;
  run.sink.on_state = [&](const engine::Snapshot& s) {
    double uz = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < s.model->node_count(); ++i)
      for (int id : tip)
        if (s.model->node_id[i] == id) {
          uz += s.nodes->uz[i];
          ++count;
        }
    deflection.push_back(-uz / count);
  };
  run_deck(w.text(), run);
  ratio_error = 0.0;
  for (const engine::Energies& e : run.sink.energies)
    ratio_error = std::max(ratio_error, std::abs(e.ratio - 1.0));
  return deflection;
}

TEST(TiedContacts, AShellEdgeTieCarriesTheMomentAsTheUncutCantilever) {
  double books = 0.0;
  const std::vector<double> uncut = cantilever(Cut::none, books);
  // Beam theory, for scale: P L^3 / (3 E I) = 2.38 mm statically (the run is dynamic).
  const double peak = *std::max_element(uncut.begin(), uncut.end());
  ASSERT_GT(peak, 1.0);
  for (const Cut cut : {Cut::edge, Cut::edge_finer, Cut::edge_offset}) {
    SCOPED_TRACE(static_cast<int>(cut));
    const std::vector<double> tied = cantilever(cut, books);
    ASSERT_EQ(tied.size(), uncut.size());
    for (std::size_t k = 0; k < uncut.size(); ++k)
      EXPECT_NEAR(tied[k], uncut[k], 0.01 * peak) << "state " << k;
    EXPECT_LT(books, 0.01) << "the energy ratio";
  }
  // Translations alone: the cut is a hinge.
  const std::vector<double> hinge = cantilever(Cut::nodes_only, books);
  EXPECT_GT(*std::max_element(hinge.begin(), hinge.end()), 5.0 * peak);
}

}  // namespace
}  // namespace plyform::test
