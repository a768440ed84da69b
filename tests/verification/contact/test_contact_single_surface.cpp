// *CONTACT_AUTOMATIC_SINGLE_SURFACE and the initial penetrations (IGNORE), end to end.
// References: statics (the contact carries the load pressing a sheet onto itself), Coulomb
// (friction mu times the normal force between two pieces of one part), and that a surface does
// not touch itself through its own mesh: a free plate bending and a sheet folded into a hairpin
// get no force from their own neighbouring faces. IGNORE = 0 moves a penetrating node out by
// its depth before the run (the model starts at rest); IGNORE = 1 leaves it where it is and
// acts only on deeper penetration; neither gives the model energy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact_decks.hpp"

namespace plyform {
namespace test_contact_single_surface {

constexpr double kE = 2.0e5, kNu = 0.3, kRho = 7.85e-9;

void common(test::DeckWriter& d, double end, int parts) {
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 300);
  d.kw("*DATABASE_RCFORC").card(end / 300);
  for (int p = 1; p <= parts; ++p)
    d.kw("*PART").kw("sheet").card(p, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, kRho, kE, kNu);
}

// Two plates of ONE part (an 8 x 8 mm plate held, a 4 x 4 mm plate 1 mm above it: the surfaces
// touch), the upper one pressed by a load and dragged: the part's self contact carries the load
// and rubs with mu = 0.3, as a two-part contact would.
TEST(ContactSingleSurface, TwoPiecesOfOnePartCarryTheLoadWithCoulombFriction) {
  test::DeckWriter d;
  const double end = 3e-3, load = 16.0;
  common(d, end, 1);
  const auto lower = d.plate(1, 1, 1, 0, 8, 0, 8, 4, 4, 0.0);
  const auto upper = d.plate(1, 1001, 1001, 2, 6, 2, 6, 2, 2, 1.0);
  d.kw("*SET_NODE_LIST").card(1).ids(lower);
  d.kw("*SET_NODE_LIST").card(2).ids(upper);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end / 6, 1.0).card(end, 1.0);
  d.kw("*DEFINE_CURVE").card(2).card(0.0, 10.0).card(end, 10.0);
  d.kw("*LOAD_NODE_SET").card(2, 3, 1, -load / static_cast<double>(upper.size()));
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 0, 2, 1.0);
  d.kw("*CONTACT_AUTOMATIC_SINGLE_SURFACE_ID").card(7, "self");
  d.card(1, 0, 3, 0).card(0.3, 0.3, 0, 0, 20);
  test::DeckRun r;
  test::run_deck(d.text(), r);
  // A single surface's resultant on its own nodes sums to zero, so the test reads the books:
  // in steady sliding friction dissipates mu N v per unit time (N the load), which it can only
  // do if the upper plate rests on the lower one.
  double friction_rate = 0.0;
  const auto& c = r.sink.contact;
  ASSERT_GT(c.size(), 30u);
  const auto& [t0, r0] = c[2 * c.size() / 3];
  const auto& [t1, r1] = c.back();
  friction_rate = (r1.at(0).friction - r0.at(0).friction) / (t1 - t0);
  EXPECT_NEAR(friction_rate, 0.3 * load * 10.0, 0.01 * 0.3 * load * 10.0);
  EXPECT_NEAR(r1.at(0).stored + r1.at(0).friction + r1.at(0).damping, r1.at(0).work,
              0.01 * r1.at(0).work);
}

// A hairpin: a strip folded back on itself (lower leg, a 2 mm wall, upper leg: the legs' faces
// 1 mm apart; elements 1 mm long, two across the 2 mm width), the lower leg held; a load on the
// upper leg's free end bends it down onto the lower leg (a soft sheet, E = 2 GPa, so that the
// load closes the gap many times over). References: the free end comes to rest on the lower
// leg, its mid-surface one thickness above the lower leg's (the gap closed, within the
// penalty's penetration), not through it; the strip's own faces round the fold never push
// (the contact does no work before the legs touch); the model's energy balance closes.
TEST(ContactSingleSurface, AFoldedStripPressedOntoItselfRestsOnItself) {
  test::DeckWriter d;
  const double end = 6e-3, load = 20.0;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 300);
  d.kw("*DATABASE_RCFORC").card(end / 300);
  d.kw("*DATABASE_NODOUT").card(end / 300);
  d.kw("*PART").kw("sheet").card(1, 1, 1, 0, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 3).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, kRho, 2000.0, kNu);
  d.kw("*HOURGLASS").card(1, 4, 0.05);
  // Stations along the strip: lower leg x = 0..10 at z = 0, the wall at x = 10, the upper leg
  // x = 10..0 at z = 2; three nodes across (y = 0, 1, 2).
  std::vector<std::array<double, 2>> path;
  for (int i = 0; i <= 10; ++i)
    path.push_back({static_cast<double>(i), 0.0});
  path.push_back({10.0, 1.0});
  for (int i = 10; i >= 0; --i)
    path.push_back({static_cast<double>(i), 2.0});
  const int n = static_cast<int>(path.size());
  const auto node = [](int station, int across) { return 3 * station + across + 1; };
  d.kw("*NODE");
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 3; ++j)
      d.card(node(i, j), path[static_cast<std::size_t>(i)][0], 1.0 * j,
             path[static_cast<std::size_t>(i)][1]);
  d.kw("*ELEMENT_SHELL");
  int e = 1;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j < 2; ++j)
      d.card(e++, 1, node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1));
  std::vector<int> held, loaded;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j < 3; ++j)
      held.push_back(node(i, j));
  for (int j = 0; j < 3; ++j)
    loaded.push_back(node(n - 1, j));
  d.kw("*SET_NODE_LIST").card(1).ids(held);
  d.kw("*SET_NODE_LIST").card(2).ids(loaded);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*DATABASE_HISTORY_NODE").card(node(n - 1, 1));
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end / 3, 1.0).card(end, 1.0);
  d.kw("*LOAD_NODE_SET").card(2, 3, 1, -load / 3.0);
  d.kw("*CONTACT_AUTOMATIC_SINGLE_SURFACE").card(1, 0, 3, 0).card(0, 0, 0, 0, 20);
  test::DeckRun r;
  test::run_deck(d.text(), r);
  const auto& c = r.sink.contact;
  ASSERT_FALSE(c.empty());
  // Before the legs meet (the free end above half the gap) the contact does nothing.
  for (std::size_t k = 0; k < r.uz.size() && k < c.size(); ++k) {
    if (r.uz[k].second.at(0) > -0.5) {
      EXPECT_EQ(c[k].second.at(0).work, 0.0) << "t = " << c[k].first;
    }
  }
  // On the lower leg: the gap closed (the tip's mid-surface a thickness above the lower leg's,
  // less the penalty's penetration under the load on its small contact area), and not through
  // it (through would be uz = -2).
  const double tip = r.uz.back().second.at(0);
  EXPECT_LT(tip, -0.95);
  EXPECT_GT(tip, -1.5);
  EXPECT_GT(c.back().second.at(0).in_contact, 0u);
  const auto& en = r.sink.energies.back();
  EXPECT_NEAR(en.kinetic + en.internal + en.hourglass + en.contact, en.external_work,
              0.02 * en.external_work);
}

// A cantilever plate (1 mm elements, as thick as they are long: the hardest case for the
// neighbours) clamped at x = 0 and bent by a tip load into a curve several times its thickness
// deep: its faces meet only their own neighbours, which the self contact leaves out: no force,
// no work.
TEST(ContactSingleSurface, ABendingPlateDoesNotTouchItself) {
  test::DeckWriter d;
  const double end = 2e-4;
  common(d, end, 1);
  d.kw("*DATABASE_NODOUT").card(end / 300);
  (void)d.plate(1, 1, 1, 0, 10, 0, 10, 10, 10, 0.0);
  std::vector<int> clamped, tip;
  for (int j = 0; j <= 10; ++j) {
    clamped.push_back(1 + 11 * j);
    tip.push_back(11 + 11 * j);
  }
  d.kw("*SET_NODE_LIST").card(1).ids(clamped);
  d.kw("*SET_NODE_LIST").card(2).ids(tip);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*DATABASE_HISTORY_NODE").card(11 + 11 * 5);  // the tip's middle
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 1.0).card(end, 1.0);
  d.kw("*LOAD_NODE_SET").card(2, 3, 1, -1500.0 / 11.0);
  d.kw("*CONTACT_AUTOMATIC_SINGLE_SURFACE_ID").card(3, "self").card(1, 0, 3, 0);
  test::DeckRun r;
  test::run_deck(d.text(), r);
  double deepest = 0.0;
  for (const auto& [t, uz] : r.uz)
    deepest = std::min(deepest, uz.at(0));
  EXPECT_LT(deepest, -2.0);  // it did bend, several thicknesses deep
  ASSERT_FALSE(r.sink.contact.empty());
  for (const auto& [t, reports] : r.sink.contact) {
    EXPECT_EQ(reports.at(0).work, 0.0) << "t = " << t;
    EXPECT_EQ(reports.at(0).in_contact, 0u) << "t = " << t;
  }
}

// A plate placed 0.05 mm into a held plate (its surface inside the other's thickness offset).
struct Sunk {
  int ignore = 0;  // *CONTROL_CONTACT IGNORE
  double load = 0.0;
};

std::string sunk_deck(const Sunk& c) {
  test::DeckWriter d;
  const double end = 1e-3;
  common(d, end, 2);
  d.kw("*CONTROL_CONTACT").card(0.1).kw("").kw("").card(c.ignore);
  const auto lower = d.plate(1, 1, 1, 0, 8, 0, 8, 4, 4, 0.0);
  const auto upper = d.plate(2, 1001, 1001, 2, 6, 2, 6, 2, 2, 0.95);
  d.kw("*SET_NODE_LIST").card(1).ids(lower);
  d.kw("*SET_NODE_LIST").card(2).ids(upper);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 1, 1, 0, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(end / 4, 1.0).card(end, 1.0);
  d.kw("*LOAD_NODE_SET").card(2, 3, 1, -c.load / static_cast<double>(upper.size()));
  d.kw("*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_ID").card(5, "sunk");
  d.card(2, 1, 3, 3).card(0, 0, 0, 0, 20);
  return d.text();
}

TEST(ContactInitialPenetration, Ignore0MovesTheNodesOutBeforeTheRun) {
  const std::string text = sunk_deck({.ignore = 0});
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("deck.k", text));
  ASSERT_TRUE(read.ok());
  const auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty());
  const core::Model& m = *built.model;
  // The upper plate's nodes (ids 1001..) now lie 1 mm above the lower plate: moved 0.05 mm.
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    if (m.node_id[i] >= 1001) {
      EXPECT_NEAR(m.z0[i], 1.0, 1e-12) << m.node_id[i];
    }
  }
  bool warned = false;
  for (const auto& w : built.warnings)
    warned = warned ||
             (w.field == "IGNORE" && w.message.find("9 slave node moves") != std::string::npos);
  EXPECT_TRUE(warned);
  // Nothing pushes the plates apart: the run stays at rest.
  test::DeckRun r;
  test::run_deck(text, r);
  for (const auto& e : r.sink.energies)
    EXPECT_LT(e.kinetic, 1e-12) << "t = " << e.time;
}

TEST(ContactInitialPenetration, Ignore1TracksThePenetrationAndActsBeyondIt) {
  // Unloaded: at rest where it was placed.
  test::DeckRun rest;
  test::run_deck(sunk_deck({.ignore = 1}), rest);
  for (const auto& e : rest.sink.energies)
    EXPECT_LT(e.kinetic, 1e-12) << "t = " << e.time;
  // Loaded: the contact carries the load (statics), pressed in beyond the tracked depth.
  test::DeckRun loaded;
  test::run_deck(sunk_deck({.ignore = 1, .load = 10.0}), loaded);
  double fz = 0.0;
  int n = 0;
  for (const auto& [t, reports] : loaded.sink.contact) {
    if (t < 0.6e-3)
      continue;
    fz += reports.at(0).force[2];
    ++n;
  }
  ASSERT_GT(n, 10);
  EXPECT_NEAR(fz / n, 10.0, 0.05);
  // The penalty's books: what it holds is what the load did on it (no energy from nowhere).
  const auto& last = loaded.sink.contact.back().second.at(0);
  EXPECT_NEAR(last.stored + last.damping, last.work, 0.02 * last.work);
}

// Two plates of two parts meshed in one plane and overlapping (a lap joint drawn coplanar, as
// the crush box deck of ../shared/decks/real has its flanges): every node of the overlap lies in
// the other part's band, penetrating by half the two thicknesses, and no move clears it (each
// plate's nodes are moved into the other's band). Nothing loads the model: it must stay at
// rest, whatever IGNORE says. The penalty used to fire such nodes out (IGNORE 0: what setup
// could not move clear), or a node that took a segment of the other plate's far edge read the
// distance to it as depth (9 kJ within three cycles in the crush box).
TEST(ContactInitialPenetration, CoplanarOverlappingPlatesStayAtRest) {
  for (const int ignore : {0, 1}) {
    SCOPED_TRACE(ignore);
    test::DeckWriter d;
    d.kw("*CONTROL_CONTACT").card(0.1).card("").card("").card(ignore);
    common(d, 2e-5, 2);
    d.plate(1, 1, 1, 0.0, 20.0, 0.0, 10.0, 4, 2, 0.0);
    d.plate(2, 1001, 1001, 12.0, 30.0, 0.0, 10.0, 3, 3, 0.0);
    d.kw("*CONTACT_AUTOMATIC_SINGLE_SURFACE").card(0, 0, 0, 0);
    test::DeckRun r;
    test::run_deck(d.text(), r);
    ASSERT_FALSE(r.sink.energies.empty());
    for (const auto& e : r.sink.energies) {
      EXPECT_LT(e.kinetic, 1e-12) << "t = " << e.time;
      EXPECT_GT(e.contact, -1e-12) << "t = " << e.time;
    }
  }
}

}  // namespace test_contact_single_surface
}  // namespace plyform
