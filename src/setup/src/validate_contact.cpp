#include "plyform/setup/validate_contact.hpp"

#include <array>
#include <string>
#include <string_view>
#include <unordered_map>

#include "id_table.hpp"

namespace plyform::setup {
namespace {

using detail::at;
using detail::cat;
using detail::check_ref;
using detail::IdTable;
using keyword::Diagnostic;
using model::ContactSideType;
using model::NodeTarget;

constexpr std::array<std::string_view, 4> kSegmentFields{"N1", "N2", "N3", "N4"};

std::string_view side_noun(ContactSideType t) {
  switch (t) {
    case ContactSideType::segment_set:
      return "segment set";
    case ContactSideType::part_set:
      return "part set";
    case ContactSideType::part:
      return "part";
    case ContactSideType::node_set:
      return "node set";
    case ContactSideType::all_parts:
      return "every part";
  }
  return "side";
}

std::string_view target_field(NodeTarget t) {
  return t == NodeTarget::kNode ? "NID" : "NSID";
}
std::string_view initial_keyword(NodeTarget t) {
  return t == NodeTarget::kNode ? "*INITIAL_TEMPERATURE_NODE" : "*INITIAL_TEMPERATURE_SET";
}
std::string_view boundary_keyword(NodeTarget t) {
  return t == NodeTarget::kNode ? "*BOUNDARY_TEMPERATURE_NODE" : "*BOUNDARY_TEMPERATURE_SET";
}

/// The id tables the contact checks refer to.
struct Tables {
  IdTable nodes{"node", "*NODE"};
  IdTable parts{"part", "*PART"};
  IdTable part_sets{"part set", "*SET_PART_LIST"};
  IdTable node_sets{"node set", "*SET_NODE_LIST"};
  IdTable segment_sets{"segment set", "*SET_SEGMENT"};
  IdTable curves{"curve", "*DEFINE_CURVE"};

  const IdTable& side(ContactSideType t) const {
    switch (t) {
      case ContactSideType::segment_set:
        return segment_sets;
      case ContactSideType::part_set:
        return part_sets;
      case ContactSideType::part:
        return parts;
      case ContactSideType::node_set:
        return node_sets;
      case ContactSideType::all_parts:
        return parts;
    }
    return parts;
  }
};

/// Segment nodes: defined; N1, N2, N3 distinct; N4 distinct from them or N4 = N3.
void check_segments(const model::SetSegmentDesc& s, const IdTable& nodes,
                    std::vector<Diagnostic>& errors) {
  for (std::size_t k = 0; k < s.segments.size(); ++k) {
    const std::array<int, 4>& n = s.segments[k];
    const model::SourceLocation& where =
        k < s.segments_where.size() ? s.segments_where[k] : s.where;
    const bool triangle = n[3] == n[2];
    for (std::size_t i = 0; i < n.size(); ++i) {
      if (i == 3 && triangle) {
        continue;
      }
      if (!nodes.contains(n[i])) {
        errors.push_back({where, "*SET_SEGMENT", std::string(kSegmentFields[i]),
                          cat("segment set ", s.id, ", segment ", k + 1, ": node ", n[i],
                              " is not defined (no *NODE with this id)")});
      }
    }
    bool repeated = false;
    for (std::size_t i = 1; i < n.size() && !repeated; ++i) {
      for (std::size_t j = 0; j < i && !repeated; ++j) {
        if (n[i] == n[j] && !(i == 3 && j == 2)) {
          repeated = true;
          errors.push_back({where, "*SET_SEGMENT", std::string(kSegmentFields[i]),
                            cat("segment set ", s.id, ", segment ", k + 1, ": ", kSegmentFields[i],
                                " repeats node ", n[j], " of ", kSegmentFields[j],
                                "; the only repeat accepted is N4 = N3 (a triangle)")});
        }
      }
    }
  }
}

void check_contact_side(const model::ContactDesc& c, bool slave, const Tables& tables,
                        std::vector<Diagnostic>& errors) {
  const int id = slave ? c.ssid : c.msid;
  const ContactSideType type = slave ? c.sstyp : c.mstyp;
  const std::string_view field = slave ? "SSID" : "MSID";
  if (c.kind == model::ContactKind::automatic_single_surface) {
    // One side (SSID; 0 is every part); MSID is not used.
    if (!slave || id == 0)
      return;
  } else if (id == 0) {
    errors.push_back(
        {c.card1, c.keyword, std::string(field),
         cat(field, " = 0 (every part) is not supported: name a ",
             slave ? "segment set, part set, part or node set" : "segment set, part set or part",
             " (", slave ? "SSTYP" : "MSTYP", " gives which)")});
    return;
  }
  const IdTable& table = tables.side(type);
  if (!table.contains(id)) {
    errors.push_back(
        {c.card1, c.keyword, std::string(field),
         cat(side_noun(type), " ", id, " is not defined (no ", table.keyword(), " with this id; ",
             slave ? "SSTYP" : "MSTYP", " = ", static_cast<int>(type), ")")});
  }
}

/// A node with two *BOUNDARY_TEMPERATURE entries (directly or through sets) on the same face
/// (LOC: a thick thermal shell's bottom, middle and top are held apart): an error on the later
/// entry, naming the first node and the earlier entry.
void check_single_prescription(const model::ModelDesc& model, std::vector<Diagnostic>& errors) {
  std::unordered_map<int, const model::SetListDesc*> node_sets;
  for (const model::SetListDesc& s : model.node_sets) {
    node_sets.emplace(s.id, &s);
  }
  std::unordered_map<long long, const model::BoundaryTemperatureDesc*> owner;  // node, LOC
  for (const model::BoundaryTemperatureDesc& b : model.temperature_histories) {
    std::vector<int> nodes;
    if (b.target == NodeTarget::kNode) {
      nodes.push_back(b.target_id);
    } else if (const auto set = node_sets.find(b.target_id); set != node_sets.end()) {
      nodes = set->second->ids;
    }
    int conflicts = 0;
    int first_node = 0;
    const model::BoundaryTemperatureDesc* first_owner = nullptr;
    for (int n : nodes) {
      const auto [it, inserted] = owner.emplace(3LL * n + (b.loc + 1), &b);
      if (inserted || it->second == &b) {
        continue;
      }
      if (conflicts++ == 0) {
        first_node = n;
        first_owner = it->second;
      }
    }
    if (conflicts > 0) {
      errors.push_back(
          {b.where, std::string(boundary_keyword(b.target)), std::string(target_field(b.target)),
           cat("node ", first_node, " already has a prescribed temperature (",
               boundary_keyword(first_owner->target), " at ", at(first_owner->where), ")",
               conflicts > 1 ? cat(" and so have ", conflicts - 1, " more nodes of the set") : "",
               "; a node takes one *BOUNDARY_TEMPERATURE entry per face (LOC)")});
    }
  }
}

}  // namespace

std::vector<Diagnostic> validate_contact(const model::ModelDesc& model) {
  std::vector<Diagnostic> errors;
  std::vector<Diagnostic> ignored;  // duplicates of these ids are reported by validate_mesh
  Tables t;
  for (const model::NodeDesc& n : model.nodes) {
    t.nodes.add(n.id, n.where, "NID", ignored);
  }
  for (const model::PartDesc& p : model.parts) {
    t.parts.add(p.id, p.where, "PID", ignored);
  }
  for (const model::SetListDesc& s : model.part_sets) {
    t.part_sets.add(s.id, s.where, "SID", ignored);
  }
  for (const model::SetListDesc& s : model.node_sets) {
    t.node_sets.add(s.id, s.where, "SID", ignored);
  }
  for (const model::CurveDesc& c : model.curves) {
    t.curves.add(c.id, c.where, "LCID", ignored);
  }
  for (const model::SetSegmentDesc& s : model.segment_sets) {
    t.segment_sets.add(s.id, s.where, "SID", errors);
  }
  for (const model::SetSegmentDesc& s : model.segment_sets) {
    check_segments(s, t.nodes, errors);
  }

  // Contact ids need not be unique (LS-PrePost writes the same CID on copies of a contact, and
  // build_contacts warns); only an id a *USER_INTERFACE_FRICTION names must say which contact.
  IdTable contacts("contact", "*CONTACT_..._ID");
  std::vector<keyword::Diagnostic> duplicates;
  std::unordered_map<int, int> named;
  for (const model::UserInterfaceFrictionDesc& u : model.user_interface_frictions)
    named[u.contact_id] = 1;
  for (const model::ContactDesc& c : model.contacts) {
    if (c.id != 0) {
      contacts.add(c.id, c.where, "CID", named.contains(c.id) ? errors : duplicates, c.keyword);
    }
    check_contact_side(c, true, t, errors);
    check_contact_side(c, false, t, errors);
  }

  // A deck of the law alone (no mesh, no contact) is what `plyform law` drives.
  if (!model.nodes.empty() || !model.contacts.empty()) {
    for (const model::UserInterfaceFrictionDesc& u : model.user_interface_frictions) {
      if (!contacts.contains(u.contact_id)) {
        errors.push_back({u.where, "*USER_INTERFACE_FRICTION", "NOSID",
                          cat("no *CONTACT_..._ID with CID ", u.contact_id,
                              ": the law must name the contact it applies to")});
      }
    }
  }

  const auto check_target = [&](NodeTarget target, int id, const model::SourceLocation& where,
                                std::string_view keyword) {
    check_ref(target == NodeTarget::kNode ? t.nodes : t.node_sets, id, where, keyword,
              target_field(target), errors);
  };
  for (const model::InitialTemperatureDesc& i : model.initial_temperatures) {
    // *INITIAL_TEMPERATURE_SET NSID 0 is every node of the model.
    if (i.target == NodeTarget::kSet && i.target_id == 0)
      continue;
    check_target(i.target, i.target_id, i.where, initial_keyword(i.target));
  }
  for (const model::BoundaryTemperatureDesc& b : model.temperature_histories) {
    check_target(b.target, b.target_id, b.where, boundary_keyword(b.target));
    if (b.curve_id != 0) {
      check_ref(t.curves, b.curve_id, b.where, boundary_keyword(b.target), "LCID", errors);
    }
  }
  check_single_prescription(model, errors);
  return errors;
}

}  // namespace plyform::setup
