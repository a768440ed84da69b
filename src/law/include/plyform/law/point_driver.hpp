#pragma once
// Drives one contact point of the law along a prescribed path of gap, tangential slip and
// temperature: the engine of `plyform law`, of the probe example and of the law's tests.

#include <span>
#include <vector>

#include "plyform/law/law.hpp"

namespace plyform::law {

/// One point of the path. Slips are cumulative tangential displacements of the slave point
/// relative to the master; the driver feeds their increments to the law.
struct PathPoint {
  double time = 0.0;
  double gap = 0.0;
  double slip[2] = {0, 0};
  double temperature = 0.0;
};

struct DriverSettings {
  double k_normal = 0.0;   ///< penalty stiffness per area [stress/length]
  double k_tangent = 0.0;  ///< stick stiffness per area; 0 takes k_normal
  double area = 1.0;       ///< tributary area: energies are per this area
  double mass = 0.0;       ///< effective mass for normal damping (0: no damping)
};

/// The state after each path point.
struct PathSample {
  PathPoint at;
  Response response;
  NodeHistory history;
};

/// Runs the path. The first sample is the initial state (bonded at t0 when the first gap is
/// within BOND_TOL), with zero tractions; each later point is one update with dt = t_i -
/// t_{i-1}, which must be positive (a non-increasing time throws std::invalid_argument naming
/// the row, 1-based).
[[nodiscard]] std::vector<PathSample> drive(const Law& law, std::span<const PathPoint> path,
                                            const DriverSettings& settings);

/// Work done on the interface along the samples, per the trapezoidal rule:
/// sum of -P dg - tau . d slip (positive when the interface absorbs energy).
[[nodiscard]] double interface_work(std::span<const PathSample> samples);

}  // namespace plyform::law
