#pragma once
// PROBE.csv of `plyform fit`: one measured curve. Columns by header name, in any order, case
// and a unit suffix ("force [N]", "gap (mm)") ignored; other columns are passed over, so the
// output of `plyform law` is itself a valid input.
//   time                          optional with --rate (then gap = rate * (time - t0))
//   gap | opening | separation    optional with --rate and time (see above)
//   stress | traction | tension   normal traction, positive in tension; or
//   pressure                      positive in compression (as `plyform law` writes it); or
//   force | load                  positive in tension, with --area (stress = force / area)
//   temperature, slip_x, slip_y   optional (default: --temperature, no slip)
// Without a time column the rate gives the times of a monotone opening; a path that holds or
// closes needs its times.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "plyform/fit/measured_curve.hpp"

namespace plyform::app {

struct ProbeCsvOptions {
  std::optional<double> rate;         ///< opening rate [length/time]
  std::optional<double> area;         ///< probe area, for force columns
  std::optional<double> temperature;  ///< when the file has no temperature column
};

struct ProbeCurve {
  fit::MeasuredCurve curve;
  std::string traction_column;     ///< the column the traction came from, as written
  std::vector<std::string> notes;  ///< how the file was read (ignored columns, rate unused)
};

/// Reads one curve; throws PathError naming the file, line and column.
[[nodiscard]] ProbeCurve read_probe_csv(const std::filesystem::path& file,
                                        const ProbeCsvOptions& options);

}  // namespace plyform::app
