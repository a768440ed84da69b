#pragma once
// Rigid bodies: the parts whose material is *MAT_RIGID (020) move as rigid bodies.
//
// The engine meets this class in two places: it skips the rigid nodes (is_rigid_node) in its
// deformable velocity update, and once per cycle, after the nodal forces at t_{n+1} are known,
// it calls advance(), which writes the velocities of the rigid nodes for the step to come.
//
// State of a body: centre x_c, orientation R (a unit quaternion; R = 1 at t = 0), velocity V
// and angular velocity Omega at the half steps (central differences, as the nodes), angular
// momentum L = J(R) Omega about the centre in global axes, J(R) = R J_0 R^T.
//
// advance(t_{n+1}, ...), per body:
//   F = sum_i (e_i - f_i) + *LOAD_RIGID_BODY forces,   M = sum_i r_i x (e_i - f_i) + moments,
//       r_i = R_{n+1} (X_i - X_c) (X: reference positions),
//   V_{n+3/2} = V_{n+1/2} + F / m dt_avg, then CON1 (V_d = 0) and prescribed translations;
//   L* = L_{n+1/2} + M dt_avg; Omega_{n+3/2} solves, by fixed-point iteration (to 1e-15),
//       J(R_h) Omega = L* on the free rotational components and Omega_d = prescribed value
//       (CON2: 0) on the others, with the mid-step orientation R_h = exp(Omega dt_next / 2) R;
//       L_{n+3/2} = L* on the free components, (J(R_h) Omega)_d on the constrained ones
//       (without moment and constraint L is conserved exactly; a spin about a principal axis
//       keeps Omega exactly);
//   x_c' = x_c + V dt_next,  R' = exp(Omega dt_next) R (quaternion product, renormalised);
//   nodal velocities: the secant field v_i = (x_c' + R' (X_i - X_c) - x_i) / dt_next with
//       x_i = X_i + u_i the engine's current position. The engine's x_i + v_i dt_next then lands
//       on the rigid position at t_{n+2} to round-off, and since every step aims at the rigid
//       image of the reference configuration, round-off does not accumulate over the steps.
//       v_i differs from V + Omega x r_i by O(|Omega|^2 dt |r|) (the chord of the arc).
//
// Prescribed motions (*BOUNDARY_PRESCRIBED_MOTION_RIGID), active when t + dt_next/2 lies in
// [birth, death], override the constraints on their component (s: scale, c: curve):
//   velocity:      V_d = s * mean of c over [t, t + dt_next] (segment by segment): the position
//                  follows the integral of the curve exactly at every step, kinks or not;
//   acceleration:  V_d = V_d(n+1/2) + s c(t) dt_avg;
//   displacement:  V_d = (X_c,d + s c(t + dt_next) - x_c,d) / dt_next (reached exactly);
//   rotations (dof 3-5: about the global axis through the centre), the same for Omega_d, with
//   the angle kind measured by the accumulated angle theta_d = sum Omega_d dt (the rotation
//   angle when the body turns about that one axis).
//
// CMO (*MAT_RIGID): 0 none; +1 global constraints, CON1 translations and CON2 rotations with the
// codes 0 none, 1 x, 2 y, 3 z, 4 x and y, 5 y and z, 6 z and x, 7 x, y and z; -1 (local system)
// is not supported (std::invalid_argument).
//
// Initial velocities (Model::v0x...) of the rigid nodes are fitted: V = sum m_a v_a / m,
// Omega from J_lumped Omega = sum m_a r_a x v_a (m_a: consistent nodal masses), which recovers a
// rigid initial field exactly.

#include <array>
#include <vector>

#include "plyform/core/load_curve.hpp"
#include "plyform/core/model.hpp"
#include "plyform/core/state_archive.hpp"
#include "plyform/rigid/mass_properties.hpp"

namespace plyform::rigid {

/// Times of one call of RigidBodies::advance [time].
struct StepTimes {
  double t = 0.0;        ///< t_{n+1}: the time of the forces
  double dt_prev = 0.0;  ///< t_{n+1} - t_n (0 at the first call, t = 0)
  double dt_next = 0.0;  ///< t_{n+2} - t_{n+1}: the step the new velocities are for (> 0)
  double dt_avg = 0.0;   ///< (dt_prev + dt_next) / 2
  /// The pass at the end time: prescribed motions keep the bodies' last velocities instead of
  /// reading their curves beyond the end.
  bool hold = false;
};

/// The engine's nodal arrays (structure of arrays, length node_count), as pointers.
struct NodalArrays {
  const double* fx = nullptr;  ///< internal forces at t_{n+1} [force]
  const double* fy = nullptr;
  const double* fz = nullptr;
  const double* ex = nullptr;  ///< external forces at t_{n+1} (loads, contact) [force]
  const double* ey = nullptr;
  const double* ez = nullptr;
  const double* ux = nullptr;  ///< displacements at t_{n+1} from Model::x0/y0/z0 [length]
  const double* uy = nullptr;
  const double* uz = nullptr;
  double* vx =
      nullptr;  ///< out: velocities of the rigid nodes for [t_{n+1}, t_{n+2}] [length/time]
  double* vy = nullptr;
  double* vz = nullptr;
  double* wx = nullptr;  ///< out, optional (null: not written): angular velocities [rad/s]
  double* wy = nullptr;
  double* wz = nullptr;
};

class RigidBodies {
 public:
  /// One body, for outputs. Quantities at the time of the last advance (t_{n+1}); velocities
  /// interpolated between the half steps as the engine does for its nodes.
  struct BodyReport {
    core::GlobalId part_id = 0;
    double mass = 0.0;                    ///< [mass]
    std::array<double, 3> force{};        ///< sum of e - f over the body's nodes [force]
    std::array<double, 3> moment{};       ///< their moment about the centre [force length]
    std::array<double, 3> load_force{};   ///< *LOAD_RIGID_BODY forces [force]
    std::array<double, 3> load_moment{};  ///< *LOAD_RIGID_BODY moments [force length]
    /// Force and moment of the constraints and prescribed motions:
    /// m dV/dt - (force + load_force), dL/dt - (moment + load_moment) [force], [force length].
    std::array<double, 3> reaction{};
    std::array<double, 3> reaction_moment{};
    std::array<double, 3> centre{};    ///< centre of mass [length]
    std::array<double, 3> velocity{};  ///< [length/time]
    std::array<double, 3> omega{};     ///< angular velocity, global axes [1/time]
    std::array<double, 3>
        angular_momentum{};  ///< about the centre, global axes [mass length^2/time]
    /// The velocities of the half step the last advance computed (t_{n+1/2}); `velocity` and
    /// `omega` are those of t_n.
    std::array<double, 3> velocity_half{}, omega_half{};
    /// The velocities of the half step before it (t_{n-1/2}).
    std::array<double, 3> velocity_before{}, omega_before{};
  };

  /// Finds the parts with RigidMaterial, their nodes (of their solid and shell elements) and
  /// mass properties (see mass_properties.hpp), constraints, motions and loads. Throws
  /// std::invalid_argument naming the part when a rigid part has no element or no mass, for
  /// CMO = -1 or codes out of range, a node shared by two rigid parts, or a motion or load on a
  /// part that is not rigid.
  explicit RigidBodies(const core::Model& model);

  [[nodiscard]] bool empty() const { return bodies_.empty(); }
  [[nodiscard]] std::size_t size() const { return bodies_.size(); }
  /// 1 for the nodes of a rigid body (length node_count): the engine skips them in its update.
  [[nodiscard]] const std::vector<unsigned char>& is_rigid_node() const { return is_rigid_; }
  /// The rigid nodes, ascending.
  [[nodiscard]] const std::vector<core::Index>& rigid_nodes() const { return rigid_nodes_; }
  /// Mass properties of body b (in reference configuration; nodes and nodal masses included).
  [[nodiscard]] const MassProperties& mass_properties(std::size_t b) const {
    return bodies_[b].props;
  }

  /// One cycle, after the forces at t_{n+1}: advances every body and writes its nodes'
  /// velocities (and angular velocities when nodes.wx is not null). No allocation.
  void advance(const StepTimes& step, const NodalArrays& nodes);

  /// Body b's report; report() gives all of them (it allocates: for outputs, not the cycle).
  [[nodiscard]] BodyReport report(std::size_t b) const;
  [[nodiscard]] std::vector<BodyReport> report() const;
  /// Kinetic energy of the bodies at t_{n+1}: m V.V / 2 + Omega.L / 2 [energy].
  [[nodiscard]] double kinetic_energy() const;
  /// Saves or restores the bodies' motion (checkpoints): centre, orientation, momenta, the
  /// accumulated angles and the last resultants, per body.
  void visit_state(core::StateArchive& archive);

 private:
  struct Motion {
    int dof = 0;
    core::MotionKind kind = core::MotionKind::velocity;
    std::size_t curve = 0;
    double scale = 1.0, birth = 0.0, death = 1e28;
  };
  struct Load {
    int dof = 0;
    std::size_t curve = 0;
    double scale = 1.0;
  };
  struct Body {
    core::Index part = 0;
    core::GlobalId part_id = 0;
    MassProperties props;
    std::vector<double> X, Y, Z;     ///< reference positions of the nodes
    std::vector<double> rx, ry, rz;  ///< X - X_c
    std::array<bool, 6> fixed{};
    std::vector<Motion> motions;
    std::vector<Load> loads;
    // State.
    std::array<double, 3> xc{};                       ///< centre at the next step's start
    std::array<double, 4> q{1.0, 0.0, 0.0, 0.0};      ///< orientation (w, x, y, z)
    std::array<double, 3> v{}, l{}, w{};              ///< V, L, Omega of the step to come
    std::array<double, 3> v_old{}, l_old{}, w_old{};  ///< of the step just taken
    std::array<double, 3> xc_t{};                     ///< centre at the last advance's t
    std::array<double, 3> angle{};                    ///< accumulated Omega dt
    // Last resultants.
    std::array<double, 3> force{}, moment{}, load_force{}, load_moment{};
    std::array<double, 3> reaction{}, reaction_moment{};
  };

  void advance_body(Body& b, const StepTimes& step, const NodalArrays& nodes) const;

  std::vector<Body> bodies_;
  std::vector<core::LoadCurve> curves_;
  std::vector<unsigned char> is_rigid_;
  std::vector<core::Index> rigid_nodes_;
  double w_interp_ = 0.0;  ///< dt_prev / (2 dt_avg) of the last advance
};

}  // namespace plyform::rigid
