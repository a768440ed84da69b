#include "validate_pressure_loads.hpp"

#include <array>
#include <string>
#include <string_view>

#include "id_table.hpp"

namespace plyform::setup {

using detail::cat;
using detail::check_ref;
using detail::IdTable;

std::vector<keyword::Diagnostic> validate_pressure_loads(const model::ModelDesc& model) {
  std::vector<keyword::Diagnostic> errors;
  if (model.pressure_loads.empty() && model.shell_sets.empty())
    return errors;
  // Duplicates of nodes, shells, curves and segment sets are reported by the passes that own
  // them; these tables only answer "is it defined".
  std::vector<keyword::Diagnostic> ignored;
  IdTable nodes{"node", "*NODE"}, shells{"shell element", "*ELEMENT_SHELL"};
  IdTable curves{"curve", "*DEFINE_CURVE"}, segment_sets{"segment set", "*SET_SEGMENT"};
  IdTable shell_sets{"shell set", "*SET_SHELL"};
  for (const model::NodeDesc& n : model.nodes)
    nodes.add(n.id, n.where, "NID", ignored);
  for (const model::ElementShellDesc& e : model.shells)
    shells.add(e.id, e.where, "EID", ignored);
  for (const model::CurveDesc& c : model.curves)
    curves.add(c.id, c.where, "LCID", ignored);
  for (const model::SetSegmentDesc& s : model.segment_sets)
    segment_sets.add(s.id, s.where, "SID", ignored);
  for (const model::SetListDesc& s : model.shell_sets)
    shell_sets.add(s.id, s.where, "SID", errors);

  for (const model::SetListDesc& s : model.shell_sets) {
    for (std::size_t i = 0; i < s.ids.size(); ++i) {
      if (!shells.contains(s.ids[i])) {
        errors.push_back({s.ids_where[i], "*SET_SHELL", cat("EID", i + 1),
                          cat("shell set ", s.id, ": shell element ", s.ids[i],
                              " is not defined (no *ELEMENT_SHELL with this id)")});
      }
    }
  }

  constexpr std::array<std::string_view, 4> kCorner{"N1", "N2", "N3", "N4"};
  for (const model::LoadPressureDesc& l : model.pressure_loads) {
    check_ref(curves, l.curve_id, l.where, l.keyword, "LCID", errors);
    switch (l.target) {
      case model::PressureTarget::kSegment: {
        bool defined = true;
        for (std::size_t i = 0; i < 4; ++i) {
          if (!nodes.contains(l.nodes[i])) {
            check_ref(nodes, l.nodes[i], l.where, l.keyword, kCorner[i], errors);
            defined = false;
          }
        }
        const auto& n = l.nodes;
        const bool distinct = n[0] != n[1] && n[0] != n[2] && n[1] != n[2] &&
                              (n[3] == n[2] || (n[3] != n[0] && n[3] != n[1]));
        if (defined && !distinct) {
          errors.push_back(
              {l.where, l.keyword, "N1",
               cat("segment ", n[0], " ", n[1], " ", n[2], " ", n[3],
                   ": its corners must be distinct nodes (a triangle repeats N3 as N4 or leaves "
                   "N4 blank)")});
        }
        break;
      }
      case model::PressureTarget::kSegmentSet:
        check_ref(segment_sets, l.target_id, l.where, l.keyword, "SSID", errors);
        break;
      case model::PressureTarget::kShell:
        check_ref(shells, l.target_id, l.where, l.keyword, "EID", errors);
        break;
      case model::PressureTarget::kShellSet:
        check_ref(shell_sets, l.target_id, l.where, l.keyword, "ESID", errors);
        break;
    }
  }
  return errors;
}

}  // namespace plyform::setup
