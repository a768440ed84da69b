// The metal plasticity laws in one element through the whole chain (reader, validation, build,
// engine), against closed forms in uniaxial stress (SI units, steel, a 10 mm element loaded
// slowly: thousands of wave transits, quasi-static):
//  - *MAT_PLASTIC_KINEMATIC, a hexahedron and a shell pulled to 1 % true strain, pushed to
//    -1 %, pulled back: every state's stress against the 1D closed form of bilinear mixed
//    hardening along the element's own strain path, and the reverse yield stress against
//    sigma_max - 2 SIGY (BETA 0), -sigma_max (BETA 1), sigma_max - 2 (SIGY + BETA E_p e1)
//    (between), all within 1 % of sigma_max;
//  - its Cowper-Symonds factor in a hexahedron pulled at two strain rates (perfectly plastic:
//    sigma = SIGY (1 + (rate / C)^(1/P)), rate = sqrt(D : D) = sqrt(3/2) D_xx in plastic flow),
//    and the factor of *MAT_003, *MAT_PIECEWISE_LINEAR_PLASTICITY and *MAT_POWER_LAW_PLASTICITY
//    in a hexahedron and a shell at three rates;
//  - *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC, a shell pulled in x, free in y: the plastic
//    width-to-thickness strain ratio is R.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace {

constexpr double kE = 2.0e11, kNu = 0.3, kRho = 7800.0, kSigy = 2.5e8, kEtan = 2.0e9;
constexpr double kSide = 0.01, kThickness = 0.001;
const double kEp = kE * kEtan / (kE - kEtan);

core::Model build(const std::string& text) {
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("metal.k", text));
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().to_string());
  const auto problems = setup::validate(read.model);
  EXPECT_TRUE(problems.empty()) << problems.front().to_string();
  auto built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  return *built.model;
}

enum class Body { hex, shell };

// One element in uniaxial stress along x: a cube of side kSide (nodes 4 i + 2 j + k + 1 at
// (i, j, k) kSide) or a square shell (nodes 2 i + j + 1 at (i, j) kSide), the x = 0 face held in
// x, the y = 0 (and z = 0) faces in y (z), the x = kSide face (set 2) moved by the velocity
// curve 7 (`velocity` as (time, velocity) points).
std::string deck(Body b, const std::string& material, double end_time, int states,
                 const std::vector<std::pair<double, double>>& velocity) {
  std::ostringstream os;
  os.precision(12);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << "\n";
  os << "*DATABASE_BINARY_D3PLOT\n" << end_time / states << "\n";
  os << material;
  if (b == Body::shell) {
    os << "*PART\nsheet\n1,1,1\n*SECTION_SHELL\n1,2,0.8333,2\n"
       << kThickness << "," << kThickness << "," << kThickness << "," << kThickness << "\n";
    os << "*NODE\n1,0,0,0\n2,0," << kSide << ",0\n3," << kSide << ",0,0\n4," << kSide << ","
       << kSide << ",0\n*ELEMENT_SHELL\n1,1,1,3,4,2\n";
    os << "*SET_NODE_LIST\n1\n1,2\n*SET_NODE_LIST\n2\n3,4\n*SET_NODE_LIST\n3\n1,2,3,4\n";
    os << "*BOUNDARY_SPC_SET\n1,0,1,0,1,0,0,0\n*BOUNDARY_SPC_NODE\n1,0,0,1,0\n3,0,0,1,0\n";
    os << "*BOUNDARY_SPC_SET\n3,0,0,0,1,0,0,0\n";
  } else {
    os << "*PART\ncube\n1,1,1\n*SECTION_SOLID\n1,1\n*NODE\n";
    for (int i = 0; i <= 1; ++i)
      for (int j = 0; j <= 1; ++j)
        for (int k = 0; k <= 1; ++k)
          os << 4 * i + 2 * j + k + 1 << "," << kSide * i << "," << kSide * j << "," << kSide * k
             << "\n";
    os << "*ELEMENT_SOLID\n1,1,1,5,7,3,2,6,8,4\n";
    os << "*SET_NODE_LIST\n1\n1,2,3,4\n*SET_NODE_LIST\n2\n5,6,7,8\n";
    os << "*SET_NODE_LIST\n4\n1,2,5,6\n*SET_NODE_LIST\n5\n1,3,5,7\n";
    os << "*BOUNDARY_SPC_SET\n1,0,1,0,0\n*BOUNDARY_SPC_SET\n4,0,0,1,0\n";
    os << "*BOUNDARY_SPC_SET\n5,0,0,0,1\n";
  }
  os << "*DEFINE_CURVE\n7\n";
  for (const auto& [t, v] : velocity)
    os << t << "," << v << "\n";
  os << "*BOUNDARY_PRESCRIBED_MOTION_SET\n2,1,0,7,1.0\n*END\n";
  return os.str();
}

// What each state shows: the axial true strain, the axial stress, the effective plastic
// strain, the width strain and the thickness strain (shells).
struct State {
  double strain, stress, eps_p, width, thickness;
  double rate;  ///< sqrt(D : D) from the nodes' velocities (a shell's D_zz = -(D_xx + D_yy))
};

std::vector<State> run(Body b, const std::string& text) {
  const core::Model m = build(text);
  std::vector<State> states;
  test::RecordingSink sink;
  sink.on_state = [&](const engine::Snapshot& s) {
    State st{};
    const std::size_t far = b == Body::shell ? 2 : 4;  // node 3 (shell), node 5 (hex)
    st.strain = std::log(1.0 + s.nodes->ux[far] / kSide);
    // The rate of deformation from the far nodes' velocities at the state (stretch rates of
    // the element's sides).
    const auto stretch = [&](std::size_t i, const std::vector<double>& u,
                             const std::vector<double>& v) { return v[i] / (kSide + u[i]); };
    const double dxx = stretch(far, s.nodes->ux, s.nodes->vnx);
    const double dyy = b == Body::shell ? stretch(1, s.nodes->uy, s.nodes->vny)
                                        : stretch(2, s.nodes->uy, s.nodes->vny);
    const double dzz = b == Body::shell ? -(dxx + dyy) : stretch(1, s.nodes->uz, s.nodes->vnz);
    st.rate = std::sqrt(dxx * dxx + dyy * dyy + dzz * dzz);
    if (b == Body::shell) {
      const auto& blk = s.shells->front();
      st.stress = blk.s[0].front();
      st.eps_p = blk.eps_p.front();
      st.width = std::log(1.0 + s.nodes->uy[3] / kSide);  // node 4 at y = kSide
      st.thickness = std::log(blk.thickness.front() / kThickness);
    } else {
      st.stress = s.solids->front().s[0].front();
      st.eps_p = s.solids->front().eps_p.front();
    }
    states.push_back(st);
  };
  const engine::RunResult r = engine::run(m, sink, {});
  EXPECT_TRUE(r.ok) << r.error;
  return states;
}

// The far face's velocity for a constant true strain rate r over [0, end] (it grows with the
// length), after a linear ramp over the first 5 %: 40 points of the curve.
std::vector<std::pair<double, double>> constant_rate_pull(double rate, double end) {
  std::vector<std::pair<double, double>> velocity{{0.0, 0.0}};
  for (int i = 1; i <= 40; ++i) {
    const double t = end * i / 40.0;
    const double ramp = std::min(1.0, t / (0.05 * end));
    velocity.emplace_back(t, ramp * rate * kSide * std::exp(rate * t));
  }
  return velocity;
}

std::string mat003(double beta, double etan, double src = 0.0, double srp = 0.0) {
  std::ostringstream os;
  os.precision(12);
  os << "*MAT_PLASTIC_KINEMATIC\n1," << kRho << "," << kE << "," << kNu << "," << kSigy << ","
     << etan << "," << beta << "\n"
     << src << "," << srp << "\n";
  return os.str();
}

// The 1D closed form of bilinear mixed hardening in uniaxial stress, exact along any
// piecewise-linear strain path (linear hardening): stress, back stress, yield radius.
struct Uniaxial {
  double beta;
  double sigma = 0.0, back = 0.0, radius = kSigy, strain = 0.0;
  void to(double e) {
    const double trial = sigma + kE * (e - strain);
    strain = e;
    const double over = std::abs(trial - back) - radius;
    if (over <= 0.0) {
      sigma = trial;
      return;
    }
    const double dp = over / (kE + kEp), sign = trial > back ? 1.0 : -1.0;
    sigma = trial - sign * kE * dp;
    back += sign * (1.0 - beta) * kEp * dp;
    radius += beta * kEp * dp;
  }
};

struct LoopCase {
  Body body;
  double beta;
};

class KinematicLoop : public ::testing::TestWithParam<LoopCase> {};

TEST_P(KinematicLoop, FollowsTheClosedFormAndReversesWhereItSays) {
  const auto [b, beta] = GetParam();
  const double end = 0.01, e_a = 0.01;
  const double v = e_a * kSide / (0.24 * end);
  const std::vector<std::pair<double, double>> velocity{
      {0.0, 0.0},       {0.02 * end, v}, {0.24 * end, v}, {0.26 * end, -v},
      {0.74 * end, -v}, {0.76 * end, v}, {end, v}};
  const std::vector<State> states = run(b, deck(b, mat003(beta, kEtan), end, 400, velocity));
  ASSERT_GT(states.size(), 300u);
  // The closed form along the element's strain path.
  Uniaxial ref{beta};
  double sigma_max = 0.0, e1 = 0.0, worst = 0.0;
  std::size_t peak = 0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    ref.to(states[i].strain);
    worst = std::max(worst, std::abs(states[i].stress - ref.sigma));
    if (states[i].stress > sigma_max && i < states.size() / 2) {
      sigma_max = states[i].stress;
      e1 = states[i].eps_p;
      peak = i;
    }
  }
  EXPECT_LT(worst, 0.01 * sigma_max) << "largest stress difference " << worst;
  // The reverse yield: the first state in compression-going flow (past the elastic unloading
  // by SIGY, below any reverse yield stress the closed forms allow: sigma_max - 2 k <
  // sigma_max - SIGY) whose plastic strain grew, less the hardening of that growth (exact in
  // uniaxial stress with linear hardening).
  double reverse = 0.0;
  for (std::size_t i = peak + 1; i < states.size(); ++i) {
    if (states[i].stress < sigma_max - kSigy && states[i].eps_p > states[i - 1].eps_p + 1e-12) {
      reverse = states[i].stress + kEp * (states[i].eps_p - states[i - 1].eps_p);
      break;
    }
  }
  const double closed = sigma_max - 2.0 * (kSigy + beta * kEp * e1);
  if (beta == 0.0) {
    EXPECT_NEAR(closed, sigma_max - 2.0 * kSigy, 1e-9 * kSigy);
  }
  if (beta == 1.0) {
    EXPECT_NEAR(closed, -sigma_max, 0.002 * sigma_max);  // sigma_max = SIGY + E_p e1
  }
  EXPECT_NEAR(reverse, closed, 0.01 * sigma_max)
      << "sigma_max " << sigma_max << ", e1 " << e1 << ", reverse yield " << reverse;
  RecordProperty("reverse_yield_error", std::to_string((reverse - closed) / sigma_max));
  RecordProperty("loop_error", std::to_string(worst / sigma_max));
}

INSTANTIATE_TEST_SUITE_P(Elements, KinematicLoop,
                         ::testing::Values(LoopCase{Body::hex, 0.0}, LoopCase{Body::hex, 0.5},
                                           LoopCase{Body::hex, 1.0}, LoopCase{Body::shell, 0.0},
                                           LoopCase{Body::shell, 0.5}, LoopCase{Body::shell, 1.0}),
                         [](const auto& p) {
                           return std::string(p.param.body == Body::hex ? "hex" : "shell") +
                                  "_beta_" + std::to_string(static_cast<int>(10 * p.param.beta));
                         });

// Perfectly plastic (ETAN 0, BETA 1) with C = 40/s, P = 5, pulled at a constant true strain
// rate r (the velocity grows with the length): in plastic flow D = r (1, -1/2, -1/2), so the
// flow stress is SIGY (1 + (sqrt(3/2) r / C)^(1/P)).
TEST(PlasticKinematicRate, HexFlowStressFollowsCowperSymondsAtTwoRates) {
  const double c = 40.0, p = 5.0;
  for (const double rate : {20.0, 400.0}) {
    const double end = 0.03 / rate;  // 3 % strain
    const std::vector<std::pair<double, double>> velocity = constant_rate_pull(rate, end);
    const std::vector<State> states =
        run(Body::hex, deck(Body::hex, mat003(1.0, 0.0, c, p), end, 60, velocity));
    const double want = kSigy * (1.0 + std::pow(std::sqrt(1.5) * rate / c, 1.0 / p));
    int checked = 0;
    double worst = 0.0;
    for (const State& s : states) {
      if (s.strain > 0.015) {
        EXPECT_NEAR(s.stress, want, 0.01 * want) << "rate " << rate << ", strain " << s.strain;
        worst = std::max(worst, std::abs(s.stress - want) / want);
        ++checked;
      }
    }
    EXPECT_GE(checked, 10);
    RecordProperty("rate_error_" + std::to_string(static_cast<int>(rate)), std::to_string(worst));
  }
}

// *MAT_037 pulled in x to 6 %, free in y: between 1.5 % and the end the plastic width and
// thickness strains (the totals less the elastic -nu sigma / E of each) grow in the ratio R.
TEST(TransverselyAnisotropic, UniaxialTensionGivesThePlasticStrainRatioR) {
  for (const double r : {0.6, 1.8}) {
    std::ostringstream mat;
    mat.precision(12);
    mat << "*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC\n1," << kRho << "," << kE << "," << kNu
        << "," << kSigy << "," << kEtan << "," << r << "\n";
    const double end = 0.01;
    const double v = 0.06 * kSide / (0.95 * end);
    const std::vector<State> states =
        run(Body::shell,
            deck(Body::shell, mat.str(), end, 100, {{0.0, 0.0}, {0.1 * end, v}, {end, v}}));
    const State* a = nullptr;
    for (const State& s : states) {
      if (a == nullptr && s.strain > 0.015)
        a = &s;
    }
    ASSERT_NE(a, nullptr);
    const State& z = states.back();
    const auto plastic = [](double total, double stress) { return total + kNu * stress / kE; };
    const double dw = plastic(z.width, z.stress) - plastic(a->width, a->stress);
    const double dt = plastic(z.thickness, z.stress) - plastic(a->thickness, a->stress);
    EXPECT_NEAR(dw / dt, r, 0.01 * r) << "width " << dw << ", thickness " << dt;
    RecordProperty("r_error_" + std::to_string(r), std::to_string((dw / dt - r) / r));
  }
}

}  // namespace
}  // namespace plyform

namespace plyform {
namespace {

// Cowper-Symonds on every law that takes it, in a hexahedron and a shell, at three rates: each
// pulled at a constant true strain rate r to 3 %; in plastic flow D = r (1, -1/2, -1/2) (the
// shell's D_zz taken as -(D_xx + D_yy), which it is in that flow), so the flow stress is
// sigma_y(eps_p) (1 + (sqrt(3/2) r / C)^(1/P)), the yield curve read at the state's own
// plastic strain. C = 40/s, P = 5: factors 1.66, 2.04 and 2.65 at 4, 40 and 400/s.
struct RateCase {
  const char* name;
  std::string card;                     // the material
  std::function<double(double)> yield;  // sigma_y(eps_p)
};

std::vector<RateCase> rate_cases() {
  const double c = 40.0, p = 5.0, k = 3.0e8, n = 0.1;
  std::ostringstream m024, m018;
  m024.precision(12);
  m018.precision(12);
  m024 << "*MAT_PIECEWISE_LINEAR_PLASTICITY\n1," << kRho << "," << kE << "," << kNu << "," << kSigy
       << ",0.0\n"
       << c << "," << p << "\n";
  m018 << "*MAT_POWER_LAW_PLASTICITY\n1," << kRho << "," << kE << "," << kNu << "," << k << "," << n
       << "," << c << "," << p << "\n";
  // *MAT_018 without SIGY: eps_yp where the power law meets the elastic line.
  const double e0 = std::pow(kE / k, 1.0 / (n - 1.0));
  return {{"mat003", mat003(1.0, 0.0, c, p), [](double) { return kSigy; }},
          {"mat024", m024.str(), [](double) { return kSigy; }},
          {"mat018", m018.str(), [=](double e) { return k * std::pow(e0 + e, n); }}};
}

// *MAT_024 with LCSS naming a *DEFINE_TABLE of yield curves by strain rate (here flat, perfectly
// plastic curves at four rates, the values given as rates or, when the first is negative, as
// their natural logarithms): in plastic flow at the constant true strain rate r the point's rate
// is sqrt(3/2) r, and the flow stress is the table's curves read linearly in the value (rate or
// log rate) between the two around it, within 1 %.
TEST(RateTable, FlowStressIsTheTablesCurveAtThePointsRate) {
  const std::vector<double> rates{1.0, 50.0, 300.0, 1000.0};
  const std::vector<double> yields{2.5e8, 3.0e8, 3.6e8, 4.2e8};
  for (const bool logarithmic : {false, true}) {
    std::ostringstream m024;
    m024.precision(12);
    m024 << "*MAT_PIECEWISE_LINEAR_PLASTICITY\n1," << kRho << "," << kE << "," << kNu
         << ",0.0,0.0\n"
         << "0,0,10\n*DEFINE_TABLE\n10\n";
    // In log form the first value is ln(0.01) < 0 (LS-DYNA's sign of the convention).
    std::vector<double> values = rates;
    if (logarithmic) {
      values.front() = 0.01;
      for (double& v : values)
        v = std::log(v);
    }
    for (std::size_t i = 0; i < values.size(); ++i)
      m024 << values[i] << "," << 11 + i << "\n";
    for (std::size_t i = 0; i < values.size(); ++i)
      m024 << "*DEFINE_CURVE\n" << 11 + i << "\n0.0," << yields[i] << "\n1.0," << yields[i] << "\n";
    const auto want_at = [&](double rate) {
      const double x = logarithmic ? std::log(rate) : rate;
      std::size_t i = 0;
      while (i + 2 < values.size() && x > values[i + 1])
        ++i;
      const double w = std::clamp((x - values[i]) / (values[i + 1] - values[i]), 0.0, 1.0);
      return (1.0 - w) * yields[i] + w * yields[i + 1];
    };
    for (const Body body : {Body::hex, Body::shell}) {
      for (const double rate : {20.0, 100.0, 400.0}) {
        SCOPED_TRACE(std::string(logarithmic ? "log values" : "rate values") +
                     (body == Body::hex ? " hex" : " shell") + ", rate " + std::to_string(rate));
        const double end = 0.03 / rate;
        const std::vector<std::pair<double, double>> velocity = constant_rate_pull(rate, end);
        const std::vector<State> states = run(body, deck(body, m024.str(), end, 60, velocity));
        const double want = want_at(std::sqrt(1.5) * rate);
        double worst = 0.0;
        int checked = 0;
        for (const State& st : states) {
          if (st.strain > 0.015) {
            worst = std::max(worst, std::abs(st.stress - want) / want);
            ++checked;
          }
        }
        EXPECT_GE(checked, 10);
        EXPECT_LT(worst, 0.01);
        std::printf("rate table (%s) %s at %g/s: flow stress %.4g MPa within %.2e\n",
                    logarithmic ? "log" : "linear", body == Body::hex ? "hex" : "shell", rate,
                    want * 1e-6, worst);
      }
    }
  }
}

TEST(CowperSymonds, FlowStressFollowsTheFactorOnEveryLawAndElementAtThreeRates) {
  const double c = 40.0, p = 5.0;
  for (const RateCase& law : rate_cases()) {
    for (const Body body : {Body::hex, Body::shell}) {
      for (const double rate : {20.0, 100.0, 400.0}) {
        SCOPED_TRACE(std::string(law.name) + (body == Body::hex ? " hex" : " shell") + ", rate " +
                     std::to_string(rate));
        const double end = 0.03 / rate;  // 3 % strain
        const std::vector<std::pair<double, double>> velocity = constant_rate_pull(rate, end);
        const std::vector<State> states = run(body, deck(body, law.card, end, 60, velocity));
        const double factor = 1.0 + std::pow(std::sqrt(1.5) * rate / c, 1.0 / p);
        int checked = 0;
        double worst = 0.0, worst_rate = 0.0;
        for (const State& s : states) {
          if (s.strain > 0.015) {
            // Against the factor of the rate the state's nodes show: at 4/s the factor's slope
            // turns the elastic ringing's few percent of the rate into 1 % of the stress.
            const double want = law.yield(s.eps_p) * (1.0 + std::pow(s.rate / c, 1.0 / p));
            worst_rate = std::max(worst_rate, std::abs(s.rate / (std::sqrt(1.5) * rate) - 1.0));
            worst = std::max(worst, std::abs(s.stress - want) / want);
            ++checked;
          }
        }
        EXPECT_GE(checked, 10);
        EXPECT_LT(worst, 0.01);
        EXPECT_LT(worst_rate, 0.02);  // the pull is the constant rate r in plastic flow
        std::printf(
            "Cowper-Symonds %s %s at %g/s (factor %.4f): flow stress within %.2e, the "
            "rate within %.2e of sqrt(3/2) r\n",
            law.name, body == Body::hex ? "hex" : "shell", rate, factor, worst, worst_rate);
      }
    }
  }
}

}  // namespace
}  // namespace plyform
