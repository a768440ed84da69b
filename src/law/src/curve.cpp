#include "plyform/law/curve.hpp"

#include <algorithm>
#include <cmath>

namespace plyform::law {

Curve::Curve(int id, std::vector<double> x, std::vector<double> y)
    : id_(id), x_(std::move(x)), y_(std::move(y)) {}

std::string Curve::validate() const {
  if (x_.size() != y_.size())
    return "abscissa and ordinate counts differ";
  if (x_.size() < 2)
    return "a curve needs at least 2 points";
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      return "non-finite value in the curve";
    if (i > 0 && !(x_[i] > x_[i - 1]))
      return "abscissae must increase strictly";
  }
  return {};
}

double Curve::operator()(double t) const {
  if (t <= x_.front())
    return y_.front();
  if (t >= x_.back())
    return y_.back();
  // First abscissa greater than t; t lies in [x[i-1], x[i]).
  const auto it = std::upper_bound(x_.begin(), x_.end(), t);
  const auto i = static_cast<std::size_t>(it - x_.begin());
  const double w = (t - x_[i - 1]) / (x_[i] - x_[i - 1]);
  return y_[i - 1] + w * (y_[i] - y_[i - 1]);
}

}  // namespace plyform::law
