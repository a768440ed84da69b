// *BOUNDARY_PRESCRIBED_MOTION DOF 9, 10, 11 against the rigid rotation in closed form. The flap
// of a box: a shell panel held by SPCs, and a second panel joined to it along a hinge line; the
// flap's free nodes turn about the hinge (an axis parallel to x, y or z through OFFSET1,
// OFFSET2, off the origin). Their two coordinates across the axis must be the turned initial
// ones (to round-off for a prescribed angle), the one along it stays free, and glstat's books
// close: kinetic + internal energy = the work of the prescribed motions' reactions.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"

namespace plyform {
namespace {

constexpr double kEnd = 2.0e-3;  // s: the run, and the time the flap takes to turn 90 degrees
constexpr double kHalfPi = std::numbers::pi / 2.0;
constexpr double kAxisA = 3.0;          // mm: the hinge's coordinate along a (OFFSET1)
constexpr double kAxisB = -2.0;         // mm: and along b (OFFSET2): the panels' plane
constexpr int kColumns = 5, kRows = 3;  // nodes across (s = -10 .. 10) and along the hinge

/// The two global axes across axis k (0, 1, 2 = x, y, z), in LS-DYNA's order of OFFSET1 and
/// OFFSET2: (y, z) about x, (z, x) about y, (x, y) about z.
std::array<int, 2> across(int k) {
  return {(k + 1) % 3, (k + 2) % 3};
}

/// The curve of a motion, sampled at 41 points over the run (the deck's curve is their
/// piecewise-linear interpolation, held constant after the run).
using Shape = double (*)(double t);

/// The flap's angle for VAD 2: 0 to 90 degrees with no angular velocity at either end
/// (smoothstep), so that no motion starts with a jump.
double smooth_turn(double t) {
  const double x = std::clamp(t / kEnd, 0.0, 1.0);
  return kHalfPi * x * x * (3.0 - 2.0 * x);
}

/// The deck curve's value at t: the linear interpolation of the 41 samples of `shape`.
double sampled(Shape shape, double t) {
  const double x = std::clamp(t / kEnd, 0.0, 1.0) * 40.0;
  const double i = std::min(std::floor(x), 39.0);
  const double f0 = shape(kEnd * i / 40.0), f1 = shape(kEnd * (i + 1.0) / 40.0);
  return f0 + (f1 - f0) * (x - i);
}

struct Motion {
  int dof = 10;  // 9, 10, 11
  int vad = 2;   // 0, 1, 2
  Shape shape = smooth_turn;
  double birth = 0.0;
  double death = 0.0;       // 0: none
  double young = 210000.0;  // MPa
  double thickness = 0.5;   // mm
};

/// Node n (0-based) of the 5 x 3 mesh: s = -10 + 5 i across the hinge (held panel s <= 0,
/// flap s > 0), w = 5 j along it. Global coordinates: a = kAxisA + s, k = w, b = kAxisB.
std::array<double, 3> initial_position(int dof, int n) {
  const int k = dof - 9;
  const auto [a, b] = across(k);
  std::array<double, 3> p{};
  p[static_cast<std::size_t>(a)] = kAxisA - 10.0 + 5.0 * (n % kColumns);
  p[static_cast<std::size_t>(k)] = 5.0 * (n / kColumns);
  p[static_cast<std::size_t>(b)] = kAxisB;
  return p;
}
bool on_flap(int n) {
  return n % kColumns > 2;
}

std::string deck(const Motion& motion) {
  std::ostringstream os;
  os.precision(17);
  // Every card in free format (commas): 17 digits do not fit fixed 10-character fields.
  os << "*KEYWORD\n*CONTROL_TERMINATION\n"
     << kEnd << ",\n*DATABASE_GLSTAT\n"
     << kEnd / 40 << ",\n*DATABASE_BINARY_D3PLOT\n"
     << kEnd / 40 << ",\n"
     << "*PART\nflap and panel\n1,1,1\n*SECTION_SHELL\n1,2,0.8333,3\n"
     << motion.thickness << "," << motion.thickness << "," << motion.thickness << ","
     << motion.thickness << "\n*MAT_ELASTIC\n1,7.85e-9," << motion.young << ",0.3\n*NODE\n";
  for (int n = 0; n < kColumns * kRows; ++n) {
    const auto p = initial_position(motion.dof, n);
    os << n + 1 << "," << p[0] << "," << p[1] << "," << p[2] << "\n";
  }
  os << "*ELEMENT_SHELL\n";
  int e = 1;
  for (int j = 0; j + 1 < kRows; ++j)
    for (int i = 0; i + 1 < kColumns; ++i) {
      const int n1 = j * kColumns + i + 1;
      os << e++ << ",1," << n1 << "," << n1 + 1 << "," << n1 + 1 + kColumns << "," << n1 + kColumns
         << "\n";
    }
  // Set 1: the held panel with the hinge (translations fixed, rotations free); set 2: the flap.
  os << "*SET_NODE_LIST\n1\n";
  for (int n = 0; n < kColumns * kRows; ++n)
    if (!on_flap(n))
      os << n + 1 << "\n";
  os << "*SET_NODE_LIST\n2\n";
  for (int n = 0; n < kColumns * kRows; ++n)
    if (on_flap(n))
      os << n + 1 << "\n";
  os << "*BOUNDARY_SPC_SET\n1,0,1,1,1\n";
  os << "*BOUNDARY_PRESCRIBED_MOTION_SET\n2," << motion.dof << "," << motion.vad << ",1,1.0,0,"
     << motion.death << "," << motion.birth << "\n"
     << kAxisA << "," << kAxisB << ",0\n";
  os << "*DEFINE_CURVE\n1\n";
  for (int i = 0; i <= 40; ++i)
    os << kEnd * i / 40.0 << "," << motion.shape(kEnd * i / 40.0) << "\n";
  os << 10.0 * kEnd << "," << motion.shape(kEnd) << "\n*END\n";
  return os.str();
}

struct FlapRun {
  std::vector<double> times;
  // Per state: each flap node's turned angle about the hinge, its radius, its axial drift and
  // its position error against `expected` (the angle the test asks for, across the axis).
  std::vector<std::vector<double>> angle, radius, axial;
  std::vector<double> max_reaction;  // the largest reaction on the flap's nodes
  std::vector<engine::Energies> energies;
};

FlapRun run(const Motion& motion) {
  const keyword::ReadResult read = keyword::read_deck_text(deck(motion), "flap.k");
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().to_string());
  const auto invalid = setup::validate(read.model);
  EXPECT_TRUE(invalid.empty()) << invalid.front().to_string();
  const setup::BuildResult built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  FlapRun out;
  if (!built.model)
    return out;
  const int k = motion.dof - 9;
  const auto [a, b] = across(k);
  test::RecordingSink sink;
  sink.on_state = [&](const engine::Snapshot& s) {
    out.times.push_back(s.time);
    std::vector<double> angle, radius, axial;
    double reaction = 0.0;
    const engine::NodalState& st = *s.nodes;
    for (int n = 0; n < kColumns * kRows; ++n) {
      if (!on_flap(n))
        continue;
      const auto i = static_cast<std::size_t>(n);  // deck order is the model's order here
      const std::array<double, 3> p{s.model->x0[i] + st.ux[i], s.model->y0[i] + st.uy[i],
                                    s.model->z0[i] + st.uz[i]};
      const double ra = p[static_cast<std::size_t>(a)] - kAxisA;
      const double rb = p[static_cast<std::size_t>(b)] - kAxisB;
      angle.push_back(std::atan2(rb, ra));
      radius.push_back(std::hypot(ra, rb));
      axial.push_back(p[static_cast<std::size_t>(k)] -
                      initial_position(motion.dof, n)[static_cast<std::size_t>(k)]);
      reaction = std::max({reaction, std::abs(st.rx[i]), std::abs(st.ry[i]), std::abs(st.rz[i])});
    }
    out.angle.push_back(angle);
    out.radius.push_back(radius);
    out.axial.push_back(axial);
    out.max_reaction.push_back(reaction);
  };
  const engine::RunResult r = engine::run(*built.model, sink, {});
  EXPECT_TRUE(r.ok) << r.error;
  out.energies = sink.energies;
  return out;
}

/// The initial radius of flap node n (its column's distance from the hinge).
double initial_radius(std::size_t flap_node) {
  return 5.0 * static_cast<double>(flap_node % 2 + 1);
}

/// |total - W| relative to W at the last glstat: the energy books close.
double energy_gap(const FlapRun& r) {
  const engine::Energies& e = r.energies.back();
  return std::abs(e.total - e.external_work) / e.external_work;
}

TEST(DeckPrescribedRotation, FlapTurnsThroughNinetyDegreesAboutEachAxis) {
  for (int dof : {9, 10, 11}) {
    SCOPED_TRACE(dof);
    const FlapRun r = run({.dof = dof, .vad = 2});
    ASSERT_EQ(r.times.size(), 41u);
    double worst_angle = 0.0, worst_radius = 0.0, worst_axial = 0.0;
    for (std::size_t s = 0; s < r.times.size(); ++s) {
      const double expected = sampled(smooth_turn, r.times[s]);
      for (std::size_t f = 0; f < r.angle[s].size(); ++f) {
        worst_angle = std::max(worst_angle, std::abs(r.angle[s][f] - expected));
        worst_radius = std::max(worst_radius, std::abs(r.radius[s][f] - initial_radius(f)));
        worst_axial = std::max(worst_axial, std::abs(r.axial[s][f]));
      }
    }
    EXPECT_NEAR(r.angle.back()[0], kHalfPi, 1e-15);
    // The turned position to round-off (radians, and mm on a 10 mm flap).
    EXPECT_LT(worst_angle, 1e-13);
    EXPECT_LT(worst_radius, 1e-12);
    // Along the axis the nodes are free: the hinge's bending pulls them by a little (measured
    // 1e-3 mm on the 10 mm flap, the same about each axis).
    EXPECT_LT(worst_axial, 5e-3);
    EXPECT_LT(energy_gap(r), 1e-3);
    std::printf(
        "DOF %d: angle error %.2e rad, radius error %.2e mm, axial drift %.2e mm, "
        "energy gap %.2e (W = %.4e, KE %.4e, IE %.4e)\n",
        dof, worst_angle, worst_radius, worst_axial, energy_gap(r), r.energies.back().external_work,
        r.energies.back().kinetic, r.energies.back().internal);
  }
}

/// Angular velocity for VAD 0: up from 0 over the first quarter of the run, then constant;
/// its integral (the angle) in closed form.
constexpr double kOmega = kHalfPi / (0.875 * kEnd);  // 90 degrees at the end
double omega_ramp(double t) {
  return kOmega * std::min(1.0, t / (0.25 * kEnd));
}
double omega_ramp_angle(double t) {
  const double ramp = 0.25 * kEnd;
  return t < ramp ? 0.5 * kOmega * t * t / ramp : kOmega * (t - 0.5 * ramp);
}
constexpr double kAlpha = 2.0 * kHalfPi / (kEnd * kEnd);  // 90 degrees at the end
double constant_alpha(double) {
  return kAlpha;
}
double constant_omega(double) {
  return kOmega;
}

TEST(DeckPrescribedRotation, AngularVelocityAndAcceleration) {
  // VAD 0: the midpoint rule integrates the piecewise-linear angular velocity exactly but on
  // the step across the ramp's end.
  const FlapRun v = run({.dof = 10, .vad = 0, .shape = omega_ramp});
  double worst = 0.0, worst_radius = 0.0;
  for (std::size_t s = 0; s < v.times.size(); ++s)
    for (std::size_t f = 0; f < v.angle[s].size(); ++f) {
      worst = std::max(worst, std::abs(v.angle[s][f] - omega_ramp_angle(v.times[s])));
      worst_radius = std::max(worst_radius, std::abs(v.radius[s][f] - initial_radius(f)));
    }
  // The step across the ramp's end is off by up to (slope / 8) dt^2.
  const double dt = v.energies[1].dt;
  EXPECT_LT(worst, kOmega / (0.25 * kEnd) * dt * dt / 8.0 + 1e-13);
  EXPECT_LT(worst_radius, 1e-11);
  EXPECT_LT(energy_gap(v), 1e-3);
  std::printf("VAD 0: angle error %.2e rad, radius error %.2e mm, energy gap %.2e\n", worst,
              worst_radius, energy_gap(v));
  // VAD 1: alpha constant from rest, angle alpha t^2 / 2 (exact for a constant step; the step
  // varies a little with the hinge's bending).
  const FlapRun acc = run({.dof = 10, .vad = 1, .shape = constant_alpha});
  worst = 0.0, worst_radius = 0.0;
  for (std::size_t s = 0; s < acc.times.size(); ++s)
    for (std::size_t f = 0; f < acc.angle[s].size(); ++f) {
      const double t = acc.times[s];
      worst = std::max(worst, std::abs(acc.angle[s][f] - 0.5 * kAlpha * t * t));
      worst_radius = std::max(worst_radius, std::abs(acc.radius[s][f] - initial_radius(f)));
    }
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(worst_radius, 1e-11);
  EXPECT_LT(energy_gap(acc), 1e-3);
  std::printf("VAD 1: angle error %.2e rad, radius error %.2e mm, energy gap %.2e\n", worst,
              worst_radius, energy_gap(acc));
}

TEST(DeckPrescribedRotation, BirthAndDeath) {
  // Born at a quarter of the run with a constant angular velocity: at rest before, then
  // omega (t - birth), late by at most the part of a step before its midpoint passes BIRTH.
  const double birth = 0.25 * kEnd;
  const FlapRun born = run({.dof = 9, .vad = 0, .shape = constant_omega, .birth = birth});
  const double dt = born.energies[1].dt;  // (the last step is cut to the end time)
  double worst = 0.0;
  for (std::size_t s = 0; s < born.times.size(); ++s)
    for (std::size_t f = 0; f < born.angle[s].size(); ++f) {
      const double expected = kOmega * std::max(0.0, born.times[s] - birth);
      worst = std::max(worst, std::abs(born.angle[s][f] - expected));
      if (born.times[s] < birth) {
        EXPECT_EQ(born.angle[s][f], 0.0) << "t = " << born.times[s];
      }
    }
  EXPECT_LE(worst, kOmega * dt);
  EXPECT_LT(energy_gap(born), 1e-3);
  std::printf("birth: angle error %.2e rad (omega dt %.2e), energy gap %.2e\n", worst, kOmega * dt,
              energy_gap(born));
  // Dead at half the run, at full angular velocity: the flap's nodes are released (no
  // reaction, no more work), and leave the prescribed path: the bent hinge springs the flap
  // back. (The books are checked up to DEATH: after it the steel flap flaps about violently,
  // and a free shell's books drift by themselves when its nodes' rotations catch up with its
  // spin, a matter of the shell, not of the release.)
  const double death = 0.5 * kEnd;
  const FlapRun dead = run({.dof = 11, .vad = 2, .death = death});
  double active = 0.0;
  for (std::size_t s = 0; s < dead.times.size(); ++s) {
    if (dead.times[s] > 0.0 && dead.times[s] < death)
      active = std::max(active, dead.max_reaction[s]);
  }
  ASSERT_GT(active, 0.0);
  for (std::size_t s = 0; s < dead.times.size(); ++s) {
    if (dead.times[s] > death + dead.energies[1].dt) {
      EXPECT_LT(dead.max_reaction[s], 1e-9 * active) << "t = " << dead.times[s];
    }
  }
  // The books at the last glstat before DEATH, and the work at the first one after it.
  double work_at_death = -1.0, gap_at_death = 0.0;
  for (const engine::Energies& e : dead.energies) {
    if (e.time < death)
      gap_at_death = std::abs(e.total - e.external_work) / e.external_work;
    else if (work_at_death < 0.0)
      work_at_death = e.external_work;
  }
  EXPECT_LT(gap_at_death, 1e-3);
  EXPECT_NEAR(dead.energies.back().external_work, work_at_death, 1e-9 * work_at_death);
  const double at_death = smooth_turn(death);
  EXPECT_LT(dead.angle.back()[1], at_death - 0.1);
  std::printf(
      "death: tip angle %.4f rad at the end (%.4f at DEATH, %.4f prescribed), energy "
      "gap %.2e at DEATH, work %.6e then %.6e\n",
      dead.angle.back()[1], at_death, smooth_turn(kEnd), gap_at_death, work_at_death,
      dead.energies.back().external_work);
}

}  // namespace
}  // namespace plyform
