#pragma once
// Curves the law cannot represent, found before fitting so that the user reads the reason
// instead of a silent best effort: no tension at all, compression while open, no peak, or a
// path along which the starting law never bonds.

#include <span>
#include <string>
#include <vector>

#include "plyform/fit/law_model.hpp"
#include "plyform/fit/measured_curve.hpp"
#include "plyform/law/law.hpp"

namespace plyform::fit {

/// Every reason found (empty: none); each message names the curve, the point and the reason.
[[nodiscard]] std::vector<std::string> unrepresentable(std::span<const MeasuredCurve> curves,
                                                       const law::Law& start,
                                                       const ModelSettings& settings);

}  // namespace plyform::fit
