#include "plyform/fit/curve_checks.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace plyform::fit {
namespace {

// Measured noise must not trip the checks: compression in opening counts when it exceeds this
// fraction of the curve's peak tension and this many times the noise of the curve, and a curve
// "has passed its peak" when its last tension is below (1 - kPeakDrop) of its last pull's peak.
constexpr double kCompressionTolerance = 0.05;
constexpr double kCompressionNoise = 5.0;
constexpr double kPeakDrop = 0.1;

/// The standard deviation of the noise on a smooth curve: second differences of white noise
/// have the variance 6 sigma^2, and their median absolute value (1.4826 MAD for a Gaussian) is
/// not moved by the few points where the curve itself bends sharply.
double noise_level(const std::vector<double>& s) {
  std::vector<double> d;
  for (std::size_t i = 1; i + 1 < s.size(); ++i)
    d.push_back(std::abs(s[i + 1] - 2.0 * s[i] + s[i - 1]));
  if (d.empty())
    return 0.0;
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return 1.4826 * d[d.size() / 2] / std::sqrt(6.0);
}

std::string where(const MeasuredCurve& c, std::size_t i) {
  return fmt::format("point {} (time {:g}, gap {:g})", i + 1, c.path[i].time, c.path[i].gap);
}

void check_one(const MeasuredCurve& c, const law::Law& start, const ModelSettings& settings,
               std::vector<std::string>& out) {
  const std::size_t n = c.path.size();
  if (c.stress.size() != n || n < 3) {
    out.push_back(
        fmt::format("curve {}: needs at least 3 points with a path and a traction each", c.name));
    return;
  }
  const auto peak_it = std::max_element(c.stress.begin(), c.stress.end());
  const double peak = *peak_it;
  if (!(peak > 0.0)) {
    out.push_back(fmt::format(
        "curve {}: no tension anywhere (largest traction {:g}): the law's cohesive traction is a "
        "tension, positive in the fit; if the file gives the pressure positive in compression, "
        "name that column 'pressure'",
        c.name, peak));
    return;
  }
  const double tolerance =
      std::max(kCompressionTolerance * peak, kCompressionNoise * noise_level(c.stress));
  for (std::size_t i = 0; i < n; ++i) {
    if (c.path[i].gap > 0.0 && c.stress[i] < -tolerance) {
      out.push_back(fmt::format(
          "curve {}: compression {:g} at {} while open: in opening (gap > 0) the law carries "
          "tension only (check the sign of the force or stress column, or the gap's zero)",
          c.name, -c.stress[i], where(c, i)));
      return;
    }
  }
  // The last pull: from the last point in contact (gap <= 0), or from the start.
  std::size_t first = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (c.path[i].gap <= 0.0)
      first = i;
  }
  if (n - first >= 3) {
    const auto pull_peak =
        std::max_element(c.stress.begin() + static_cast<long>(first), c.stress.end());
    const auto i_peak = static_cast<std::size_t>(pull_peak - c.stress.begin());
    if (*pull_peak > 0.0 && c.stress.back() > (1.0 - kPeakDrop) * *pull_peak) {
      out.push_back(fmt::format(
          "curve {}: no peak: the tension still rises or stays within {:.0f} % of its largest "
          "value {:g} (at {}) to the end of the data (gap {:g}); the law softens past sigma_max, "
          "so the measurement must go beyond the peak",
          c.name, 100.0 * kPeakDrop, *pull_peak, where(c, i_peak), c.path.back().gap));
      return;
    }
  }
  const std::vector<double> model = model_stress(start, c, settings);
  if (std::all_of(model.begin(), model.end(), [](double s) { return s <= 0.0; })) {
    const law::Parameters& p = start.parameters();
    const bool touches =
        std::any_of(c.path.begin(), c.path.end(), [](const auto& x) { return x.gap <= 0.0; });
    out.push_back(fmt::format(
        "curve {}: the starting law carries no tension along it: the point {} (first gap {:g}, "
        "BOND_TOL {:g}, BETA0 {:g}); the measured tension up to {:g} cannot be fitted",
        c.name,
        touches ? "touches only with BETA0 = 0 and no healing (ZETA = 0) to bond it"
                : "starts beyond BOND_TOL and never touches (gap <= 0), so it never bonds",
        c.path.front().gap, p.bond_tol, p.beta0, peak));
  }
}

}  // namespace

std::vector<std::string> unrepresentable(std::span<const MeasuredCurve> curves,
                                         const law::Law& start, const ModelSettings& settings) {
  std::vector<std::string> out;
  for (const MeasuredCurve& c : curves)
    check_one(c, start, settings, out);
  return out;
}

}  // namespace plyform::fit
