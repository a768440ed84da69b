// Tied contacts (*CONTACT_TIED_NODES_TO_SURFACE, *CONTACT_TIED_SHELL_EDGE_TO_SURFACE and their
// _OFFSET forms) against the uncut structure: a shell cantilever (steel, 100 x 10 x 2 mm,
// ELFORM 16) cut at mid-length into two meshes and tied along the cut
// - with the shell edge tied (rotations too), on a matching mesh, on a finer mesh across the
//   cut (3 shells against 2) and on a mesh offset by half the thickness, deflects as the uncut
//   cantilever under the same tip load within 1 % of its peak at every output (measured: to
//   round-off, 2e-4 and 1e-3): the tie carries the moment; the books close within 1e-5;
// - with the nodes tied alone (translations), the cut is a hinge: the tip falls 16 times
//   further;
// - the tie's reaction in rcforc.csv (the force the left half applies to the right half's tied
//   edge) against the right half's momentum balance: its impulse over the run equals the right
//   half's momentum at the end less the tip load's impulse (a free body's element forces sum to
//   zero), within 1e-4 of the load's impulse (measured: 3e-8).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "contact_decks.hpp"

namespace plyform::test {
namespace {

constexpr double kE = 210000.0, kRho = 7.85e-9, kLength = 100.0, kWidth = 10.0, kT = 2.0;

enum class Cut { none, edge, edge_finer, edge_offset, nodes_only };

constexpr double kLoad = 10.0, kRamp = 6e-3, kEnd = 9e-3;

// The tip load's z component at time t: -P ramped smoothly over kRamp (a half cosine), held.
double tip_load(double t) {
  return -kLoad * (t < kRamp ? 0.5 * (1.0 - std::cos(std::numbers::pi * t / kRamp)) : 1.0);
}

// The tip deflection (mean uz of the tip nodes) at each state time, for the tip load. With
// `run_out`, rcforc at every cycle and the run kept there.
std::vector<double> cantilever(Cut cut, double& ratio_error, DeckRun* run_out = nullptr) {
  const double p = kLoad, t_ramp = kRamp, t_end = kEnd;
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(t_end);
  if (run_out != nullptr)
    w.kw("*DATABASE_RCFORC").card(1e-9);  // below the step: every cycle
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
  DeckRun local;
  DeckRun& run = run_out != nullptr ? *run_out : local;
  // A caller's own state probe runs after the deflection's.
  std::function<void(const engine::Snapshot&)> probe = std::move(run.sink.on_state);
  run.sink.on_state = [&](const engine::Snapshot& s) {
    if (probe)
      probe(s);
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

// The right half (nodes 1001 on) is a free body loaded by the tip load and the tie's reaction
// R on its edge: sum m a = P + R, its element forces summing to zero. So the impulse of R
// over the run (rcforc at every cycle, the trapezoid rule on the cycles' times) is the right
// half's momentum at the end less the load's impulse.
TEST(TiedContacts, TheTiesReactionInRcforcIsTheRightHalfsMomentumBalance) {
  double books = 0.0;
  DeckRun run;
  std::array<double, 3> momentum{0.0, 0.0, 0.0};
  double end_time = 0.0;
  run.sink.on_state = [&](const engine::Snapshot& s) {  // the last state's is kept
    momentum = {0.0, 0.0, 0.0};
    end_time = s.time;
    ASSERT_EQ(s.nodes->mass.size(), s.model->node_count());
    for (std::size_t i = 0; i < s.model->node_count(); ++i) {
      if (s.model->node_id[i] < 1001)
        continue;
      momentum[0] += s.nodes->mass[i] * s.nodes->vx[i];
      momentum[1] += s.nodes->mass[i] * s.nodes->vy[i];
      momentum[2] += s.nodes->mass[i] * s.nodes->vz[i];
    }
  };
  cantilever(Cut::edge, books, &run);
  EXPECT_NEAR(end_time, kEnd, 1e-9);
  const auto& rows = run.sink.contact;
  ASSERT_GT(rows.size(), 1000u);
  std::array<double, 3> impulse{0.0, 0.0, 0.0};
  double load = 0.0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].second.size(), 1u);
    EXPECT_TRUE(rows[k].second[0].tied);
    const double dt = rows[k].first - rows[k - 1].first;
    for (int d = 0; d < 3; ++d)
      impulse[d] += 0.5 * dt * (rows[k].second[0].force[d] + rows[k - 1].second[0].force[d]);
    load += 0.5 * dt * (tip_load(rows[k].first) + tip_load(rows[k - 1].first));
  }
  // The reaction holds the load up: R_z about +P once the ramp is over.
  EXPECT_GT(rows.back().second[0].force[2], 0.5 * kLoad);
  EXPECT_NEAR(impulse[2], momentum[2] - load, 1e-4 * std::abs(load))
      << "impulse " << impulse[2] << ", momentum " << momentum[2] << ", load " << load;
  EXPECT_NEAR(impulse[0], momentum[0], 1e-4 * std::abs(load));
  EXPECT_NEAR(impulse[1], momentum[1], 1e-4 * std::abs(load));
  char error[32];
  std::snprintf(error, sizeof error, "%.3g", (impulse[2] - (momentum[2] - load)) / load);
  RecordProperty("impulse_error", error);
}

}  // namespace
}  // namespace plyform::test
