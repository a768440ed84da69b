#include "plyform/setup/validate_mesh.hpp"

#include <array>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

namespace plyform::setup {
namespace {

using keyword::Diagnostic;
using model::SourceLocation;

/// Concatenates values as text (fmt is not a dependency of this library).
template <typename... Parts>
std::string cat(const Parts&... parts) {
  std::ostringstream out;
  (out << ... << parts);
  return out.str();
}

std::string at(const SourceLocation& w) {
  return cat(w.file, ":", w.line);
}

/// Ids of one kind with where each was first defined.
class IdTable {
 public:
  IdTable(std::string_view noun, std::string_view keyword) : noun_(noun), keyword_(keyword) {}

  /// Adds an id; a duplicate is an error on the later definition.
  void add(int id, const SourceLocation& where, std::string_view field,
           std::vector<Diagnostic>& errors, std::string_view keyword = {}) {
    const auto [it, inserted] = ids_.emplace(id, where);
    if (!inserted) {
      errors.push_back({where, std::string(keyword.empty() ? keyword_ : keyword),
                        std::string(field),
                        cat(noun_, " ", id, " is already defined at ", at(it->second))});
    }
  }
  bool contains(int id) const { return ids_.contains(id); }
  std::string_view noun() const { return noun_; }
  std::string_view keyword() const { return keyword_; }

 private:
  std::string noun_;
  std::string keyword_;
  std::unordered_map<int, SourceLocation> ids_;
};

/// Reports a reference to an id the table does not hold.
void check_ref(const IdTable& table, int id, const SourceLocation& where, std::string_view keyword,
               std::string_view field, std::vector<Diagnostic>& errors) {
  if (!table.contains(id)) {
    errors.push_back(
        {where, std::string(keyword), std::string(field),
         cat(table.noun(), " ", id, " is not defined (no ", table.keyword(), " with this id)")});
  }
}

constexpr std::array<std::string_view, 8> kNodeFields{"N1", "N2", "N3", "N4",
                                                      "N5", "N6", "N7", "N8"};

/// True when the node list is a hexahedron or one of the accepted degenerate patterns.
bool accepted_pattern(const std::array<int, 8>& n) {
  // Equalities that each pattern requires; the listed representatives must be distinct.
  struct Pattern {
    std::array<std::array<int, 2>, 4> equal;  // pairs of positions holding the same node
    int equal_count;
    std::array<int, 8> distinct;  // positions that must hold distinct nodes
    int distinct_count;
  };
  static constexpr std::array<Pattern, 6> kPatterns{{
      {{}, 0, {0, 1, 2, 3, 4, 5, 6, 7}, 8},                      // hexahedron
      {{{{4, 5}, {6, 7}}}, 2, {0, 1, 2, 3, 4, 6}, 6},            // wedge a b c d e e f f
      {{{{2, 3}, {6, 7}}}, 2, {0, 1, 2, 4, 5, 6}, 6},            // wedge a b c c d e f f
      {{{{4, 5}, {4, 6}, {4, 7}}}, 3, {0, 1, 2, 3, 4}, 5},       // pyramid a b c d e e e e
      {{{{3, 4}, {3, 5}, {3, 6}, {3, 7}}}, 4, {0, 1, 2, 3}, 4},  // tet a b c d d d d d
      {{{{2, 3}, {4, 5}, {4, 6}, {4, 7}}}, 4, {0, 1, 2, 4}, 4},  // tet a b c c d d d d
  }};
  for (const Pattern& p : kPatterns) {
    bool ok = true;
    for (int i = 0; i < p.equal_count && ok; ++i) {
      ok = n[static_cast<std::size_t>(p.equal[static_cast<std::size_t>(i)][0])] ==
           n[static_cast<std::size_t>(p.equal[static_cast<std::size_t>(i)][1])];
    }
    for (int i = 0; i < p.distinct_count && ok; ++i) {
      for (int j = i + 1; j < p.distinct_count && ok; ++j) {
        ok = n[static_cast<std::size_t>(p.distinct[static_cast<std::size_t>(i)])] !=
             n[static_cast<std::size_t>(p.distinct[static_cast<std::size_t>(j)])];
      }
    }
    if (ok) {
      return true;
    }
  }
  return false;
}

void check_element_nodes(const model::ElementSolidDesc& e, std::vector<Diagnostic>& errors) {
  if (accepted_pattern(e.nodes)) {
    return;
  }
  for (std::size_t i = 1; i < e.nodes.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (e.nodes[i] == e.nodes[j]) {
        errors.push_back({e.where, "*ELEMENT_SOLID", std::string(kNodeFields[i]),
                          cat("element ", e.id, ": ", kNodeFields[i], " repeats node ", e.nodes[j],
                              " of ", kNodeFields[j],
                              "; repeated nodes are accepted only in the degenerate patterns of "
                              "LS-DYNA (pentahedron N1 N2 N3 N4 N5 N5 N6 N6, pyramid N1..N5 N5 N5 "
                              "N5, tetrahedron N1 N2 N3 N4 N4 N4 N4 N4)")});
        return;
      }
    }
  }
}

std::string_view motion_keyword(model::NodeTarget t) {
  return t == model::NodeTarget::kNode ? "*BOUNDARY_PRESCRIBED_MOTION_NODE"
                                       : "*BOUNDARY_PRESCRIBED_MOTION_SET";
}
std::string_view spc_keyword(model::NodeTarget t) {
  return t == model::NodeTarget::kNode ? "*BOUNDARY_SPC_NODE" : "*BOUNDARY_SPC_SET";
}
std::string_view load_keyword(model::NodeTarget t) {
  return t == model::NodeTarget::kNode ? "*LOAD_NODE_POINT" : "*LOAD_NODE_SET";
}
std::string_view target_field(model::NodeTarget t) {
  return t == model::NodeTarget::kNode ? "NID" : "NSID";
}

}  // namespace

std::vector<Diagnostic> validate_mesh(const model::ModelDesc& model) {
  std::vector<Diagnostic> errors;

  IdTable nodes("node", "*NODE");
  for (const model::NodeDesc& n : model.nodes) {
    nodes.add(n.id, n.where, "NID", errors);
  }
  IdTable elements("element", "*ELEMENT_SOLID");
  for (const model::ElementSolidDesc& e : model.solids) {
    elements.add(e.id, e.where, "EID", errors);
  }
  IdTable parts("part", "*PART");
  for (const model::PartDesc& p : model.parts) {
    parts.add(p.id, p.where, "PID", errors);
  }
  // Section ids are shared by all section keywords; solid_sections marks the solid ones.
  std::vector<Diagnostic> ignored;  // duplicates reported through another table
  IdTable sections("section", "*SECTION_SOLID");
  IdTable solid_sections("solid section", "*SECTION_SOLID");
  for (const model::SectionSolidDesc& s : model.solid_sections) {
    sections.add(s.id, s.where, "SECID", errors);
    solid_sections.add(s.id, s.where, "SECID", ignored);
  }
  // Material ids are shared by all *MAT_ keywords.
  IdTable materials("material", "*MAT_ keyword");
  for (const model::MatElasticDesc& m : model.elastic_materials) {
    materials.add(m.id, m.where, "MID", errors, "*MAT_ELASTIC");
  }
  for (const model::MatMooneyRivlinDesc& m : model.mooney_rivlin_materials) {
    materials.add(m.id, m.where, "MID", errors, "*MAT_MOONEY-RIVLIN_RUBBER");
  }
  IdTable hourglasses("hourglass", "*HOURGLASS");
  for (const model::HourglassDesc& h : model.hourglasses) {
    hourglasses.add(h.id, h.where, "HGID", errors);
  }
  IdTable node_sets("node set", "*SET_NODE_LIST");
  for (const model::SetListDesc& s : model.node_sets) {
    node_sets.add(s.id, s.where, "SID", errors);
  }
  IdTable part_sets("part set", "*SET_PART_LIST");
  for (const model::SetListDesc& s : model.part_sets) {
    part_sets.add(s.id, s.where, "SID", errors);
  }
  IdTable curves("curve", "*DEFINE_CURVE");
  // Duplicate curves are reported by setup::validate.
  for (const model::CurveDesc& c : model.curves) {
    curves.add(c.id, c.where, "LCID", ignored);
  }

  // Parts -> section, material, hourglass.
  std::unordered_map<int, const model::PartDesc*> part_by_id;
  for (const model::PartDesc& p : model.parts) {
    part_by_id.emplace(p.id, &p);
    check_ref(sections, p.section_id, p.where, "*PART", "SECID", errors);
    check_ref(materials, p.material_id, p.where, "*PART", "MID", errors);
    if (p.hourglass_id != 0) {
      check_ref(hourglasses, p.hourglass_id, p.where, "*PART", "HGID", errors);
    }
  }

  // Elements -> part (with a solid section), nodes; node patterns.
  std::unordered_set<int> reported_parts;
  for (const model::ElementSolidDesc& e : model.solids) {
    const auto part = part_by_id.find(e.part_id);
    if (part == part_by_id.end()) {
      check_ref(parts, e.part_id, e.where, "*ELEMENT_SOLID", "PID", errors);
    } else if (sections.contains(part->second->section_id) &&
               !solid_sections.contains(part->second->section_id) &&
               reported_parts.insert(e.part_id).second) {
      errors.push_back(
          {e.where, "*ELEMENT_SOLID", "PID",
           cat("element ", e.id, ": part ", e.part_id, " has section ", part->second->section_id,
               ", which is not a *SECTION_SOLID (the first such element is reported)")});
    }
    for (std::size_t i = 0; i < e.nodes.size(); ++i) {
      if (!nodes.contains(e.nodes[i])) {
        errors.push_back({e.where, "*ELEMENT_SOLID", std::string(kNodeFields[i]),
                          cat("element ", e.id, ": node ", e.nodes[i],
                              " is not defined (no *NODE with this id)")});
      }
    }
    check_element_nodes(e, errors);
  }

  // Sets -> nodes, parts.
  for (const model::SetListDesc& s : model.node_sets) {
    for (std::size_t i = 0; i < s.ids.size(); ++i) {
      if (!nodes.contains(s.ids[i])) {
        errors.push_back({s.ids_where[i], "*SET_NODE_LIST", cat("NID", i + 1),
                          cat("node set ", s.id, ": node ", s.ids[i],
                              " is not defined (no *NODE with this id)")});
      }
    }
  }
  for (const model::SetListDesc& s : model.part_sets) {
    for (std::size_t i = 0; i < s.ids.size(); ++i) {
      if (!parts.contains(s.ids[i])) {
        errors.push_back({s.ids_where[i], "*SET_PART_LIST", cat("PID", i + 1),
                          cat("part set ", s.id, ": part ", s.ids[i],
                              " is not defined (no *PART with this id)")});
      }
    }
  }

  // Constraints, motions, loads -> node or node set, curve.
  const auto check_target = [&](model::NodeTarget t, int id, const SourceLocation& where,
                                std::string_view keyword) {
    check_ref(t == model::NodeTarget::kNode ? nodes : node_sets, id, where, keyword,
              target_field(t), errors);
  };
  for (const model::BoundarySpcDesc& s : model.spcs) {
    check_target(s.target, s.target_id, s.where, spc_keyword(s.target));
  }
  for (const model::PrescribedMotionDesc& m : model.prescribed_motions) {
    check_target(m.target, m.target_id, m.where, motion_keyword(m.target));
    check_ref(curves, m.curve_id, m.where, motion_keyword(m.target), "LCID", errors);
  }
  for (const model::LoadNodeDesc& l : model.nodal_loads) {
    check_target(l.target, l.target_id, l.where, load_keyword(l.target));
    check_ref(curves, l.curve_id, l.where, load_keyword(l.target), "LCID", errors);
  }
  for (const model::InitialVelocityGenerationDesc& v : model.initial_velocities) {
    constexpr std::string_view kKeyword = "*INITIAL_VELOCITY_GENERATION";
    if (v.styp == 3) {
      check_ref(node_sets, v.target_id, v.where, kKeyword, "ID", errors);
    } else if (v.styp == 2 && v.target_id != 0) {
      check_ref(parts, v.target_id, v.where, kKeyword, "ID", errors);
    } else if (v.styp == 1 && v.target_id != 0) {
      check_ref(part_sets, v.target_id, v.where, kKeyword, "ID", errors);
    }
  }

  // Output -> nodes, part sets.
  for (const model::DatabaseHistoryNodeDesc& h : model.history_nodes) {
    for (std::size_t i = 0; i < h.node_ids.size(); ++i) {
      if (!nodes.contains(h.node_ids[i])) {
        errors.push_back({h.ids_where[i], "*DATABASE_HISTORY_NODE",
                          h.headings.empty() ? cat("NID", i + 1) : "ID",
                          cat("node ", h.node_ids[i], " is not defined (no *NODE with this id)")});
      }
    }
  }
  if (model.d3plot && model.d3plot->part_set_id != 0) {
    check_ref(part_sets, model.d3plot->part_set_id, model.d3plot->where, "*DATABASE_BINARY_D3PLOT",
              "PSETID", errors);
  }
  return errors;
}

}  // namespace plyform::setup
