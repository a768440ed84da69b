#include "plyform/model/curve_desc.hpp"

#include <algorithm>

namespace plyform::model {

double effective_scale_factor(double written) {
  return written == 0.0 ? 1.0 : written;
}

std::vector<CurvePoint> effective_points(const CurveDesc& curve) {
  const double sfa = effective_scale_factor(curve.sfa);
  const double sfo = effective_scale_factor(curve.sfo);
  std::vector<CurvePoint> points;
  const std::size_t n = std::min(curve.abscissa.size(), curve.ordinate.size());
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    points.push_back(
        {sfa * (curve.abscissa[i] + curve.offa), sfo * (curve.ordinate[i] + curve.offo)});
  }
  return points;
}

}  // namespace plyform::model
