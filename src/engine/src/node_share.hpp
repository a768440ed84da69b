#pragma once
// Over several ranks, the nodes each rank moves itself (docs/parallel.md, "Nodes").
//
// A rank computes every element around the nodes it owns (rank_exchange.hpp), so it needs the
// positions and velocities of those elements' nodes, and of no other, to compute its share of
// the next cycle: its own nodes and a ring of its neighbours' (ghost nodes). It moves exactly
// those, with the forces it computed for its own and, for each ghost node, the force its owner
// computed (complete there), received from that neighbour after the element loop. The nodes
// that the passes every rank runs whole read (the constrained and loaded nodes, the rigid
// bodies' nodes, nodes no element touches) every rank moves, their forces from their owners
// likewise. Every node's motion is then computed by the same arithmetic on the same numbers as
// on one rank, so the files do not change with the rank count; before anything reads every node
// (the outputs, the energy books, a checkpoint, a new split) the owners hand their nodes' state
// to every rank.

#include <cstddef>
#include <span>
#include <vector>

#include "plyform/comm/communicator.hpp"
#include "plyform/core/model.hpp"
#include "work_items.hpp"

namespace plyform::engine {

/// One rank's lists (NodeShare), computed from the split alone: every rank computes its own, and
/// a test every rank's.
struct NodeLists {
  /// The nodes the rank moves, increasing.
  std::vector<core::Index> nodes;
  /// For the sums over `nodes` in fixed chunks of node numbers (deterministic_sum.hpp): the place
  /// in `nodes` where each chunk's nodes begin, and one past the last.
  std::vector<std::size_t> chunk_start;
  std::size_t chunk = 0;  ///< nodes per chunk
  /// The exchange, by rank, each rank's part increasing: sent[send_start[q] .. send_start[q + 1])
  /// are this rank's nodes that rank q moves; received likewise rank q's nodes this rank moves.
  std::vector<core::Index> sent, received;
  std::vector<std::size_t> send_start, receive_start;
  /// Every owned node by owner, as `sent`.
  std::vector<core::Index> owned;
  std::vector<std::size_t> owned_start;
};

/// Rank `me`'s lists of a split over `ranks` ranks. `node_owner`: per node, the rank that owns it
/// (-1: no deformable element touches it); `everywhere`: the nodes every rank moves (any order,
/// repeats allowed).
[[nodiscard]] NodeLists node_lists(const core::Model& model,
                                   const std::vector<std::vector<WorkItem>>& phases,
                                   std::span<const int> node_owner,
                                   std::span<const core::Index> everywhere, int me, int ranks);

class NodeShare {
 public:
  /// This rank's lists (node_lists) of the split `node_owner`.
  NodeShare(const core::Model& model, const std::vector<std::vector<WorkItem>>& phases,
            std::span<const int> node_owner, std::span<const core::Index> everywhere,
            const comm::Communicator& comm);

  /// The nodes this rank moves, increasing.
  [[nodiscard]] const std::vector<core::Index>& nodes() const { return lists_.nodes; }
  /// NodeLists::chunk_start.
  [[nodiscard]] const std::vector<std::size_t>& chunk_start() const { return lists_.chunk_start; }

  /// After the element loop: each node this rank moves and another owns gets the owner's values
  /// of `fields` (arrays over the nodes), from that neighbour.
  void exchange(std::span<double* const> fields);

  /// An array over the nodes with `stride` values per node.
  struct Field {
    double* data;
    std::size_t stride;
  };
  /// Every owned node's values of `fields` from its owner to every rank.
  void gather(std::span<const Field> fields);

 private:
  const comm::Communicator* comm_;
  NodeLists lists_;
  std::vector<std::size_t> send_counts_, receive_counts_;
  std::vector<double> send_, receive_;
};

}  // namespace plyform::engine
