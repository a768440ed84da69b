#pragma once
// Least-squares calibration of the law's constants to measured normal traction curves:
// Levenberg-Marquardt (Eigen) over the free constants in log / logit form, the residual being
// the law's traction through the point driver minus the data; then standard errors
// sigma^2 (J^T J)^-1, correlations and the reasons a fit is not meaningful.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "plyform/fit/free_constants.hpp"
#include "plyform/fit/law_model.hpp"
#include "plyform/fit/measured_curve.hpp"
#include "plyform/law/curve.hpp"

namespace plyform::fit {

struct FitSettings {
  ModelSettings model;
  int max_law_runs = 5000;  ///< drives of all the curves together, Jacobians included
  /// A curve whose RMS residual exceeds this fraction of its peak tension is not represented
  /// by the law: the fit is then not meaningful.
  double max_rms_fraction = 0.1;
};

struct ConstantEstimate {
  std::string name;
  double start = 0.0;
  double value = 0.0;
  double std_error = 0.0;  ///< NaN when the fit is not meaningful
};

struct CurveResult {
  std::string name;
  std::vector<double> fitted;  ///< the law's traction at each data point
  double rms = 0.0;            ///< of the residual fitted - measured
  double max_abs = 0.0;
  double peak_data = 0.0;  ///< largest measured tension
  double peak_fit = 0.0;
};

struct FitResult {
  std::vector<std::optional<double>> constants;  ///< the start with the fitted values set
  std::vector<ConstantEstimate> estimates;       ///< one per free constant, in --free order
  std::vector<double> correlation;               ///< n x n, row-major
  std::vector<CurveResult> curves;
  double rms = 0.0;        ///< over all points
  std::size_t points = 0;  ///< data points, all curves
  int iterations = 0;      ///< Levenberg-Marquardt iterations
  int law_runs = 0;        ///< drives of all curves
  std::string solver;      ///< why the iteration stopped, in words
  std::vector<std::string> warnings;
  std::vector<std::string> problems;  ///< why the fit is not meaningful; empty: it is
  [[nodiscard]] bool meaningful() const { return problems.empty(); }
};

/// Fits `free` to `data` from the UC vector `start` (curves: the load curves that -N slots of
/// `start` refer to). Throws FitError when the start is not a valid law, a free constant cannot
/// start where it is, or a curve cannot be represented by the law (unrepresentable()); a fit
/// that runs but means nothing comes back with `problems`.
[[nodiscard]] FitResult fit_constants(std::vector<std::optional<double>> start,
                                      std::span<const law::Curve> curves,
                                      std::span<const MeasuredCurve> data,
                                      std::span<const FreeConstant> free,
                                      const FitSettings& settings);

}  // namespace plyform::fit
