#include "plyform/fit/fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/LevenbergMarquardt>

#include <fmt/format.h>

#include "identifiability.hpp"
#include "plyform/fit/curve_checks.hpp"
#include "plyform/law/law.hpp"
#include "plyform/law/user_constants.hpp"

namespace plyform::fit {
namespace {

// Central-difference step in the optimiser's variables (ln v, logit v, v / scale): a relative
// change of 1e-6, far above the law's round-off and small against its curvature.
constexpr double kStep = 1e-6;
// A positive constant that moved by this factor from its start has run to 0 or infinity.
constexpr double kRunaway = 1e6;
// A constant of [0, 1] closer than this to an end has run to it.
constexpr double kEndDistance = 1e-6;

/// The residual of the whole data set for the optimiser's variables x.
struct Residual : Eigen::DenseFunctor<double> {
  Residual(std::vector<std::optional<double>> uc, std::span<const law::Curve> law_curves,
           std::span<const MeasuredCurve> data, std::span<const FreeConstant> free,
           const ModelSettings& settings, int points, double penalty)
      : Eigen::DenseFunctor<double>(static_cast<int>(free.size()), points),
        uc_(std::move(uc)),
        law_curves_(law_curves),
        data_(data),
        free_(free),
        settings_(settings),
        penalty_(penalty) {}

  std::vector<std::optional<double>> constants(const Eigen::VectorXd& x) const {
    std::vector<std::optional<double>> uc = uc_;
    for (std::size_t j = 0; j < free_.size(); ++j)
      set_value(free_[j], from_variable(free_[j], x(static_cast<Eigen::Index>(j))), uc);
    return uc;
  }

  /// The law's traction per curve, or nothing when the constants are not a valid law.
  std::optional<std::vector<std::vector<double>>> model(const Eigen::VectorXd& x) {
    ++law_runs;
    law::FromConstantsResult built = law::from_user_constants(constants(x), law_curves_);
    if (!built.ok())
      return std::nullopt;
    const law::Law law(std::move(built.parameters));
    std::vector<std::vector<double>> out;
    for (const MeasuredCurve& c : data_)
      out.push_back(model_stress(law, c, settings_));
    return out;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    const auto m = model(x);
    Eigen::Index k = 0;
    for (std::size_t c = 0; c < data_.size(); ++c) {
      for (std::size_t i = 0; i < data_[c].stress.size(); ++i, ++k) {
        // Constants outside the law's ranges (T_HI below T_LO): a residual larger than any
        // the law gives, so the step is refused and the damping raised.
        f(k) = m ? (*m)[c][i] - data_[c].stress[i] : penalty_;
      }
    }
    return 0;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    Eigen::VectorXd plus(values()), minus(values());
    for (Eigen::Index j = 0; j < x.size(); ++j) {
      Eigen::VectorXd xp = x, xm = x;
      xp(j) += kStep;
      xm(j) -= kStep;
      (*this)(xp, plus);
      (*this)(xm, minus);
      jac.col(j) = (plus - minus) / (2.0 * kStep);
    }
    return 0;
  }

  int law_runs = 0;

 private:
  std::vector<std::optional<double>> uc_;
  std::span<const law::Curve> law_curves_;
  std::span<const MeasuredCurve> data_;
  std::span<const FreeConstant> free_;
  ModelSettings settings_;
  double penalty_;
};

std::string solver_status(Eigen::LevenbergMarquardtSpace::Status s) {
  using namespace Eigen::LevenbergMarquardtSpace;
  switch (s) {
    case RelativeReductionTooSmall:
      return "converged: the sum of squares no longer decreases";
    case RelativeErrorTooSmall:
      return "converged: the constants no longer change";
    case RelativeErrorAndReductionTooSmall:
      return "converged: neither the constants nor the sum of squares change";
    case CosinusTooSmall:
      return "converged: the residual is orthogonal to every direction of the constants";
    case TooManyFunctionEvaluation:
      return "stopped: too many law runs";
    case FtolTooSmall:
    case XtolTooSmall:
    case GtolTooSmall:
      return "stopped at the precision of the arithmetic";
    default:
      return "stopped: improper input";
  }
}

/// What a constant running to one end of its range says about the curves.
std::string runaway_hint(const std::string& name, bool to_zero) {
  if (name == "ETA" && to_zero)
    return "the curves show no rate effect (quasi-static): leave ETA out of --free and keep a "
           "small value, or add curves at faster rates";
  if (name.starts_with("ZETA") && !to_zero)
    return "the hold heals fully (beta = 1) however large zeta is: fix ZETA, or measure with a "
           "shorter hold or a lower pressure";
  if (name.starts_with("ZETA"))
    return "the curves show no healing";
  return "no finite value of it represents the curves";
}

void check_bounds(const FreeConstant& c, double start, double value,
                  std::vector<std::string>& problems) {
  if (c.transform == Transform::log && (value < start / kRunaway || value > start * kRunaway)) {
    const bool to_zero = value < start;
    problems.push_back(fmt::format("{} ran to its bound {} (from {:.4g} to {:.4g}): {}", c.name,
                                   to_zero ? "0" : "infinity", start, value,
                                   runaway_hint(c.name, to_zero)));
  } else if (c.transform == Transform::logit &&
             (value < kEndDistance || value > 1.0 - kEndDistance)) {
    problems.push_back(fmt::format("{} ran to its bound {} (from {:.4g} to {:.6g}): {}", c.name,
                                   value < 0.5 ? "0" : "1", start, value,
                                   runaway_hint(c.name, value < 0.5)));
  }
}

}  // namespace

FitResult fit_constants(std::vector<std::optional<double>> start,
                        std::span<const law::Curve> curves, std::span<const MeasuredCurve> data,
                        std::span<const FreeConstant> free, const FitSettings& settings) {
  if (data.empty())
    throw FitError("no curve to fit");
  if (free.empty())
    throw FitError("no constant to fit");
  for (const FreeConstant& c : free)
    check_start(c, start);
  law::FromConstantsResult built = law::from_user_constants(start, curves);
  if (!built.ok()) {
    std::string message = "the starting constants are not a valid law:";
    for (const law::ConstantError& e : built.errors)
      message += "\n  " + e.message;
    throw FitError(message);
  }
  const law::Law start_law(built.parameters);
  if (const auto reasons = unrepresentable(data, start_law, settings.model); !reasons.empty()) {
    std::string message;
    for (const std::string& r : reasons)
      message += (message.empty() ? "" : "\n") + r;
    throw FitError(message);
  }

  FitResult result;
  double sum_sq_data = 0.0;
  double largest = 0.0;
  for (const MeasuredCurve& c : data) {
    result.points += c.stress.size();
    for (double s : c.stress) {
      sum_sq_data += s * s;
      largest = std::max(largest, std::abs(s));
    }
  }
  const auto m = static_cast<Eigen::Index>(result.points);
  const auto n = static_cast<Eigen::Index>(free.size());
  if (m <= n) {
    throw FitError(fmt::format("{} data points cannot determine {} constants", m, n));
  }

  Eigen::VectorXd x(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const FreeConstant& c = free[static_cast<std::size_t>(j)];
    x(j) = to_variable(c, value_of(c, start));
  }
  Residual residual(start, curves, data, free, settings.model, static_cast<int>(m), 10.0 * largest);
  Eigen::LevenbergMarquardt<Residual> lm(residual);
  lm.setXtol(1e-10);
  lm.setFtol(1e-12);
  lm.setGtol(0.0);
  // Each Jacobian costs 2 n law runs; Eigen counts only the others.
  lm.setMaxfev(std::max<Eigen::Index>(10, settings.max_law_runs / (2 * n + 1)));
  const Eigen::LevenbergMarquardtSpace::Status status = lm.minimize(x);
  result.iterations = static_cast<int>(lm.iterations());
  result.solver = solver_status(status);
  if (status == Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation ||
      status == Eigen::LevenbergMarquardtSpace::ImproperInputParameters) {
    result.problems.push_back(
        fmt::format("the least-squares iteration did not converge ({}; {} iterations)",
                    result.solver, result.iterations));
  }

  result.constants = residual.constants(x);
  const auto model = residual.model(x);
  if (!model)
    throw FitError("the fitted constants are not a valid law");
  double ssr = 0.0;
  for (std::size_t c = 0; c < data.size(); ++c) {
    CurveResult cr;
    cr.name = data[c].name;
    cr.fitted = (*model)[c];
    double sq = 0.0;
    for (std::size_t i = 0; i < cr.fitted.size(); ++i) {
      const double r = cr.fitted[i] - data[c].stress[i];
      sq += r * r;
      cr.max_abs = std::max(cr.max_abs, std::abs(r));
      cr.peak_data = std::max(cr.peak_data, data[c].stress[i]);
      cr.peak_fit = std::max(cr.peak_fit, cr.fitted[i]);
    }
    ssr += sq;
    cr.rms = std::sqrt(sq / static_cast<double>(cr.fitted.size()));
    if (cr.rms > settings.max_rms_fraction * cr.peak_data) {
      result.problems.push_back(fmt::format(
          "curve {}: the law does not represent it: its RMS residual {:.4g} is {:.1f} % of its "
          "peak tension {:.4g} (more than {:.0f} %)",
          cr.name, cr.rms, 100.0 * cr.rms / cr.peak_data, cr.peak_data,
          100.0 * settings.max_rms_fraction));
    }
    result.curves.push_back(std::move(cr));
  }
  result.rms = std::sqrt(ssr / static_cast<double>(m));

  std::vector<std::string> names;
  bool at_bound = false;
  for (Eigen::Index j = 0; j < n; ++j) {
    const FreeConstant& c = free[static_cast<std::size_t>(j)];
    names.push_back(c.name);
    const double v0 = value_of(c, start);
    const double v = from_variable(c, x(j));
    result.estimates.push_back({c.name, v0, v, NAN});
    const std::size_t before = result.problems.size();
    check_bounds(c, v0, v, result.problems);
    at_bound = at_bound || result.problems.size() > before;
  }
  if (!at_bound) {
    Eigen::MatrixXd jac(m, n);
    residual.df(x, jac);
    const double sigma2 = ssr / static_cast<double>(m - n);
    const detail::Identifiability id =
        detail::analyse(jac, sigma2, names, std::sqrt(sum_sq_data / static_cast<double>(m)));
    result.problems.insert(result.problems.end(), id.problems.begin(), id.problems.end());
    result.correlation = id.correlation;
    for (Eigen::Index j = 0; j < n; ++j) {
      const FreeConstant& c = free[static_cast<std::size_t>(j)];
      ConstantEstimate& e = result.estimates[static_cast<std::size_t>(j)];
      const double sx = id.std_error[static_cast<std::size_t>(j)];
      e.std_error = std::abs(value_derivative(c, x(j))) * sx;
      // sx is the standard error of ln v for positive constants: above 1 the value is not
      // known to within a factor e.
      if (c.transform != Transform::linear && sx > 1.0) {
        result.problems.push_back(fmt::format(
            "{} is not determined by these curves: its standard error {:.3g} exceeds its value "
            "{:.4g}; fix it or add curves that depend on it",
            c.name, e.std_error, e.value));
      }
    }
  }
  result.law_runs = residual.law_runs;
  return result;
}

}  // namespace plyform::fit
