// A solid block resting on a shell plate under a pressure on its top face: the contact surface
// of a solid part is its exterior faces (found by the build), their stiffness K A^2 / V, no
// thickness offset. Reference: statics, the contact carries the applied load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

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

// A slice (4 x 1 x 1 hexahedra, one element thick in y) on another of the same mesh: every slave
// node of the upper slice's bottom lies on an edge of the lower slice's surface, between its top
// faces and its side faces (y = 0 and y = 1), as near to the side face whose plane it lies in as
// to the top face it will press into. It must take the top face (the face its own surface faces)
// and carry the load: pressed, then dragged along x with friction. References: statics (the
// contact carries the load, the slice does not fall through) and Coulomb (mu times the normal
// force). Before, the nodes took the side faces (gap 0 however deep they went) and the upper
// slice fell through the lower one.
TEST(ContactSolid, SliceOnASliceTakesTheTopFaceAtTheEdgesAndSlides) {
  const double end = 3e-3, load = 8.0;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 300);
  d.kw("*DATABASE_RCFORC").card(end / 300);
  d.kw("*DATABASE_NODOUT").card(end / 300);
  d.kw("*PART").kw("lower").card(1, 1, 1);
  d.kw("*PART").kw("upper").card(2, 1, 1);
  d.kw("*SECTION_SOLID").card(1, 1);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 2.0e5, 0.3);
  (void)d.block(1, 1, 1, 0, 4, 0, 1, 0, 1, 4, 1, 1);
  const auto top = d.block(2, 1001, 1001, 0, 4, 0, 1, 1, 2, 4, 1, 1);
  // The lower slice's bottom (its first 10 nodes) held; the upper slice's top loaded and dragged.
  d.kw("*SET_NODE_LIST").card(1).ids({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  d.kw("*SET_NODE_LIST").card(2).ids(top);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1);
  d.kw("*DATABASE_HISTORY_NODE").card(1001);  // a bottom corner of the upper slice
  d.kw("*DATABASE_HISTORY_NODE").card(1002, 1003, 1004, 1005, 1006, 1007, 1008, 1009).card(1010);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end / 6, 1.0).card(end, 1.0);
  d.kw("*DEFINE_CURVE")
      .card(2)
      .card(0.0, 0.0)
      .card(end / 3, 0.0)
      .card(end / 2, 20.0)
      .card(end, 20.0);
  d.kw("*LOAD_NODE_SET").card(2, 3, 1, -load / static_cast<double>(top.size()));
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 0, 2, 1.0);
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(5, "slice on slice");
  d.card(2, 1, 3, 3).card(0.2, 0.2, 0, 0, 20).card(1, 1);
  test::DeckRun r;
  run_deck(d.text(), r);
  double fx = 0.0, fz = 0.0;
  int n = 0;
  for (const auto& [t, reports] : r.sink.contact) {
    if (t < 2.0 * end / 3.0)
      continue;
    fx += reports.at(0).force[0];
    fz += reports.at(0).force[2];
    ++n;
  }
  ASSERT_GT(n, 10);
  EXPECT_NEAR(fz / n, load, 0.01 * load);  // the contact carries the load
  EXPECT_NEAR(-fx / fz, 0.2, 0.004);       // sliding with Coulomb friction
  // The slice rests on the other: its bottom sank by the penalty's penetration only.
  EXPECT_GT(r.uz.back().second.at(0), -0.01);
  // Every node of its bottom rests on the lower slice (none sinks in at the edges).
  for (double u : r.uz.back().second)
    EXPECT_GT(u, -0.01);
  std::printf("slice on slice: normal force %.4f of the load, mu %.4f, deepest node %.2e mm\n",
              fz / n / load, -fx / fz,
              -*std::min_element(r.uz.back().second.begin(), r.uz.back().second.end()));
}

}  // namespace
}  // namespace plyform
