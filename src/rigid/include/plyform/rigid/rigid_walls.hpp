#pragma once
// Planar rigid walls (*RIGIDWALL_PLANAR), the constraint method: a slave node that would cross
// its wall during the coming step is stopped on it.
//
// The engine calls apply() once per cycle, after the velocity update v_{n+3/2} (with every
// force at t_{n+1}, the contact's included), the constraints and the rigid bodies. For a wall
// of unit normal n (towards its nodes), at position p(t_{n+1}), moving along n at V for the
// step [t_{n+1}, t_{n+2}] (0 for a fixed wall), a slave node at x with velocity v has the gap
// g = (x - p) . n and would end the step at g + (v . n - V) dt_next. It is caught when
//   s = v . n + g / dt_next < V,   g >= -tolerance (a node behind the wall is never pushed
//                                  through it; a finite wall: its projection on the rectangle)
// and its normal velocity becomes V' - g / dt_next: it lands on the wall at t_{n+2}.
//   A fixed wall: V' = V = 0.
//   A moving wall of mass M: the caught nodes and the wall share one normal velocity after the
//   (perfectly inelastic) impulse, and momentum along n is conserved exactly:
//     V' = (M V + sum_c m_c s_c) / (M + sum_c m_c)   over the caught nodes c, those with s_c < V'
//   (found by sorting the candidates by s: V' falls as nodes join, so the set is a prefix).
//   The wall then moves by V' dt_next.
// Friction (FRIC = mu) limits the tangential change of a caught node's velocity by mu times its
// normal change (Coulomb on the impulse); mu = 1 stops its sliding (LS-DYNA's "no sliding
// after contact", while the node is held).
// The wall's impulse on the nodes, J = sum m (v_after - v_before), is reported per step as the
// force J / dt_avg; its work on the nodes is the engine's (external work).

#include <array>
#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/core/state_archive.hpp"

namespace plyform::rigid {

/// The nodal arrays a wall reads and corrects.
struct WallArrays {
  const double* x0 = nullptr;  ///< reference coordinates
  const double* y0 = nullptr;
  const double* z0 = nullptr;
  const double* ux = nullptr;  ///< displacements at t_{n+1}
  const double* uy = nullptr;
  const double* uz = nullptr;
  const double* mass = nullptr;
  double* vx = nullptr;  ///< in: free velocities for [t_{n+1}, t_{n+2}]; out: corrected
  double* vy = nullptr;
  double* vz = nullptr;
};

/// One corrected node of a step: its index and its velocity before the wall (the engine books
/// the wall's work from it).
struct WallCorrection {
  core::Index node = 0;
  std::array<double, 3> free{};
};

class RigidWalls {
 public:
  explicit RigidWalls(const core::Model& model);

  [[nodiscard]] bool empty() const { return walls_.empty(); }
  [[nodiscard]] std::size_t size() const { return walls_.size(); }

  /// Corrects the velocities of the step [t, t + dt_next] (see the file comment); dt_avg is
  /// the interval between the two half steps (the force of the impulse). Returns the nodes
  /// corrected, in wall order then node order (the same vector every call: no allocation once
  /// it has grown).
  const std::vector<WallCorrection>& apply(double t, double dt_next, double dt_avg,
                                           const WallArrays& a);

  /// What rwforc.csv writes of a wall.
  struct Report {
    core::GlobalId id = 0;
    double normal_force = 0.0;      ///< the last step's normal force between nodes and wall (>= 0)
    double tangential_force = 0.0;  ///< the magnitude of its tangential (friction) part
    std::array<double, 3> force{};  ///< the force the nodes exert on the wall, global axes
    double impulse = 0.0;           ///< the normal impulse on the nodes since t = 0
    std::size_t held = 0;           ///< the nodes it stopped in the last step
    double displacement = 0.0;      ///< the wall's displacement along its normal at t
    double velocity = 0.0;          ///< its velocity along its normal
    double kinetic = 0.0;           ///< a moving wall's kinetic energy 1/2 M V^2
  };
  [[nodiscard]] Report report(std::size_t k) const;

  /// The wall's position (for outputs between cycles) and state (checkpoints).
  void visit_state(core::StateArchive& archive);

 private:
  struct Wall {
    const core::RigidWall* desc = nullptr;
    double displacement = 0.0;      ///< along the normal, at the time of the next apply
    double displacement_now = 0.0;  ///< at the time of the last apply (the outputs' time)
    double velocity = 0.0;          ///< along the normal, of the last step (V0 before the first)
    double impulse = 0.0;
    std::array<double, 3> force{};
    double normal_force = 0.0, tangential_force = 0.0;
    std::size_t held = 0;
  };
  struct Candidate {
    core::Index node = 0;
    double s = 0.0;    ///< v . n + g / dt_next
    double gap = 0.0;  ///< g at t_{n+1}
  };
  std::vector<Wall> walls_;
  std::vector<Candidate> candidates_;  // scratch of one wall
  std::vector<WallCorrection> corrected_;
};

}  // namespace plyform::rigid
