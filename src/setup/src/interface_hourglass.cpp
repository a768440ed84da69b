// `plyform check`: a cohesive interface on one-point shells with a viscous hourglass control.
// The interface's tractions act on single nodes (its springs hold the bonded layers at rest);
// a one-point shell's zero-energy modes then carry nodal forces at rest, which only a stiffness
// form resists: a viscous form (IHQ 1-3) resists rates only, and the modes grow. The DCB of
// examples/dcb with IHQ 1 goes unstable this way (its run.sh checks that the run stops on its
// hourglass energy; with IHQ 4 the hourglass energy stays below 0.1 % of the internal).

#include <fmt/format.h>

#include <algorithm>

#include "plyform/setup/contact_sides.hpp"
#include "plyform/setup/interface_warnings.hpp"

namespace plyform::setup {

std::vector<InterfaceWarning> viscous_hourglass_warnings(const core::Model& model) {
  std::vector<InterfaceWarning> out;
  for (const core::ContactInterface& c : model.contacts) {
    if (!c.cohesive)
      continue;  // a plain contact holds no node at rest against its layer
    const ContactSides sides = contact_sides(model, c);
    std::vector<std::size_t> blocks = sides.slave_shells;
    for (std::size_t b : sides.master_shells)
      if (std::find(blocks.begin(), blocks.end(), b) == blocks.end())
        blocks.push_back(b);
    for (std::size_t b : blocks) {
      const core::ShellBlock& block = model.shell_blocks[b];
      const int ihq = block.hourglass.ihq;
      if (block.formulation != core::ShellFormulation::belytschko_tsay || ihq < 1 || ihq > 3 ||
          is_rigid(model, block))
        continue;
      InterfaceWarning w;
      w.contact = c.id;
      w.part = model.parts[static_cast<std::size_t>(block.part)].id;
      w.value = ihq;
      w.message = fmt::format(
          "{} carries the cohesive law and {} is one-point shells (ELFORM 2) with a viscous "
          "hourglass control (IHQ {}, QM {:g}{}): the interface acts on single nodes and the "
          "element's zero-energy modes must resist nodal forces at rest, which a viscous form "
          "cannot (examples/dcb/README.md: with IHQ 1 the DCB goes unstable); give the part "
          "*HOURGLASS IHQ 4 (stiffness) with QM "
          "about 0.03-0.1, or ELFORM 16 (fully integrated)",
          contact_name(model, c), part_name(model, block.part), ihq, block.hourglass.qm,
          ihq == 1 ? ", the default without *HOURGLASS" : "");
      out.push_back(std::move(w));
    }
  }
  return out;
}

}  // namespace plyform::setup
