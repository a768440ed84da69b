// The formed part handed on (issue 33): a stretch-bend "draw" stopped at half stroke writes its
// dynain; a new deck (that dynain, the part's material and section, the same supports and the
// second half of the stroke measured from the half-stroke positions) continues it, and at the
// end of the stroke, after a short dwell, its thickness, plastic strain and stress match the
// uninterrupted draw's (the reference) within 1 %.
//
// The draw: a strip of bilinear J2 shells (*MAT_024), 20 x 4 x 1 mm, clamped at x = 0; its far
// end, its rotations held, is moved 0.4 mm along the strip and 4 mm across it (stretch and an
// S-bend into plastic strain of about 9 %). Each half of the stroke follows the cycloidal ramp
// tau - sin(2 pi tau) / (2 pi), at rest and without acceleration at its ends, so the strip is
// nearly at rest at half stroke: dynain carries no velocity (the continuation starts at rest),
// and the uninterrupted draw must not have much to lose there either. Each half takes 3 ms,
// some 40 periods of the strip's first bending mode (13 kHz), the dwell 0.3 ms. The residual
// vibration is what remains between the two (no damping: it does not die out in the dwell):
// with (1 - cos(pi tau)) / 2 ramps, whose acceleration jumps at their ends, the stress of the
// one-point shell differed by 4.1 % (1.5 ms halves), 1.1 % (4.5 ms) and 1.3 % (6 ms), the
// fully integrated one's by 1.8, 0.29 and 0.35 %.
// The control: the same continuation from the dynain without its *INITIAL_STRESS_SHELL (the
// formed shape and thickness only) misses the reference by some 18 % in stress and 38 % in
// plastic strain.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "dynain_decks.hpp"
#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace test_deck_dynain_continuation {

constexpr double kHalf = 3.0e-3, kDwell = 0.3e-3;
constexpr double kLength = 20.0, kWidth = 4.0, kH = 1.0;
constexpr int kNx = 10, kNy = 2;
constexpr double kPull = 0.4, kLift = 4.0;  // the whole stroke at the far end

int node(int i, int j) {
  return 1 + i + (kNx + 1) * j;
}

/// The fraction of the whole stroke at time t: each half a cosine ramp (at rest at its ends),
/// then the dwell. `continued`: the second half only, measured from half stroke.
std::string stroke_curve(bool continued) {
  std::ostringstream os;
  os.precision(17);
  os << "*DEFINE_CURVE\n1,\n";
  const int n = 80;
  const auto ramp = [](double tau) {
    return tau - std::sin(2.0 * std::numbers::pi * tau) / (2.0 * std::numbers::pi);
  };
  const int halves = continued ? 1 : 2;
  for (int h = 0; h < halves; ++h)
    for (int k = h == 0 ? 0 : 1; k <= n; ++k) {
      const double tau = static_cast<double>(k) / n;
      os << (h + tau) * kHalf << "," << 0.5 * (h + ramp(tau)) << "\n";
    }
  os << halves * kHalf + kDwell << "," << 0.5 * halves << "\n";
  return os.str();
}

/// Supports and the stroke (the same node ids in both decks).
std::string supports(bool continued) {
  std::ostringstream os;
  os.precision(17);
  os << "*BOUNDARY_SPC_NODE\n";
  for (int j = 0; j <= kNy; ++j)
    os << node(0, j) << ",0,1,1,1,1,1,1\n" << node(kNx, j) << ",0,0,0,0,1,1,1\n";
  os << stroke_curve(continued) << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int j = 0; j <= kNy; ++j)
    os << node(kNx, j) << ",1,2,1," << kPull << "\n" << node(kNx, j) << ",3,2,1," << kLift << "\n";
  return os.str();
}

std::string draw_deck(int elform, int nip) {
  std::ostringstream os;
  os.precision(17);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n"
     << 2 * kHalf + kDwell << ",\n*INTERFACE_SPRINGBACK_LSDYNA\n0,\n"
     << test::j2_part(elform, nip, kH) << "*NODE\n";
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i)
      os << node(i, j) << "," << kLength * i / kNx << "," << kWidth * j / kNy << ",0\n";
  os << "*ELEMENT_SHELL\n";
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i)
      os << 1 + i + kNx * j << ",1," << node(i, j) << "," << node(i + 1, j) << ","
         << node(i + 1, j + 1) << "," << node(i, j + 1) << "\n";
  os << supports(false) << "*END\n";
  return os.str();
}

/// The new deck: the dynain, the part (its section's thickness is not used: the elements carry
/// theirs), the supports and the second half of the stroke.
std::string continuation_deck(const std::filesystem::path& dynain, int elform, int nip) {
  std::ostringstream os;
  os.precision(17);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n"
     << kHalf + kDwell << ",\n*INTERFACE_SPRINGBACK_LSDYNA\n0,\n*INCLUDE\n"
     << dynain.string() << "\n"
     << test::j2_part(elform, nip, kH) << supports(true) << "*END\n";
  return os.str();
}

std::filesystem::path run(const std::filesystem::path& deck, const std::string& out,
                          std::optional<double> end_time = std::nullopt) {
  app::RunOptions o;
  o.deck = deck;
  o.output = deck.parent_path() / out;
  o.progress = false;
  o.end_time = end_time;
  std::ostringstream text, err;
  EXPECT_EQ(app::run_deck(o, text, err), 0) << err.str() << text.str();
  return *o.output / "dynain";
}

double norm(const std::array<double, 6>& s) {
  double v = 0.0;
  for (std::size_t c = 0; c < 6; ++c)
    v += (c < 3 ? 1.0 : 2.0) * s[c] * s[c];
  return std::sqrt(v);
}

struct Case {
  int elform, nip;
};

/// The continuation against the reference at the end: each largest difference, stresses and
/// plastic strains as a share of the reference's largest (and the plastic strain of its own
/// where it is above a tenth of the largest), thickness of its own, positions of the stroke.
struct Difference {
  double sigma_max = 0.0, eps_max = 0.0, h_min = 1e30;
  double stress = 0.0, eps = 0.0, eps_own = 0.0, thickness = 0.0, position = 0.0;
};

Difference compare(const test::Dynain& whole, const test::Dynain& next, int shells = kNx * kNy,
                   double stroke = kLift) {
  Difference r;
  EXPECT_EQ(whole.shells.size(), static_cast<std::size_t>(shells));
  EXPECT_EQ(next.shells.size(), whole.shells.size());
  for (const auto& [id, s] : whole.shells) {
    r.h_min = std::min(r.h_min, s.thickness[0]);
    for (const auto& p : s.stress.points) {
      r.sigma_max = std::max(r.sigma_max, norm(p.sigma));
      r.eps_max = std::max(r.eps_max, p.eps);
    }
  }
  for (const auto& [id, s] : whole.shells) {
    const test::DynainShell& t = next.shells.at(id);
    r.thickness = std::max(r.thickness, std::abs(t.thickness[0] - s.thickness[0]) / s.thickness[0]);
    EXPECT_EQ(t.stress.points.size(), s.stress.points.size());
    for (std::size_t k = 0; k < s.stress.points.size() && k < t.stress.points.size(); ++k) {
      const auto& a = s.stress.points[k];
      const auto& b = t.stress.points[k];
      std::array<double, 6> diff{};
      for (std::size_t cc = 0; cc < 6; ++cc)
        diff[cc] = b.sigma[cc] - a.sigma[cc];
      r.stress = std::max(r.stress, norm(diff) / r.sigma_max);
      r.eps = std::max(r.eps, std::abs(b.eps - a.eps) / r.eps_max);
      if (a.eps > 0.1 * r.eps_max)
        r.eps_own = std::max(r.eps_own, std::abs(b.eps - a.eps) / a.eps);
    }
  }
  for (const auto& [id, p] : whole.nodes) {
    const auto& q = next.nodes.at(id);
    r.position = std::max(r.position, std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]) / stroke);
  }
  return r;
}

/// The dynain less its *INITIAL_STRESS_SHELL: the formed shape and thickness without the
/// stresses (the control: a continuation that forgets them must miss the reference).
std::filesystem::path without_stresses(const std::filesystem::path& dynain,
                                       const test::TempDir& dir) {
  std::ifstream in(dynain);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const auto from = s.find("*INITIAL_STRESS_SHELL"), to = s.find("*INITIAL_STRAIN_SHELL");
  EXPECT_TRUE(from != std::string::npos && to != std::string::npos);
  s.erase(from, to - from);
  return dir.write("bare/dynain", s);
}

class DynainContinuation : public ::testing::TestWithParam<Case> {};

TEST_P(DynainContinuation, MatchesTheUninterruptedDrawAfterADwell) {
  const Case c = GetParam();
  test::TempDir dir;
  const auto deck = dir.write("draw.k", draw_deck(c.elform, c.nip));
  const test::Dynain whole = test::read_dynain(run(deck, "whole"));
  const auto half = run(deck, "half", kHalf);  // the draw stopped at half stroke
  const Difference d =
      compare(whole, test::read_dynain(run(
                         dir.write("next.k", continuation_deck(half, c.elform, c.nip)), "next")));
  const Difference bare = compare(
      whole,
      test::read_dynain(
          run(dir.write("bare.k", continuation_deck(without_stresses(half, dir), c.elform, c.nip)),
              "bare")));
  std::printf(
      "ELFORM %d NIP %d: max plastic strain %.4f, thinnest %.4f mm; continued from "
      "dynain vs uninterrupted: stress %.3g of the largest (%.1f MPa), plastic strain "
      "%.3g of the largest (%.3g of its own where above a tenth of it), thickness "
      "%.3g, positions %.3g of the stroke. Without the stresses: stress %.3g, plastic "
      "strain %.3g\n",
      c.elform, c.nip, d.eps_max, d.h_min, d.stress, d.sigma_max, d.eps, d.eps_own, d.thickness,
      d.position, bare.stress, bare.eps);
  EXPECT_GT(d.eps_max, 0.05);  // well into the plastic range
  EXPECT_LT(d.stress, 0.01);
  EXPECT_LT(d.eps, 0.01);
  EXPECT_LT(d.eps_own, 0.01);
  EXPECT_LT(d.thickness, 0.01);
  EXPECT_LT(d.position, 0.01);
  // The control: the same continuation without the dynain's stresses is far off.
  EXPECT_GT(bare.eps, 0.1);
  EXPECT_GT(bare.stress, 0.1);
}

// --- The draw over a rigid punch (fully integrated shells): the strip clamped at both ends
// (x = -20 and 20 mm, 40 x 2 shells), a rigid half cylinder of radius 5 mm (axis along y)
// pushed 6.5 mm down onto its middle through *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE
// without friction (0.5 mm of gap, then a stretch-bend around the punch to 15 % plastic
// strain). The new deck gives the punch at its half-stroke position; the contact starts afresh
// there. Nothing of its state is carried: frictionless, it has no sticking spring to lose, but
// the sheet's penetration of half stroke is lost (IGNORE 0 moves the node out, IGNORE 1 makes
// the depth its tolerance) and the penalty stiffness is computed from the formed mesh.
// Measured (the continuation against the uninterrupted draw, stress and plastic strain as a
// share of their largest): with the default stiffness (SFS 1, 0.009 mm deep at half stroke
// under the punch) 6.1 % and 4.0 % there; with SFS 10 (here) 6.1 % and 0.97 % (3.4 % and 0.94 %
// with the punch 0.05 mm higher at the start); SFS 100 3.1 % and 1.0 %. The stress of this draw
// is itself that sensitive: the uninterrupted draw at twice the duration ends 5.2 % off its
// own stress (0.24 % in plastic strain), at SFS 100 3.0 % (0.31 %). Hence the tolerances here:
// 10 % of the largest stress, 1.5 % of the largest plastic strain, 1 % in thickness and
// positions; the 1 % is met by the prescribed stretch-bend above, not by this contact
// draw's stress. Without the dynain's stresses the continuation is 28 % off in both (the
// control). Belytschko-Tsay shells under viscous hourglass control fold into hourglass modes
// over the punch (11 % hourglass energy early in the draw) and end 13 % off in stress; the
// stiffness forms' hourglass forces are not carried by dynain.

constexpr double kPunchRadius = 5.0, kPunchStroke = 6.5, kPunchTool = 0.1;
constexpr int kDrawNx = 40;

int draw_node(int i, int j) {
  return 1 + i + (kDrawNx + 1) * j;
}

/// The punch (part 2) with its lowest line `drop` below its start (0.5 mm above the sheet's
/// contact surface), its segments' normals outward.
std::string punch(double drop) {
  std::ostringstream os;
  os.precision(17);
  const int n = 16;
  const double zc = 0.5 * kH + 0.5 + kPunchRadius - drop;
  os << "*NODE\n";
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= n; ++i) {
      const double th = std::numbers::pi * (static_cast<double>(i) / n - 0.5);
      os << 1001 + i + (n + 1) * j << "," << kPunchRadius * std::sin(th) << ","
         << -1.0 + (kWidth + 2.0) * j << "," << zc - kPunchRadius * std::cos(th) << "\n";
    }
  os << "*ELEMENT_SHELL\n";
  for (int i = 0; i < n; ++i) {
    const int a = 1001 + i;
    os << 1001 + i << ",2," << a << "," << a + n + 1 << "," << a + n + 2 << "," << a + 1 << "\n";
  }
  return os.str();
}

/// Everything but the sheet's nodes and elements: parts, contact, supports, the stroke.
std::string draw_tools(bool continued) {
  std::ostringstream os;
  os.precision(17);
  os << "*CONTROL_TERMINATION\n"
     << (continued ? kHalf : 2 * kHalf) + kDwell << ",\n*INTERFACE_SPRINGBACK_LSDYNA\n0,\n"
     << test::j2_part(16, 3, kH) << "*PART\npunch\n2,2,2\n*SECTION_SHELL\n2,2,0.8333,2\n"
     << kPunchTool << "," << kPunchTool << "," << kPunchTool << "," << kPunchTool << "\n"
     << "*MAT_RIGID\n2,7.85e-9,210000,0.3\n1.0,4,7\n"
     << punch(continued ? 0.5 * kPunchStroke : 0.0) << "*BOUNDARY_SPC_NODE\n";
  for (int j = 0; j <= kNy; ++j)
    os << draw_node(0, j) << ",0,1,1,1,1,1,1\n" << draw_node(kDrawNx, j) << ",0,1,1,1,1,1,1\n";
  os << stroke_curve(continued) << "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n2,3,2,1," << -kPunchStroke
     << "\n*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID\n5,sheet on punch\n"
     << "1,2,3,3\n0,0,0,0,20\n10,10\n";
  return os.str();
}

std::string punch_draw_deck() {
  std::ostringstream os;
  os.precision(17);
  os << "*KEYWORD\n" << draw_tools(false) << "*NODE\n";
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kDrawNx; ++i)
      os << draw_node(i, j) << "," << -kLength + 2.0 * kLength * i / kDrawNx << ","
         << kWidth * j / kNy << ",0\n";
  os << "*ELEMENT_SHELL\n";
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kDrawNx; ++i)
      os << 1 + i + kDrawNx * j << ",1," << draw_node(i, j) << "," << draw_node(i + 1, j) << ","
         << draw_node(i + 1, j + 1) << "," << draw_node(i, j + 1) << "\n";
  os << "*END\n";
  return os.str();
}

TEST(DynainDraw, OverARigidPunchWithTheToolsAtHalfStroke) {
  test::TempDir dir;
  const auto deck = dir.write("draw.k", punch_draw_deck());
  const test::Dynain whole = test::read_dynain(run(deck, "whole"));
  const auto half = run(deck, "half", kHalf);
  const std::string next =
      "*KEYWORD\n*INCLUDE\n" + half.string() + "\n" + draw_tools(true) + "*END\n";
  const Difference d = compare(whole, test::read_dynain(run(dir.write("next.k", next), "next")),
                               kDrawNx * kNy, kPunchStroke);
  const std::string bare_next = "*KEYWORD\n*INCLUDE\n" + without_stresses(half, dir).string() +
                                "\n" + draw_tools(true) + "*END\n";
  const Difference bare =
      compare(whole, test::read_dynain(run(dir.write("bare.k", bare_next), "bare")), kDrawNx * kNy,
              kPunchStroke);
  std::printf(
      "punch draw, ELFORM 16 NIP 3: max plastic strain %.4f, thinnest %.4f mm; "
      "continued from dynain vs uninterrupted: stress %.3g of the largest (%.1f MPa), "
      "plastic strain %.3g of the largest, thickness %.3g, positions %.3g of the "
      "stroke. Without the stresses: stress %.3g, plastic strain %.3g\n",
      d.eps_max, d.h_min, d.stress, d.sigma_max, d.eps, d.thickness, d.position, bare.stress,
      bare.eps);
  EXPECT_GT(d.eps_max, 0.1);
  EXPECT_LT(d.stress, 0.1);
  EXPECT_LT(d.eps, 0.015);
  EXPECT_LT(d.thickness, 0.01);
  EXPECT_LT(d.position, 0.01);
  EXPECT_GT(bare.eps, 0.1);  // the control
}

INSTANTIATE_TEST_SUITE_P(ElformNip, DynainContinuation, ::testing::Values(Case{2, 5}, Case{16, 3}),
                         [](const auto& param) {
                           return "Elform" + std::to_string(param.param.elform) + "Nip" +
                                  std::to_string(param.param.nip);
                         });

}  // namespace test_deck_dynain_continuation
}  // namespace plyform
