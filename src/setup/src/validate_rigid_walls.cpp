#include "validate_rigid_walls.hpp"

#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <unordered_map>

#include "id_table.hpp"

namespace plyform::setup {

using detail::at;
using detail::cat;
using detail::check_ref;
using detail::IdTable;

namespace {

using Vec = std::array<double, 3>;

Vec minus(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double norm(const Vec& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

}  // namespace

std::vector<keyword::Diagnostic> validate_rigid_walls(const model::ModelDesc& model) {
  std::vector<keyword::Diagnostic> errors;
  if (model.rigid_walls.empty())
    return errors;
  std::vector<keyword::Diagnostic> ignored;  // duplicates are the owners' to report
  IdTable nodes{"node", "*NODE"}, node_sets{"node set", "*SET_NODE"};
  for (const model::NodeDesc& n : model.nodes)
    nodes.add(n.id, n.where, "NID", ignored);
  for (const model::SetListDesc& s : model.node_sets)
    node_sets.add(s.id, s.where, "SID", ignored);
  // Nodes of elements: a display node must belong to none (it would be moved twice).
  std::unordered_map<int, bool> element_node;
  for (const model::ElementShellDesc& e : model.shells)
    for (int id : e.nodes)
      element_node[id] = true;
  for (const model::ElementSolidDesc& e : model.solids)
    for (int id : e.nodes)
      element_node[id] = true;

  std::unordered_map<int, model::SourceLocation> ids;
  for (const model::RigidWallDesc& w : model.rigid_walls) {
    if (w.id > 0) {
      const auto [it, inserted] = ids.emplace(w.id, w.where);
      if (!inserted) {
        errors.push_back({w.where, w.keyword, "ID",
                          cat("rigid wall ", w.id, " is already defined at ", at(it->second))});
      }
    }
    if (w.nsid > 0)
      check_ref(node_sets, w.nsid, w.card1, w.keyword, "NSID", errors);
    if (w.nsidex > 0)
      check_ref(node_sets, w.nsidex, w.card1, w.keyword, "NSIDEX", errors);
    const Vec n = minus(w.head, w.tail);
    const double length = norm(n);
    if (!(length > 0.0)) {
      errors.push_back({w.card2, w.keyword, "XH",
                        cat("the normal's head (", w.head[0], ", ", w.head[1], ", ", w.head[2],
                            ") is its tail: the normal points from XT, YT, ZT to XH, YH, ZH "
                            "and must have a length")});
    } else if (w.finite) {
      const Vec l = minus(w.edge, w.tail);
      const double ll = norm(l);
      const double along =
          ll > 0.0 ? std::abs((l[0] * n[0] + l[1] * n[1] + l[2] * n[2]) / (ll * length)) : 1.0;
      if (along > 1.0 - 1e-6) {
        errors.push_back(
            {w.where, w.keyword, "XHEV",
             cat("the edge vector from the tail to (", w.edge[0], ", ", w.edge[1], ", ", w.edge[2],
                 ") is zero or along the normal: it must give a direction in the "
                 "wall's plane")});
      }
    }
    constexpr std::array<std::string_view, 4> kField{"N1", "N2", "N3", "N4"};
    for (std::size_t k = 0; k < 4; ++k) {
      const int id = w.display[k];
      if (id == 0)
        continue;
      if (!nodes.contains(id)) {
        check_ref(nodes, id, w.forces_card, w.keyword, kField[k], errors);
      } else if (element_node.contains(id)) {
        errors.push_back({w.forces_card, w.keyword, std::string(kField[k]),
                          cat("node ", id,
                              " belongs to an element: a node that shows the wall "
                              "must belong to none (the wall moves it)")});
      }
    }
  }
  return errors;
}

}  // namespace plyform::setup
