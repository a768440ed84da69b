// LS-DYNA's built-in tiebreak (*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK), end to
// end: a 3 x 3 mm shell plate (one element, its four nodes alike) lying on a fixed plate (the
// two surfaces touch: gap 0 after the half-thickness offsets) is moved by prescribed velocities.
// References: the failure criterion of the keyword manual, (sigma_n / NFLS)^2 + (tau / SFLS)^2
// = 1 with the stresses the tie carried (force over the slave's area), reached within the
// force's growth per cycle; after failure no tension (contact), Coulomb friction mu times the
// normal force; OPTION 4 slides with Coulomb friction while tied; OPTION 1 holds a node that
// touches later with the same spring in tension as in compression (Hooke), and never fails.
// The interface's books close: its work is what its springs hold plus what failure released
// plus friction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact_decks.hpp"

namespace plyform {
namespace test_contact_tiebreak {

constexpr double kE = 2.0e5, kNu = 0.3, kRho = 7.85e-9;
constexpr double kArea = 9.0;  // the slave plate, 3 x 3 mm

struct Tie {
  std::string card = "2,10,20";  // OPTION NFLS SFLS PARAM
  double vx = 0.0, vz = 0.0;     // the slave's velocity [mm/s]
  double end = 2e-4;
  double gap = 0.0;  // initial surface gap of the slave plate
  // A displacement history of the slave in z instead of vz (time, uz pairs), VAD 2.
  std::vector<std::pair<double, double>> uz;
  std::string friction = "0,0";  // FS FD
};

std::string deck(const Tie& c) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(c.end);
  d.kw("*DATABASE_GLSTAT").card(c.end / 2000);
  d.kw("*DATABASE_RCFORC").card(c.end / 2000);
  d.kw("*DATABASE_NODOUT").card(c.end / 200);
  d.kw("*PART").kw("master").card(1, 1, 1);
  d.kw("*PART").kw("slave").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, kRho, kE, kNu);
  const auto master = d.plate(1, 1, 1, 0, 8, 0, 8, 4, 4, 0.0);
  const auto slave = d.plate(2, 1001, 1001, 2.5, 5.5, 2.5, 5.5, 1, 1, 1.0 + c.gap);
  d.kw("*SET_NODE_LIST").card(1).ids(master);
  d.kw("*SET_NODE_LIST").card(2).ids(slave);
  d.kw("*DATABASE_HISTORY_NODE").ids(slave);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 1.0).card(c.end, 1.0);
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 0, 1, c.vx);
  if (!c.uz.empty()) {
    d.kw("*DEFINE_CURVE").card(2);
    for (const auto& [t, u] : c.uz)
      d.card(t, u);
    d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 3, 2, 2, 1.0);
  } else {
    d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 3, 0, 1, c.vz);
  }
  d.kw("*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK_ID").card(7, "tie");
  d.card(2, 1, 3, 3).kw(c.friction).kw("1,1").kw(c.card);
  return d.text();
}

struct Peak {
  double fx = 0.0, fz = 0.0;  // the slave side's force at the largest |F| (tension: fz > 0)
  double time = 0.0;
};

// The force on the slave side is the contact's reaction on it: pulling the slave up (+z) the
// tie pulls it down, so its force is negative; -force is what the tie carries.
Peak peak(const test::DeckRun& r) {
  Peak p;
  double best = -1.0;
  for (const auto& [t, reports] : r.sink.contact) {
    const auto& f = reports.at(0).force;
    const double m = std::hypot(f[0], f[2]);
    if (m > best) {
      best = m;
      p = {-f[0], -f[2], t};
    }
  }
  return p;
}

// The books against the largest energy the interface held or took during the run (a tie that
// was pressed and let go ends with almost no work).
void expect_books_close(const test::DeckRun& r, const char* what) {
  double scale = 0.0;
  for (const auto& [t, reports] : r.sink.contact)
    scale = std::max({scale, std::abs(reports.at(0).work), reports.at(0).stored});
  const auto& last = r.sink.contact.back().second.at(0);
  EXPECT_NEAR(r.sink.energies.back().contact, last.work, 1e-9 * scale) << what;
  EXPECT_NEAR(last.stored + last.damage + last.friction, last.work, 0.01 * scale)
      << what << ": stored " << last.stored << ", damage " << last.damage << ", friction "
      << last.friction;
}

TEST(ContactTiebreak, NormalPullFailsAtNfls) {
  for (const char* card : {"2,10,20", "3,10,20", "4,10"}) {
    Tie c;
    c.card = card;
    c.vz = 20.0;
    test::DeckRun r;
    test::run_deck(deck(c), r);
    const Peak p = peak(r);
    EXPECT_NEAR(p.fz, 10.0 * kArea, 0.01 * 10.0 * kArea) << card;
    EXPECT_NEAR(p.fx, 0.0, 1e-6) << card;
    // Failed: no tension afterwards, the plate leaves freely.
    const auto& last = r.sink.contact.back().second.at(0);
    EXPECT_EQ(last.force[2], 0.0) << card;
    EXPECT_GT(last.damage, 0.0) << card;
    EXPECT_EQ(last.bonded, 0u) << card;
    expect_books_close(r, card);
    // The slave nodes' results (cohesive.csv, the VTU's beta): 1 while tied, 0 once failed.
    ASSERT_FALSE(r.cohesive.empty()) << card;
    for (const auto& [t, nodes] : r.cohesive) {
      ASSERT_EQ(nodes.size(), 4u) << card;
      for (const auto& n : nodes) {
        EXPECT_EQ(n.interface, 7);
        EXPECT_EQ(n.beta, t < p.time ? 1.0 : t > p.time + 1e-6 ? 0.0 : n.beta) << card << " " << t;
      }
    }
    EXPECT_EQ(r.cohesive.front().second.front().beta, 1.0) << card;
    EXPECT_EQ(r.cohesive.back().second.front().beta, 0.0) << card;
  }
}

TEST(ContactTiebreak, ShearFailsAtSfls) {
  Tie c;
  c.vx = 20.0;
  c.end = 4e-4;
  test::DeckRun r;
  test::run_deck(deck(c), r);
  const Peak p = peak(r);
  EXPECT_NEAR(p.fx, 20.0 * kArea, 0.01 * 20.0 * kArea);
  EXPECT_NEAR(p.fz, 0.0, 1e-6 * 20.0 * kArea);
  // No pressure after failure, so no friction either.
  EXPECT_EQ(r.sink.contact.back().second.at(0).force[0], 0.0);
  expect_books_close(r, "");
}

TEST(ContactTiebreak, CombinedLoadFailsOnTheEllipse) {
  Tie c;
  c.vx = 20.0;
  c.vz = 20.0;
  test::DeckRun r;
  test::run_deck(deck(c), r);
  const Peak p = peak(r);
  const double sn = p.fz / kArea, tau = p.fx / kArea;
  // The tangential and normal springs are alike (k_t = k_n): the two stresses grow together.
  EXPECT_NEAR(sn, tau, 1e-3 * tau);
  EXPECT_NEAR(std::hypot(sn / 10.0, tau / 20.0), 1.0, 0.01);
  expect_books_close(r, "");
}

// Pressed (the slave plate pushed 2 micrometres into the tie, then held) and dragged: OPTION 2
// holds the plate until the shear reaches SFLS, then it slides with Coulomb friction; OPTION 4
// slides with friction from the start and stays tied.
TEST(ContactTiebreak, PressedPlateSlidesWithCoulombFrictionAfterFailureOrUnderOption4) {
  for (const char* card : {"2,10,20", "4,10"}) {
    Tie c;
    c.card = card;
    c.friction = "0.2,0.2";
    c.vx = 20.0;
    c.end = 4e-4;
    c.uz = {{0.0, 0.0}, {2e-5, -0.002}, {4e-4, -0.002}};
    test::DeckRun r;
    test::run_deck(deck(c), r);
    // The last quarter: sliding, steady.
    double fx = 0.0, fz = 0.0;
    int n = 0;
    bool held_beyond_friction = false;
    for (const auto& [t, reports] : r.sink.contact) {
      const auto& f = reports.at(0).force;
      if (std::abs(f[0]) > 0.3 * std::abs(f[2]))
        held_beyond_friction = true;
      if (t < 0.75 * c.end)
        continue;
      fx += f[0];
      fz += f[2];
      ++n;
    }
    ASSERT_GT(n, 10);
    fx /= n;
    fz /= n;
    EXPECT_GT(fz, 0.0) << card;                 // compression on the slave
    EXPECT_NEAR(-fx / fz, 0.2, 0.002) << card;  // Coulomb, against the drag
    const auto& last = r.sink.contact.back().second.at(0);
    if (std::string(card).starts_with("2")) {
      EXPECT_TRUE(held_beyond_friction);  // tied in shear until SFLS
      EXPECT_NEAR(peak(r).fx, 20.0 * kArea, 0.01 * 20.0 * kArea);
      EXPECT_GT(last.damage, 0.0);
    } else {
      EXPECT_FALSE(held_beyond_friction);  // sliding while tied
      EXPECT_EQ(last.damage, 0.0);
    }
    expect_books_close(r, card);
  }
}

// OPTION 1: the plate starts 0.2 mm above (beyond the tolerance of initial ties), is pushed
// 2 micrometres into the master surface and pulled back 2 micrometres beyond it. It ties as it
// touches and the tie holds in tension: force against the surface gap is one straight line
// through zero (the same spring both ways), and it never fails. OPTION 2 on the same path does
// not tie (it was not in contact at t = 0): no tension.
TEST(ContactTiebreak, Option1TiesOnContactAndHoldsInTension) {
  for (const char* card : {"1", "2,10,20"}) {
    Tie c;
    c.card = card;
    c.gap = 0.2;
    c.end = 6e-4;
    c.uz = {{0.0, 0.0}, {4e-4, -0.202}, {6e-4, -0.198}};
    test::DeckRun r;
    test::run_deck(deck(c), r);
    // The slave plate moves with the curve: its surface gap at t is 0.2 + uz(t).
    const auto gap_at = [&](double t) {
      const double u = t <= 4e-4 ? -0.202 * t / 4e-4 : -0.202 + 0.004 * (t - 4e-4) / 2e-4;
      return 0.2 + u;
    };
    double k_press = 0.0, k_pull = 0.0, most_tension = 0.0;
    for (const auto& [t, reports] : r.sink.contact) {
      const double fz = reports.at(0).force[2], g = gap_at(t);
      most_tension = std::min(most_tension, fz);
      if (std::abs(g - (-0.0015)) < 1e-4 && t < 4e-4)
        k_press = fz / -g;  // pressing: compression (fz > 0) at penetration -g
      if (std::abs(g - 0.0015) < 2e-5 && t > 4e-4)
        k_pull = fz / -g;  // pulled back: tension (fz < 0) at opening g
    }
    if (std::string(card) == "1") {
      ASSERT_GT(k_press, 0.0);
      EXPECT_NEAR(k_pull, k_press, 0.02 * k_press);
      EXPECT_EQ(r.sink.contact.back().second.at(0).damage, 0.0);
      EXPECT_EQ(r.sink.contact.back().second.at(0).bonded, 4u);
    } else {
      EXPECT_EQ(most_tension, 0.0);
    }
    expect_books_close(r, card);
  }
}

// The contact's normal damping (VDC, percent of critical) acts on a tied node as on any contact
// spring. A one-element plate tied to a fixed rigid plate and let go at 10 mm/s normal to it
// rings on its tie springs alone (its four nodes alike, x, y and the rotations held): a damped
// oscillator, whose amplitude falls by exp(2 pi zeta / sqrt(1 - zeta^2)) per period with zeta =
// VDC / 100, the master being rigid (m* = the slave's mass). The SFS puts the springs well
// below the step's limit (sqrt(k / m) dt about 0.1), where the central differences keep that
// decrement. The damper's work is booked as the contact's work is (work = stored + damping
// within 1e-3; booked as c (dg/dt)^2 dt it was 1.5 % above).
TEST(ContactTiebreak, ContactDampingDecaysATiedNodesVibrationAtItsFractionOfCritical) {
  for (const double vdc : {0.0, 10.0}) {
    test::DeckWriter d;
    const double end = 2e-4;
    d.kw("*CONTROL_TERMINATION").card(end);
    d.kw("*DATABASE_GLSTAT").card(end / 200);
    d.kw("*DATABASE_RCFORC").card(end / 200);
    d.kw("*DATABASE_NODOUT").card(end / 4000);
    d.kw("*PART").kw("fixed rigid plate").card(1, 1, 2);
    d.kw("*PART").kw("tied plate").card(2, 1, 1);
    d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
    d.kw("*MAT_ELASTIC").card(1, kRho, kE, kNu);
    d.kw("*MAT_RIGID").card(2, kRho, kE, kNu).card(1, 7, 7);
    d.plate(1, 1, 1, 0, 8, 0, 8, 4, 4, 0.0);
    const auto slave = d.plate(2, 1001, 1001, 2.5, 5.5, 2.5, 5.5, 1, 1, 1.0);
    d.kw("*SET_NODE_LIST").card(2).ids(slave);
    d.kw("*DATABASE_HISTORY_NODE").ids(slave);
    d.kw("*BOUNDARY_SPC_SET").card(2, 0, 1, 1, 0, 1, 1, 1);
    d.kw("*INITIAL_VELOCITY_NODE");
    for (int n : slave)
      d.card(n, 0.0, 0.0, 10.0);
    d.kw("*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK_ID").card(7, "tie");
    d.card(2, 1, 3, 3).card(0, 0, 0, 0, vdc).card(0.1, 1).card(2, 1e3, 1e3);
    test::DeckRun r;
    test::run_deck(d.text(), r);
    // The peaks of the slave's uz (one node: all four move alike).
    std::vector<std::pair<double, double>> peaks;
    for (std::size_t i = 1; i + 1 < r.uz.size(); ++i) {
      const double a = r.uz[i - 1].second[0], b = r.uz[i].second[0], c = r.uz[i + 1].second[0];
      if (b > a && b >= c)
        peaks.emplace_back(r.uz[i].first, b);
    }
    ASSERT_GE(peaks.size(), 4u) << "VDC " << vdc;
    const double zeta = vdc / 100.0;
    const double per_period = std::exp(-2.0 * M_PI * zeta / std::sqrt(1.0 - zeta * zeta));
    for (std::size_t i = 1; i < 4; ++i)
      EXPECT_NEAR(peaks[i].second / peaks[i - 1].second, per_period, 0.01)
          << "VDC " << vdc << ", peak " << i << " at t = " << peaks[i].first;
    const auto& last = r.sink.contact.back().second.at(0);
    EXPECT_EQ(last.bonded + last.in_contact, 4u) << "VDC " << vdc;  // still tied
    EXPECT_NEAR(last.stored + last.damping, last.work, 1e-3 * last.work) << "VDC " << vdc;
    if (vdc == 0.0) {
      EXPECT_EQ(last.damping, 0.0);
    }
  }
}

// Build: the cohesive law cannot be put on a tiebreak contact (the tie is that interface's law);
// a repeated contact id is a warning naming both contacts.
TEST(ContactTiebreak, CohesiveLawOnATiebreakIsAnErrorAndRepeatedIdsAWarning) {
  const auto build_of = [](const std::string& text) {
    test::TempDir dir;
    const auto read = keyword::read_deck(dir.write("deck.k", text));
    EXPECT_TRUE(read.ok());
    return setup::build(read.model);
  };
  std::string with_law = deck(Tie{});
  with_law.insert(with_law.rfind("*END"),
                  "*USER_INTERFACE_FRICTION\n7,20,0\n1,1e5,1.0,1.0,100.0,200.0,1e-9,0.0\n"
                  "0.0,1.0,0,0,0.2,0.2,0.0,0.0\n0.0,0.0,1e-3,0.0\n");
  const auto b = build_of(with_law);
  ASSERT_FALSE(b.errors.empty());
  EXPECT_EQ(b.errors[0].keyword, "*USER_INTERFACE_FRICTION");
  EXPECT_NE(b.errors[0].message.find("is a tiebreak contact"), std::string::npos)
      << b.errors[0].to_string();

  std::string twice = deck(Tie{});
  twice.insert(twice.rfind("*END"),
               "*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_ID\n7\n2,1,3,3\n");
  const auto w = build_of(twice);
  ASSERT_TRUE(w.errors.empty()) << w.errors[0].to_string();
  bool warned = false;
  for (const auto& d : w.warnings)
    warned =
        warned || d.message.find("contact 7 is also the id of the contact at") != std::string::npos;
  EXPECT_TRUE(warned);
}

}  // namespace test_contact_tiebreak
}  // namespace plyform
