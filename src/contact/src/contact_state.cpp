// The passes' state in the checkpoint (restart): every array that changes during the run.

#include <string>
#include <vector>

#include "pass_runtime.hpp"
#include "plyform/core/state_archive.hpp"
#include "slave_share.hpp"

namespace plyform::contact {

void ContactSet::visit_state(core::StateArchive& a) {
  a.value("searches", searches_);
  a.value("rested", rested_);
  a.value("node_cycles", node_cycles_);
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
    pr.st.visit(a);
  }
}

void PassState::visit(core::StateArchive& a) {
  a.fixed("friction_heated", std::span<double>(friction_heated));
  a.fixed("tie_state", std::span<std::int8_t>(tie_state));
  a.fixed("tie_gap0", std::span<double>(tie_gap0));
  a.fixed("resting", std::span<std::uint8_t>(resting));
  a.fixed("rest_wait", std::span<std::uint8_t>(rest_wait));
  a.fixed("rest_room", std::span<double>(rest_room));
  a.fixed("rest_from", std::span<double>(rest_from));
  a.array("cand_start", cand_start);
  a.array("cand", cand);
  a.array("seg_radius", seg_radius);
  a.array("tracked_ref", tracked_ref);
  a.value("cycles_since_search", cycles_since_search);
  a.value("searched", searched);
  a.value("dt_vote", dt_vote);
  a.value("measured", measured);
  a.value("work", work);
  a.value("surface", surface);
  a.value("dt_last", dt_last);
  a.value("resultant", resultant);
  a.value("master_resultant", master_resultant);
  a.value("seg_normal_current", seg_normal_current);
  a.array("seg", seg);
  a.array("prev_seg", prev_seg);
  a.array("side", side);
  for (auto [name, v] : {std::pair{"slave_offset", &slave_offset},
                         {"seg_offset", &seg_offset},
                         {"node_offset", &node_offset},
                         {"shape", &shape},
                         {"prev_shape", &prev_shape},
                         {"frame", &frame},
                         {"gap", &gap},
                         {"slip_x", &slip_x},
                         {"slip_y", &slip_y},
                         {"temperature", &temperature},
                         {"k_normal", &k_normal},
                         {"k_tangent", &k_tangent},
                         {"m_eff", &m_eff},
                         {"arrival_depth", &arrival_depth},
                         {"pressure", &pressure},
                         {"tau_x", &tau_x},
                         {"tau_y", &tau_y},
                         {"stored", &stored},
                         {"force", &force},
                         {"prev_force", &prev_force},
                         {"work_part", &work_part},
                         {"gap_jump", &gap_jump},
                         {"surface_part", &surface_part},
                         {"end_power", &end_power},
                         {"master_normal", &master_normal},
                         {"seg_normal", &seg_normal},
                         {"slave_normal", &slave_normal},
                         {"slave_face_normal", &slave_face_normal},
                         {"rs", &rs},
                         {"prev_rs", &prev_rs}}) {
    a.array(name, *v);
  }
}

void ContactSet::gather_state() {
  if (shares_.empty() || gathered_at_ == applies_)
    return;
  for (std::size_t p = 0; p < passes_.size(); ++p)
    shares_[p]->gather_state(*passes_[p]);
  gathered_at_ = applies_;
}

}  // namespace plyform::contact
