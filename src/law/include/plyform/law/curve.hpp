#pragma once
// A piecewise-linear function of one variable (here: a parameter against temperature).

#include <span>
#include <string>
#include <vector>

namespace plyform::law {

/// Piecewise-linear table y(x) with strictly increasing abscissae. Outside the table the end
/// values are held constant: a material parameter must not run away when a node leaves the
/// tabulated temperature range.
class Curve {
 public:
  Curve() = default;
  /// Throws nothing; check `valid()` (or use `validate()` for the reason).
  Curve(int id, std::vector<double> x, std::vector<double> y);

  /// Empty string when the table is usable, else the reason (fewer than 2 points, sizes
  /// differ, abscissae not strictly increasing, non-finite values).
  [[nodiscard]] std::string validate() const;
  [[nodiscard]] bool valid() const { return validate().empty(); }

  [[nodiscard]] int id() const { return id_; }
  [[nodiscard]] std::span<const double> x() const { return x_; }
  [[nodiscard]] std::span<const double> y() const { return y_; }

  /// Value at `t` (linear interpolation, constant extrapolation). O(log n).
  [[nodiscard]] double operator()(double t) const;

 private:
  int id_ = 0;
  std::vector<double> x_;
  std::vector<double> y_;
};

}  // namespace plyform::law
