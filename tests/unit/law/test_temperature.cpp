// Temperature dependence: the two-region C1 cubic transition and the curve form.
#include <gtest/gtest.h>

#include "plyform/law/parameters.hpp"

namespace plyform::law {
namespace {

Parameters two_region() {
  Parameters p;
  p.t_lo = 400.0;
  p.t_hi = 500.0;
  p.sigma_max = {0.5, 0.1, -1};
  return p;
}

TEST(Temperature, EndValuesHeldOutsideTheTransition) {
  const Parameters p = two_region();
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 300.0), 0.5);
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 400.0), 0.5);
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 500.0), 0.1);
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 900.0), 0.1);
}

TEST(Temperature, MidpointIsTheMeanOfTheTwoValues) {
  // s = 1/2: 3 s^2 - 2 s^3 = 1/2 exactly.
  const Parameters p = two_region();
  EXPECT_NEAR(evaluate(p.sigma_max, p, 450.0), 0.3, 1e-15);
}

TEST(Temperature, ValueAndSlopeAreContinuousAtBothEnds) {
  const Parameters p = two_region();
  const double h = 1e-4;
  for (double t : {p.t_lo, p.t_hi}) {
    const double left = evaluate(p.sigma_max, p, t - h);
    const double mid = evaluate(p.sigma_max, p, t);
    const double right = evaluate(p.sigma_max, p, t + h);
    EXPECT_NEAR(left, mid, 1e-7) << "value jump at T = " << t;
    EXPECT_NEAR(right, mid, 1e-7) << "value jump at T = " << t;
    // One-sided slopes vanish at both ends (outside: constant; inside: d/ds = 6 s (1 - s) = 0).
    EXPECT_NEAR((right - mid) / h, 0.0, 1e-5);
    EXPECT_NEAR((mid - left) / h, 0.0, 1e-5);
  }
  // Inside, the slope peaks at the midpoint at 1.5 (hi - lo) / (T_hi - T_lo).
  const double slope =
      (evaluate(p.sigma_max, p, 450.0 + h) - evaluate(p.sigma_max, p, 450.0 - h)) / (2 * h);
  EXPECT_NEAR(slope, 1.5 * (0.1 - 0.5) / 100.0, 1e-8);
}

TEST(Temperature, CurveFormInterpolatesLinearlyAndHoldsEnds) {
  Parameters p;
  p.curves.emplace_back(7, std::vector<double>{300.0, 400.0, 600.0},
                        std::vector<double>{1.0, 0.5, 0.1});
  p.sigma_max.curve = 0;
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 200.0), 1.0);
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 300.0), 1.0);
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 350.0), 0.75);
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 400.0), 0.5);
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 500.0), 0.3);
  EXPECT_DOUBLE_EQ(evaluate(p.sigma_max, p, 700.0), 0.1);
}

TEST(Temperature, InvalidCurvesAreNamed) {
  EXPECT_EQ(Curve(1, {1.0}, {2.0}).validate(), "a curve needs at least 2 points");
  EXPECT_EQ(Curve(1, {1.0, 1.0}, {2.0, 3.0}).validate(), "abscissae must increase strictly");
  EXPECT_EQ(Curve(1, {1.0, 2.0}, {2.0}).validate(), "abscissa and ordinate counts differ");
}

}  // namespace
}  // namespace plyform::law
