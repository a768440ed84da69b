#pragma once
// One measured normal traction-opening curve, as the fit sees it: the path the point was driven
// along (as `plyform law` takes it) and the traction measured at each of its points.

#include <stdexcept>
#include <string>
#include <vector>

#include "plyform/law/point_driver.hpp"

namespace plyform::fit {

struct MeasuredCurve {
  std::string name;                  ///< for messages and reports, e.g. the file name
  std::vector<law::PathPoint> path;  ///< time, gap, slips, temperature of every data point
  std::vector<double> stress;        ///< measured normal traction, tension positive [stress]
  double area = 0.0;  ///< probe area when the data were forces (reports in force too); 0: none
};

/// An input the fit cannot use (a curve the law cannot represent, a constant that cannot be
/// fitted): the message names the curve or the constant and the reason.
class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace plyform::fit
