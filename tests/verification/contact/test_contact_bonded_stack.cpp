// Three shell layers bonded by the cohesive law act as one section, in bending and in shear.
//
// A cantilever strip of three elastic layers, 0.25 / 1.00 / 0.25 mm (each its own shell mesh,
// mid-surfaces 0.625 mm apart), clamped at x = 0 and loaded at the tip of the top layer. The two
// interfaces are one-way contacts from the skins onto the core.
// - Bonded (*USER_INTERFACE_FRICTION, C_N = C_T = 1e5 MPa/mm, sigma_max never reached): the
//   interface holds the layers' surfaces together tangentially as well as normally, so the stack
//   bends as one 1.5 mm section: delta = P L^3 / (3 E I) + P L / (kappa G A), I = B h^3 / 12.
// - Frictionless penalty contact: each layer bends about its own mid-surface, the bending
//   stiffnesses add: delta = P L^3 / (3 E sum I_i) (+ the core's share of the shear).
// The layers' surfaces slide relative to each other by the rotation times the offsets; the
// contact measures that slip at the surfaces (node velocity plus rotation times offset), so the
// adhesive shear resists it. Poisson's ratio 0: beam theory holds for the strip as it is.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact_decks.hpp"

namespace plyform {
namespace {

constexpr double kE = 2.1e5, kRho = 7.85e-9, kLength = 20.0, kWidth = 1.0, kLoad = 1.0;
constexpr double kCore = 1.0, kSkin = 0.25;
// The load ramps over many periods of the first mode, then holds for about one (twice as long,
// 4 and 5 ms, gave the same deflections within 0.05 %).
constexpr double kRamp = 2e-3, kEnd = 2.6e-3;
constexpr int kNx = 40;

// Mean deflection of the tip of the core over the hold, and the run's energy ratio.
struct StackResult {
  double deflection = 0.0;
  double ratio = 0.0;
  double hourglass_share = 0.0;
};

StackResult run_stack(bool bonded) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(kEnd);
  d.kw("*DATABASE_NODOUT").card(kEnd / 500);
  d.kw("*DATABASE_GLSTAT").card(kEnd / 100);
  for (int p = 1; p <= 3; ++p)
    d.kw("*PART").kw("layer").card(p, p, 1, 0, 1);
  d.kw("*HOURGLASS").card(1, 4, 0.1);
  const double t[3] = {kSkin, kCore, kSkin};
  for (int p = 1; p <= 3; ++p)
    d.kw("*SECTION_SHELL").card(p, 2, 0.8333, 3).card(t[p - 1], t[p - 1], t[p - 1], t[p - 1]);
  d.kw("*MAT_ELASTIC").card(1, kRho, kE, 0.0);
  const double zs = 0.5 * (kCore + kSkin);
  const auto bottom = d.plate(1, 1, 1, 0, kLength, 0, kWidth, kNx, 1, -zs);
  const auto core = d.plate(2, 1001, 1001, 0, kLength, 0, kWidth, kNx, 1, 0.0);
  const auto top = d.plate(3, 2001, 2001, 0, kLength, 0, kWidth, kNx, 1, zs);
  const auto at_x = [&](const std::vector<int>& plate, int i) {
    return std::vector<int>{plate[static_cast<std::size_t>(i)],
                            plate[static_cast<std::size_t>(i + kNx + 1)]};
  };
  std::vector<int> clamp, all;
  for (const auto* plate : {&bottom, &core, &top}) {
    for (int n : at_x(*plate, 0))
      clamp.push_back(n);
    all.insert(all.end(), plate->begin(), plate->end());
  }
  d.kw("*DATABASE_HISTORY_NODE").card(at_x(core, kNx)[0]);
  d.kw("*SET_NODE_LIST").card(1).ids(clamp);
  d.kw("*SET_NODE_LIST").card(2).ids(all);
  d.kw("*SET_NODE_LIST").card(3).ids(at_x(top, kNx));
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 0, 1);  // plane strip: y, rx, rz held
  d.kw("*DEFINE_CURVE").card(1);
  for (int i = 0; i <= 20; ++i) {
    const double s = i / 20.0;
    d.card(s * kRamp, s * s * (3.0 - 2.0 * s));
  }
  d.card(kEnd, 1.0);
  d.kw("*LOAD_NODE_SET").card(3, 3, 1, -0.5 * kLoad);
  for (int c = 1; c <= 2; ++c) {
    d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(c, "skin on core");
    d.card(c == 1 ? 3 : 1, 2, 3, 3).card(0).card(1, 1);
    if (bonded) {
      // MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA; BETA0 BOND_TOL FRIC MU; VDC BETA_MIN CT.
      d.kw("*USER_INTERFACE_FRICTION").card(c, 20, 0);
      d.card(1, 1e5, 1e4, 1e4, 0.0, 0.0, 1e-9, 0.0);
      d.card(0.0, 1.0, 1e-3, 0, 0.0, 0.0, 0.0, 0.0);
      d.card(0.0, 10.0, 1e-3, 1e5);
    }
  }
  test::DeckRun r;
  run_deck(d.text(), r);
  StackResult out;
  double sum = 0.0;
  int count = 0;
  for (const auto& [time, uz] : r.uz) {
    if (time > kRamp + 1e-9) {
      sum += -uz.at(0);
      ++count;
    }
  }
  out.deflection = count > 0 ? sum / count : 0.0;
  out.ratio = r.result.last.ratio;
  for (const auto& e : r.sink.energies)
    if (e.internal > 0.0)
      out.hourglass_share = std::max(out.hourglass_share, e.hourglass / e.internal);
  return out;
}

TEST(ContactBondedStack, BondedLayersBendAsOneSection) {
  const double h = kCore + 2.0 * kSkin;
  const double i = kWidth * h * h * h / 12.0, g = 0.5 * kE;
  const double expected =
      kLoad * std::pow(kLength, 3) / (3.0 * kE * i) + kLoad * kLength / (0.8333 * g * kWidth * h);
  const StackResult r = run_stack(true);
  std::printf("bonded stack: tip %.5f mm against %.5f (%+.2f %%)\n", r.deflection, expected,
              100.0 * (r.deflection / expected - 1.0));
  EXPECT_NEAR(r.deflection, expected, 0.02 * expected);
  EXPECT_NEAR(r.ratio, 1.0, 0.01);
  EXPECT_LT(r.hourglass_share, 0.05);
}

TEST(ContactBondedStack, FrictionlessLayersAddTheirBendingStiffnesses) {
  const double i_core = kWidth * std::pow(kCore, 3) / 12.0;
  const double i_sum = i_core + 2.0 * kWidth * std::pow(kSkin, 3) / 12.0, g = 0.5 * kE;
  const double expected = kLoad * std::pow(kLength, 3) / (3.0 * kE * i_sum) +
                          kLoad * (i_core / i_sum) * kLength / (0.8333 * g * kWidth * kCore);
  const StackResult r = run_stack(false);
  std::printf("frictionless stack: tip %.5f mm against %.5f (%+.2f %%)\n", r.deflection, expected,
              100.0 * (r.deflection / expected - 1.0));
  EXPECT_NEAR(r.deflection, expected, 0.02 * expected);
  EXPECT_NEAR(r.ratio, 1.0, 0.01);
}

}  // namespace
}  // namespace plyform
