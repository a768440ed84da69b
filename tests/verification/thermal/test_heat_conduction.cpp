// Heat conduction against closed forms: transient conduction in a strip of hexahedra and of
// thin shells between two fixed end temperatures (Fourier series) and its linear steady state;
// a cube and a plate cooling by convection (exp(-h A t / (rho c V))); the thermal speed-up
// factor (a process 1000 times faster with TSF 1000 gives the slow one's temperatures). The
// heat ledger closes in each.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"
#include "thermal_decks.hpp"

namespace plyform {
namespace {

core::Model build(const std::string& text) {
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("thermal.k", text));
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().to_string());
  const auto problems = setup::validate(read.model);
  EXPECT_TRUE(problems.empty()) << problems.front().to_string();
  auto built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  return *built.model;
}

// Temperatures of every node at each state time.
struct Probe {
  std::map<double, std::vector<double>> temperature;
  test::RecordingSink sink;
  Probe() {
    sink.on_state = [this](const engine::Snapshot& s) {
      temperature[s.time] = s.nodes->temperature;
    };
  }
};

// The heat ledger closes: the heat stored equals the heat that entered, within 0.5 % of the
// heat moved.
void expect_ledger_closes(const engine::RunResult& r) {
  const thermal::HeatLedger& h = r.heat;
  ASSERT_GT(h.moved, 0.0);
  EXPECT_NEAR(h.stored, h.entered(), 5e-3 * h.moved)
      << "stored " << h.stored << ", entered " << h.entered() << ", moved " << h.moved;
}

// T(x, t) in a bar of length L at 0 initially, T(0) = T1 and T(L) = 0 from t = 0.
double bar_temperature(double x, double t, double length, double t1, double alpha) {
  double v = t1 * (1.0 - x / length);
  for (int n = 1; n < 2000; ++n) {
    const double k = n * std::numbers::pi / length;
    const double term =
        2.0 * t1 / (n * std::numbers::pi) * std::sin(k * x) * std::exp(-k * k * alpha * t);
    v -= term;
    if (k * k * alpha * t > 50.0)
      break;
  }
  return v;
}

struct StripCase {
  const char* name;
  bool shells;
  int solver;  // 11 direct, 12 conjugate gradients
};

class StripConduction : public ::testing::TestWithParam<StripCase> {};

TEST_P(StripConduction, FollowsTheFourierSeriesAndReachesTheLinearProfile) {
  const bool shells = GetParam().shells;
  const int n = 50;
  const double length = 0.1, a = 0.002, t1 = 100.0;
  const double alpha = test::kConductivity / (test::kRho * test::kHeatCapacity);
  test::ThermalControls c;
  c.end_time = 4000.0;  // 5 L^2 / alpha: the steady state
  c.step = 0.5;
  c.state_dt = 20.0;
  c.solver = GetParam().solver;
  std::string deck = test::thermal_header(c);
  deck += shells ? test::shell_strip(n, length, a, 0.001) : test::hex_strip(n, length, a);
  deck += "*BOUNDARY_TEMPERATURE_SET\n1,0," + std::to_string(t1) + "\n2,0,0.0\n*END\n";
  const core::Model m = build(deck);
  Probe probe;
  const engine::RunResult r = engine::run(m, probe.sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GT(r.thermal_steps, 7000);
  if (c.solver == 12) {
    EXPECT_GT(r.thermal_iterations, 100);  // the iterative solver did the work
  }
  // The 1 % criterion on the range T1 - 0, at every node, at early, middle and late times.
  for (double t : {20.0, 100.0, 300.0, 4000.0}) {
    ASSERT_TRUE(probe.temperature.count(t)) << "no state at t = " << t;
    const std::vector<double>& temp = probe.temperature.at(t);
    double worst = 0.0;
    for (std::size_t i = 0; i < m.node_count(); ++i) {
      const double expected = bar_temperature(m.x0[i], t, length, t1, alpha);
      worst = std::max(worst, std::abs(temp[i] - expected) / t1);
    }
    EXPECT_LT(worst, 0.01) << "t = " << t;
    if (t == 4000.0) {  // the steady state is linear to the solver's precision
      for (std::size_t i = 0; i < m.node_count(); ++i)
        EXPECT_NEAR(temp[i], t1 * (1.0 - m.x0[i] / length), 1e-3) << "node " << m.node_id[i];
    }
  }
  expect_ledger_closes(r);
}

INSTANTIATE_TEST_SUITE_P(Elements, StripConduction,
                         ::testing::Values(StripCase{"hexahedra", false, 11},
                                           StripCase{"shells", true, 11},
                                           StripCase{"hexahedra_cg", false, 12}),
                         [](const auto& p) { return std::string(p.param.name); });

// A body cooling by convection from its faces, uniform through its thickness.
struct ConvectionCase {
  const char* name;
  bool shell;
};

class ConvectionCooling : public ::testing::TestWithParam<ConvectionCase> {};

std::string cooling_body(bool shell, double a, double t_shell) {
  std::string deck = shell ? test::shell_strip(1, a, a, t_shell) : test::hex_strip(1, a, a);
  // Every face of the cube (node ids 4 i + 2 j + k + 1), or the plate's one face.
  if (shell)
    return deck + "*SET_SEGMENT\n7\n1,3,4,2\n";
  return deck + "*SET_SEGMENT\n7\n1,3,4,2\n5,6,8,7\n1,2,6,5\n3,7,8,4\n1,5,7,3\n2,4,8,6\n";
}

double cooling_rate(bool shell, double a, double t_shell, double h) {
  // h A / (rho c V): the cube's six faces over its volume, the plate's one face over A t.
  return shell ? h / (test::kRho * test::kHeatCapacity * t_shell)
               : 6.0 * h / (test::kRho * test::kHeatCapacity * a);
}

TEST_P(ConvectionCooling, FollowsTheExponentialDecay) {
  const bool shell = GetParam().shell;
  const double a = 0.01, t_shell = 0.001, h = 100.0, t_inf = 20.0, t0 = 200.0;
  test::ThermalControls c;
  c.end_time = 100.0;
  c.step = 0.1;
  c.state_dt = 10.0;
  std::ostringstream extra;
  extra << "*INITIAL_TEMPERATURE_SET\n0," << t0 << "\n*BOUNDARY_CONVECTION_SET\n7\n0," << h << ",0,"
        << t_inf << "\n*END\n";
  const core::Model m =
      build(test::thermal_header(c) + cooling_body(shell, a, t_shell) + extra.str());
  Probe probe;
  const engine::RunResult r = engine::run(m, probe.sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  const double rate = cooling_rate(shell, a, t_shell, h);
  for (const auto& [t, temp] : probe.temperature) {
    const double expected = std::exp(-rate * t);
    for (std::size_t i = 0; i < m.node_count(); ++i)
      EXPECT_NEAR((temp[i] - t_inf) / (t0 - t_inf), expected, 5e-3 * expected)
          << "t = " << t << ", node " << m.node_id[i];
  }
  EXPECT_GT(probe.temperature.size(), 10u);
  EXPECT_LT(r.heat.convection, 0.0);  // heat left the body
  expect_ledger_closes(r);
}

INSTANTIATE_TEST_SUITE_P(Bodies, ConvectionCooling,
                         ::testing::Values(ConvectionCase{"cube", false},
                                           ConvectionCase{"plate", true}),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(ThermalSpeedUp, AThousandTimesFasterProcessWithTsf1000GivesTheSlowTemperatures) {
  // The cube cooling for 100 s, once as a thermal-only run and once coupled with the
  // mechanics over 0.1 s with TSF 1000 (thermal step 1e-4 s: 0.1 s of the slow process).
  const double a = 0.01, h = 100.0, t_inf = 20.0, t0 = 200.0;
  std::ostringstream extra;
  extra << "*INITIAL_TEMPERATURE_SET\n0," << t0 << "\n*BOUNDARY_CONVECTION_SET\n7\n0," << h << ",0,"
        << t_inf << "\n*END\n";
  test::ThermalControls slow;
  slow.end_time = 100.0;
  slow.step = 0.1;
  test::ThermalControls fast = slow;
  fast.soln = 2;
  fast.end_time = 0.1;
  fast.step = 1e-4;
  fast.tsf = 1000.0;
  const core::Model ms =
      build(test::thermal_header(slow) + cooling_body(false, a, 0.0) + extra.str());
  const core::Model mf =
      build(test::thermal_header(fast) + cooling_body(false, a, 0.0) + extra.str());
  Probe ps, pf;
  const engine::RunResult rs = engine::run(ms, ps.sink, {});
  const engine::RunResult rf = engine::run(mf, pf.sink, {});
  ASSERT_TRUE(rs.ok) << rs.error;
  ASSERT_TRUE(rf.ok) << rf.error;
  EXPECT_GT(rf.cycles, 10 * rf.thermal_steps);  // many mechanical steps per thermal step
  const double expected = std::exp(-cooling_rate(false, a, 0.0, h) * 100.0);
  const std::vector<double>& ts = ps.temperature.rbegin()->second;
  const std::vector<double>& tf = pf.temperature.rbegin()->second;
  for (std::size_t i = 0; i < ms.node_count(); ++i) {
    EXPECT_NEAR((tf[i] - t_inf) / (t0 - t_inf), expected, 0.01 * expected);
    EXPECT_NEAR(tf[i], ts[i], 0.01 * (ts[i] - t_inf));
  }
  expect_ledger_closes(rf);
}

}  // namespace
}  // namespace plyform
