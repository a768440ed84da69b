#pragma once
// Constraints and prescribed motions applied to the half-step velocities, and nodal loads.

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/engine/nodal_state.hpp"

namespace plyform::engine {

class BoundaryConditions {
 public:
  explicit BoundaryConditions(const core::Model& model);

  /// External nodal forces at time t into s.ex, s.ey, s.ez (only loaded entries are touched:
  /// the others stay 0).
  void loads(double t, NodalState& s) const;

  /// Imposes constraints on the velocities of the step [t, t + dt] (t = t_n, displacement u at
  /// t_n); `old` are the previous half-step velocities (x, y, z), `dt_avg` the interval between
  /// the two half steps (for prescribed accelerations).
  void constrain(double t, double dt, double dt_avg, const double* const old[3],
                 NodalState& s) const;

  /// True for (node, direction) pairs whose velocity is imposed (reactions are computed there).
  [[nodiscard]] const std::vector<unsigned char>& constrained() const { return constrained_; }
  /// The nodes with at least one constrained direction, in index order.
  [[nodiscard]] const std::vector<core::Index>& constrained_nodes() const {
    return constrained_nodes_;
  }

 private:
  const core::Model& model_;
  std::vector<unsigned char> constrained_;  ///< 3 per node
  std::vector<core::Index> constrained_nodes_;
};

}  // namespace plyform::engine
