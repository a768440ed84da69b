// A bonded node carried over a ridge of the master, where the master's layer changes thickness:
// two fixed shell strips meet at a 35 degree kink (the core's surface over a die's shoulder), the
// flat one 0.244 mm thick, the sloping one 0.200 mm (its half-thickness 22 um less). A small
// soft shell lies on the flat one, bonded at t = 0 by the cohesive law (sigma_max 1 MPa, C_N 100
// MPa/mm: the law damages only past the opening sigma_max / C_N = 10 um), pressed by 0.5 MPa,
// and is carried along x over the kink and down the slope (slowly: the normal oscillation's
// amplitude at the kink, v sin(35) / omega, is below 1 um), free to follow the surface in z and
// to tilt onto the slope (its rotations free: held, the shell would resist the tilt by its
// transverse shear and lift its leading nodes off, a real opening).
// References (conservation and the law's own threshold, no fitted numbers):
// - pressed throughout and never opened past 10 um, the bond takes no damage: the damage book
//   stays zero and the node stays bonded;
// - frictionless, with no tangential adhesion and no damping, the interface's books close at
//   every output: work + surface = stored + damage + viscous + friction + damping.
// Before the offset surface met at its nodes and a node took the neighbour across an edge once
// its gaps on the two parted (projection.hpp, across_edge; surface_geometry.hpp,
// corner_offset), the slider rode on past the kink on the flat segment's extension to MAXPAR's
// tolerance and then found the slope below it by that overshoot times sin(35), plus the 22 um
// step of the two half-thicknesses: a sudden opening past the law's peak, which damaged the
// bond and broke the books (the frictionless square cup's interfaces, 1.9 % of their work).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact_decks.hpp"

namespace plyform {
namespace {

TEST(ContactRidge, ABondedNodeCarriedOverAKinkBetweenLayersOfTwoThicknessesKeepsItsBond) {
  constexpr double kEnd = 9e-3, kPress = kEnd / 9, kSlide = 4.0;
  constexpr double kThick = 0.244, kThin = 0.200, kSlider = 0.05, kPressure = 0.5;
  constexpr double kCn = 100.0, kSmax = 1.0;
  const double slope = std::tan(35.0 * M_PI / 180.0);
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(kEnd);
  d.kw("*DATABASE_RCFORC").card(kEnd / 300);
  d.kw("*PART").kw("flat, thick").card(1, 1, 1);
  d.kw("*PART").kw("slope, thin").card(2, 2, 1);
  d.kw("*PART").kw("slider").card(3, 3, 1);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(kThick, kThick, kThick, kThick);
  d.kw("*SECTION_SHELL").card(2, 2, 0.8333, 2).card(kThin, kThin, kThin, kThin);
  d.kw("*SECTION_SHELL").card(3, 2, 0.8333, 2).card(kSlider, kSlider, kSlider, kSlider);
  // Soft: the master is held, the slider's nodes follow the surface nearly independently.
  d.kw("*MAT_ELASTIC").card(1, 7.85e-9, 10.0, 0.3);
  // The master: x = 0, 2, 4 flat at z = 0, then down at 35 degrees to x = 8; 2 mm wide.
  d.kw("*NODE");
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 4; ++i)
      d.card(1 + 5 * j + i, 2.0 * i, 2.0 * j, i <= 2 ? 0.0 : -(2.0 * i - 4.0) * slope);
  d.kw("*ELEMENT_SHELL").card(1, 1, 1, 2, 7, 6).card(2, 1, 2, 3, 8, 7);
  d.card(3, 2, 3, 4, 9, 8).card(4, 2, 4, 5, 10, 9);
  // The slider: 0.05 mm square at x = 1, its lower face on the master's upper face.
  constexpr double xc = 1.0, yc = 1.0, h = 0.025, zc = 0.5 * kThick + 0.5 * kSlider;
  d.kw("*NODE");
  d.card(101, xc - h, yc - h, zc).card(102, xc + h, yc - h, zc).card(103, xc + h, yc + h, zc);
  d.card(104, xc - h, yc + h, zc);
  d.kw("*ELEMENT_SHELL").card(101, 3, 101, 102, 103, 104);
  d.kw("*SET_NODE_LIST").card(1).ids({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  d.kw("*SET_NODE_LIST").card(2).ids({101, 102, 103, 104});
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 0, 0, 0);
  // The pressure comes on over the first ninth and holds; then the slide (smooth, at most
  // 0.75 m/s).
  d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(kPress, 1.0).card(kEnd, 1.0);
  d.kw("*SET_SHELL_LIST").card(1).ids({101});
  d.kw("*LOAD_SHELL_SET").card(1, 1, kPressure);
  d.kw("*DEFINE_CURVE").card(2).card(0.0, 0.0);
  for (int i = 0; i <= 80; ++i) {
    const double s = i / 80.0;
    d.card(kPress + s * (kEnd - kPress), kSlide * s * s * (3.0 - 2.0 * s));
  }
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 2, 2, 1.0);
  d.kw("*SET_PART_LIST").card(1).card(1, 2);
  d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(1, "slider bonded on the ridge");
  d.card(3, 1, 3, 2).card(0).card(1, 1);
  test::bonded_without_shear(d, 1, kCn, kSmax);
  test::DeckRun r;
  test::run_deck(d.text(), r);
  ASSERT_FALSE(r.sink.contact.empty());
  EXPECT_TRUE(r.result.distrust.empty());
  const double omega_area = kSmax * kSmax / kCn * (2 * h) * (2 * h);  // the bond's adhesion
  double most = 0.0, worst = 0.0, damage = 0.0;
  for (const auto& [t, reports] : r.sink.contact)
    most = std::max(most, reports.at(0).stored);
  ASSERT_GT(most, 0.0);
  for (const auto& [t, reports] : r.sink.contact) {
    const auto& b = reports.at(0);
    const double books = b.stored + b.damage + b.viscous + b.friction + b.damping;
    worst = std::max(worst, std::abs(b.work + b.surface - books));
    damage = std::max(damage, b.damage);
    EXPECT_NEAR(b.work + b.surface, books, 1e-3 * most) << "t = " << t;
    EXPECT_LE(b.damage, 1e-9 * omega_area) << "t = " << t;
  }
  const auto& last = r.sink.contact.back().second.at(0);
  EXPECT_EQ(last.in_contact + last.bonded, 4u);  // on the slope, held
  std::printf(
      "ridge: springs at most %.4g mJ, |books - work - surface| at most %.3g mJ, damage "
      "at most %.3g mJ (adhesion %.3g mJ)\n",
      most, worst, damage, omega_area);
}

}  // namespace
}  // namespace plyform
