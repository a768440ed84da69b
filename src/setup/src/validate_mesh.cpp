#include "plyform/setup/validate_mesh.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "id_table.hpp"

namespace plyform::setup {
namespace {

using detail::at;
using detail::cat;
using detail::check_ref;
using detail::IdTable;
using keyword::Diagnostic;
using model::SourceLocation;

/// One definition of an id whose range several keywords share (sections, materials).
struct Definition {
  int id = 0;
  SourceLocation where;
  std::string_view keyword;
};

/// Adds definitions in deck order (files in the order read, then lines), so that a duplicate
/// is reported on the later definition whatever the keywords.
void add_in_deck_order(IdTable& table, std::vector<Definition> definitions,
                       const model::ModelDesc& model, std::string_view field,
                       std::vector<Diagnostic>& errors) {
  const auto file_index = [&](const std::string& file) {
    const auto it = std::find(model.files_read.begin(), model.files_read.end(), file);
    return static_cast<std::size_t>(it - model.files_read.begin());
  };
  std::stable_sort(definitions.begin(), definitions.end(),
                   [&](const Definition& a, const Definition& b) {
                     const std::size_t fa = file_index(a.where.file);
                     const std::size_t fb = file_index(b.where.file);
                     return fa != fb ? fa < fb : a.where.line < b.where.line;
                   });
  for (const Definition& d : definitions) {
    table.add(d.id, d.where, field, errors, d.keyword);
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

/// Shell node lists: N1, N2, N3 distinct; N4 distinct from them, or N4 = N3 (a triangle).
void check_shell_nodes(const model::ElementShellDesc& e, std::vector<Diagnostic>& errors) {
  const std::array<int, 4>& n = e.nodes;
  for (std::size_t i = 1; i < n.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (n[i] == n[j] && !(i == 3 && j == 2)) {
        errors.push_back(
            {e.where, "*ELEMENT_SHELL", std::string(kNodeFields[i]),
             cat("shell element ", e.id, ": ", kNodeFields[i], " repeats node ", n[j], " of ",
                 kNodeFields[j], "; the only repeat accepted is N4 = N3 (a triangle)")});
        return;
      }
    }
  }
}

/// True when the element gets a thickness: from its _THICKNESS card or the section's T1.
bool has_thickness(const model::ElementShellDesc& e, const model::SectionShellDesc& section) {
  if (section.thickness[0] > 0.0) {
    return true;
  }
  const std::size_t corners = e.nodes[3] == e.nodes[2] ? 3 : 4;  // a triangle needs THIC1..3
  for (std::size_t i = 0; i < corners; ++i) {
    if (!(e.thickness[i] > 0.0)) {
      return false;
    }
  }
  return e.has_thickness_card;
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
  // Shell ids are a range of their own, as in LS-DYNA (a shell and a solid may share an id).
  IdTable shell_elements("shell element", "*ELEMENT_SHELL");
  for (const model::ElementShellDesc& e : model.shells) {
    shell_elements.add(e.id, e.where, "EID", errors);
  }
  IdTable parts("part", "*PART");
  for (const model::PartDesc& p : model.parts) {
    parts.add(p.id, p.where, "PID", errors);
  }
  // Section ids are shared by all section keywords; solid_sections and shell_sections mark the
  // kinds.
  std::vector<Diagnostic> ignored;  // duplicates reported through another table
  IdTable sections("section", "*SECTION_ keyword");
  std::vector<Definition> section_definitions;
  IdTable solid_sections("solid section", "*SECTION_SOLID");
  for (const model::SectionSolidDesc& s : model.solid_sections) {
    section_definitions.push_back({s.id, s.where, "*SECTION_SOLID"});
    solid_sections.add(s.id, s.where, "SECID", ignored);
  }
  IdTable shell_sections("shell section", "*SECTION_SHELL");
  std::unordered_map<int, const model::SectionShellDesc*> shell_section_by_id;
  for (const model::SectionShellDesc& s : model.shell_sections) {
    section_definitions.push_back({s.id, s.where, "*SECTION_SHELL"});
    shell_sections.add(s.id, s.where, "SECID", ignored);
    shell_section_by_id.emplace(s.id, &s);
  }
  add_in_deck_order(sections, std::move(section_definitions), model, "SECID", errors);
  // Material ids are shared by all *MAT_ keywords; rigid_materials marks *MAT_RIGID.
  IdTable materials("material", "*MAT_ keyword");
  std::vector<Definition> material_definitions;
  const auto add_materials = [&](const auto& descs, std::string_view keyword) {
    for (const auto& m : descs) {
      material_definitions.push_back({m.id, m.where, keyword});
    }
  };
  add_materials(model.elastic_materials, "*MAT_ELASTIC");
  add_materials(model.orthotropic_elastic_materials, "*MAT_ORTHOTROPIC_ELASTIC");
  add_materials(model.power_law_materials, "*MAT_POWER_LAW_PLASTICITY");
  add_materials(model.rigid_materials, "*MAT_RIGID");
  add_materials(model.piecewise_linear_materials, "*MAT_PIECEWISE_LINEAR_PLASTICITY");
  add_materials(model.mooney_rivlin_materials, "*MAT_MOONEY-RIVLIN_RUBBER");
  add_materials(model.elastic_plastic_thermal_materials, "*MAT_ELASTIC_PLASTIC_THERMAL");
  add_materials(model.reinforced_thermoplastic_materials, "*MAT_REINFORCED_THERMOPLASTIC");
  add_materials(model.plastic_kinematic_materials, "*MAT_PLASTIC_KINEMATIC");
  add_materials(model.transversely_anisotropic_materials,
                "*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC");
  add_materials(model.barlat89_materials, "*MAT_3-PARAMETER_BARLAT");
  add_materials(model.hill_3r_materials, "*MAT_HILL_3R");
  add_in_deck_order(materials, std::move(material_definitions), model, "MID", errors);
  IdTable rigid_materials("rigid material", "*MAT_RIGID");
  for (const model::MatRigidDesc& m : model.rigid_materials) {
    rigid_materials.add(m.id, m.where, "MID", ignored);
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
  // *DEFINE_COORDINATE_SYSTEM and _VECTOR share one id range.
  IdTable coordinate_systems("coordinate system", "*DEFINE_COORDINATE_SYSTEM or _VECTOR");
  for (const model::CoordinateSystemDesc& c : model.coordinate_systems) {
    coordinate_systems.add(
        c.id, c.where, "CID", errors,
        c.from_vectors ? "*DEFINE_COORDINATE_VECTOR" : "*DEFINE_COORDINATE_SYSTEM");
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

  // *CONTROL_SHELL ESORT 1/2 asks for a C0 triangle formulation plyform does not have: an
  // error when there is a triangle to sort (none: the run is LS-DYNA's).
  if (model.control_shell && model.control_shell->esort != 0) {
    std::size_t triangles = 0;
    const model::ElementShellDesc* first = nullptr;
    for (const model::ElementShellDesc& e : model.shells) {
      if (e.nodes[2] == e.nodes[3]) {
        ++triangles;
        if (first == nullptr)
          first = &e;
      }
    }
    if (triangles > 0) {
      errors.push_back(
          {model.control_shell->where, "*CONTROL_SHELL", "ESORT",
           cat("ESORT = ", model.control_shell->esort, " sorts the model's ", triangles,
               " triangular shells (the first: element ", first->id, " at ", at(first->where),
               ") into a C0 triangle formulation, which plyform does not have; ESORT = 0 runs "
               "them as degenerate Belytschko-Tsay quadrilaterals")});
    }
  }

  // Shell elements -> part (with a shell section and a thickness), nodes; node patterns.
  std::unordered_set<int> reported_shell_parts;
  for (const model::ElementShellDesc& e : model.shells) {
    const auto part = part_by_id.find(e.part_id);
    if (part == part_by_id.end()) {
      check_ref(parts, e.part_id, e.where, "*ELEMENT_SHELL", "PID", errors);
    } else if (reported_shell_parts.contains(e.part_id)) {
      // One error per part: the first offending element.
    } else if (const int secid = part->second->section_id;
               sections.contains(secid) && !shell_sections.contains(secid)) {
      reported_shell_parts.insert(e.part_id);
      errors.push_back(
          {e.where, "*ELEMENT_SHELL", "PID",
           cat("shell element ", e.id, ": part ", e.part_id, " has section ", secid,
               ", which is not a *SECTION_SHELL (the first such element is reported)")});
    } else if (const auto section = shell_section_by_id.find(secid);
               section != shell_section_by_id.end() && !has_thickness(e, *section->second)) {
      reported_shell_parts.insert(e.part_id);
      errors.push_back(
          {e.where, "*ELEMENT_SHELL", "PID",
           cat("shell element ", e.id, ": no thickness: section ", secid,
               " has T1 = 0 and the element has no *ELEMENT_SHELL_THICKNESS card with THIC1..4 "
               "> 0 (the first such element of part ",
               e.part_id, " is reported)")});
    }
    for (std::size_t i = 0; i < e.nodes.size(); ++i) {
      if (!nodes.contains(e.nodes[i])) {
        errors.push_back({e.where, "*ELEMENT_SHELL", std::string(kNodeFields[i]),
                          cat("shell element ", e.id, ": node ", e.nodes[i],
                              " is not defined (no *NODE with this id)")});
      }
    }
    check_shell_nodes(e, errors);
  }

  // Materials -> curves.
  for (const model::MatPiecewiseLinearPlasticityDesc& m : model.piecewise_linear_materials) {
    const bool table = std::any_of(model.tables.begin(), model.tables.end(),
                                   [&](const model::DefineTableDesc& t) { return t.id == m.lcss; });
    if (m.lcss != 0 && !table && !curves.contains(m.lcss)) {
      errors.push_back({m.where, "*MAT_PIECEWISE_LINEAR_PLASTICITY", "LCSS",
                        cat("material ", m.id, ": curve ", m.lcss,
                            " is not defined (no *DEFINE_CURVE or *DEFINE_TABLE with this id)")});
    }
    // LS-DYNA ignores the Cowper-Symonds constants when LCSS is a table of curves by rate:
    // plyform says so rather than pass over them.
    if (table && (m.c > 0.0 || m.p > 0.0)) {
      errors.push_back({m.where, "*MAT_PIECEWISE_LINEAR_PLASTICITY", "C",
                        cat("material ", m.id, ": LCSS ", m.lcss,
                            " is a table of yield curves by strain rate, which gives the rate "
                            "effect; C = ",
                            m.c, " and P = ", m.p,
                            " would be ignored (LS-DYNA's rule): leave them 0 or give a curve")});
    }
  }

  // The returns of the sheet-metal laws bracket their plastic multiplier with a yield stress
  // that is positive and does not soften, as the hardening curve of a sheet metal is.
  const auto check_curve = [&](const model::SourceLocation& where, std::string_view keyword,
                               std::string_view field, int mid, int curve_id) {
    const auto c = std::find_if(model.curves.begin(), model.curves.end(),
                                [&](const model::CurveDesc& x) { return x.id == curve_id; });
    if (c == model.curves.end()) {
      errors.push_back({where, std::string(keyword), std::string(field),
                        cat("material ", mid, ": curve ", curve_id,
                            " is not defined (no *DEFINE_CURVE with this id)")});
      return;
    }
    const std::vector<model::CurvePoint> points = model::effective_points(*c);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!(points[i].y > 0.0) || (i > 0 && points[i].y < points[i - 1].y)) {
        errors.push_back(
            {where, std::string(keyword), std::string(field),
             cat("material ", mid, ": the yield stresses of curve ", curve_id,
                 " must be > 0 and must not decrease (point ", i + 1, " is ", points[i].y, ")")});
        break;
      }
    }
  };
  for (const model::MatTransverselyAnisotropicDesc& m : model.transversely_anisotropic_materials) {
    const std::string_view keyword = "*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC";
    if (m.hlcid != 0)
      check_curve(m.where, keyword, "HLCID", m.id, m.hlcid);
  }
  for (const model::MatBarlat89Desc& m : model.barlat89_materials) {
    if (m.hardening.hr == 3)
      check_curve(m.where, "*MAT_3-PARAMETER_BARLAT", "LCID", m.id, m.hardening.lcid);
  }
  for (const model::MatHill3RDesc& m : model.hill_3r_materials) {
    if (m.hardening.hr == 3)
      check_curve(m.where, "*MAT_HILL_3R", "LCID", m.id, m.hardening.lcid);
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
    if (s.cid != 0)
      check_ref(coordinate_systems, s.cid, s.where, spc_keyword(s.target), "CID", errors);
  }
  for (const model::PrescribedMotionDesc& m : model.prescribed_motions) {
    check_target(m.target, m.target_id, m.where, motion_keyword(m.target));
    check_ref(curves, m.curve_id, m.where, motion_keyword(m.target), "LCID", errors);
  }
  if (model.timestep && model.timestep->lctm != 0)
    check_ref(curves, model.timestep->lctm, model.timestep->where, "*CONTROL_TIMESTEP", "LCTM",
              errors);
  for (const model::LoadNodeDesc& l : model.nodal_loads) {
    check_target(l.target, l.target_id, l.where, load_keyword(l.target));
    check_ref(curves, l.curve_id, l.where, load_keyword(l.target), "LCID", errors);
  }
  // Rigid parts: each needs elements (its mass and inertia come from them), and no node may
  // belong to two of them (merging rigid bodies, *CONSTRAINED_RIGID_BODIES, is not supported):
  // found here, with the card, rather than when the run starts.
  {
    const auto is_rigid = [&](int part_id) {
      const auto p = part_by_id.find(part_id);
      return p != part_by_id.end() && rigid_materials.contains(p->second->material_id);
    };
    std::unordered_map<int, int> rigid_part_of_node;  // node id -> the first rigid part using it
    std::unordered_set<int> with_elements;
    std::set<std::pair<int, int>> reported_pairs;
    const auto visit = [&](const auto& e, std::string_view keyword) {
      if (!is_rigid(e.part_id))
        return;
      with_elements.insert(e.part_id);
      for (std::size_t i = 0; i < e.nodes.size(); ++i) {
        const auto [it, fresh] = rigid_part_of_node.emplace(e.nodes[i], e.part_id);
        if (fresh || it->second == e.part_id)
          continue;
        if (reported_pairs.emplace(it->second, e.part_id).second) {
          errors.push_back(
              {e.where, std::string(keyword), std::string(kNodeFields[i]),
               cat("element ", e.id, " of rigid part ", e.part_id, " uses node ", e.nodes[i],
                   ", which rigid part ", it->second,
                   " uses too: merging rigid bodies is not supported (give each body its own "
                   "nodes; the first shared node of each pair of parts is reported)")});
        }
      }
    };
    for (const model::ElementSolidDesc& e : model.solids)
      visit(e, "*ELEMENT_SOLID");
    for (const model::ElementShellDesc& e : model.shells)
      visit(e, "*ELEMENT_SHELL");
    for (const model::PartDesc& p : model.parts) {
      if (is_rigid(p.id) && !with_elements.count(p.id)) {
        errors.push_back({p.where, "*PART", "PID",
                          cat("part ", p.id, " is rigid (*MAT_RIGID ", p.material_id,
                              ") but has no elements: a rigid body takes its mass and inertia "
                              "from its elements")});
      }
    }
  }
  // Rigid body motions and loads -> a part whose material is *MAT_RIGID, curve.
  const auto check_rigid_part = [&](int part_id, const SourceLocation& where,
                                    std::string_view keyword) {
    const auto part = part_by_id.find(part_id);
    if (part == part_by_id.end()) {
      check_ref(parts, part_id, where, keyword, "PID", errors);
    } else if (materials.contains(part->second->material_id) &&
               !rigid_materials.contains(part->second->material_id)) {
      errors.push_back({where, std::string(keyword), "PID",
                        cat("part ", part_id, " has material ", part->second->material_id,
                            ", which is not a *MAT_RIGID: only rigid bodies take this keyword")});
    }
  };
  for (const model::PrescribedMotionRigidDesc& m : model.rigid_motions) {
    constexpr std::string_view kKeyword = "*BOUNDARY_PRESCRIBED_MOTION_RIGID";
    check_rigid_part(m.part_id, m.where, kKeyword);
    check_ref(curves, m.curve_id, m.where, kKeyword, "LCID", errors);
  }
  for (const model::LoadRigidBodyDesc& l : model.rigid_body_loads) {
    constexpr std::string_view kKeyword = "*LOAD_RIGID_BODY";
    check_rigid_part(l.part_id, l.where, kKeyword);
    check_ref(curves, l.curve_id, l.where, kKeyword, "LCID", errors);
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

  for (const model::InitialVelocityNodeDesc& v : model.initial_node_velocities)
    check_ref(nodes, v.node_id, v.where, "*INITIAL_VELOCITY_NODE", "NID", errors);

  // Output -> nodes, part sets.
  for (const model::DatabaseHistoryNodeDesc& h : model.history_nodes) {
    for (std::size_t i = 0; i < h.set_ids.size(); ++i)
      check_ref(node_sets, h.set_ids[i], h.sets_where[i], "*DATABASE_HISTORY_NODE_SET",
                cat("NSID", i + 1), errors);
    for (std::size_t i = 0; i < h.node_ids.size(); ++i) {
      if (!nodes.contains(h.node_ids[i])) {
        errors.push_back({h.ids_where[i], "*DATABASE_HISTORY_NODE",
                          h.headings.empty() ? cat("NID", i + 1) : "ID",
                          cat("node ", h.node_ids[i], " is not defined (no *NODE with this id)")});
      }
    }
  }
  // Element histories (elout.csv) -> shells, solids; each kind its own id range.
  for (const model::DatabaseHistoryElementDesc& h : model.history_elements) {
    const IdTable& table = h.shell ? shell_elements : elements;
    for (std::size_t i = 0; i < h.element_ids.size(); ++i) {
      if (!table.contains(h.element_ids[i])) {
        errors.push_back(
            {h.ids_where[i], h.shell ? "*DATABASE_HISTORY_SHELL" : "*DATABASE_HISTORY_SOLID",
             h.headings.empty() ? "EID" : "ID",
             cat(h.shell ? "shell" : "solid", " element ", h.element_ids[i], " is not defined (no ",
                 h.shell ? "*ELEMENT_SHELL" : "*ELEMENT_SOLID", " with this id)")});
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
