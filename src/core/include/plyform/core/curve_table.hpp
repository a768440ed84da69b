#pragma once
// A table of the runtime model (*DEFINE_TABLE): curves y(x), one for each of an increasing
// sequence of values v (temperatures, strain rates), read as one function y(v, x).

#include <vector>

#include "plyform/core/load_curve.hpp"

namespace plyform::core {

struct CurveTable {
  std::vector<double> value;     ///< strictly increasing (the table's SFA and OFFA applied)
  std::vector<LoadCurve> curve;  ///< one per value

  /// Each of the two curves around v at x, linear in v between them; outside the values the
  /// first or last curve (a table does not extrapolate in v). Every curve holds its end values
  /// outside its abscissae, as a LoadCurve does.
  [[nodiscard]] double operator()(double v, double x) const;
};

}  // namespace plyform::core
