// Thick thermal shells (*CONTROL_SHELL THSHEL 1) against the closed forms of a slab: a 1 mm
// composite plate quenched by convection on its top face (LOC 1) at a Biot number of 2,
// insulated below, follows the series solution of transient conduction through its thickness
// (bottom, middle and top temperatures); a thin metal skin (Biot 0.005) with the same option
// stays uniform through its thickness and cools as a lumped body. The heat ledger closes. A
// strip whose faces are held 100 apart bends by the thermal curvature alpha dT / t: each
// thickness point of the mechanics reads the profile.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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
  const auto read = keyword::read_deck(dir.write("thick_shells.k", text));
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().to_string());
  const auto problems = setup::validate(read.model);
  EXPECT_TRUE(problems.empty()) << problems.front().to_string();
  auto built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  return *built.model;
}

struct Slab {
  double rho, c, k, thickness, h;
  [[nodiscard]] double diffusivity() const { return k / (rho * c); }
  [[nodiscard]] double biot() const { return h * thickness / k; }
};

// The deck: one square shell (side 10 mm) of the slab's material, thermal only, THSHEL 1,
// convection to 0 on its top face from 100, insulated elsewhere; states every `state_dt`.
std::string slab_deck(const Slab& s, double end_time, double step, double state_dt) {
  std::ostringstream os;
  os.precision(12);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << "\n*CONTROL_SOLUTION\n1\n";
  os << "*CONTROL_THERMAL_SOLVER\n1,0,11\n*CONTROL_THERMAL_TIMESTEP\n0,0.5," << step << "\n";
  os << "*CONTROL_SHELL\n20,0,0,1,2\n1.0,0,0,1,1\n";
  os << "*DATABASE_BINARY_D3PLOT\n" << state_dt << "\n*DATABASE_GLSTAT\n" << state_dt << "\n";
  os << "*MAT_ELASTIC\n1," << s.rho << ",1.0e10,0.3\n";
  os << "*MAT_THERMAL_ISOTROPIC\n1,0.0\n" << s.c << "," << s.k << "\n";
  os << test::shell_strip(1, 0.01, 0.01, s.thickness);
  os << "*SET_SEGMENT\n7\n1,3,4,2\n";
  os << "*BOUNDARY_CONVECTION_SET\n7\n0," << s.h << ",0,0.0,1\n";
  os << "*INITIAL_TEMPERATURE_SET\n0,100.0\n*END\n";
  return os.str();
}

// theta / theta_0 at depth fraction xi from the insulated face (0) to the cooled one (1), at
// Fourier number fo: sum C_n cos(l_n xi) exp(-l_n^2 fo), l_n tan l_n = Bi,
// C_n = 4 sin l_n / (2 l_n + sin 2 l_n).
double slab_solution(double bi, double xi, double fo) {
  double sum = 0.0;
  for (int n = 0; n < 60; ++n) {
    // l_n in (n pi, n pi + pi/2): bisection on l tan l - Bi.
    double lo = n * std::numbers::pi + 1e-12,
           hi = n * std::numbers::pi + std::numbers::pi / 2 - 1e-12;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (mid * std::tan(mid) - bi > 0.0 ? hi : lo) = mid;
    }
    const double l = 0.5 * (lo + hi);
    const double cn = 4.0 * std::sin(l) / (2.0 * l + std::sin(2.0 * l));
    sum += cn * std::cos(l * xi) * std::exp(-l * l * fo);
  }
  return sum;
}

struct Faces {
  std::map<double, std::array<double, 3>> temperature;  // bottom, middle, top (node 1)
  test::RecordingSink sink;
  explicit Faces(double time_unit) {
    sink.on_state = [this, time_unit](const engine::Snapshot& s) {
      ASSERT_FALSE(s.nodes->temperature_top.empty());
      temperature[std::round(s.time / time_unit * 1e6) / 1e6] = {
          s.nodes->temperature_bottom[0], s.nodes->temperature[0], s.nodes->temperature_top[0]};
    };
  }
};

TEST(ThickThermalShell, AQuenchedCompositeFollowsTheSlabSolution) {
  const Slab s{1500.0, 1500.0, 0.5, 0.001, 1000.0};                  // Bi = 2
  const double t_ref = s.thickness * s.thickness / s.diffusivity();  // Fo = t / t_ref
  Faces faces(t_ref);
  const core::Model m = build(slab_deck(s, t_ref, t_ref / 1000.0, 0.05 * t_ref));
  const engine::RunResult r = engine::run(m, faces.sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  double worst = 0.0;
  for (double fo : {0.1, 0.2, 0.5, 1.0}) {
    ASSERT_TRUE(faces.temperature.count(fo)) << "no state at Fo = " << fo;
    const std::array<double, 3>& t = faces.temperature.at(fo);
    for (int level = 0; level < 3; ++level) {
      const double expected = 100.0 * slab_solution(s.biot(), 0.5 * level, fo);
      worst = std::max(worst, std::abs(t[static_cast<std::size_t>(level)] - expected));
      EXPECT_NEAR(t[static_cast<std::size_t>(level)], expected, 2.0)
          << "Fo " << fo << ", level " << level;  // 2 % of the initial difference
    }
  }
  std::printf("thick shell quench, Bi 2: worst error %.3f %% of the initial difference\n", worst);
  EXPECT_NEAR(r.heat.stored, r.heat.entered(), 1e-6 * r.heat.moved);
}

TEST(ThickThermalShell, AThinMetalSkinStaysUniformAndCoolsAsALumpedBody) {
  const Slab s{7800.0, 500.0, 50.0, 0.00025, 1000.0};  // Bi = 0.005
  const double tau = s.rho * s.c * s.thickness / s.h;
  Faces faces(tau);
  const core::Model m = build(slab_deck(s, tau, tau / 500.0, 0.25 * tau));
  const engine::RunResult r = engine::run(m, faces.sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  for (const auto& [t, temp] : faces.temperature) {
    if (t == 0.0)
      continue;
    // A lumped body cools as exp(-t / tau); the profile is within Bi/2 of uniform.
    const double expected = 100.0 * std::exp(-t);
    EXPECT_NEAR(temp[1], expected, 0.005 * 100.0) << "t / tau " << t;
    EXPECT_LT(temp[0] - temp[2], 0.005 * temp[1]) << "t / tau " << t;
    EXPECT_GT(temp[0] - temp[2], 0.0) << "the cooled top is the colder face";
  }
}

// A cantilever strip (50 x 5 x 1 mm, 10 shells, clamped at x = 0 with its rotation about x
// free) with alpha = 1e-5: its top faces brought to 100 and its bottom ones held at 0 over
// 40 ms (a smooth ramp, 13 periods of its first mode), the steady linear profile through the
// thickness makes the free curvature alpha (T_top - T_bottom) / t: the tip deflects by
// -kappa L^2 / 2.
TEST(ThickThermalShell, AGradientThroughTheThicknessBendsAStripByTheThermalCurvature) {
  const double length = 0.05, width = 0.005, t = 0.001, alpha = 1e-5, dtemp = 100.0;
  const double end_time = 0.05;
  std::ostringstream os;
  os.precision(12);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << "\n*CONTROL_SOLUTION\n2\n";
  os << "*CONTROL_THERMAL_SOLVER\n1,0,11\n*CONTROL_THERMAL_TIMESTEP\n0,1.0,1.0e-4\n";
  os << "*CONTROL_SHELL\n20,0,0,1,2\n1.0,0,0,1,1\n";
  os << "*DATABASE_BINARY_D3PLOT\n0.01\n*DATABASE_GLSTAT\n0.01\n";
  os << "*MAT_ELASTIC\n1,7800,2.0e11,0.3\n*MAT_THERMAL_ISOTROPIC\n1,0.0\n500,5000\n";
  os << "*MAT_ADD_THERMAL_EXPANSION\n1,0," << alpha << "\n";
  os << test::shell_strip(10, length, width, t);
  os << "*SET_NODE_LIST\n3\n";
  for (int i = 1; i <= 22; ++i)
    os << i << (i % 8 == 0 || i == 22 ? "\n" : ",");
  // 0.5 (1 - cos(pi t / 0.04)), then held.
  os << "*DEFINE_CURVE\n8\n";
  for (int k = 0; k <= 16; ++k) {
    const double tk = 0.04 * k / 16.0;
    os << tk << "," << 0.5 * (1.0 - std::cos(std::numbers::pi * k / 16.0)) << "\n";
  }
  os << "1.0,1.0\n";
  os << "*BOUNDARY_TEMPERATURE_SET\n3,8," << dtemp << ",1\n3,0,0.0,-1\n";
  os << "*BOUNDARY_SPC_SET\n1,0,1,1,1,0,1,1\n*END\n";
  const core::Model m = build(os.str());
  test::RecordingSink sink;
  double tip = 0.0, top = 0.0, bottom = 0.0, middle = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    tip = 0.5 * (s.nodes->uz[20] + s.nodes->uz[21]);
    top = s.nodes->temperature_top[10];
    bottom = s.nodes->temperature_bottom[10];
    middle = s.nodes->temperature[10];
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NEAR(top, dtemp, 1e-9 * dtemp);
  EXPECT_NEAR(bottom, 0.0, 1e-9 * dtemp);
  EXPECT_NEAR(middle, 0.5 * dtemp, 1e-6 * dtemp);  // the steady profile is linear
  const double kappa = alpha * dtemp / t;
  const double expected = -0.5 * kappa * length * length;
  EXPECT_NEAR(tip, expected, 0.02 * std::abs(expected));
  std::printf("thermal bending: tip %.6g m, closed form %.6g m (%.2f %%)\n", tip, expected,
              100.0 * (tip - expected) / std::abs(expected));
}

// Two thick thermal shells stacked face to face (1 mm steel, mid-surfaces 1 mm apart: the
// faces touch) in a _THERMAL contact with h0 = 5e4, the lower bottom face held at 400 and
// the upper top face at 300: the steady faces across the contact follow the series
// resistances t / k + 1 / h0 + t / k, which only holds when the contact couples the faces that
// touch (not the middles); the contact law reads the slave's touching face.
TEST(ThickThermalShell, HeatCrossesAContactBetweenTheFacesThatTouch) {
  const double t = 0.001, k = 50.0, h0 = 5e4, a = 0.01;
  std::ostringstream os;
  os.precision(12);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n1e-2\n*CONTROL_SOLUTION\n2\n";
  os << "*CONTROL_THERMAL_SOLVER\n1,0,11\n0,0,0,0,0,,,1000\n";
  os << "*CONTROL_THERMAL_TIMESTEP\n0,0.5,1.0e-5\n*CONTROL_SHELL\n20,0,0,1,2\n1.0,0,0,1,1\n";
  os << "*DATABASE_BINARY_D3PLOT\n1e-3\n*DATABASE_GLSTAT\n1e-3\n";
  os << "*MAT_ELASTIC\n1,7800,2.0e11,0.3\n*MAT_THERMAL_ISOTROPIC\n1,0.0\n500," << k << "\n";
  os << "*PART\nlower\n1,1,1,0,0,0,0,1\n*PART\nupper\n2,1,1,0,0,0,0,1\n";
  os << "*SECTION_SHELL\n1,2,0.8333,2\n" << t << "," << t << "," << t << "," << t << "\n";
  os << "*NODE\n";
  int id = 1;
  for (double z : {0.0, t})
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {a, 0.0}, {a, a}, {0.0, a}})
      os << id++ << "," << x << "," << y << "," << z << "\n";
  os << "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,2,5,6,7,8\n";
  os << "*CONTACT_SURFACE_TO_SURFACE_THERMAL\n2,1,3,3\n0,0\n0,0\n0,0," << h0
     << ",1e-5,1e-4,0.5,0,0\n";
  os << "*SET_NODE_LIST\n1\n1,2,3,4\n*SET_NODE_LIST\n2\n5,6,7,8\n";
  os << "*BOUNDARY_TEMPERATURE_SET\n1,0,400.0,-1\n2,0,300.0,1\n";
  os << "*INITIAL_TEMPERATURE_SET\n0,300.0\n*END\n";
  const core::Model m = build(os.str());
  test::RecordingSink sink;
  double lower_top = 0.0, upper_bottom = 0.0, interface = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    lower_top = s.nodes->temperature_top[0];
    upper_bottom = s.nodes->temperature_bottom[4];
    interface = s.nodes->temperature_interface[4];
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  const double q = 100.0 / (t / k + 1.0 / h0 + t / k);
  EXPECT_NEAR(lower_top, 400.0 - q * t / k, 0.5);  // 0.5 % of the difference
  EXPECT_NEAR(upper_bottom, 300.0 + q * t / k, 0.5);
  EXPECT_NEAR(h0 * (lower_top - upper_bottom), q, 5e-3 * q);
  EXPECT_DOUBLE_EQ(interface, upper_bottom);
  std::printf("thick shells in contact: faces %.4f / %.4f (closed form %.4f / %.4f)\n", lower_top,
              upper_bottom, 400.0 - q * t / k, 300.0 + q * t / k);
}

}  // namespace
}  // namespace plyform
