#pragma once
// A pass's slave nodes over several MPI ranks (docs/parallel.md): each rank runs the kinematics,
// the law and the forces of the slave nodes it owns (the owner of the node in the model's split;
// a rigid body's node by its place in the pass), while the search, the normals, the scatter and
// the books run whole on every rank. After the forces, what the scatter and the books read of
// each slave node goes from its owner to every rank; the rest of a node's state (its law's
// history, gap, frame, tractions) only when something reads the whole pass (reports, heat, the
// checkpoint): gather_state.

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "pass_runtime.hpp"
#include "plyform/comm/communicator.hpp"

namespace plyform::contact {

class SlaveShare {
 public:
  /// `owner`: per slave node of the pass, its rank.
  SlaveShare(const comm::Communicator& comm, const std::vector<int>& owner);

  /// 1 for the slave nodes this rank handles.
  [[nodiscard]] const std::vector<unsigned char>& mine() const { return mine_; }

  /// After the forces of every pass: each slave node's segment, side, force, normal, surface
  /// point, shape weights and its step's work and surface book, from its owner to every rank,
  /// for the passes marked `active` (the same on every rank), in one all-gather. A node whose
  /// force and books are +0 is not sent: the others set them to +0 (its segment, weights and
  /// frame then wait for gather_state, as nothing but its owner reads them before).
  static void exchange_cycle(std::vector<std::unique_ptr<SlaveShare>>& shares,
                             std::vector<std::unique_ptr<PassRuntime>>& passes,
                             const std::vector<unsigned char>& active);
  /// Every slave node's whole state (PassState's per-node arrays and the law's history) from its
  /// owner to every rank.
  void gather_state(PassRuntime& pr);

 private:
  const comm::Communicator* comm_;
  std::vector<unsigned char> mine_;
  std::vector<std::size_t> owned_;  // slave nodes by owner: owned_[owned_start_[r] ..)
  std::vector<std::size_t> owned_start_;
  std::vector<std::byte> send_bytes_, receive_bytes_;
};

}  // namespace plyform::contact
