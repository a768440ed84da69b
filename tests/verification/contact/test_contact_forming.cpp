// A rigid punch (*MAT_RIGID, prescribed motion) pressed into a clamped elastic-plastic sheet
// through *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE: the tool mesh is its surface (no
// offset for rigid shells), the sheet is offset by half its thickness. References: Newton's
// third law through the rigid body (the force the body's nodes receive is minus the contact
// force on the sheet), the sheet does not pass through the punch (the centre under it has
// moved at least the punch's travel beyond the first touch, less a small penetration), and
// the energy balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "contact_decks.hpp"

namespace plyform {
namespace {

TEST(ContactForming, RigidPunchReceivesMinusTheContactForce) {
  const double end = 1e-3;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 100);
  d.kw("*DATABASE_RCFORC").card(end / 100);
  d.kw("*DATABASE_NODOUT").card(end / 100);
  d.kw("*PART").kw("sheet").card(1, 1, 1);
  d.kw("*PART").kw("punch").card(2, 1, 2);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 3).card(0.5, 0.5, 0.5, 0.5);
  d.kw("*MAT_PIECEWISE_LINEAR_PLASTICITY").card(1, 7.85e-9, 2.1e5, 0.3, 200.0, 1000.0);
  d.kw("*MAT_RIGID").card(2, 7.85e-9, 2.1e5, 0.3).card(1.0, 4, 7);
  const auto sheet = d.plate(1, 1, 1, 0, 20, 0, 20, 10, 10, 0.0);
  // The punch face 4 x 4 mm, 0.05 mm above the sheet's upper surface (offset 0.25).
  d.plate(2, 1001, 1001, 8, 12, 8, 12, 2, 2, 0.3);
  d.kw("*DATABASE_HISTORY_NODE").card(sheet[60]);  // the centre, under the punch
  std::vector<int> edge;
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 10; ++i)
      if (i == 0 || j == 0 || i == 10 || j == 10)
        edge.push_back(sheet[static_cast<std::size_t>(j * 11 + i)]);
  d.kw("*SET_NODE_LIST").card(1).ids(edge);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end, 1.0);
  // The punch moves down 1 mm over the run: v = -2000 t/end mm/s, a smooth start.
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_RIGID").card(2, 3, 0, 1, -2000.0);
  d.kw("*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID").card(5, "sheet against punch");
  d.card(1, 2, 3, 3).card(0.1, 0.1, 0, 0, 20).card(1, 1);
  test::DeckRun r;
  std::array<double, 3> body{};
  double body_time = -1.0;
  r.sink.on_state = [&](const engine::Snapshot& s) {
    body = s.rigid->report().at(0).force;
    body_time = s.time;
  };
  run_deck(d.text(), r);
  ASSERT_FALSE(r.sink.contact.empty());
  const auto& rep = r.sink.contact.back().second.at(0);
  // The sheet is pushed down, the punch up.
  EXPECT_LT(rep.force[2], -1.0);
  ASSERT_EQ(body_time, r.sink.contact.back().first);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(rep.force[k] + rep.master_force[k], 0.0, 1e-10 * std::abs(rep.force[2]));
    EXPECT_NEAR(body[k], rep.master_force[k], 1e-9 * std::abs(rep.force[2]));
  }
  // The punch (1 mm of travel, starting 0.05 mm above the sheet's surface) has pushed the
  // sheet's centre at least 0.95 mm down, less a penetration of k delta = force (about 5e-3
  // mm here): the sheet never passes through the punch (dynamically it may run ahead).
  const double uz = r.uz.back().second.at(0);
  EXPECT_LT(uz, -0.95 + 0.01);
  const engine::Energies& e = r.sink.energies.back();
  EXPECT_NEAR(e.total, r.sink.energies.front().kinetic + e.external_work, 0.01 * e.external_work);
  EXPECT_GT(e.internal, 0.1 * e.external_work);  // the sheet took the work, plastically
}

// A coarse aluminium sheet (0.25 mm on 7.5 mm Belytschko-Tsay shells, the restart tests' square
// cup at n 10) pressed onto a rigid die by 2 MPa, with friction and nothing else: it must stay
// at rest (statics: a uniform pressure on a plane sheet on a plane does no in-plane work), its
// books closed. The stick spring of friction acts in the sheet's plane, where the membrane's
// highest mode is already at the step's limit; with the normal penalty as its stiffness (about
// 18,000 N/mm on an edge node of 1.9e-8 t, sqrt(k / m) dt = 1.2) the two together passed it and
// the sheet rang along the die at every second cycle: kinetic energy -0.78 mJ (the conserved
// form of a mode beyond the limit), internal 1.0 mJ and an energy ratio of 1.096 after 640
// cycles, the friction booking a negative dissipation in the square cup. The stick spring is
// held at sqrt(k / m*) dt0 = 1/2 (docs/contact.md).
TEST(ContactForming, ASheetPressedOnADieWithFrictionStaysAtRest) {
  const double end = 8e-4, h = 7.5, pressure = 2.0;
  const int n = 8;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 80);
  d.kw("*DATABASE_RCFORC").card(end / 80);
  d.kw("*HOURGLASS").card(1, 4, 0.03);
  d.kw("*PART").kw("sheet").card(1, 1, 1, 0, 1);
  d.kw("*PART").kw("die").card(2, 2, 2);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 5).card(0.25, 0.25, 0.25, 0.25);
  d.kw("*SECTION_SHELL").card(2, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_PIECEWISE_LINEAR_PLASTICITY").card(1, 2.7e-9, 70000.0, 0.33, 135.0, 300.0);
  d.kw("*MAT_RIGID").card(2, 7.85e-9, 2.1e5, 0.3).card(1.0, 7, 7);
  // The sheet's mid-surface half its thickness above the die (a tool mesh is its surface).
  const auto sheet = d.plate(1, 1, 1, 0.0, n * h, 0.0, n * h, n, n, 0.125);
  (void)d.plate(2, 1001, 1001, -h, (n + 1) * h, -h, (n + 1) * h, n + 2, n + 2, 0.0);
  d.kw("*SET_NODE_LIST").card(1).ids(sheet);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end / 8, 1.0).card(end, 1.0);
  const double area = n * h * n * h;
  d.kw("*LOAD_NODE_SET").card(1, 3, 1, -pressure * area / static_cast<double>(sheet.size()));
  d.kw("*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID").card(3, "sheet on die");
  d.card(1, 2, 3, 3).card(0.16, 0.16, 0, 0, 20).card(1, 1);
  test::DeckRun r;
  run_deck(d.text(), r);
  ASSERT_FALSE(r.sink.energies.empty());
  double worst_ratio = 0.0, most_kinetic = 0.0, most_internal = 0.0;
  for (const auto& e : r.sink.energies) {
    worst_ratio = std::max(worst_ratio, std::abs(e.ratio - 1.0));
    most_kinetic = std::max(most_kinetic, std::abs(e.kinetic));
    most_internal = std::max(most_internal, std::abs(e.internal));
  }
  const engine::Energies& last = r.sink.energies.back();
  // The work the press does is the contact's spring energy (the sheet sinks k delta into the
  // die); the sheet itself takes next to nothing, moving or strained.
  EXPECT_LT(worst_ratio, 1e-3);
  EXPECT_LT(most_kinetic, 1e-3 * last.external_work);
  EXPECT_LT(most_internal, 1e-3 * last.external_work);
  EXPECT_TRUE(r.result.distrust.empty());
  // The contact carries the press: the die pushes the sheet up by the pressure's resultant.
  const auto& rep = r.sink.contact.back().second.at(0);
  EXPECT_NEAR(rep.force[2], pressure * area, 0.01 * pressure * area);
  std::printf(
      "sheet pressed on a die with friction: energy ratio within %.1e of 1, largest "
      "kinetic %.1e and internal %.1e of the work %.3g mJ\n",
      worst_ratio, most_kinetic / last.external_work, most_internal / last.external_work,
      last.external_work);
}

}  // namespace
}  // namespace plyform
