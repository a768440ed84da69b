#pragma once
// Constraints and prescribed motions applied to the half-step velocities, nodal loads and
// pressure loads.

#include <array>
#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/engine/nodal_state.hpp"

namespace plyform::engine {

class BoundaryConditions {
 public:
  explicit BoundaryConditions(const core::Model& model);

  /// External nodal forces at time t into s.ex, s.ey, s.ez (only loaded entries are touched:
  /// the others stay 0): the nodal loads, and the pressure loads on the segments at their
  /// positions x0 + u (the displacement at t).
  void loads(double t, NodalState& s) const;

  /// The step whose velocities are constrained: [t, t + dt], after the step [t - dt_prev, t]
  /// (dt_prev = 0 at t = 0); dt_avg is the interval between the two half steps.
  struct StepTimes {
    double t = 0.0;
    double dt_prev = 0.0;
    double dt = 0.0;
    double dt_avg = 0.0;
    /// The pass at the end time: prescribed motions keep the velocity of the step just taken
    /// instead of reading their curves beyond the end (see Simulation's step_vote).
    bool hold = false;
  };

  /// Imposes constraints on the velocities of the step [t, t + dt] (displacement u at t);
  /// `old` are the previous half-step velocities (x, y, z), for prescribed accelerations.
  void constrain(const StepTimes& step, const double* const old[3], NodalState& s) const;

  /// True for (node, direction) pairs whose velocity is imposed (reactions are computed there).
  [[nodiscard]] const std::vector<unsigned char>& constrained() const { return constrained_; }
  /// The nodes with at least one constrained direction, in index order.
  [[nodiscard]] const std::vector<core::Index>& constrained_nodes() const {
    return constrained_nodes_;
  }
  /// The corners of the pressure loads' segments (each once).
  [[nodiscard]] const std::vector<core::Index>& pressure_nodes() const { return pressure_nodes_; }

 private:
  /// Adds the nodal forces of pressure p on one segment (N4 = N3: a triangle) to s.ex, s.ey,
  /// s.ez.
  void press_segment(const std::array<core::Index, 4>& seg, double p, NodalState& s) const;

  const core::Model& model_;
  std::vector<unsigned char> constrained_;  ///< 3 per node
  std::vector<core::Index> constrained_nodes_;
  std::vector<core::Index> pressure_nodes_;  ///< the corners of the pressure segments, once
};

}  // namespace plyform::engine
