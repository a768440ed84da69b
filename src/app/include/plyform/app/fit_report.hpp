#pragma once
// The report of `plyform fit` in words: fitted constants with standard errors, correlations,
// residuals per curve; printed on the terminal and repeated as comments in FIT.k.

#include <span>
#include <string>
#include <vector>

#include "plyform/fit/fit.hpp"
#include "plyform/fit/measured_curve.hpp"

namespace plyform::app {

/// The lines of the report (no trailing newlines).
[[nodiscard]] std::vector<std::string> fit_report(const fit::FitResult& result,
                                                  std::span<const fit::MeasuredCurve> data);

}  // namespace plyform::app
