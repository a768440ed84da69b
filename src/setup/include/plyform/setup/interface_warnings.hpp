#pragma once
// What `plyform check` warns about before a run, on the contact interfaces between layers: the
// choices known to break them (docs/contact.md). Each check is a pure function of the built
// model (and, for the step, of the steps the run will start with) and gives one warning per
// interface (and part) concerned, naming it by its deck ids with the remedy.

#include <string>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::setup {

struct InterfaceWarning {
  core::GlobalId contact = 0;  ///< the interface's CID (0: the deck gave none)
  core::GlobalId part = 0;     ///< the part concerned, where one is (its deck id), else 0
  double value = 0.0;          ///< the figure judged: see each check
  std::string message;         ///< one line, without "warning: "
};

/// A cohesive interface (a *USER_INTERFACE_FRICTION names it) with a side of one-point
/// (Belytschko-Tsay, ELFORM 2) shells under a viscous hourglass control (IHQ 1-3): the
/// interface acts on single nodes, and the element's zero-energy modes must resist those
/// nodal forces at rest, which a viscous form cannot. One warning per (interface, part);
/// `value` is the part's IHQ.
[[nodiscard]] std::vector<InterfaceWarning> viscous_hourglass_warnings(const core::Model& model);

/// A penetration of more than this share of the thinner layer is worth a warning.
inline constexpr double kPenetrationShare = 0.05;

/// Layer interfaces whose penalty in compression the tool pressure pushes through: for each
/// rigid shell tool loaded by a force (*LOAD_RIGID_BODY, or nodal loads on its nodes), the
/// pressure force / area through the stack of layers it presses, and the penetration
/// pressure / k of each layer interface in that stack against the thinner layer's thickness;
/// a warning where it exceeds kPenetrationShare. `value` is that share. Nothing without a
/// force-driven tool (a tool driven by its motion puts no known force through the layers).
[[nodiscard]] std::vector<InterfaceWarning> penalty_pressure_warnings(const core::Model& model);

/// Layer interfaces whose stable-step vote at t = 0 is below the elements' step: the
/// interface then sets the run's step. `element_step` is the elements' first step with TSSFAC
/// (engine::initial_stable_step times TSSFAC), `contact_steps` each interface's vote
/// (engine::initial_contact_steps; empty: no warning). `value` is element_step / vote, how
/// many times longer the run takes.
[[nodiscard]] std::vector<InterfaceWarning> contact_step_warnings(
    const core::Model& model, double element_step, const std::vector<double>& contact_steps);

}  // namespace plyform::setup
