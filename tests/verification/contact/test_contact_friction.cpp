// Penalty contact with friction, end to end (reader, build, engine): a shell plate pressed
// onto a fixed plate by a load and dragged at constant speed. References: the contact force
// carries the load (statics), the friction force is mu times the normal force (Coulomb), mu
// follows LS-DYNA's FD + (FS - FD) exp(-DC v), the master side receives minus the slave side's
// force, the penetration equals load / stiffness of docs/contact.md (SOFT = 0 and 1), and
// automatic contact does not care how the segments are oriented.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact_decks.hpp"

namespace plyform {
namespace {

constexpr double kE = 2.0e5, kNu = 0.3, kRho = 7.85e-9;

struct TwoPlates {
  double end = 3e-3;
  std::string contact = "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID";
  std::string friction = "0.3,0.3,0,0,20";  // FS FD DC VC VDC
  std::string card3 = "1,1";                // SFS SFM ...
  std::string card_a;                       // optional card A (SOFT ...)
  int slave_n = 2;                          // slave shells per side (4 x 4 mm)
  int master_n = 4;                         // master shells per side (8 x 8 mm)
  double slave_size = 4.0;
  double load = 16.0;  // total normal load on the slave plate [N]
  double vx = 10.0;    // drag speed [mm/s]
  bool flip_master = false, flip_slave = false;
  bool split_master = false;  // the master of two parts, x < 4 and x > 4, the second flipped
  int sstyp = 3, mstyp = 3, ssid = 2, msid = 1;
  std::string extra;   // more keywords
  int slave_tmid = 0;  // the slave part's thermal material (friction heating)
};

std::string two_plates(const TwoPlates& c) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(c.end);
  d.kw("*DATABASE_GLSTAT").card(c.end / 300);
  d.kw("*DATABASE_RCFORC").card(c.end / 300);
  d.kw("*DATABASE_NODOUT").card(c.end / 300);
  d.kw("*PART").kw("master").card(1, 1, 1);
  if (c.slave_tmid > 0)
    d.kw("*PART").kw("slave").card(2, 1, 1, 0, 0, 0, 0, c.slave_tmid);
  else
    d.kw("*PART").kw("slave").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, kRho, kE, kNu);
  const double m = 8.0, s0 = 0.5 * (m - c.slave_size);
  std::vector<int> master;
  if (c.split_master) {
    master = d.plate(1, 1, 1, 0, 0.5 * m, 0, m, c.master_n / 2, c.master_n, 0.0, false);
    const auto right =
        d.plate(3, 501, 501, 0.5 * m, m, 0, m, c.master_n / 2, c.master_n, 0.0, true);
    master.insert(master.end(), right.begin(), right.end());
    d.kw("*PART").kw("master, flipped half").card(3, 1, 1);
    d.kw("*SET_PART_LIST").card(9).card(1, 3);
  } else {
    master = d.plate(1, 1, 1, 0, m, 0, m, c.master_n, c.master_n, 0.0, c.flip_master);
  }
  const auto slave = d.plate(2, 1001, 1001, s0, s0 + c.slave_size, s0, s0 + c.slave_size, c.slave_n,
                             c.slave_n, 1.0, c.flip_slave);
  d.kw("*DATABASE_HISTORY_NODE").card(slave[slave.size() / 2]);
  d.kw("*SET_NODE_LIST").card(1).ids(master);
  d.kw("*SET_NODE_LIST").card(2).ids(slave);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(c.end / 6, 1.0).card(c.end, 1.0);
  d.kw("*DEFINE_CURVE").card(2).card(0.0, c.vx).card(c.end, c.vx);
  d.kw("*LOAD_NODE_SET").card(2, 3, 1, -c.load / static_cast<double>(slave.size()));
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 0, 2, 1.0);
  d.kw(c.contact).card(7, "plates");
  d.card(c.ssid, c.msid, c.sstyp, c.mstyp).kw(c.friction).kw(c.card3);
  if (!c.card_a.empty())
    d.kw(c.card_a);
  d.raw(c.extra);
  return d.text();
}

// Time averages over the last third of the run (the load is steady, the drag too).
struct Steady {
  double fx = 0, fy = 0, fz = 0;
};
Steady steady(const test::DeckRun& r, double end) {
  Steady s;
  int n = 0;
  for (const auto& [t, reports] : r.sink.contact) {
    if (t < 2.0 * end / 3.0)
      continue;
    s.fx += reports.at(0).force[0];
    s.fy += reports.at(0).force[1];
    s.fz += reports.at(0).force[2];
    ++n;
  }
  s.fx /= n;
  s.fy /= n;
  s.fz /= n;
  return s;
}

TEST(ContactFriction, LoadIsCarriedAndFrictionIsMuTimesNormalForce) {
  TwoPlates c;
  test::DeckRun r;
  run_deck(two_plates(c), r);
  const Steady s = steady(r, c.end);
  EXPECT_NEAR(s.fz, c.load, 0.005 * c.load);  // statics: the contact carries the load
  EXPECT_NEAR(-s.fx / s.fz, 0.3, 0.003);      // Coulomb, sliding against the drag
  EXPECT_NEAR(s.fy, 0.0, 1e-9 * c.load);
  // Force balance at every output: master side = minus slave side, to round-off.
  for (const auto& [t, reports] : r.sink.contact) {
    const auto& rep = reports.at(0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(
          rep.force[static_cast<std::size_t>(k)] + rep.master_force[static_cast<std::size_t>(k)],
          0.0, 1e-12 * c.load)
          << "t = " << t;
    }
  }
  // The glstat contact energy is the interface's work, which its books account for.
  const auto& last = r.sink.contact.back().second.at(0);
  EXPECT_NEAR(r.sink.energies.back().contact, last.work, 1e-12 * std::abs(last.work));
  EXPECT_NEAR(last.stored + last.friction + last.damping, last.work, 0.01 * last.work);
  EXPECT_GT(last.friction, 0.5 * last.work);
}

// Friction heating (SOLN 2, FRCENG 1, a _THERMAL contact with no conductance, H0 = 0: the slave
// plate is insulated): the heat the slave stores grows at FTOSA times the friction power
// |F_x| v, within 1 %, and is the ledger's friction heat. Steel in mm, t, s: c = 5e8
// mm^2/(s^2 K), k = 50 N/(s K).
TEST(ContactFriction, FrictionHeatsTheInsulatedSlaveAtItsShareOfTheFrictionPower) {
  TwoPlates c;
  c.contact = "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_THERMAL_ID";
  c.card_a = "0,0,0,0,0.1,0.7,0,0";  // the thermal card: K FRAD H0 LMIN LMAX FTOSA BC_FLG ALGO
  c.slave_tmid = 1;
  c.extra =
      "*CONTROL_CONTACT\n0.1\n\n\n0,1\n*CONTROL_SOLUTION\n2\n*CONTROL_THERMAL_TIMESTEP\n"
      "0,0.5,1e-5\n*MAT_THERMAL_ISOTROPIC\n1,0.0\n5e8,50.0\n*INITIAL_TEMPERATURE_SET\n0,293.0\n";
  test::DeckRun r;
  run_deck(two_plates(c), r);
  ASSERT_TRUE(r.result.ok) << r.result.error;
  const Steady s = steady(r, c.end);
  const auto& books = r.sink.heat_books;
  ASSERT_GT(books.size(), 100u);
  // The stored heat's rate over the last third (steady load and drag).
  const auto at = [&](double t) {
    const auto it = std::lower_bound(books.begin(), books.end(), t,
                                     [](const auto& b, double x) { return b.first < x; });
    return *it;
  };
  const auto [t0, h0] = at(2.0 * c.end / 3.0);
  const auto [t1, h1] = books.back();
  const double rate = (h1.stored - h0.stored) / (t1 - t0);
  const double power = std::abs(s.fx) * c.vx;
  EXPECT_NEAR(rate, 0.7 * power, 0.01 * 0.7 * power);
  EXPECT_NEAR(h1.stored, h1.friction, 5e-3 * h1.moved);  // the ledger closes
  EXPECT_GT(h1.friction, 0.0);
}

// A master surface whose segments are not oriented alike (two patches, one flipped, as tool
// meshes put together from several pieces often are): a slave node keeps its physical side as
// it slides from one patch onto the other (its side against the new segment is the one its
// contact normal is on), so the contact carries the load and friction as on one patch, and the
// books close. The slave plate straddles the seam and slides 3 mm across it.
TEST(ContactFriction, SlavesCrossBetweenOppositelyOrientedSegments) {
  TwoPlates c;
  c.split_master = true;
  c.msid = 9;
  c.mstyp = 2;
  c.vx = 1000.0;
  test::DeckRun r;
  run_deck(two_plates(c), r);
  const Steady s = steady(r, c.end);
  EXPECT_NEAR(s.fz, c.load, 0.005 * c.load);
  EXPECT_NEAR(-s.fx / s.fz, 0.3, 0.003);
  const auto& last = r.sink.contact.back().second.at(0);
  EXPECT_NEAR(last.stored + last.friction + last.damping, last.work, 0.01 * last.work);
  for (const auto& e : r.sink.energies)
    EXPECT_GE(e.contact, -1e-9 * std::abs(last.work)) << "t = " << e.time;
}

TEST(ContactFriction, StaticToDynamicDecayFollowsTheExponentialLaw) {
  for (double v : {10.0, 40.0}) {
    TwoPlates c;
    c.friction = "0.4,0.2,0.05,0,20";
    c.vx = v;
    test::DeckRun r;
    run_deck(two_plates(c), r);
    const Steady s = steady(r, c.end);
    const double mu = 0.2 + (0.4 - 0.2) * std::exp(-0.05 * v);
    EXPECT_NEAR(-s.fx / s.fz, mu, 0.01 * mu) << "v = " << v;
  }
}

TEST(ContactFriction, ViscousLimitCapsTheFrictionTraction) {
  TwoPlates c;
  c.friction = "0.3,0.3,0,0.2,20";  // VC = 0.2 MPa < mu P = 0.3 MPa
  test::DeckRun r;
  run_deck(two_plates(c), r);
  const Steady s = steady(r, c.end);
  EXPECT_NEAR(-s.fx, 0.2 * 16.0, 0.01 * 3.2);  // VC times the contact area (16 mm^2)
}

TEST(ContactFriction, NodeSetAndSegmentSetSidesGiveThePartResult) {
  TwoPlates parts;
  test::DeckRun a;
  run_deck(two_plates(parts), a);
  TwoPlates sets = parts;
  sets.sstyp = 4;  // node set 2
  sets.mstyp = 0;  // segment set 5: the master plate's shells, same node order
  sets.ssid = 2;
  sets.msid = 5;
  std::ostringstream seg;
  seg << "*SET_SEGMENT\n5\n";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int n = 1 + j * 5 + i;
      seg << n << "," << n + 1 << "," << n + 6 << "," << n + 5 << "\n";
    }
  sets.extra = seg.str();
  test::DeckRun b;
  run_deck(two_plates(sets), b);
  ASSERT_EQ(a.sink.contact.size(), b.sink.contact.size());
  for (std::size_t i = 0; i < a.sink.contact.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      // The same model to rounding: each side builds its faces' normals (the offset surfaces'
      // directors) from its own corner order, and the stick-slip of the sliding plate carries
      // last-bit differences to about 1e-7 of the force.
      EXPECT_NEAR(a.sink.contact[i].second[0].force[k], b.sink.contact[i].second[0].force[k],
                  1e-6 * 16.0);
    }
  }
}

TEST(ContactFriction, AutomaticContactIgnoresSegmentOrientation) {
  for (bool flip : {false, true}) {
    TwoPlates c;
    c.contact = "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID";
    c.flip_master = flip;
    c.flip_slave = flip;
    test::DeckRun r;
    run_deck(two_plates(c), r);
    const Steady s = steady(r, c.end);
    EXPECT_NEAR(s.fz, c.load, 0.005 * c.load) << "flipped " << flip;
    EXPECT_NEAR(-s.fx / s.fz, 0.3, 0.003) << "flipped " << flip;
    for (const auto& [t, reports] : r.sink.contact) {
      for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(reports[0].force[k] + reports[0].master_force[k], 0.0, 1e-12 * c.load);
    }
  }
}

// One slave shell (2 x 2 mm) on one master shell (8 x 8 mm), 1 N per slave node, held still.
// docs/contact.md: SOFT = 0, PENOPT 1: k = min(slave node share, master segment) with
// segment stiffness SLSFAC K A / (max diagonal); SOFT = 1: max(that, SOFSCL m* / (2 dt0^2)).
double one_element_penetration(const std::string& card_a, test::DeckRun& r) {
  TwoPlates c;
  c.slave_n = 1;
  c.master_n = 1;
  c.slave_size = 2.0;
  c.load = 4.0;
  c.vx = 0.0;
  c.friction = "0,0,0,0,60";
  c.card_a = card_a;
  run_deck(two_plates(c), r);
  double uz = 0.0;
  int n = 0;
  for (const auto& [t, v] : r.uz) {
    if (t >= 2.0 * c.end / 3.0) {
      uz += v.at(0);
      ++n;
    }
  }
  return -uz / n;
}

TEST(ContactStiffness, PenetrationMatchesTheSoft0Formula) {
  test::DeckRun r;
  const double delta = one_element_penetration("", r);
  const double bulk = kE / (3.0 * (1.0 - 2.0 * kNu));
  const double k_slave = 0.1 * bulk * 4.0 / std::sqrt(8.0) / 4.0;  // a quarter of its segment
  const double k_master = 0.1 * bulk * 64.0 / std::sqrt(128.0);
  EXPECT_NEAR(delta, 1.0 / std::min(k_slave, k_master), 0.02 / std::min(k_slave, k_master));
}

TEST(ContactStiffness, PenetrationMatchesTheSoft1Formula) {
  test::DeckRun r;
  const double delta = one_element_penetration("1,0.5", r);
  const double bulk = kE / (3.0 * (1.0 - 2.0 * kNu));
  const double k0 = 0.1 * bulk * 4.0 / std::sqrt(8.0) / 4.0;
  const double ms = kRho * 1.0 * 4.0 / 4.0, mm = kRho * 1.0 * 64.0 / 4.0;  // lumped masses
  const double m_eff = ms * mm / (ms + mm);
  const double dt0 = r.result.dt_first;
  const double k1 = 0.5 * 0.5 * m_eff / (dt0 * dt0);
  ASSERT_GT(k1, 1.5 * k0) << "the test needs the SOFT = 1 stiffness to govern";
  EXPECT_NEAR(delta, 1.0 / k1, 0.02 / k1);
}

}  // namespace
}  // namespace plyform

namespace plyform {
namespace {

// A plate dragged onto the master plate from beyond its edge, its surface 1e-4 mm into the
// master's (held in z), with normal damping: nodes that find their first segment must not feel
// a damping kick from the gap change since they had none (the stand-in gap of a node out of
// reach); the force is then the penalty alone, k delta summed over the slave nodes.
TEST(ContactFriction, NodesArrivingOverAnEdgeFeelNoDampingKick) {
  const double end = 2e-3;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 400);
  d.kw("*DATABASE_RCFORC").card(end / 2000);
  d.kw("*PART").kw("master").card(1, 1, 1);
  d.kw("*PART").kw("slave").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, kRho, kE, kNu);
  const auto master = d.plate(1, 1, 1, 0, 8, 0, 4, 4, 2, 0.0);
  const auto slave = d.plate(2, 1001, 1001, 9, 11, 1, 3, 2, 2, 1.0 - 1e-4);
  d.kw("*SET_NODE_LIST").card(1).ids(master);
  d.kw("*SET_NODE_LIST").card(2).ids(slave);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 1, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0.0, -2000.0).card(end, -2000.0);  // 4 mm in -x
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 0, 1, 1.0);
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(8, "arrival");
  d.card(2, 1, 3, 3).card(0, 0, 0, 0, 50).card(1, 1);
  test::DeckRun r;
  run_deck(d.text(), r);
  // SOFT = 0, PENOPT 1: slave segments (1 mm) are softer than master ones (2 mm); each node
  // takes its share: 4, 2 (edges) or 1 (corners) quarters of 0.1 K A / d of a slave segment.
  const double bulk = kE / (3.0 * (1.0 - 2.0 * kNu));
  const double k_seg = 0.1 * bulk * 1.0 / std::sqrt(2.0);
  const double k_total = k_seg * (4.0 + 4 * 2.0 + 4 * 1.0) / 4.0;
  double worst = 0.0, last = 0.0;
  for (const auto& [t, reports] : r.sink.contact) {
    worst = std::max(worst, std::abs(reports.at(0).force[2]));
    last = reports.at(0).force[2];
  }
  EXPECT_NEAR(last, k_total * 1e-4, 1e-6 * k_total * 1e-4);
  EXPECT_LE(worst, last * (1.0 + 1e-9));
  // The gap never changes once a node is on the plate (z is held): nothing for the damper to
  // dissipate. A kick (one cycle per arriving node, between rcforc outputs) would book
  // c (g_rate)^2 dt A with g_rate ~ reach / dt here.
  EXPECT_LT(r.sink.contact.back().second.at(0).damping, 1e-12);
}

}  // namespace
}  // namespace plyform
