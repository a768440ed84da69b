// `plyform check`: a layer interface whose stable-step vote sets the run's step. The contact
// votes TSSFAC sqrt(2 m* / k) per slave node (contact::ContactSet's search, the formula's one
// place; engine::initial_contact_steps runs it at t = 0), k its stiffest spring: for a
// cohesive interface at least C_N times the node's area. A stiff interface on light nodes
// then votes below the elements' step and the whole run takes the interface's step.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "plyform/setup/contact_penalty.hpp"
#include "plyform/setup/contact_sides.hpp"
#include "plyform/setup/interface_warnings.hpp"

namespace plyform::setup {

std::vector<InterfaceWarning> contact_step_warnings(const core::Model& model, double element_step,
                                                    const std::vector<double>& contact_steps) {
  std::vector<InterfaceWarning> out;
  if (contact_steps.size() != model.contacts.size() || !(element_step > 0.0) ||
      !(element_step < 1e300))
    return out;
  const double end = model.controls.end_time;
  for (std::size_t i = 0; i < model.contacts.size(); ++i) {
    const core::ContactInterface& c = model.contacts[i];
    const double vote = contact_steps[i];
    if (!(vote < element_step) || !(vote > 0.0))
      continue;
    if (!is_layer_interface(model, c, contact_sides(model, c)))
      continue;
    const double ratio = element_step / vote;
    // The remedy: the vote goes as 1 / sqrt(k); a cohesive interface whose C_N is its
    // stiffest spring is softened by F = ratio^2, keeping G_Ic = sigma_max^2 / C_N.
    double penalty = 0.0;
    for (const core::ContactPass& p : c.passes) {
      const SidePenalty s = side_penalty(model, p);
      penalty = std::max(penalty, std::max(s.slave, s.master));
    }
    const double f = ratio * ratio;
    const std::string remedy =
        c.cohesive && c.law.cn >= penalty
            ? fmt::format(
                  "soften the interface keeping its G_Ic: C_N / F and sigma_max / sqrt(F) "
                  "(F = {:.3g} brings the vote to the elements' step; examples/dcb --soften), "
                  "or scale the layers' mass (*CONTROL_TIMESTEP DT2MS)",
                  f)
            : fmt::format(
                  "lower its penalty (SFS and SFM {:.3g} times smaller) or scale the layers' "
                  "mass (*CONTROL_TIMESTEP DT2MS)",
                  f);
    InterfaceWarning w;
    w.contact = c.id;
    w.value = ratio;
    w.message = fmt::format(
        "{}, between layers, sets the run's time step: its stable-step vote at t = 0 is {:.4g}, "
        "below the elements' step {:.4g} (both with TSSFAC); the run takes {:.3g} times as many "
        "cycles{}; {}",
        contact_name(model, c), vote, element_step, ratio,
        end > 0.0 ? fmt::format(", about {:.4g} instead of {:.4g}", end / vote, end / element_step)
                  : std::string(),
        remedy);
    out.push_back(std::move(w));
  }
  return out;
}

}  // namespace plyform::setup
