#include "plyform/core/load_curve.hpp"

#include <algorithm>

namespace plyform::core {

double LoadCurve::operator()(double t) const {
  if (x.empty())
    return 0.0;
  if (t <= x.front())
    return y.front();
  if (t >= x.back())
    return y.back();
  const auto i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin());
  const double w = (t - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + w * (y[i] - y[i - 1]);
}

double LoadCurve::integral(double t) const {
  if (x.empty() || t <= x.front())
    return 0.0;
  double sum = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (t <= x[i - 1])
      break;
    const double b = std::min(t, x[i]);
    const double yb = y[i - 1] + (y[i] - y[i - 1]) * (b - x[i - 1]) / (x[i] - x[i - 1]);
    sum += 0.5 * (y[i - 1] + yb) * (b - x[i - 1]);
  }
  if (t > x.back())
    sum += y.back() * (t - x.back());
  return sum;
}

}  // namespace plyform::core
