#pragma once
// Per-slave-node state of the interlayer law: the history a host stores between cycles, the
// kinematic increment it supplies, and the response it applies.

#include <cstdint>
#include <string_view>

namespace plyform::law {

/// The state machine of docs/contact-law.md:
/// APPROACHING -(g<=0)-> CONTACT -(g>0, beta>0)-> SEPARATING -(beta=0 or g>g_release)-> DETACHED
/// -(g<=0)-> CONTACT ...  SEPARATING -(g<=0)-> CONTACT.  CONTACT -(g>0, beta=0)-> DETACHED.
enum class NodeState : std::int32_t {
  approaching = 0,  ///< never touched, not bonded: no force
  contact = 1,      ///< g <= 0: penalty pressure, friction, re-healing
  separating = 2,   ///< g > 0 and bonded (beta > 0): cohesive tension with damage
  detached = 3,     ///< g > 0 and beta = 0: no force until contact again
};

[[nodiscard]] constexpr std::string_view to_string(NodeState s) {
  switch (s) {
    case NodeState::approaching:
      return "APPROACHING";
    case NodeState::contact:
      return "CONTACT";
    case NodeState::separating:
      return "SEPARATING";
    case NodeState::detached:
      return "DETACHED";
  }
  return "UNKNOWN";
}

/// History of one slave node. Energies are accumulated in energy units: each increment is
/// per area times the node's `Increment::area` (a point driver passes area = 1).
struct NodeHistory {
  NodeState state = NodeState::approaching;
  double beta = 1.0;             ///< adhesion intensity in [0, 1]
  double gap = 0.0;              ///< surface gap of the last update [length]
  double slip[2] = {0, 0};       ///< elastic tangential slip of the Coulomb spring [length]
  double opening_t[2] = {0, 0};  ///< tangential opening since bonding, mixed mode [length]
  double e_damage = 0.0;         ///< adhesion energy released by damage, omega * (-d beta) [energy]
  double e_viscous = 0.0;        ///< viscous dissipation of the adhesion evolution [energy]
  double e_friction = 0.0;       ///< frictional (Coulomb or film) dissipation [energy]
  double e_damping = 0.0;        ///< normal damping dissipation [energy]
  double e_healing = 0.0;  ///< adhesion energy restored by re-healing, omega * d beta [energy]
  /// The normal damping traction of the last update (VDC) [stress]: its work over the next
  /// step, the second half of the trapezoid the host books, goes to e_damping then.
  double damping = 0.0;
};

/// What the host supplies for one node and one cycle.
struct Increment {
  double gap = 0.0;         ///< surface gap at t_{n+1} (g < 0 penetration) [length]
  double slip[2] = {0, 0};  ///< slave-minus-master tangential slip increment, master plane [length]
  double dt = 0.0;          ///< t_{n+1} - t_n [time], > 0
  double temperature = 0.0;  ///< slave node temperature [temperature]
  double k_normal = 0.0;     ///< contact penalty stiffness per area [stress/length]
  double k_tangent = 0.0;    ///< tangential (stick) penalty stiffness per area [stress/length]
  double area = 1.0;         ///< tributary area of the slave node [length^2]
  double mass = 0.0;         ///< effective mass m_s m_m / (m_s + m_m) for damping (0: none) [mass]
};

/// The law's answer for one node.
struct Response {
  double pressure = 0.0;   ///< normal traction, positive in compression [stress]
  double tau[2] = {0, 0};  ///< tangential traction on the slave node [stress]
  double stored = 0.0;     ///< recoverable energy held now (penalty, cohesive, springs) [energy]
};

}  // namespace plyform::law
