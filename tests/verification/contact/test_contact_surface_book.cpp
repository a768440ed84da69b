// The interface's `surface` book: the energy its tractions exchange with gap changes that no
// motion of the nodes made.
//
// A steel plate (8 x 8 x 1 mm, 4 x 4 shells) lies on a fixed one under a uniform pressure p of
// 1 MPa, through a frictionless one-way contact whose offsets follow the shells' thickness
// (*CONTROL_CONTACT THKCHG 1). Held, it is then stretched along x by 2 % (its left edge held in
// x, its right edge pulled, y free: uniaxial stress), so it thins by nu eps_x t0 = 6 microns.
// Its lower surface rises by half of that relative to its mid-surface: the gap opens without any
// node moving, and the pressure pushes the plate down after it, doing work on the nodes that the
// interface's spring never held.
// References:
// - the surface book is -p A nu eps_x t0 / 2 (the pressure's work on the offset's motion;
//   plane stress, small strain);
// - the interface's books close: work + surface = stored (frictionless, undamped);
// - with THKCHG 0 the offsets stay and the surface book stays at zero.
// And the adhesion a bonded node takes with it when it slides off the master's edge (a skin's
// edge passing the core's): a plate bonded by the cohesive law (sigma_max 1 MPa, C_N 100
// MPa/mm: omega = sigma_max^2 / C_N = 0.01 mJ/mm^2), no tangential adhesion and no friction,
// slid 4.5 mm along x so that its last two columns of nodes (13.5 mm^2) leave the master: the
// surface book is omega times that area, the damage book the same, and the books close.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact_decks.hpp"

namespace plyform {
namespace test_contact_surface_book {

constexpr double kSide = 8.0, kThickness = 1.0, kNu = 0.3, kPressure = 1.0, kStretch = 0.02;
constexpr double kEnd = 4e-4;

std::string deck(bool follow_thickness) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(kEnd);
  d.kw("*CONTROL_CONTACT").card(0.1, 0, 0, 0, 0, follow_thickness ? 1 : 0);
  d.kw("*DATABASE_GLSTAT").card(kEnd / 100);
  d.kw("*DATABASE_RCFORC").card(kEnd / 100);
  for (int p : {1, 2}) {
    d.kw("*PART").kw("plate").card(p, 1, 1);
  }
  d.kw("*SECTION_SHELL")
      .card(1, 16, 0.8333, 2)
      .card(kThickness, kThickness, kThickness, kThickness);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 2.0e5, kNu);
  const auto below = d.plate(1, 1, 1, -1.0, kSide + 1.0, -1.0, kSide + 1.0, 5, 5, 0.0);
  const auto plate = d.plate(2, 1001, 1001, 0.0, kSide, 0.0, kSide, 4, 4, kThickness);
  std::vector<int> left, right;
  for (int j = 0; j <= 4; ++j) {
    left.push_back(plate[static_cast<std::size_t>(5 * j)]);
    right.push_back(plate[static_cast<std::size_t>(5 * j + 4)]);
  }
  d.kw("*SET_NODE_LIST").card(1).ids(below);
  d.kw("*SET_NODE_LIST").card(2).ids(plate);
  d.kw("*SET_NODE_LIST").card(3).ids(left);
  d.kw("*SET_NODE_LIST").card(4).ids(right);
  d.kw("*SET_NODE_LIST").card(5).ids({left[0]});
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(3, 0, 1, 0, 0, 0, 0, 0);
  d.kw("*BOUNDARY_SPC_SET").card(5, 0, 0, 1, 0, 0, 0, 0);
  // The pressure comes on over the first quarter and holds; the stretch follows over the
  // second and third (a smooth displacement, zero velocity at both ends).
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(kEnd / 4, 1.0).card(kEnd, 1.0);
  d.kw("*SET_SHELL_LIST")
      .card(1)
      .ids({1001, 1002, 1003, 1004, 1005, 1006, 1007, 1008, 1009, 1010, 1011, 1012, 1013, 1014,
            1015, 1016});
  d.kw("*LOAD_SHELL_SET").card(1, 1, kPressure);
  d.kw("*DEFINE_CURVE").card(2);
  const double t0 = kEnd / 4, t1 = 3 * kEnd / 4;
  for (int i = 0; i <= 40; ++i) {
    const double s = i / 40.0;
    d.card(t0 + s * (t1 - t0), kStretch * kSide * s * s * (3.0 - 2.0 * s));
  }
  d.card(kEnd, kStretch * kSide);
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(4, 1, 2, 2, 1.0);
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(1, "plate on the fixed plate");
  d.card(2, 1, 3, 3).card(0, 0).card(1, 1);
  return d.text();
}

TEST(ContactSurfaceBook, AThinningPlateUnderPressureBooksThePressuresWorkOnItsOffset) {
  test::DeckRun thin;
  test::run_deck(deck(true), thin);
  ASSERT_FALSE(thin.sink.contact.empty());
  const auto& last = thin.sink.contact.back().second.at(0);
  const double area = kSide * kSide;
  const double expected = -kPressure * area * kNu * kStretch * kThickness / 2.0;
  EXPECT_NEAR(last.surface, expected, 0.02 * std::abs(expected));
  // The books, at every output once the pressure is on.
  for (const auto& [t, reports] : thin.sink.contact) {
    const auto& r = reports.at(0);
    EXPECT_NEAR(r.work + r.surface, r.stored, 1e-3 * std::abs(expected)) << "t = " << t;
  }
  EXPECT_TRUE(thin.result.distrust.empty());

  test::DeckRun fixed;
  test::run_deck(deck(false), fixed);
  const auto& held = fixed.sink.contact.back().second.at(0);
  EXPECT_NEAR(held.surface, 0.0, 1e-3 * std::abs(expected));
  EXPECT_NEAR(held.work, held.stored, 1e-3 * std::abs(expected));
}

TEST(ContactSurfaceBook, ABondedNodeThatSlidesOffTheMasterTakesItsAdhesionWithIt) {
  constexpr double end = 4e-4, slide = 4.5, cn = 100.0, smax = 1.0;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_RCFORC").card(end / 100);
  d.kw("*PART").kw("master").card(1, 1, 1);
  d.kw("*PART").kw("slave").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 2.0e5, 0.3);
  const auto master = d.plate(1, 1, 1, 0.0, 10.0, 0.0, 6.0, 8, 4, 0.0);
  const auto slave = d.plate(2, 1001, 1001, 2.0, 8.0, 0.0, 6.0, 4, 4, 1.0);
  d.kw("*SET_NODE_LIST").card(1).ids(master);
  d.kw("*SET_NODE_LIST").card(2).ids(slave);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 1, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(2);
  for (int i = 0; i <= 40; ++i) {
    const double s = i / 40.0;
    d.card(s * end, slide * s * s * (3.0 - 2.0 * s));
  }
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 2, 2, 1.0);
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(3, "bonded layers");
  d.card(2, 1, 3, 3).card(0).card(1, 1);
  test::bonded_without_shear(d, 3, cn, smax);
  test::DeckRun r;
  test::run_deck(d.text(), r);
  ASSERT_FALSE(r.sink.contact.empty());
  const auto& last = r.sink.contact.back().second.at(0);
  const double omega = smax * smax / cn;
  const double left = (0.75 + 1.5) * 6.0;  // the two columns beyond x = 10 at the end
  EXPECT_NEAR(last.surface, omega * left, 1e-6 * omega * left);
  EXPECT_NEAR(last.damage, omega * left, 1e-3 * omega * left);
  for (const auto& [t, reports] : r.sink.contact) {
    const auto& b = reports.at(0);
    EXPECT_NEAR(b.work + b.surface, b.stored + b.damage + b.viscous + b.friction + b.damping,
                1e-3 * omega * left)
        << "t = " << t;
  }
}

/// A plate (6 x 6 mm, 4 x 4 shells, 1 mm thick) starting at x0 over a fixed rigid plate that
/// ends at x = 10, pressed 2 microns into it over the first quarter of the run (a frictionless
/// penalty contact; the rigid master keeps each node's effective mass, and so its spring, the
/// same wherever it is), then slid along x by `slide` (a smooth displacement).
void press_and_slide(double x0, double slide, test::DeckRun& r) {
  constexpr double end = 4e-4, depth = 0.002;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_RCFORC").card(end / 100);
  d.kw("*PART").kw("fixed rigid master").card(1, 1, 2);
  d.kw("*PART").kw("slave").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 2.0e5, 0.3);
  d.kw("*MAT_RIGID").card(2, 7.85e-9, 2.0e5, 0.3).card(1, 7, 7);
  d.plate(1, 1, 1, 0.0, 10.0, 0.0, 6.0, 8, 4, 0.0);
  // A rigid tool's mesh is its surface (no offset): the plate's lower face on it.
  const auto slave = d.plate(2, 1001, 1001, x0, x0 + 6.0, 0.0, 6.0, 4, 4, 0.5);
  d.kw("*SET_NODE_LIST").card(2).ids(slave);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end / 4, -depth).card(end, -depth);
  d.kw("*DEFINE_CURVE").card(2).card(0.0, 0.0).card(end / 4, 0.0);
  for (int i = 1; i <= 40; ++i) {
    const double s = i / 40.0;
    d.card(end / 4 + s * 3 * end / 4, slide * s * s * (3.0 - 2.0 * s));
  }
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 3, 2, 1, 1.0);
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 2, 2, 1.0);
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(3, "pressed plate");
  d.card(2, 1, 3, 3).card(0).card(1, 1);
  test::run_deck(d.text(), r);
}

/// The frictionless, undamped interface's books at every output: work + surface = stored.
void expect_books_close(const test::DeckRun& r, double tolerance) {
  for (const auto& [t, reports] : r.sink.contact) {
    const auto& b = reports.at(0);
    EXPECT_NEAR(b.work + b.surface, b.stored + b.friction + b.damping, tolerance) << "t = " << t;
  }
}

// Slid off: until two of the plate's four columns of elements overhang the master's edge, the
// nodes that leave take their springs' energy with them, unloaded by no work. The surface book
// pays it out: it is minus the springs' energy of the nodes that left, the share of the plate's
// area beyond the edge, and the books close at every output (before, the springs' energy
// vanished from them: a pressed holder contact fell 1.6 % below its work in the hot draw).
TEST(ContactSurfaceBook, APressedNodeThatSlidesOffTheMasterTakesItsSpringsEnergyWithIt) {
  test::DeckRun r;
  press_and_slide(2.0, 4.5, r);
  ASSERT_FALSE(r.sink.contact.empty());
  double held = 0.0;  // the springs' energy once pressed, before any node leaves
  for (const auto& [t, reports] : r.sink.contact)
    held = std::max(held, reports.at(0).stored);
  ASSERT_GT(held, 0.0);
  const auto& last = r.sink.contact.back().second.at(0);
  const double left = (0.75 + 1.5) / 6.0;  // the share of the plate's area beyond x = 10
  EXPECT_NEAR(last.surface, -left * held, 0.03 * left * held);
  EXPECT_NEAR(last.stored, (1.0 - left) * held, 0.03 * held);
  expect_books_close(r, 1e-3 * held);
}

// Slid on: pressed while two of its five columns of nodes (37.5 % of its area) overhang the
// master's edge, then slid back onto the master. Each node that arrives is inside the master
// already, by less than the shallow first part of an arrival the penalty pushes out (1 % of the
// offsets), and its spring takes energy that no work put in: the surface book pays it (+ the
// springs' energy of the arrived share), and the books close at every output. Before it did,
// the arrivals' energy was in no book (the frictionless square cup's skins kept arriving at the
// core's receding edge).
TEST(ContactSurfaceBook, APressedNodeThatArrivesOnTheMasterBooksItsSpringsEnergyAsSurface) {
  test::DeckRun r;
  press_and_slide(6.0, -4.5, r);
  ASSERT_FALSE(r.sink.contact.empty());
  const auto& last = r.sink.contact.back().second.at(0);
  ASSERT_GT(last.stored, 0.0);
  const double arrived = 2.25 / 6.0;  // the share of the plate's area that was beyond x = 10
  EXPECT_NEAR(last.surface, arrived * last.stored, 0.03 * arrived * last.stored);
  expect_books_close(r, 1e-3 * last.stored);
}

}  // namespace test_contact_surface_book
}  // namespace plyform
