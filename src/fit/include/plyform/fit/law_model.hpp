#pragma once
// The model side of the fit: the law's normal traction along a measured curve's path, through
// the same point driver as `plyform law`.

#include <vector>

#include "plyform/fit/measured_curve.hpp"
#include "plyform/law/law.hpp"

namespace plyform::fit {

struct ModelSettings {
  double penalty = 0.0;  ///< contact penalty per area; 0: C_N of the law driven (as `plyform law`)
  /// Law updates per data interval (the path is interpolated linearly between data points):
  /// 1 drives exactly the data's points, as `plyform law` would; more for coarse data.
  int substeps = 1;
};

/// The law's traction (tension positive, -pressure) at every point of `curve`.
[[nodiscard]] std::vector<double> model_stress(const law::Law& law, const MeasuredCurve& curve,
                                               const ModelSettings& settings);

}  // namespace plyform::fit
