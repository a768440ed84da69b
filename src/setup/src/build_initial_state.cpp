#include "build_initial_state.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <variant>

namespace plyform::setup {
namespace {

using core::Index;

constexpr const char* kStress = "*INITIAL_STRESS_SHELL";
constexpr const char* kStrain = "*INITIAL_STRAIN_SHELL";
constexpr const char* kSpringback = "*INTERFACE_SPRINGBACK_LSDYNA";

bool rigid_block(const core::Model& m, const core::ShellBlock& b) {
  const core::Part& p = m.parts[static_cast<std::size_t>(b.part)];
  return std::holds_alternative<core::RigidMaterial>(
      m.materials[static_cast<std::size_t>(p.material)]);
}

/// The shells by deck id.
std::unordered_map<int, core::BlockElement> shells_by_id(const core::Model& m) {
  std::unordered_map<int, core::BlockElement> at;
  for (std::size_t b = 0; b < m.shell_blocks.size(); ++b) {
    const core::ShellBlock& blk = m.shell_blocks[b];
    for (std::size_t e = 0; e < blk.size(); ++e)
      at.emplace(static_cast<int>(blk.element_id[e]),
                 core::BlockElement{static_cast<Index>(b), static_cast<Index>(e)});
  }
  return at;
}

/// The element of a card: a deformable shell, else an error naming EID.
const core::BlockElement* find_shell(const core::Model& m,
                                     const std::unordered_map<int, core::BlockElement>& at, int id,
                                     const model::SourceLocation& where, const char* keyword,
                                     std::vector<keyword::Diagnostic>& errors) {
  const auto it = at.find(id);
  if (it == at.end()) {
    errors.push_back(
        {where, keyword, "EID", "element " + std::to_string(id) + " is not a shell of this deck"});
    return nullptr;
  }
  if (rigid_block(m, m.shell_blocks[static_cast<std::size_t>(it->second.block)])) {
    errors.push_back({where, keyword, "EID",
                      "element " + std::to_string(id) +
                          " is a shell of a rigid part: it has no stresses to set"});
    return nullptr;
  }
  return &it->second;
}

/// One card group to the engine's form: the thickness points sorted by T (LS-DYNA writes them
/// from the bottom up, but nothing requires it), the in-plane points of one thickness point
/// checked to share their T.
bool resolve_stress(const model::InitialStressShellDesc& d, core::InitialShellStress& out,
                    std::vector<keyword::Diagnostic>& errors) {
  const auto nplane = static_cast<std::size_t>(d.nplane);
  const auto nthick = static_cast<std::size_t>(d.nthick);
  for (std::size_t k = 0; k < nthick; ++k) {
    for (std::size_t g = 1; g < nplane; ++g) {
      const model::InitialStressPoint& p = d.points[k * nplane + g];
      if (p.t != d.points[k * nplane].t) {
        errors.push_back({p.where, kStress, "T",
                          "the in-plane points of one thickness point must share its T (" +
                              std::to_string(d.points[k * nplane].t) + " above)"});
        return false;
      }
    }
  }
  std::vector<std::size_t> order(nthick);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return d.points[a * nplane].t < d.points[b * nplane].t;
  });
  for (std::size_t i = 1; i < nthick; ++i) {
    if (d.points[order[i] * nplane].t == d.points[order[i - 1] * nplane].t) {
      errors.push_back(
          {d.points[order[i] * nplane].where, kStress, "T", "two thickness points at the same T"});
      return false;
    }
  }
  out.in_plane = d.nplane;
  for (std::size_t k : order) {
    out.t.push_back(d.points[k * nplane].t);
    for (std::size_t g = 0; g < nplane; ++g) {
      const model::InitialStressPoint& p = d.points[k * nplane + g];
      out.stress.insert(out.stress.end(), p.sigma.begin(), p.sigma.end());
      out.plastic_strain.push_back(p.eps);
    }
  }
  return true;
}

void resolve_stresses(const model::ModelDesc& desc, core::Model& m,
                      const std::unordered_map<int, core::BlockElement>& at,
                      std::vector<keyword::Diagnostic>& errors) {
  std::unordered_set<int> seen;
  for (const model::InitialStressShellDesc& d : desc.initial_shell_stresses) {
    const core::BlockElement* shell = find_shell(m, at, d.element_id, d.where, kStress, errors);
    if (shell == nullptr)
      continue;
    if (!seen.insert(d.element_id).second) {
      errors.push_back({d.where, kStress, "EID",
                        "element " + std::to_string(d.element_id) + " is given a second time"});
      continue;
    }
    core::InitialShellStress s{
        .shell = *shell, .in_plane = 1, .t = {}, .stress = {}, .plastic_strain = {}};
    if (resolve_stress(d, s, errors))
      m.initial_shell_stresses.push_back(std::move(s));
  }
}

void check_strains(const model::ModelDesc& desc, const core::Model& m,
                   const std::unordered_map<int, core::BlockElement>& at,
                   std::vector<keyword::Diagnostic>& errors,
                   std::vector<keyword::Diagnostic>& warnings) {
  for (const model::InitialStrainShellDesc& d : desc.initial_shell_strains)
    (void)find_shell(m, at, d.element_id, d.where, kStrain, errors);
  if (!desc.initial_shell_strains.empty()) {
    warnings.push_back(
        {desc.initial_shell_strains.front().where, kStrain, "",
         std::to_string(desc.initial_shell_strains.size()) +
             " shells' strains read and checked, not applied: plyform computes its strain "
             "outputs (STRFLG, formability) from the geometry, so they measure from this "
             "deck's node positions (the formed shape)"});
  }
}

void resolve_dynain(const model::ModelDesc& desc, core::Model& m,
                    std::vector<keyword::Diagnostic>& errors,
                    std::vector<keyword::Diagnostic>& warnings) {
  if (!desc.springback)
    return;
  const model::InterfaceSpringbackDesc& sb = *desc.springback;
  std::unordered_set<int> parts;
  if (sb.psid != 0) {
    const auto set = std::find_if(desc.part_sets.begin(), desc.part_sets.end(),
                                  [&](const model::SetListDesc& s) { return s.id == sb.psid; });
    if (set == desc.part_sets.end()) {
      errors.push_back({sb.where, kSpringback, "PSID",
                        "part set " + std::to_string(sb.psid) + " is not defined"});
      return;
    }
    parts.insert(set->ids.begin(), set->ids.end());
  }
  m.output.dynain.write = true;
  for (std::size_t b = 0; b < m.shell_blocks.size(); ++b) {
    const core::ShellBlock& blk = m.shell_blocks[b];
    const core::GlobalId part = m.parts[static_cast<std::size_t>(blk.part)].id;
    if (!parts.empty() && parts.count(static_cast<int>(part)) == 0)
      continue;
    if (rigid_block(m, blk)) {
      if (!parts.empty()) {
        warnings.push_back({sb.where, kSpringback, "PSID",
                            "part " + std::to_string(part) +
                                " is rigid: it has no stresses, so dynain leaves it out"});
      }
      continue;
    }
    m.output.dynain.shell_blocks.push_back(static_cast<Index>(b));
  }
  if (m.output.dynain.shell_blocks.empty()) {
    warnings.push_back({sb.where, kSpringback, "PSID",
                        "no deformable shell part to write: dynain will hold no element"});
  }
}

}  // namespace

void build_initial_state(const model::ModelDesc& desc, core::Model& model,
                         std::vector<keyword::Diagnostic>& errors,
                         std::vector<keyword::Diagnostic>& warnings) {
  const auto at = shells_by_id(model);
  resolve_stresses(desc, model, at, errors);
  check_strains(desc, model, at, errors, warnings);
  resolve_dynain(desc, model, errors, warnings);
}

}  // namespace plyform::setup
