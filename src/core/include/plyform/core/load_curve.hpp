#pragma once
// A load curve of the runtime model: y(t), piecewise linear, end values held outside.

#include <vector>

namespace plyform::core {

struct LoadCurve {
  std::vector<double> x;  ///< strictly increasing (scale factors and offsets applied)
  std::vector<double> y;

  [[nodiscard]] double operator()(double t) const;
  /// Integral from x.front() to t (0 before x.front(); the last value is held beyond x.back()).
  [[nodiscard]] double integral(double t) const;
};

}  // namespace plyform::core
