// The energy books where the strain rate jumps within a cycle and the step changes with it,
// against conservation of energy (what the model holds against what entered: the ratio stays 1).
// The central differences move the nodes with each force of t_n over dt_avg around t_n; the books
// follow them exactly when the stresses (with the bulk viscosity's pressure q), the stiffness
// hourglass forces and the reactions each work dt_avg / 2 on each side (docs/energy.md). Before:
// q booked as its new value alone on the step's rate, the stresses and reactions on the steps'
// own halves: 1.05 over the first cycles of a wall's impact, 1.07 in a block whose face is heated
// by 200 K at once. The viscous hourglass forces are still booked on the step's rate alone (their
// forces of t_n are not kept, for speed). The wall striking a bar with the default bulk
// viscosity: test_rigid_walls.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "../contact/contact_decks.hpp"

namespace plyform {
namespace test_viscosity_books {

using test::DeckRun;
using test::DeckWriter;

constexpr double kE = 210000.0, kRho = 7.85e-9;  // steel: MPa, t/mm^3 (mm, s, N)

// The worst |ratio - 1| of a run's outputs.
double worst_ratio(const DeckRun& r) {
  double worst = 0.0;
  for (const engine::Energies& e : r.sink.energies)
    worst = std::max(worst, std::abs(e.ratio - 1.0));
  return worst;
}

// A steel block of 4 x 4 x 8 hexahedra (8 x 8 x 16 mm), its face z = 0 held and heated from 300 K
// to 500 K at once, its far face pulled by 0.01 mm; expansion 1.2e-5 /K (200 K: 2.4e-3, some
// 500 MPa where held) drives the elements next to the face in compression within a cycle. The
// one-point hexahedra with stiffness hourglass control, which is booked by the midpoint rule.
std::string heated_block(int elform) {
  DeckWriter w;
  if (elform == 1)
    w.kw("*CONTROL_HOURGLASS").card(4, 0.05);  // stiffness control: booked by the midpoint rule
  const double end = 2e-5;
  w.kw("*CONTROL_TERMINATION").card(end);
  w.kw("*DATABASE_GLSTAT").card(end / 100);
  w.kw("*PART").card("block").card(1, 1, 1, 0, 0, 0, 0, 1);
  w.kw("*SECTION_SOLID").card(1, elform);
  w.kw("*MAT_ELASTIC").card(1, kRho, kE, 0.3);
  w.kw("*MAT_ADD_THERMAL_EXPANSION").card(1, 0, 1.2e-5);
  w.block(1, 1, 1, 0.0, 8.0, 0.0, 8.0, 0.0, 16.0, 4, 4, 8);
  std::vector<int> held, pulled;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) {
      held.push_back(1 + j * 5 + i);
      pulled.push_back(1 + (8 * 5 + j) * 5 + i);
    }
  w.kw("*SET_NODE_LIST").card(1).ids(held);
  w.kw("*SET_NODE_LIST").card(2).ids(pulled);
  w.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1);
  w.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end, 0.01);
  w.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 3, 2, 1, 1.0);
  w.raw(
      "*CONTROL_SOLUTION\n2\n*CONTROL_THERMAL_SOLVER\n1,0,12\n0,0,0,1e-9,0,,,1e5\n"
      "*CONTROL_THERMAL_TIMESTEP\n0,0.5,2e-7\n*MAT_THERMAL_ISOTROPIC\n1,0.0\n5e8,50.0\n"
      "*INITIAL_TEMPERATURE_SET\n0,300.0\n*BOUNDARY_TEMPERATURE_SET\n1,0,500.0\n");
  return w.text();
}

TEST(ViscosityBooks, ABlockWhoseFaceIsHeatedAtOnceKeepsTheBooks) {
  for (int elform : {1, 2}) {
    DeckRun r;
    run_deck(heated_block(elform), r);
    ASSERT_GT(r.sink.energies.size(), 90u);
    // Heat at work (the expansion's) enters through the internal energy's stress work, which the
    // forces do: the books close as for any mechanical run.
    const double worst = worst_ratio(r);
    EXPECT_LT(worst, 1e-3) << "ELFORM " << elform;
    std::printf("block heated by 200 K at once, ELFORM %d: ratio within %.2e of 1\n", elform,
                worst);
  }
}

}  // namespace test_viscosity_books
}  // namespace plyform
