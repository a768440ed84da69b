// The cohesive law inside the contact, end to end: initial bonding (BOND_TOL), the history of
// a slave node surviving its moves from master segment to master segment, a prescribed
// temperature history read by the law, and bit-identical results for 1 and 2 threads.
// References: the law's closed forms (docs/contact-law.md): partial damage leaves
// beta = omega / (C_N g_max^2), no damage while C_N g^2 beta <= omega, sigma_max(T) of the
// two-region cubic.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_decks.hpp"

namespace plyform {
namespace {

constexpr double kCn = 100.0, kSmaxLo = 1.0, kSmaxHi = 0.5, kGc = kSmaxLo / kCn;

struct Bonded {
  double bond_tol = 1e-3;
  double gap0 = 0.0;  // initial surface gap
  double end = 8e-3;
  std::string z_curve;  // time,uz pairs of the slave plate
  std::string x_curve;  // time,ux pairs
  int master_n = 8;     // master shells along x (1 mm each)
  std::string extra;
};

std::string bonded_deck(const Bonded& c) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(c.end);
  d.kw("*DATABASE_RCFORC").card(c.end / 400);
  d.kw("*DATABASE_NODOUT").card(c.end / 400);
  d.kw("*PART").kw("master").card(1, 1, 1);
  d.kw("*PART").kw("slave").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 2.0e5, 0.3);
  const auto master = d.plate(1, 1, 1, 0, c.master_n, 0, 1, c.master_n, 1, 0.0);
  const auto slave = d.plate(2, 1001, 1001, 0.25, 1.25, 0.0, 1.0, 1, 1, 1.0 + c.gap0);
  d.kw("*DATABASE_HISTORY_NODE").card(slave[0]);
  d.kw("*SET_NODE_LIST").card(1).ids(master);
  d.kw("*SET_NODE_LIST").card(2).ids(slave);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).raw(c.z_curve);
  d.kw("*DEFINE_CURVE").card(2).raw(c.x_curve);
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 3, 2, 1, 1.0);
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 2, 2, 1.0);
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(3, "bonded layers");
  d.card(2, 1, 3, 3).card(0).card(1, 1);
  // UC1..UC20: MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL FRIC
  // MU_LO MU_HI VISC_LO VISC_HI FILM_H VDC BETA_MIN CT
  d.kw("*USER_INTERFACE_FRICTION").card(3, 20, 0);
  d.card(1, kCn, kSmaxLo, kSmaxHi, 100.0, 200.0, 1e-9, 0.0);
  d.card(0.0, 1.0, c.bond_tol, 0, 0.2, 0.2, 0.0, 0.0);
  d.card(0.0, 0.0, 1e-3, 0.0);
  d.raw(c.extra);
  return d.text();
}

double pressure_min(const test::DeckRun& r) {
  double p = 0.0;
  for (const auto& [t, v] : r.cohesive)
    for (const auto& n : v)
      p = std::min(p, n.pressure);
  return p;
}

TEST(ContactCohesive, HistorySurvivesMovesToNeighbouringSegments) {
  // Bonded at t = 0, opened to 2 g_c (beta = 1/4), closed to 0.5 g_c (still open: no
  // healing; C_N g^2 beta < omega: no damage), then slid 4 mm across 4 master segments.
  Bonded c;
  c.z_curve = "0,0\n0.002,0.02\n0.003,0.005\n0.008,0.005\n";
  c.x_curve = "0,0\n0.003,0\n0.008,4.0\n";
  test::DeckRun r;
  run_deck(bonded_deck(c), r);
  ASSERT_FALSE(r.cohesive.empty());
  const auto& first = r.cohesive.front().second.at(0);
  EXPECT_NE(first.state, law::NodeState::approaching) << "BOND_TOL bonds the node at t = 0";
  double beta_before_slide = -1.0;
  for (const auto& [t, v] : r.cohesive) {
    if (t <= 0.003)
      beta_before_slide = v.at(0).beta;
  }
  const double expected = (kGc / 0.02) * (kGc / 0.02);  // omega / (C_N g_max^2)
  EXPECT_NEAR(beta_before_slide, expected, 0.02 * expected);
  for (const auto& [t, v] : r.cohesive) {
    if (t < 0.0031)
      continue;
    for (const auto& n : v) {
      EXPECT_EQ(n.beta, beta_before_slide) << "t = " << t << " node " << n.node;
      EXPECT_EQ(n.state, law::NodeState::separating);
      EXPECT_NEAR(n.pressure, -kCn * 0.005 * n.beta * n.beta, 1e-6 * kCn * 0.005);
    }
  }
}

TEST(ContactCohesive, WithoutBondTolANodeOpenAtStartCarriesNoTension) {
  Bonded c;
  c.bond_tol = 0.0;
  c.gap0 = 0.5 * kGc;
  c.end = 3e-3;
  c.z_curve = "0,0\n0.003,0.02\n";
  c.x_curve = "0,0\n0.003,0\n";
  test::DeckRun r;
  run_deck(bonded_deck(c), r);
  EXPECT_EQ(pressure_min(r), 0.0);
  c.bond_tol = 1.0 * kGc;  // now within the tolerance: bonded, full cohesive response
  test::DeckRun b;
  run_deck(bonded_deck(c), b);
  EXPECT_NEAR(-pressure_min(b), kSmaxLo, 0.03 * kSmaxLo);
}

TEST(ContactCohesive, PrescribedTemperatureHistorySetsThePeak) {
  // The slave plate is heated from 20 to 200 degrees (T_HI) before the pull: the peak is
  // SMAX_HI. Then the same at 150: the cubic midpoint (SMAX_LO + SMAX_HI) / 2.
  for (double top : {200.0, 150.0}) {
    Bonded c;
    c.end = 4e-3;
    c.z_curve = "0,0\n0.001,0\n0.004,0.03\n";
    c.x_curve = "0,0\n0.004,0\n";
    std::ostringstream os;
    os << "*INITIAL_TEMPERATURE_SET\n2,20\n*DEFINE_CURVE\n9\n0,20\n0.001," << top << "\n0.004,"
       << top << "\n*BOUNDARY_TEMPERATURE_SET\n2,9,1.0\n";
    c.extra = os.str();
    test::DeckRun r;
    run_deck(bonded_deck(c), r);
    const double s = (top - 100.0) / 100.0;
    const double expected = kSmaxLo + (kSmaxHi - kSmaxLo) * s * s * (3.0 - 2.0 * s);
    EXPECT_NEAR(-pressure_min(r), expected, 0.03 * expected) << "T = " << top;
  }
}

TEST(ContactCohesive, OneAndTwoThreadsGiveTheSameBits) {
  // Enough slave nodes (a 34 x 34 slave plate: 1225 nodes) for the parallel loops and the
  // chunked sums to split.
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(1.6e-4);
  d.kw("*DATABASE_GLSTAT").card(1e-5);
  d.kw("*DATABASE_RCFORC").card(1e-5);
  d.kw("*PART").kw("master").card(1, 1, 1);
  d.kw("*PART").kw("slave").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(0.5, 0.5, 0.5, 0.5);
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 2.0e5, 0.3);
  const auto master = d.plate(1, 1, 1, 0, 18, 0, 18, 24, 24, 0.0);
  const auto slave = d.plate(2, 10001, 10001, 0.5, 17.5, 0.5, 17.5, 34, 34, 0.5);
  d.kw("*SET_NODE_LIST").card(1).ids(master);
  d.kw("*SET_NODE_LIST").card(2).ids(slave);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(1).card(0, 0).card(8e-5, 1).card(1.6e-4, -1);
  d.kw("*DEFINE_CURVE").card(2).card(0, 0).card(4e-5, 1).card(1.6e-4, 1);
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 0, 1, 50.0);
  d.kw("*LOAD_NODE_SET").card(2, 3, 2, -0.05);
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(3, "layers");
  d.card(2, 1, 3, 3).card(0).card(1, 1);
  d.kw("*USER_INTERFACE_FRICTION").card(3, 20, 0);
  d.card(1, kCn, kSmaxLo, kSmaxHi, 100.0, 200.0, 1e-6, 50.0);
  d.card(50.0, 1.0, 1e-3, 0, 0.2, 0.2, 0.0, 0.0);
  d.card(0.0, 10.0, 1e-3, 0.0);
  test::DeckRun one, two;
  run_deck(d.text(), one, 1);
  run_deck(d.text(), two, 2);
  ASSERT_EQ(one.sink.contact.size(), two.sink.contact.size());
  for (std::size_t i = 0; i < one.sink.contact.size(); ++i) {
    const auto& a = one.sink.contact[i].second[0];
    const auto& b = two.sink.contact[i].second[0];
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ(a.force[k], b.force[k]);
    EXPECT_EQ(a.work, b.work);
    EXPECT_EQ(a.damage, b.damage);
    EXPECT_EQ(a.friction, b.friction);
  }
  ASSERT_EQ(one.sink.energies.size(), two.sink.energies.size());
  for (std::size_t i = 0; i < one.sink.energies.size(); ++i)
    EXPECT_EQ(one.sink.energies[i].total, two.sink.energies[i].total);
  EXPECT_GT(one.sink.contact.back().second[0].in_contact, 100u);
}

TEST(ContactCohesive, TwoWayContactWithTheCohesiveLawIsALocatedError) {
  Bonded c;
  c.z_curve = "0,0\n0.001,0\n";
  c.x_curve = "0,0\n0.001,0\n";
  std::string text = bonded_deck(c);
  const std::string one_way = "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID";
  text.replace(text.find(one_way), one_way.size(), "*CONTACT_SURFACE_TO_SURFACE_ID");
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("deck.k", text));
  ASSERT_TRUE(read.ok());
  ASSERT_TRUE(setup::validate(read.model).empty());
  const auto built = setup::build(read.model);
  ASSERT_EQ(built.errors.size(), 1u);
  const keyword::Diagnostic& e = built.errors.front();
  EXPECT_EQ(e.keyword, "*USER_INTERFACE_FRICTION");
  EXPECT_EQ(e.field, "NOSID");
  EXPECT_GT(e.where.line, 0);
  EXPECT_NE(e.message.find("ONE_WAY"), std::string::npos) << e.message;
}

}  // namespace
}  // namespace plyform

namespace plyform {
namespace {

// Two bonded plastic layers stretched together, equibiaxially by 5 %: each thins by about
// 10 % (plastic incompressibility). The cohesive gap is measured between the layer surfaces
// as they are now, so the adhesion pulls the free top layer down by the thinning of both
// half-layers (about 0.1 mm) and the interface stays closed and intact. With the initial
// thicknesses the interface would not see the surfaces part: the top layer would stay where it
// was, 0.1 mm (10 g_c) above a bonded surface, with no tension.
TEST(ContactCohesive, OffsetsFollowTheLayersThinning) {
  const double end = 2e-3, e = 0.05;
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_NODOUT").card(end / 100);
  d.kw("*PART").kw("bottom").card(1, 1, 1);
  d.kw("*PART").kw("top").card(2, 1, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 3).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_PIECEWISE_LINEAR_PLASTICITY").card(1, 7.85e-9, 2.0e5, 0.3, 100.0, 100.0);
  const auto bottom = d.plate(1, 1, 1, 0, 4, 0, 4, 2, 2, 0.0);
  const auto top = d.plate(2, 1001, 1001, 0, 4, 0, 4, 2, 2, 1.0);
  d.kw("*DATABASE_HISTORY_NODE").card(top[4]);
  d.kw("*SET_NODE_LIST").card(1).ids(bottom);
  d.kw("*SET_NODE_LIST").card(2).ids(top);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 0, 0, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 0, 0, 1, 1, 1);
  // u = e x r(t), r a smooth ramp from 0 to 1.
  d.kw("*DEFINE_CURVE").card(1);
  for (int i = 0; i <= 20; ++i) {
    const double s = i / 20.0;
    d.card(s * end, s * s * (3.0 - 2.0 * s));
  }
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_NODE");
  for (const auto* plate : {&bottom, &top}) {
    for (std::size_t k = 0; k < plate->size(); ++k) {
      const double x = 2.0 * static_cast<double>(k % 3), y = 2.0 * static_cast<double>(k / 3);
      d.card((*plate)[k], 1, 2, 1, e * x);
      d.card((*plate)[k], 2, 2, 1, e * y);
    }
  }
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(3, "bonded layers");
  d.card(2, 1, 3, 3).card(0).card(1, 1);
  d.kw("*USER_INTERFACE_FRICTION").card(3, 20, 0);
  d.card(1, kCn, kSmaxLo, kSmaxHi, 100.0, 200.0, 1e-9, 0.0);
  d.card(0.0, 1.0, 1e-3, 0, 0.2, 0.2, 0.0, 0.0);
  d.card(0.0, 20.0, 1e-3, 0.0);
  test::DeckRun r;
  run_deck(d.text(), r);
  ASSERT_FALSE(r.cohesive.empty());
  for (const auto& n : r.cohesive.back().second) {
    EXPECT_GT(n.beta, 0.99) << "node " << n.node;
    EXPECT_LT(std::abs(n.gap), kGc) << "node " << n.node;
  }
  // The top layer came down by the thinning of both half-layers: about 0.1 mm.
  EXPECT_LT(r.uz.back().second.at(0), -0.05);
}

}  // namespace
}  // namespace plyform
