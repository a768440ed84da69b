// Heat through the cohesive interface (the _THERMAL option on a contact with the cohesive law):
// a hot and a cold plate bonded at t = 0 approach the capacity-weighted mean temperature with
// the conductance's time constant C1 C2 / (h A (C1 + C2)) while bonded, and once the slave is
// pulled beyond LMAX (full separation) no heat crosses: both temperatures stay where they were.
// The same with the layers tied by a tiebreak contact (_TIEBREAK_THERMAL) until the tie fails.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact_decks.hpp"

namespace plyform {
namespace test_contact_cohesive_heat {

// mm, tonne, s, K: steel-like plates (rho 7.85e-9, c 5e8 mm^2/(s^2 K)) conducting well (k 5e3,
// so each stays uniform); h0 = 1 N/(s mm K) over the slave's 1 mm^2. The slow process runs 1000
// times faster (TSF 1000): 1 ms of the run is 1 s of heat.
constexpr double kRho = 7.85e-9, kC = 5e8, kH0 = 1.0;
constexpr double kHot = 400.0, kCold = 300.0;

// tiebreak: the layers tied by LS-DYNA's built-in tiebreak (_TIEBREAK_THERMAL, OPTION 2, failing
// at 1 MPa) instead of the cohesive law: the same heat while tied, none once the tie failed and
// the plates are apart.
std::string heated_bond_deck(bool tiebreak = false) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(8e-3);
  d.kw("*DATABASE_NODOUT").card(2.5e-4);
  d.kw("*CONTROL_SOLUTION").card(2);
  d.kw("*CONTROL_THERMAL_SOLVER").card(1, 0, 11).card(0, 0, 0, 0, 0, "", "", 1000.0);
  d.kw("*CONTROL_THERMAL_TIMESTEP").card(0, 0.5, 2e-6);
  d.kw("*MAT_THERMAL_ISOTROPIC").card(1, 0.0).card(kC, 5e3);
  d.kw("*PART").kw("master").card(1, 1, 1, 0, 0, 0, 0, 1);
  d.kw("*PART").kw("slave").card(2, 1, 1, 0, 0, 0, 0, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, kRho, 2.0e5, 0.3);
  // The master [0, 2] x [0, 1] (capacity 2 C), the slave [0.25, 1.25] x [0, 1] (C) above it.
  const auto master = d.plate(1, 1, 1, 0, 2, 0, 1, 2, 1, 0.0);
  const auto slave = d.plate(2, 1001, 1001, 0.25, 1.25, 0.0, 1.0, 1, 1, 1.0);
  d.kw("*DATABASE_HISTORY_NODE").card(slave[0]);
  d.kw("*SET_NODE_LIST").card(1).ids(master);
  d.kw("*SET_NODE_LIST").card(2).ids(slave);
  d.kw("*INITIAL_TEMPERATURE_SET").card(1, kHot).card(2, kCold);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 1, 1, 0, 1, 1, 1);
  // Bonded until 4 ms, then pulled 0.5 mm away (far beyond the law's full separation and
  // LMAX 0.1) by 5 ms, held there.
  d.kw("*DEFINE_CURVE").card(1).raw("0,0\n0.004,0\n0.005,0.5\n0.008,0.5\n");
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 3, 2, 1, 1.0);
  if (tiebreak) {
    d.kw("*CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK_THERMAL_ID").card(3, "tied");
    d.card(2, 1, 3, 3).card(0).card(1, 1).card(2, 1.0, 1.0);
    d.card(0.0, 0.0, kH0, 1e-5, 0.1, 0.5, 0, 0);
    return d.text();
  }
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_THERMAL_ID").card(3, "bonded layers");
  d.card(2, 1, 3, 3).card(0).card(1, 1);
  d.card(0.0, 0.0, kH0, 1e-5, 0.1, 0.5, 0, 0);  // K FRAD H0 LMIN LMAX FTOSA BC_FLG ALGO
  // UC1..UC20: MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL FRIC
  // MU_LO MU_HI VISC_LO VISC_HI FILM_H VDC BETA_MIN CT
  d.kw("*USER_INTERFACE_FRICTION").card(3, 20, 0);
  d.card(1, 100.0, 1.0, 0.5, 100.0, 200.0, 1e-9, 0.0);
  d.card(0.0, 1.0, 1e-3, 0, 0.2, 0.2, 0.0, 0.0);
  d.card(0.0, 0.0, 1e-3, 0.0);
  return d.text();
}

double mean(const std::vector<double>& t, std::size_t first, std::size_t count) {
  double s = 0.0;
  for (std::size_t i = first; i < first + count; ++i)
    s += t[i];
  return s / static_cast<double>(count);
}

void expect_heat_while_bonded_only(bool tiebreak) {
  const char* what = tiebreak ? "tiebreak" : "cohesive";
  test::DeckRun r;
  run_deck(heated_bond_deck(tiebreak), r);
  ASSERT_FALSE(r.temperature.empty());
  const double c_slave = kRho * kC * 1.0 * 1.0 * 1.0, c_master = 2.0 * c_slave;
  const double tau = c_master * c_slave / (kH0 * 1.0 * (c_master + c_slave));  // slow seconds
  const double mean_t = (c_master * kHot + c_slave * kCold) / (c_master + c_slave);
  double at_separation = -1.0, apart = -1.0, worst = 0.0;
  for (const auto& [time, temp] : r.temperature) {
    const double lower = mean(temp, 0, 6), upper = mean(temp, 6, 4);  // 6 master, 4 slave nodes
    EXPECT_NEAR((c_master * lower + c_slave * upper) / (c_master + c_slave), mean_t, 1e-6 * mean_t);
    const double slow = time * 1000.0;
    if (time <= 0.004 + 1e-9) {
      const double expected = (kHot - kCold) * std::exp(-slow / tau);
      EXPECT_NEAR(lower - upper, expected, 0.01 * expected)
          << what << ", bonded, t = " << slow << " s";
      worst = std::max(worst, std::abs(lower - upper - expected) / expected);
      at_separation = lower - upper;
    } else if (time >= 0.005 - 1e-9) {
      // Separated beyond LMAX: the difference left (less what crossed while the gap opened)
      // stays to round-off.
      if (apart < 0.0)
        apart = lower - upper;
      EXPECT_GT(lower - upper, 0.5 * at_separation) << what;
      EXPECT_NEAR(lower - upper, apart, 1e-9 * kHot) << what << ", separated, t = " << slow;
    }
  }
  std::printf("%s interface heat: worst %.3f %% of the bonded decay, %.3f K left apart\n", what,
              100.0 * worst, at_separation);
  EXPECT_GT(at_separation, 0.0) << what;
}

TEST(ContactCohesiveHeat, HeatCrossesWhileBondedAndNotOnceSeparated) {
  expect_heat_while_bonded_only(false);
}

TEST(ContactCohesiveHeat, HeatCrossesATiebreakWhileTiedAndNotOnceItFailed) {
  expect_heat_while_bonded_only(true);
}

}  // namespace test_contact_cohesive_heat
}  // namespace plyform
