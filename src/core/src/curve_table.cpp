#include "plyform/core/curve_table.hpp"

#include <algorithm>

namespace plyform::core {

double CurveTable::operator()(double v, double x) const {
  if (curve.empty())
    return 0.0;
  if (v <= value.front())
    return curve.front()(x);
  if (v >= value.back())
    return curve.back()(x);
  const auto i =
      static_cast<std::size_t>(std::upper_bound(value.begin(), value.end(), v) - value.begin());
  const double w = (v - value[i - 1]) / (value[i] - value[i - 1]);
  return (1.0 - w) * curve[i - 1](x) + w * curve[i](x);
}

}  // namespace plyform::core
