#include <gtest/gtest.h>

#include "plyform/model/curve_desc.hpp"

namespace plyform::model {
namespace {

TEST(CurveDesc, EffectivePointsApplyOffsetsThenScales) {
  CurveDesc curve;
  curve.sfa = 2.0;
  curve.sfo = 10.0;
  curve.offa = 1.0;
  curve.offo = -0.5;
  curve.abscissa = {0.0, 1.0};
  curve.ordinate = {0.5, 1.5};
  const std::vector<CurvePoint> points = effective_points(curve);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_DOUBLE_EQ(points[0].x, 2.0);
  EXPECT_DOUBLE_EQ(points[0].y, 0.0);
  EXPECT_DOUBLE_EQ(points[1].x, 4.0);
  EXPECT_DOUBLE_EQ(points[1].y, 10.0);
}

TEST(CurveDesc, ZeroScaleFactorMeansOne) {
  CurveDesc curve;
  curve.sfa = 0.0;
  curve.sfo = 0.0;
  curve.abscissa = {1.0, 2.0};
  curve.ordinate = {3.0, 4.0};
  const std::vector<CurvePoint> points = effective_points(curve);
  EXPECT_DOUBLE_EQ(points[1].x, 2.0);
  EXPECT_DOUBLE_EQ(points[1].y, 4.0);
}

}  // namespace
}  // namespace plyform::model
