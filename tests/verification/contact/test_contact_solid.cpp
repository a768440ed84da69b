// A solid block resting on a shell plate under a pressure on its top face: the contact surface
// of a solid part is its exterior faces (found by the build), their stiffness K A^2 / V, no
// thickness offset. Reference: statics, the contact carries the applied load.
#include <gtest/gtest.h>

#include "contact_decks.hpp"

namespace plyform {
namespace {

TEST(ContactSolid, BlockUnderPressureTransmitsTheLoad) {
  const double end = 3e-3, load = 16.0;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 300);
  d.kw("*DATABASE_RCFORC").card(end / 300);
  d.kw("*PART").kw("plate").card(1, 1, 1);
  d.kw("*PART").kw("block").card(2, 2, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*SECTION_SOLID").card(2, 1);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 2.0e5, 0.3);
  const auto plate = d.plate(1, 1, 1, 0, 8, 0, 8, 4, 4, 0.0);
  // Bottom face on the plate's upper surface (offset 0.5): 2 x 2 x 1 hexahedra, 4 x 4 x 2 mm.
  const auto top = d.block(2, 1001, 1001, 2, 6, 2, 6, 0.5, 2.5, 2, 2, 1);
  d.kw("*SET_NODE_LIST").card(1).ids(plate);
  d.kw("*SET_NODE_LIST").card(2).ids(top);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end / 6, 1.0).card(end, 1.0);
  d.kw("*LOAD_NODE_SET").card(2, 3, 1, -load / static_cast<double>(top.size()));
  d.kw("*CONTACT_SURFACE_TO_SURFACE_ID").card(4, "block on plate");
  d.card(2, 1, 3, 3).card(0, 0, 0, 0, 20).card(1, 1);
  test::DeckRun r;
  run_deck(d.text(), r);
  double fz = 0.0;
  int n = 0;
  for (const auto& [t, reports] : r.sink.contact) {
    if (t >= 2.0 * end / 3.0) {
      fz += reports.at(0).force[2];
      ++n;
    }
    // Two-way contact: both passes together still balance to round-off.
    EXPECT_NEAR(reports.at(0).force[2] + reports.at(0).master_force[2], 0.0, 1e-12 * load);
  }
  EXPECT_NEAR(fz / n, load, 0.005 * load);
  EXPECT_LT(std::abs(r.sink.energies.back().total -
                     (r.sink.energies.front().kinetic + r.sink.energies.back().external_work)),
            0.01 * r.sink.energies.back().external_work);
}

}  // namespace
}  // namespace plyform
