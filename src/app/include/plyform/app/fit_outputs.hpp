#pragma once
// The files `plyform fit` writes: FIT.k (the fitted *USER_INTERFACE_FRICTION card, complete,
// with the report as comments) and FIT_curves.csv (data and fitted traction point by point).

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "plyform/fit/fit.hpp"
#include "plyform/fit/measured_curve.hpp"
#include "plyform/law/curve.hpp"

namespace plyform::app {

/// Writes a deck that `plyform check` and `run` read: *KEYWORD, *TITLE, `comments` as `$`
/// lines, the load curves the constants refer to (-N), *USER_INTERFACE_FRICTION NOSID with
/// every constant at full precision (comma-separated cards), *END. Throws std::runtime_error
/// when the file cannot be written.
void write_fit_deck(const std::filesystem::path& file, const std::string& title,
                    std::span<const std::string> comments,
                    std::span<const std::optional<double>> constants,
                    std::span<const law::Curve> curves, int nosid);

/// Columns curve,file,point,time,gap,temperature,stress_data,stress_fit,residual,area (area 0
/// when the data were stresses). Throws std::runtime_error when it cannot be written.
void write_fit_curves(const std::filesystem::path& file, std::span<const fit::MeasuredCurve> data,
                      const fit::FitResult& result);

}  // namespace plyform::app
