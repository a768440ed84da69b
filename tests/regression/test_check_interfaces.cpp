// `plyform check` warns before the run about the interface choices known to go wrong
// (setup/interface_warnings.hpp, docs/contact.md), each on a deck that shows it and decks that
// must not: a cohesive interface on one-point shells with viscous hourglass control; a layer
// interface whose penalty the tool's pressure pushes through; a layer interface whose step
// vote sets the run's step. The decks: two 10 x 10 mm shell layers of one element each (mid-
// surfaces one thickness apart: their surfaces touch), and for the pressure a rigid holder on
// top, pressed by a force.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace test_check_interfaces {

constexpr double kRho = 7.85e-9, kSteel = 2.1e5, kNu = 0.3, kT = 1.0, kSize = 10.0;
constexpr double kTssfac = 0.9;

struct Stack {
  int elform = 2;           // both layers' ELFORM
  int ihq = 0;              // their *HOURGLASS IHQ; 0: none (the default, IHQ 1)
  bool cohesive = true;     // *USER_INTERFACE_FRICTION on the interface
  double cn = 100.0;        // its C_N
  double bond_tol = 0.0;    // its BOND_TOL (> 0: bonded at t = 0)
  double e_upper = kSteel;  // Young's modulus of the upper layer (the slave side)
  int soft = 0;             // SOFT of the interface
  int penopt = 0;           // *CONTROL_CONTACT PENOPT; 0: no *CONTROL_CONTACT
  bool holder = false;      // a rigid holder on the upper layer
  double force = 0.0;       // > 0: *LOAD_RIGID_BODY pressing the holder; 0: a prescribed motion
  bool nodal = false;       // the force as *LOAD_NODE_POINT, a quarter on each holder node
};

// Nodes of layer l at z = l * kT; its element 1 + l; part 1 + l.
std::string deck(const Stack& s) {
  std::ostringstream d;
  d << "*KEYWORD\n*CONTROL_TERMINATION\n1.0e-3\n*NODE\n";
  const int layers = s.holder ? 3 : 2;
  for (int l = 0; l < layers; ++l) {
    // The rigid holder's mesh is its surface (no offset in a forming contact): on the upper
    // layer's top.
    const double z = l < 2 ? l * kT : 1.5 * kT;
    const int n = 10 * l;
    d << n + 1 << ",0,0," << z << "\n"
      << n + 2 << "," << kSize << ",0," << z << "\n"
      << n + 3 << "," << kSize << "," << kSize << "," << z << "\n"
      << n + 4 << ",0," << kSize << "," << z << "\n";
  }
  d << "*ELEMENT_SHELL\n";
  for (int l = 0; l < layers; ++l) {
    const int n = 10 * l;
    d << l + 1 << "," << l + 1 << "," << n + 1 << "," << n + 2 << "," << n + 3 << "," << n + 4
      << "\n";
  }
  const int hg = s.ihq > 0 ? 1 : 0;
  d << "*PART\nlower\n1,1,1,0," << hg << "\n*PART\nupper\n2,1,2,0," << hg << "\n";
  if (s.holder)
    d << "*PART\nholder\n3,2,3\n*SECTION_SHELL\n2,2,0.8333,2\n1.0,1.0,1.0,1.0\n"
      << "*MAT_RIGID\n3," << kRho << "," << kSteel << "," << kNu << "\n\n";
  d << "*SECTION_SHELL\n1," << s.elform << ",0.8333,3\n"
    << kT << "," << kT << "," << kT << "," << kT << "\n";
  if (s.ihq > 0)
    d << "*HOURGLASS\n1," << s.ihq << ",0.05\n";
  d << "*MAT_ELASTIC\n1," << kRho << "," << kSteel << "," << kNu << "\n*MAT_ELASTIC\n2," << kRho
    << "," << s.e_upper << "," << kNu << "\n";
  if (s.penopt > 0)
    d << "*CONTROL_CONTACT\n0.1,0,0,0," << s.penopt << "\n";
  d << "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n         1interface\n2,1,3,3\n0.0\n1.0,1.0\n";
  if (s.soft != 0)
    d << s.soft << "\n";
  if (s.cohesive) {
    // MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL
    d << "*USER_INTERFACE_FRICTION\n1,11,0\n1," << s.cn << ",1.0,1.0,0.0,0.0,1.0e-7,0.0\n0.0,1.0,"
      << s.bond_tol << "\n";
  }
  if (s.holder) {
    d << "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID\n         2holder\n2,3,3,3\n0.1\n1.0,1.0\n"
      << "*DEFINE_CURVE\n1\n0.0,1.0\n1.0,1.0\n";
    if (s.force > 0.0 && s.nodal) {
      d << "*LOAD_NODE_POINT\n";
      for (int n = 21; n <= 24; ++n)
        d << n << ",3,1," << -0.25 * s.force << "\n";
    } else if (s.force > 0.0) {
      d << "*LOAD_RIGID_BODY\n3,3,1," << -s.force << "\n";
    } else {
      d << "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n3,3,0,1,-1.0\n";
    }
  }
  d << "*END\n";
  return d.str();
}

// The warning lines of `plyform check` that contain `what`.
std::vector<std::string> warnings(const Stack& s, const std::string& what) {
  test::TempDir dir;
  std::ostringstream out, err;
  const int status = run_check(dir.write("stack.k", deck(s)), out, err);
  EXPECT_EQ(status, 0) << err.str();  // warnings keep the exit code 0
  EXPECT_NE(out.str().find("valid"), std::string::npos) << out.str();
  std::vector<std::string> lines;
  std::istringstream in(err.str());
  for (std::string line; std::getline(in, line);)
    if (line.rfind("warning: ", 0) == 0 && line.find(what) != std::string::npos)
      lines.push_back(line);
  return lines;
}

// The number after `key` in `line` (NaN if absent).
double number_after(const std::string& line, const std::string& key) {
  const auto at = line.find(key);
  if (at == std::string::npos)
    return std::nan("");
  return std::stod(line.substr(at + key.size()));
}

const std::string kHourglass = "viscous hourglass";
const std::string kPressure = "gives way under the tool pressure";
const std::string kStep = "sets the run's time step";

TEST(CheckInterfaces, CohesiveInterfaceOnViscousOnePointShellsIsWarned) {
  // No *HOURGLASS: IHQ 1 on both arms, each side of the cohesive interface one warning.
  const auto w = warnings({}, kHourglass);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("contact 1 (*CONTACT_ONE_WAY_SURFACE_TO_SURFACE"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("part 2 'upper'"), std::string::npos) << w[0];  // the slave side
  EXPECT_NE(w[1].find("part 1 'lower'"), std::string::npos) << w[1];
  EXPECT_NE(w[0].find("IHQ 1"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("IHQ 4"), std::string::npos) << w[0];  // the remedy
  EXPECT_NE(w[0].find("ELFORM 16"), std::string::npos) << w[0];
  // IHQ 2 and 3 are viscous too.
  Stack s;
  s.ihq = 3;
  EXPECT_EQ(warnings(s, kHourglass).size(), 2u);
}

TEST(CheckInterfaces, StiffnessHourglassFullIntegrationOrPlainContactIsNotWarned) {
  Stack stiff;
  stiff.ihq = 4;
  EXPECT_TRUE(warnings(stiff, kHourglass).empty());
  stiff.ihq = 5;
  EXPECT_TRUE(warnings(stiff, kHourglass).empty());
  Stack full;
  full.elform = 16;
  EXPECT_TRUE(warnings(full, kHourglass).empty());
  Stack plain;
  plain.cohesive = false;
  EXPECT_TRUE(warnings(plain, kHourglass).empty());
}

// SOFT = 0 penalty per area of a shell segment: SLSFAC K A / diagonal / A, K = E / (3 (1 - 2
// nu)), SLSFAC 0.1 (LS-DYNA's default); PENOPT 1 takes the smaller side.
double shell_penalty_per_area(double e) {
  return 0.1 * e / (3.0 * (1.0 - 2.0 * kNu)) / (kSize * std::sqrt(2.0));
}

TEST(CheckInterfaces, APenaltyThePressurePushesThroughIsWarned) {
  // A soft upper layer (E 10 MPa: a molten ply) under a holder pressed with 1 N over 100 mm^2:
  // 0.01 MPa against k = 0.0589 MPa/mm, 0.17 mm into each other, 17 % of the 1 mm layers.
  Stack s;
  s.cohesive = false;
  s.e_upper = 10.0;
  s.holder = true;
  s.force = 1.0;
  const auto w = warnings(s, kPressure);
  ASSERT_EQ(w.size(), 1u);
  const std::string& line = w[0];
  EXPECT_NE(line.find("contact 1 "), std::string::npos) << line;
  EXPECT_NE(
      line.find("the force on part 3 'holder' (1 along z) over the tool's projected area (100)"),
      std::string::npos)
      << line;
  const double pressure = 1.0 / (kSize * kSize);
  const double k = shell_penalty_per_area(10.0);
  EXPECT_NEAR(number_after(line, "presses the layers with at least "), pressure, 1e-4 * pressure)
      << line;
  EXPECT_NEAR(number_after(line, "in compression, "), k, 1e-3 * k) << line;
  const double share = 100.0 * pressure / k / kT;
  EXPECT_NEAR(number_after(line, "into each other, "), share, 2e-3 * share) << line;
  // The remedy: SOFT = 1, or the penalty that keeps it at 5 %: p / (0.05 t).
  EXPECT_NE(line.find("SOFT = 1"), std::string::npos) << line;
  EXPECT_NEAR(number_after(line, "penalty of at least "), pressure / (0.05 * kT),
              1e-3 * pressure / (0.05 * kT))
      << line;
  // The same force as nodal loads on the holder's nodes.
  s.nodal = true;
  const auto nodal = warnings(s, kPressure);
  ASSERT_EQ(nodal.size(), 1u);
  EXPECT_NEAR(number_after(nodal[0], "presses the layers with at least "), pressure,
              1e-4 * pressure)
      << nodal[0];
}

TEST(CheckInterfaces, AStiffEnoughOrMassPenaltyOrNoForceIsNotWarned) {
  Stack s;
  s.cohesive = false;
  s.e_upper = 10.0;
  s.holder = true;
  s.force = 1.0;
  Stack steel = s;  // k = 1237 MPa/mm: 8e-6 mm
  steel.e_upper = kSteel;
  EXPECT_TRUE(warnings(steel, kPressure).empty());
  Stack soft = s;  // the penalty from the nodal mass and the step
  soft.soft = 1;
  EXPECT_TRUE(warnings(soft, kPressure).empty());
  Stack moved = s;  // the holder driven by its motion: no force known before the run
  moved.force = 0.0;
  EXPECT_TRUE(warnings(moved, kPressure).empty());
  // A cohesive law that bonds the layers at t = 0 holds them with C_N = 1e4 in compression
  // (1e-6 mm). Without BOND_TOL they meet the contact's penalty: with PENOPT left blank a
  // layer interface takes the stiffer side's (the steel's 1237 MPa/mm), not warned; with
  // PENOPT 1 written in the deck, the soft side's, and it is warned again.
  Stack bonded = s;
  bonded.cohesive = true;
  bonded.cn = 1.0e4;
  bonded.bond_tol = 1.0e-3;
  bonded.ihq = 4;
  EXPECT_TRUE(warnings(bonded, kPressure).empty());
  bonded.bond_tol = 0.0;
  EXPECT_TRUE(warnings(bonded, kPressure).empty());
  bonded.penopt = 1;
  EXPECT_EQ(warnings(bonded, kPressure).size(), 1u);
}

TEST(CheckInterfaces, AnInterfaceVoteBelowTheElementsStepIsWarned) {
  // C_N = 1e4 MPa/mm on 1 mm steel layers: every node is a corner of mass rho t A / 4 with
  // area A / 4, m* = rho t A / 8, k = C_N A / 4 (above the penalty's 1237 A / 4):
  // TSSFAC sqrt(2 m* / k) = TSSFAC sqrt(rho t / C_N) = 7.97e-7 s, half the shells' step.
  Stack s;
  s.cn = 1.0e4;
  s.bond_tol = 1.0e-3;
  s.ihq = 4;
  const auto w = warnings(s, kStep);
  ASSERT_EQ(w.size(), 1u);
  const std::string& line = w[0];
  const double vote = kTssfac * std::sqrt(kRho * kT / s.cn);
  EXPECT_NEAR(number_after(line, "at t = 0 is "), vote, 1e-3 * vote) << line;
  const double element = number_after(line, "below the elements' step ");
  EXPECT_GT(element, vote) << line;
  EXPECT_NEAR(number_after(line, "the run takes "), element / vote, 1e-2 * element / vote) << line;
  EXPECT_NE(line.find("C_N / F and sigma_max / sqrt(F)"), std::string::npos) << line;
}

// The step check announces is the run's first step: `plyform run` over a few cycles writes it
// to summary.json (dt_initial).
TEST(CheckInterfaces, TheAnnouncedVoteIsTheRunsFirstStep) {
  Stack s;
  s.cn = 1.0e4;
  s.bond_tol = 1.0e-3;
  s.ihq = 4;
  const auto w = warnings(s, kStep);
  ASSERT_EQ(w.size(), 1u);
  test::TempDir dir;
  RunOptions o;
  o.deck = dir.write("stack.k", deck(s));
  o.output = dir.path() / "out";
  o.progress = false;
  o.end_time = 1.0e-5;
  std::ostringstream out, err;
  ASSERT_EQ(run_deck(o, out, err), 0) << err.str();
  std::ifstream in(*o.output / "summary.json");
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const double first = number_after(json, "\"dt_initial\":");
  const double vote = number_after(w[0], "at t = 0 is ");
  EXPECT_NEAR(first, vote, 1e-3 * vote) << json;
}

TEST(CheckInterfaces, AnInterfaceVoteAboveTheElementsStepIsNotWarned) {
  // C_N = 100: the penalty (1237 MPa/mm) is the stiffest spring, TSSFAC sqrt(rho t / 1237)
  // = 2.27e-6 s, above the shells' step; a plain contact the same.
  Stack s;
  s.ihq = 4;
  EXPECT_TRUE(warnings(s, kStep).empty());
  s.cohesive = false;
  EXPECT_TRUE(warnings(s, kStep).empty());
}

}  // namespace test_check_interfaces
}  // namespace plyform::app
