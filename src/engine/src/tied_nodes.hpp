#pragma once
// The tied contacts in the cycle (core::TiedInterface): each tied slave node s follows the
// point of its master segment with weights w_j (the segment's shape functions there), at the
// offset d = x_s - sum w_j x_j it had (docs/contact.md, "Tied contacts"). The constraint moves
// the slave's mass and forces onto the segment's nodes, so momentum is conserved exactly:
//   m_j += w_j m_s (once, at the start), f_j += w_j f_s (every cycle, before the velocity
//   update), and after it  v_s = sum w_j v_j.
// With rotations tied (a shell edge), the slave turns with the segment's mean rotation
// omega = sum w_j omega_j and, at its offset, moves as a rigidly linked point:
//   v_s = sum w_j v_j + omega x d;  the moment M_s + d x f_s goes to the nodes by w_j, and the
//   rotary inertia I_s + m_s |d|^2 with it.
// The kinetic energy the books measure (with every node's own mass) is the central
// differences' conserved one less 1/2 m_s (sum w_j v_j^2 - (sum w_j v_j)^2) per slave: nothing
// while the segment moves as a whole, a trace where it deforms.

#include <array>
#include <iterator>
#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/engine/nodal_state.hpp"

namespace plyform::engine {

class TiedNodes {
 public:
  explicit TiedNodes(const core::Model& model);

  [[nodiscard]] bool empty() const { return slave_.empty(); }

  /// The effective masses and rotary inertias of the update: the slaves' moved onto their
  /// segments' nodes (inverse 0 for a slave: the update leaves it for follow()).
  void lump(const std::vector<double>& mass, const std::vector<double>& inertia,
            std::vector<double>& inv_mass, std::vector<double>& inv_inertia) const;

  /// Before the velocity update: each slave's net force (e - f) and, with rotations, its
  /// moment and the force's moment about the surface point, onto its segment's nodes' internal
  /// force arrays (the slave's own are zeroed; its external load stays where the engine books
  /// its work).
  void gather(NodalState& s);

  /// After the update (constraints, rigid bodies and walls done): the slaves' velocities (and
  /// rotations) from their segments'. Returns the correction of the next half step's external
  /// work rate, sum (v_s - v_free) . e_s. dt_avg: the step the update took (v_{n+1/2} =
  /// v_{n-1/2} + dt_avg a_n), for the reactions.
  double follow(NodalState& s, double dt_avg);

  /// Each tied contact's reaction in the last update, in model.tied's order: the force its
  /// master surface applied to its tied nodes, sum over them of m_s a_s - (e_s - f_s) (the
  /// node's mass times the acceleration the tie gave it, less the forces that act on it).
  [[nodiscard]] const std::vector<std::array<double, 3>>& reactions() const { return reaction_; }
  /// Appends every tied slave node and its segment's nodes (what gather() and follow() read and
  /// write).
  void nodes(std::vector<core::Index>& out) const {
    for (const Link& l : slave_) {
      out.push_back(l.slave);
      out.insert(out.end(), std::begin(l.node), std::end(l.node));
    }
  }

 private:
  struct Link {
    core::Index slave = 0;
    core::Index node[4] = {0, 0, 0, 0};
    double w[4] = {0, 0, 0, 0};
    bool rotations = false;
  };
  const core::Model& model_;
  std::vector<Link> slave_;
  std::vector<std::size_t> interface_of_;  ///< each link's tied contact (model.tied's index)
  std::vector<double> net_;                ///< each slave's f - e at the last gather, 3 per link
  std::vector<std::array<double, 3>> reaction_;
};

}  // namespace plyform::engine
