// The passes' state in the checkpoint (restart): every array that changes during the run.

#include <string>
#include <vector>

#include "pass_runtime.hpp"
#include "plyform/core/state_archive.hpp"

namespace plyform::contact {

void ContactSet::visit_state(core::StateArchive& a) {
  a.value("searches", searches_);
  for (std::size_t p = 0; p < passes_.size(); ++p) {
    const auto scope = a.scope("pass/" + std::to_string(p));
    PassRuntime& pr = *passes_[p];
    // The law's history per slave node, in place (the batch view points into it).
    {
      const std::size_t ns = pr.history.size();
      const law::BatchHistory& h = pr.hist;
      a.fixed("law/state", std::span<std::int32_t>(h.state, ns));
      for (auto [name, v] : {std::pair{"beta", h.beta},
                             {"gap", h.gap},
                             {"slip_x", h.slip_x},
                             {"slip_y", h.slip_y},
                             {"opening_x", h.opening_x},
                             {"opening_y", h.opening_y},
                             {"e_damage", h.e_damage},
                             {"e_viscous", h.e_viscous},
                             {"e_friction", h.e_friction},
                             {"e_damping", h.e_damping},
                             {"e_healing", h.e_healing},
                             {"damping", h.damping}}) {
        a.fixed(std::string("law/") + name, std::span<double>(v, ns));
      }
    }
    a.fixed("friction_heated", std::span<double>(pr.friction_heated));
    a.fixed("tie_state", std::span<std::int8_t>(pr.tie_state));
    a.fixed("tie_gap0", std::span<double>(pr.tie_gap0));
    a.array("cand_start", pr.cand_start);
    a.array("cand", pr.cand);
    a.array("seg_radius", pr.seg_radius);
    a.array("tracked_ref", pr.tracked_ref);
    a.value("cycles_since_search", pr.cycles_since_search);
    a.value("searched", pr.searched);
    a.value("dt_vote", pr.dt_vote);
    a.value("measured", pr.measured);
    a.value("work", pr.work);
    a.value("surface", pr.surface);
    a.value("dt_last", pr.dt_last);
    a.value("resultant", pr.resultant);
    a.value("master_resultant", pr.master_resultant);
    a.value("seg_normal_current", pr.seg_normal_current);
    a.array("seg", pr.seg);
    a.array("prev_seg", pr.prev_seg);
    a.array("side", pr.side);
    for (auto [name, v] : {std::pair{"slave_offset", &pr.slave_offset},
                           {"seg_offset", &pr.seg_offset},
                           {"shape", &pr.shape},
                           {"prev_shape", &pr.prev_shape},
                           {"frame", &pr.frame},
                           {"gap", &pr.gap},
                           {"slip_x", &pr.slip_x},
                           {"slip_y", &pr.slip_y},
                           {"temperature", &pr.temperature},
                           {"k_normal", &pr.k_normal},
                           {"k_tangent", &pr.k_tangent},
                           {"m_eff", &pr.m_eff},
                           {"arrival_depth", &pr.arrival_depth},
                           {"pressure", &pr.pressure},
                           {"tau_x", &pr.tau_x},
                           {"tau_y", &pr.tau_y},
                           {"stored", &pr.stored},
                           {"force", &pr.force},
                           {"prev_force", &pr.prev_force},
                           {"work_part", &pr.work_part},
                           {"gap_jump", &pr.gap_jump},
                           {"surface_part", &pr.surface_part},
                           {"end_power", &pr.end_power},
                           {"master_normal", &pr.master_normal},
                           {"seg_normal", &pr.seg_normal},
                           {"slave_normal", &pr.slave_normal},
                           {"slave_face_normal", &pr.slave_face_normal},
                           {"rs", &pr.rs},
                           {"prev_rs", &pr.prev_rs}}) {
      a.array(name, *v);
    }
  }
}

}  // namespace plyform::contact
