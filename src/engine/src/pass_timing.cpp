#include <algorithm>
#include <string>
#include <variant>

#include "pass_clock.hpp"
#include "plyform/material/law_registry.hpp"

namespace plyform::engine {
namespace {

// A block's kernel as the table names it: the element kind and formulation and the law.
std::string kernel_label(const core::Model& model, bool shell, std::size_t b) {
  const auto law = [&](core::Index material) {
    return std::string(
        material::law_info(model.materials[static_cast<std::size_t>(material)]).keyword);
  };
  if (shell) {
    const core::ShellBlock& blk = model.shell_blocks[b];
    const bool full = blk.formulation == core::ShellFormulation::fully_integrated;
    return std::string(full ? "shells ELFORM 16 (fully integrated), "
                            : "shells ELFORM 2 (Belytschko-Tsay), ") +
           law(blk.material);
  }
  const core::SolidBlock& blk = model.solid_blocks[b];
  const bool one = blk.formulation == core::SolidFormulation::one_point;
  return std::string(one ? "solids ELFORM 1 (one point), " : "solids ELFORM 2 (selective), ") +
         law(blk.material);
}

}  // namespace

PassTiming timing_table(const core::Model& model, const PassClock& clock,
                        const TimingSources& sources) {
  PassTiming out;
  out.loop_seconds = sources.loop_seconds;
  std::vector<PassTime>& p = out.passes;
  const auto add = [&](std::string group, std::string name, double seconds) {
    p.push_back({std::move(group), std::move(name), std::max(seconds, 0.0)});
  };
  add("nodes", "positions", clock.at(Pass::positions));
  add("nodes", "loads and prescribed temperatures", clock.at(Pass::loads));

  // The element loop's wall time shared out among the kernels by their threads' seconds
  // (blocks of one kernel and law together, in the model's order).
  std::vector<std::pair<std::string, double>> kernels;
  double thread_seconds = 0.0;
  const auto collect = [&](const std::vector<double>& block_seconds, bool shell) {
    for (std::size_t b = 0; b < block_seconds.size(); ++b) {
      if (block_seconds[b] <= 0.0)
        continue;
      const std::string label = kernel_label(model, shell, b);
      const auto it = std::find_if(kernels.begin(), kernels.end(),
                                   [&](const auto& k) { return k.first == label; });
      if (it == kernels.end())
        kernels.emplace_back(label, block_seconds[b]);
      else
        it->second += block_seconds[b];
      thread_seconds += block_seconds[b];
    }
  };
  collect(sources.solid_block_seconds, false);
  collect(sources.shell_block_seconds, true);
  const double element_wall = clock.at(Pass::elements);
  if (kernels.empty()) {
    add("elements", "element loop", element_wall);
  } else {
    for (const auto& [label, s] : kernels)
      add("elements", label, element_wall * s / thread_seconds);
  }

  if (clock.at(Pass::exchange) > 0.0)
    add("ranks", "exchange after the element loop", clock.at(Pass::exchange));

  const double thermal = clock.at(Pass::thermal);
  if (thermal > 0.0) {
    add("thermal", "contact links and heat sources", clock.heat_sources);
    add("thermal", "assembly", thermal - clock.heat_sources - sources.heat_solve_seconds);
    add("thermal", "solve", sources.heat_solve_seconds);
  }

  double contact_timed = 0.0;
  for (const contact::InterfaceTiming& c : sources.contact) {
    // The deck's order, as rcforc.csv and interface_energy.csv count them, and the id if any.
    const std::string name = "contact " + std::to_string(c.index + 1) +
                             (c.id != 0 ? " (id " + std::to_string(c.id) + ")" : "") + ": ";
    add("contact", name + "search", c.search);
    add("contact", name + "projection and kinematics", c.projection);
    add("contact", name + "law", c.law);
    add("contact", name + "forces", c.forces);
    contact_timed += c.search + c.projection + c.law + c.forces;
  }
  if (sources.contact_exchange_seconds > 0.0) {
    add("ranks", "exchange of the contact's slave nodes", sources.contact_exchange_seconds);
    contact_timed += sources.contact_exchange_seconds;
  }
  if (!sources.contact.empty())
    add("contact", "interfaces not in their birth-death window, and the passes' set-up",
        clock.at(Pass::contact) - contact_timed);

  add("nodes", "step vote", clock.at(Pass::step_vote));
  add("nodes", "velocities, constraints, rigid bodies, external work", clock.at(Pass::velocities));
  add("outputs", "output files and progress", clock.at(Pass::outputs));
  add("outputs", "energy books", clock.at(Pass::books));
  if (clock.at(Pass::checkpoints) > 0.0)
    add("outputs", "checkpoints", clock.at(Pass::checkpoints));
  double timed = 0.0;
  for (const PassTime& x : p)
    timed += x.seconds;
  add("other", "the loop's own checks, between the passes", sources.loop_seconds - timed);
  return out;
}

}  // namespace plyform::engine
