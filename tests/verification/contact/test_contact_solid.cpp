// A solid block resting on a shell plate under a pressure on its top face: the contact surface
// of a solid part is its exterior faces (found by the build), their stiffness K A^2 / V, no
// thickness offset. Reference: statics, the contact carries the applied load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
// contact carries the load, the slice does not fall through), Coulomb (mu times the normal
// force) and the conservation of energy. Before, the nodes took the side faces (gap 0 however
// deep they went) and the upper slice fell through the lower one. Later, once the upper slice
// slid past the lower one's end (x = 4) by MAXPAR's overshoot, its end nodes hunted between the
// end face (free, sinking under the load) and the top face they had just left (pushed out of
// the depth they sank to): the contact gave the model 0.6 mJ against 0.02 that entered and the
// energy ratio reached 9. Selective reduced hexahedra (ELFORM 2): one-point slices one element
// thick hourglass under the load (11 % of the internal energy), which is not this test's subject.
TEST(ContactSolid, SliceOnASliceTakesTheTopFaceAtTheEdgesAndSlides) {
  const double end = 3e-3, load = 8.0;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 300);
  d.kw("*DATABASE_RCFORC").card(end / 300);
  d.kw("*DATABASE_NODOUT").card(end / 300);
  d.kw("*PART").kw("lower").card(1, 1, 1);
  d.kw("*PART").kw("upper").card(2, 1, 1);
  d.kw("*SECTION_SOLID").card(1, 2);
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
  // Its books: the contact never gives the model energy, and the energy balance holds.
  EXPECT_TRUE(r.result.distrust.empty())
      << r.result.distrust.front().reason << " from t = " << r.result.distrust.front().time;
  double worst = 0.0, lowest_contact = 0.0;
  for (const auto& e : r.sink.energies) {
    worst = std::max(worst, std::abs(e.ratio - 1.0));
    lowest_contact = std::min(lowest_contact, e.contact);
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_GE(lowest_contact, -1e-6 * r.sink.energies.back().external_work);
  std::printf("its books: energy ratio within %.2e of 1, lowest contact energy %.3e mJ\n", worst,
              lowest_contact);
}

// A rigid plate (a tool mesh: *MAT_RIGID shells, not offset in a non-automatic contact) pressed
// onto a block of hexahedra: neither surface has a thickness. Before, every approaching node
// that pressed in at all turned to the plate's other side before the law could push it back,
// and the tool passed through the block untouched (a rigid cylinder went through the rubber
// block of examples/deformable). References: the block's top follows the plate (it moves down
// by the plate's travel beyond the first touch, less the penalty's penetration F / (k A)),
// and the contact force is the block's uniaxial stress E A (-uz) / H from its own top face.
TEST(ContactSolid, RigidToolMeshOnASolidFacePressesIt) {
  const double end = 3e-3, gap = 0.01, travel = 0.03, h = 2.0, e = 2.0e5;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 300);
  d.kw("*DATABASE_RCFORC").card(end / 300);
  d.kw("*DATABASE_NODOUT").card(end / 300);
  d.kw("*PART").kw("block").card(1, 1, 1);
  d.kw("*PART").kw("tool").card(2, 2, 2);
  d.kw("*SECTION_SOLID").card(1, 1);
  d.kw("*SECTION_SHELL").card(2, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, e, 0.0);  // nu = 0: uniaxial stress, no lateral push
  d.kw("*MAT_RIGID").card(2, 7.85e-9, 2.1e5, 0.3).card(1.0, 4, 7);
  const auto top = d.block(1, 1, 1, 0, 4, 0, 4, 0, h, 2, 2, 2);
  d.plate(2, 1001, 1001, -1, 5, -1, 5, 2, 2, h + gap);
  std::vector<int> bottom;
  for (int i = 1; i <= 9; ++i)
    bottom.push_back(i);
  d.kw("*SET_NODE_LIST").card(1).ids(bottom);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 0, 0, 1);  // rollers
  d.kw("*BOUNDARY_SPC_NODE").card(1, 0, 1, 1, 1);
  d.kw("*DATABASE_HISTORY_NODE").ids(top);
  d.kw("*DEFINE_CURVE")
      .card(1)
      .card(0.0, 0.0)
      .card(end / 2, -(gap + travel))
      .card(end, -(gap + travel));
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_RIGID").card(2, 3, 2, 1, 1.0);
  // The slave side: the top faces (outward, +z), so that every slave node's penalty per area
  // is the top elements' (with the whole part, the edges' nodes would share the side faces').
  d.kw("*SET_SEGMENT").card(2);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = top[static_cast<std::size_t>(3 * j + i)];
      d.card(a, a + 1, a + 4, a + 3);
    }
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(5, "tool on block");
  d.card(2, 2, 0, 3).card(0, 0, 0, 0, 20).card(1, 1);
  test::DeckRun r;
  run_deck(d.text(), r);
  double fz = 0.0, uz = 0.0;
  int n = 0;
  for (const auto& [t, reports] : r.sink.contact) {
    if (t >= 2.0 * end / 3.0) {
      fz += reports.at(0).force[2];
      ++n;
    }
  }
  ASSERT_GT(n, 10);
  fz /= n;
  n = 0;
  for (const auto& [t, u] : r.uz) {
    if (t >= 2.0 * end / 3.0) {
      for (double v : u)
        uz += v;
      n += static_cast<int>(u.size());
    }
  }
  uz /= n;
  // The block is pressed: force down on its top, the top moved down.
  EXPECT_LT(fz, 0.0);
  EXPECT_LT(uz, -0.02 * travel);
  EXPECT_NEAR(-fz, e * 16.0 * (-uz) / h, 0.02 * -fz);
  // The top is behind the plate by the penetration only: F / (k A) with the block's penalty
  // per area 0.1 K A_face / V of its top elements (K = E / 3 at nu = 0); that penalty is 15
  // times softer than the 2 mm block, so the top moves about travel / 16.
  const double k_area = 0.1 * (e / 3.0) * 4.0 / 4.0;
  EXPECT_NEAR(-uz, travel - (-fz) / (k_area * 16.0), 0.05 * -uz);
  std::printf("rigid tool mesh on a solid face: force %.4g N, E A u / H %.4g N, top %.4g mm\n", -fz,
              e * 16.0 * (-uz) / h, uz);
}

}  // namespace
}  // namespace plyform
