#include "plyform/app/fit_report.hpp"

#include <cmath>

#include <fmt/format.h>

namespace plyform::app {

std::vector<std::string> fit_report(const fit::FitResult& r,
                                    std::span<const fit::MeasuredCurve> data) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format("Levenberg-Marquardt: {} ({} iterations, {} law runs)", r.solver,
                              r.iterations, r.law_runs));
  lines.push_back(fmt::format("{:<10} {:>14} {:>16} {:>12} {:>10}", "constant", "start", "fitted",
                              "std error", "rel error"));
  for (const fit::ConstantEstimate& e : r.estimates) {
    const std::string rel = std::isfinite(e.std_error) && e.value != 0.0
                                ? fmt::format("{:.3g} %", 100.0 * e.std_error / std::abs(e.value))
                                : std::string("-");
    lines.push_back(fmt::format("{:<10} {:>14.6g} {:>16.9g} {:>12.3g} {:>10}", e.name, e.start,
                                e.value, e.std_error, rel));
  }
  const std::size_t n = r.estimates.size();
  if (n > 1 && r.correlation.size() == n * n && std::isfinite(r.correlation[0])) {
    std::string head = fmt::format("{:<10}", "correlation");
    for (const auto& e : r.estimates)
      head += fmt::format(" {:>9}", e.name);
    lines.push_back(head);
    for (std::size_t i = 0; i < n; ++i) {
      std::string row = fmt::format("{:<10}", r.estimates[i].name);
      for (std::size_t j = 0; j <= i; ++j)
        row += fmt::format(" {:>9.4f}", r.correlation[i * n + j]);
      lines.push_back(row);
    }
  }
  lines.push_back(fmt::format("residual (fitted - measured traction) over {} points: RMS {:.4g}",
                              r.points, r.rms));
  lines.push_back(fmt::format("{:<4} {:<28} {:>7} {:>11} {:>11} {:>11} {:>11}", "", "curve",
                              "points", "RMS", "max |res|", "peak data", "peak fit"));
  for (std::size_t c = 0; c < r.curves.size(); ++c) {
    const fit::CurveResult& cr = r.curves[c];
    std::string line =
        fmt::format("{:<4} {:<28} {:>7} {:>11.4g} {:>11.4g} {:>11.5g} {:>11.5g}", c + 1, cr.name,
                    cr.fitted.size(), cr.rms, cr.max_abs, cr.peak_data, cr.peak_fit);
    if (c < data.size() && data[c].area > 0.0) {
      line += fmt::format("  (force: RMS {:.4g}, peak {:.5g})", cr.rms * data[c].area,
                          cr.peak_data * data[c].area);
    }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace plyform::app
