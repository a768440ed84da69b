// Heat across a _THERMAL contact against closed forms: two blocks of different heat capacity
// at different temperatures in contact reach the capacity-weighted mean temperature with the
// time constant C1 C2 / (h A (C1 + C2)); no heat crosses a gap beyond LMAX; a one-way contact
// (ALGO 1) leaves the master's temperature unchanged and brings the slave to it with the time
// constant C2 / (h A); with the outer faces held at two temperatures, the steady faces'
// temperatures and the flux follow the series resistances t1 / k + 1 / h + t2 / k. The heat
// ledger closes in each.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"
#include "thermal_decks.hpp"

namespace plyform {
namespace test_contact_heat {

core::Model build(const std::string& text) {
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("contact_heat.k", text));
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().to_string());
  const auto problems = setup::validate(read.model);
  EXPECT_TRUE(problems.empty()) << problems.front().to_string();
  auto built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  return *built.model;
}

// 10 x 10 mm blocks 1 and 2 mm thick (capacities C1, C2 = 2 C1), conducting well enough
// (k 5000: Biot number 0.004) to stay uniform; h0 = 1e4 W/(m^2 K) over 1e-4 m^2: hA = 1 W/K.
// The slow process of 1 s runs 1000 times faster (TSF 1000) with the mechanics at rest.
constexpr double kA = 0.01, kT1 = 0.001, kT2 = 0.002, kH0 = 1e4;
constexpr double kHot = 400.0, kCold = 300.0;

struct Result {
  engine::RunResult run;
  std::map<double, std::vector<double>> temperature;  // at slow time (t x 1000)
};

Result run_blocks(double gap, double lmax, int algo) {
  test::ThermalControls c;
  c.soln = 2;
  c.end_time = 1e-3;
  c.step = 1e-6;
  c.tsf = 1000.0;
  c.state_dt = 1e-4;
  std::ostringstream extra;
  extra << "*INITIAL_TEMPERATURE_SET\n1," << kHot << "\n2," << kCold << "\n*END\n";
  const core::Model m =
      build(test::thermal_header(c) +
            test::stacked_blocks(kA, kT1, kT2, gap, 5000.0, kH0, 1e-5, lmax, algo) + extra.str());
  Result r;
  test::RecordingSink sink;
  sink.on_state = [&](const engine::Snapshot& s) {
    r.temperature[std::round(s.time * 1e7) / 1e4] = s.nodes->temperature;
  };
  r.run = engine::run(m, sink, {});
  return r;
}

double block_mean(const std::vector<double>& t, int block) {
  double sum = 0.0;
  for (int i = 0; i < 8; ++i)
    sum += t[static_cast<std::size_t>(8 * block + i)];
  return sum / 8.0;
}

TEST(ContactHeat, TwoBlocksReachTheCapacityWeightedMeanWithTheConductanceTimeConstant) {
  const Result r = run_blocks(0.0, 1e-4, 0);
  ASSERT_TRUE(r.run.ok) << r.run.error;
  const double c1 = test::kRho * test::kHeatCapacity * kA * kA * kT1, c2 = 2.0 * c1;
  const double ha = kH0 * kA * kA;
  const double tau = c1 * c2 / (ha * (c1 + c2));
  const double mean = (c1 * kHot + c2 * kCold) / (c1 + c2);
  ASSERT_GT(r.temperature.size(), 8u);
  for (const auto& [t, temp] : r.temperature) {
    const double decay = std::exp(-t / tau);
    const double lower = block_mean(temp, 0), upper = block_mean(temp, 1);
    // The difference decays with tau (1 % of its start), the mean holds.
    EXPECT_NEAR(lower - upper, (kHot - kCold) * decay, 0.01 * (kHot - kCold) * decay + 1e-9)
        << "t = " << t;
    EXPECT_NEAR((c1 * lower + c2 * upper) / (c1 + c2), mean, 1e-6 * mean) << "t = " << t;
  }
  // Between two conducting blocks the contact's heat sums to 0: nothing entered, nothing was
  // stored, while C1 (T1 - mean) crossed the interface.
  const double crossed = c1 * (kHot - mean);
  EXPECT_NEAR(r.run.heat.stored, 0.0, 5e-3 * crossed);
  EXPECT_NEAR(r.run.heat.contact, 0.0, 5e-3 * crossed);
}

TEST(ContactHeat, NoHeatCrossesAGapBeyondLmax) {
  const Result r = run_blocks(2e-4, 1e-4, 0);
  ASSERT_TRUE(r.run.ok) << r.run.error;
  const std::vector<double>& temp = r.temperature.rbegin()->second;
  for (int i = 0; i < 8; ++i) {
    // Unchanged to round-off (a uniform block's conductance gives 1e-12 residuals).
    EXPECT_NEAR(temp[static_cast<std::size_t>(i)], kHot, 1e-9 * kHot);
    EXPECT_NEAR(temp[static_cast<std::size_t>(8 + i)], kCold, 1e-9 * kCold);
  }
}

TEST(ContactHeat, OneWayLeavesTheMasterUnchangedAndBringsTheSlaveToIt) {
  const Result r = run_blocks(0.0, 1e-4, 1);
  ASSERT_TRUE(r.run.ok) << r.run.error;
  const double c2 = 2.0 * test::kRho * test::kHeatCapacity * kA * kA * kT1;
  const double tau = c2 / (kH0 * kA * kA);
  for (const auto& [t, temp] : r.temperature) {
    EXPECT_NEAR(block_mean(temp, 0), kHot, 1e-9 * kHot) << "t = " << t;  // round-off only
    const double expected = kHot - (kHot - kCold) * std::exp(-t / tau);
    EXPECT_NEAR(block_mean(temp, 1), expected, 0.01 * (kHot - expected) + 1e-9) << "t = " << t;
  }
  // The heat the master gave (one-way: from outside the system) is what the slave stored.
  const thermal::HeatLedger& h = r.run.heat;
  EXPECT_GT(h.contact, 0.0);
  EXPECT_NEAR(h.stored, h.contact, 5e-3 * h.moved);
}

// BC_FLG 1: the convection on the two faces that touch is off while they touch (the ledger
// books none, the two blocks keep their heat), on with BC_FLG 0, and on with BC_FLG 1 once
// the faces are apart.
TEST(ContactHeat, BcFlgTurnsTheBoundariesOffWhereTheSidesTouch) {
  const auto run = [](double gap, int bc_flg) {
    test::ThermalControls c;
    c.soln = 2;
    c.end_time = 1e-4;
    c.step = 1e-6;
    c.tsf = 1000.0;
    c.state_dt = 1e-4;
    std::ostringstream extra;
    extra << "*SET_SEGMENT\n7\n5,6,7,8\n9,10,11,12\n*BOUNDARY_CONVECTION_SET\n7\n0,100.0,0,0.0\n";
    extra << "*INITIAL_TEMPERATURE_SET\n1," << kHot << "\n2," << kCold << "\n*END\n";
    const core::Model m = build(
        test::thermal_header(c) +
        test::stacked_blocks(kA, kT1, kT2, gap, 5000.0, kH0, 1e-5, 1e-4, 0, bc_flg) + extra.str());
    test::RecordingSink sink;
    return engine::run(m, sink, {});
  };
  const engine::RunResult off = run(0.0, 1), on = run(0.0, 0), apart = run(2e-4, 1);
  ASSERT_TRUE(off.ok && on.ok && apart.ok) << off.error << on.error << apart.error;
  // The scale: the heat the blocks exchange, C1 (T_hot - T_cold).
  const double scale = test::kRho * test::kHeatCapacity * kA * kA * kT1 * (kHot - kCold);
  EXPECT_EQ(off.heat.convection, 0.0);
  EXPECT_NEAR(off.heat.stored, 0.0, 1e-9 * scale);  // round-off of sum C (T - T0)
  EXPECT_LT(on.heat.convection, -1e-3 * scale);
  EXPECT_LT(apart.heat.convection, -1e-3 * scale);
  for (const engine::RunResult* r : {&off, &on, &apart})
    EXPECT_NEAR(r->heat.stored, r->heat.entered(), 1e-6 * std::max(r->heat.moved, scale));
}

// Steady conduction through the gap conductance: the lower block's bottom face held at T_hot,
// the upper block's top face at T_cold, steel-like blocks (k 50) with h0 = 5e4: the resistances
// t1 / k, 1 / h0 and t2 / k in series (2e-5, 2e-5, 4e-5 m^2 K / W). Slow time 10 s (TSF 1000),
// about 14 of the slowest time constants.
TEST(ContactHeat, SteadyConductionThroughTheGapFollowsTheSeriesResistances) {
  const double k = 50.0, h0 = 5e4;
  test::ThermalControls c;
  c.soln = 2;
  c.end_time = 1e-2;
  c.step = 1e-5;
  c.tsf = 1000.0;
  c.state_dt = 1e-3;
  std::ostringstream extra;
  extra << "*SET_NODE_LIST\n3\n1,2,3,4\n*SET_NODE_LIST\n4\n13,14,15,16\n";
  extra << "*BOUNDARY_TEMPERATURE_SET\n3,0," << kHot << "\n4,0," << kCold << "\n";
  extra << "*INITIAL_TEMPERATURE_SET\n0," << kCold << "\n*END\n";
  const core::Model m =
      build(test::thermal_header(c) +
            test::stacked_blocks(kA, kT1, kT2, 0.0, k, h0, 1e-5, 1e-4, 0) + extra.str());
  std::map<double, std::vector<double>> temperature;
  test::RecordingSink sink;
  sink.on_state = [&](const engine::Snapshot& s) {
    temperature[std::round(s.time * 1e7) / 1e4] = s.nodes->temperature;
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  const double resistance = kT1 / k + 1.0 / h0 + kT2 / k;
  const double q = (kHot - kCold) / resistance;
  const double face_lower = kHot - q * kT1 / k, face_upper = face_lower - q / h0;
  const std::vector<double>& temp = temperature.rbegin()->second;
  const auto mean = [&](int first) {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
      sum += temp[static_cast<std::size_t>(first + i)];
    return sum / 4.0;
  };
  const double lower = mean(4), upper = mean(8);  // nodes 5-8 and 9-12: the two faces
  EXPECT_NEAR(lower, face_lower, 5e-3 * (kHot - kCold));
  EXPECT_NEAR(upper, face_upper, 5e-3 * (kHot - kCold));
  // The flux through each resistance: the lower block, the gap and the upper block.
  EXPECT_NEAR(k * (kHot - lower) / kT1, q, 5e-3 * q);
  EXPECT_NEAR(h0 * (lower - upper), q, 5e-3 * q);
  EXPECT_NEAR(k * (upper - kCold) / kT2, q, 5e-3 * q);
  std::printf(
      "gap conductance: faces %.4f / %.4f K (closed form %.4f / %.4f), flux %.6g W/m^2 "
      "across the gap (closed form %.6g)\n",
      lower, upper, face_lower, face_upper, h0 * (lower - upper), q);
}

}  // namespace test_contact_heat
}  // namespace plyform
