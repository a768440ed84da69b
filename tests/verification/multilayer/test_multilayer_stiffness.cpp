// The bending stiffness of a three-layer strip whose layers are separate shells (issue 15):
// with bonded interfaces that of the composite beam, with frictionless ones the sum of the
// layers' own.
//
// A cantilever of length L = 100 mm and width b = 10 mm (strip_decks.hpp: aluminium 0.25 /
// core 1.00 / aluminium 0.25 mm, E_s = 70000, E_c = 1500 MPa, nu = 0), every layer clamped at
// x = 0, a load P at the tip of the upper skin ramped smoothly over two periods of the first
// mode and held for one; the tip deflection is the core's, averaged over the hold (a ramp over
// four periods and a hold of two, twice the cycles, gave the same deflections within 0.01 %).
// - Bonded (cohesive law, C_N = C_T = 1e4 MPa/mm): the composite beam, from the transformed
//   section (parallel axis theorem), EI_b = E_c b t_c^3 / 12 + 2 E_s (b t_s^3 / 12 + b t_s h^2)
//   with h = (t_c + t_s) / 2 the skins' offset; and, the core being soft in shear, sandwich
//   theory's shear deflection P L / S with S = b d^2 / (t_c / (k G_c) + 2 / C_T): the faces'
//   mid-surfaces d = 2 h apart, the core's transverse shear (shear factor k) and the two
//   interfaces' tangential springs in series. delta_b = P L^3 / (3 EI_b) + P L / S.
// - Frictionless (penalty contact, mu = 0): each layer bends about its own mid-surface and
//   the stiffnesses add, EI_f = sum of E_i b t_i^3 / 12, delta_f = P L^3 / (3 EI_f). The layers'
//   own shear adds under 1e-4 of it (each carries the share EI_i / EI_f of the load over its
//   k G_i b t_i), so it is left out.
// EI_b is 45 times EI_f here: the interfaces, not the layers, set the stiffness.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "strip_decks.hpp"

namespace plyform::test::multilayer {
namespace {

constexpr double kLength = 100.0;
constexpr int kNx = 20;

constexpr double ei_bonded() {
  return kCoreE * kWidth * kCore * kCore * kCore / 12.0 +
         2.0 * kSkinE * (kWidth * kSkin * kSkin * kSkin / 12.0 + kWidth * kSkin * kH * kH);
}
constexpr double ei_free() {
  return kCoreE * kWidth * kCore * kCore * kCore / 12.0 +
         2.0 * kSkinE * kWidth * kSkin * kSkin * kSkin / 12.0;
}

/// Period of the cantilever's first bending mode, (1.875^2) sqrt(EI / (m L^4)) in rad/s.
double first_period(double ei) {
  double mass = 0.0;  // per length
  for (const Layer& l : kLayers)
    mass += l.density * l.thickness * kWidth;
  return 2.0 * std::numbers::pi * kLength * kLength / (3.5160 * std::sqrt(ei / mass));
}

struct Bend {
  double deflection = 0.0;     ///< core's tip, mean over the hold
  double skin_mismatch = 0.0;  ///< largest |skin tip - core tip| over the hold, relative
  Books books;
};

Bend bend(Interface interface, double load) {
  const double period = first_period(interface == Interface::bonded ? ei_bonded() : ei_free());
  const double ramp = 2.0 * period, end = 3.0 * period;
  Deck d;
  d.kw("*CONTROL_TERMINATION").card(end);
  d.kw("*DATABASE_GLSTAT").card(end / 200);
  d.kw("*DATABASE_NODOUT").card(end / 600);
  d.kw("*DATABASE_HISTORY_NODE")
      .card(node_id(1, kNx, kNx, 0), node_id(2, kNx, kNx, 0), node_id(3, kNx, kNx, 0));
  write_strip(d, kLength, kNx, interface);
  d.kw("*DEFINE_CURVE").card(1);
  for (int k = 0; k <= 40; ++k)
    d.card(ramp * k / 40.0, smooth_ramp(k / 40.0));
  d.card(2.0 * end, 1.0);
  d.kw("*SET_NODE_LIST").card(3).ids({node_id(3, kNx, kNx, 0), node_id(3, kNx, kNx, 1)});
  d.kw("*LOAD_NODE_SET").card(3, 3, 1, -0.5 * load);

  TempDir dir;
  const auto out = run(dir, "strip", d.text());
  const Csv nodout = read_csv(out / "nodout.csv");
  const std::size_t time = nodout.column("time"), node = nodout.column("node");
  const std::size_t uz = nodout.column("uz");
  std::map<double, std::array<double, 3>> tips;  // time -> deflection of each layer's tip
  for (const auto& r : nodout.rows)
    tips[r[time]][static_cast<std::size_t>(r[node]) / 1000 - 1] = -r[uz];
  Bend b;
  double sum = 0.0;
  int count = 0;
  for (const auto& [t, w] : tips) {
    if (t < ramp * (1.0 + 1e-9))
      continue;
    sum += w[1];
    ++count;
    for (std::size_t skin : {0u, 2u})
      b.skin_mismatch = std::max(b.skin_mismatch, std::abs(w[skin] / w[1] - 1.0));
  }
  b.deflection = count > 0 ? sum / count : 0.0;
  b.books = read_books(out);
  return b;
}

TEST(MultilayerStiffness, BondedLayersBendAsTheCompositeBeam) {
  constexpr double kLoad = 0.2;            // N: tip deflection about 0.5 mm, L / 200
  const double shear_core = 0.5 * kCoreE;  // G = E / 2 (nu = 0)
  const double d = 2.0 * kH;
  const double s = kWidth * d * d / (kCore / (kShearFactor * shear_core) + 2.0 / kCt);
  const double bending = kLoad * std::pow(kLength, 3) / (3.0 * ei_bonded());
  const double shear = kLoad * kLength / s;
  const Bend b = bend(Interface::bonded, kLoad);
  const double expected = bending + shear;
  std::printf(
      "bonded: EI_b %.1f N mm^2, delta %.5f mm (bending %.5f + shear %.5f, the interfaces' "
      "springs %.5f of it) against %.5f measured (%+.2f %%); skins' tips within %.2g; books: "
      "ratio %.2g off 1, hourglass %.2g, kinetic %.2g of internal\n",
      ei_bonded(), expected, bending, shear, kLoad * kLength * 2.0 / kCt / (kWidth * d * d),
      b.deflection, 100.0 * (b.deflection / expected - 1.0), b.skin_mismatch, b.books.worst_ratio,
      b.books.hourglass_share, b.books.kinetic_share);
  EXPECT_NEAR(b.deflection, expected, 0.02 * expected);
  EXPECT_LT(b.skin_mismatch, 0.01);
  expect_books_close(b.books, 0.01);
}

TEST(MultilayerStiffness, FrictionlessLayersAddTheirOwnStiffnesses) {
  constexpr double kLoad = 0.005;  // N: tip deflection about 0.5 mm
  const double expected = kLoad * std::pow(kLength, 3) / (3.0 * ei_free());
  const Bend b = bend(Interface::frictionless, kLoad);
  std::printf(
      "frictionless: EI_f %.1f N mm^2 (EI_b / EI_f = %.1f), delta %.5f mm against %.5f "
      "measured (%+.2f %%); skins' tips within %.2g; books: ratio %.2g off 1, hourglass %.2g, "
      "kinetic %.2g of internal\n",
      ei_free(), ei_bonded() / ei_free(), expected, b.deflection,
      100.0 * (b.deflection / expected - 1.0), b.skin_mismatch, b.books.worst_ratio,
      b.books.hourglass_share, b.books.kinetic_share);
  EXPECT_NEAR(b.deflection, expected, 0.02 * expected);
  EXPECT_LT(b.skin_mismatch, 0.01);
  expect_books_close(b.books, 0.01);
}

}  // namespace
}  // namespace plyform::test::multilayer
