#pragma once
// A run over several MPI ranks (docs/parallel.md), as built today: every rank holds the whole
// model and state; the element loop is shared out here, the contact's work per slave node by
// contact::ContactSet::share_slaves, and every other pass runs on every rank as one rank would.
// A node's forces are complete on the rank that owns it (the split's owner,
// domain::Decomposition), which computes every element around it: its own domain's and, once
// more, those of its neighbours that touch its nodes. The owners then hand their nodes' forces,
// moments and plastic work to every rank; each work item's books come whole from the rank that
// computed all of it, or as its elements' shares from the ranks that report them (the lowest
// owner among an element's nodes), with the shells' thickness where the contact or the heat
// reads it.
//
// Why the results do not depend on the rank count, bit for bit: within one colour of a block no
// two elements share a node, so a node receives one contribution per colour and sums them in the
// colours' order, whichever rank computed them and in whatever order within the colour; a work
// item's books are those its kernel call sums on one rank, or summed again from its elements'
// shares (element::ElementBooks) in the item's order; the smallest step and the first failure
// are chosen by value, then by place in the loop. Every other pass runs on the same numbers on
// every rank.

#include <cstddef>
#include <span>
#include <vector>

#include "plyform/comm/communicator.hpp"
#include "plyform/core/model.hpp"
#include "plyform/element/shell_kernels.hpp"
#include "plyform/element/solid_kernels.hpp"
#include "work_items.hpp"

namespace plyform::engine {

/// A part of a work item this rank computes: the item's place in its phase, and the elements.
struct ItemPiece {
  std::size_t item = 0;
  WorkItem range;
};

/// A kernel call's books (the six sums of element::ElementBooks over its range).
using RangeBooks = element::ElementBooks;

/// What a rank reports of its share of the element loop, to be chosen among the ranks.
struct RankElementReport {
  double dt_min = 1e300;
  std::size_t dt_phase = 0, dt_item = 0, dt_element = 0;
  bool failed = false, unsupported_material = false;
  std::size_t failed_phase = 0, failed_item = 0, failed_element = 0;
};

class RankExchange {
 public:
  /// `node_owner`: per node, the rank that owns it, -1 for a node no deformable element touches.
  RankExchange(const core::Model& model, const std::vector<std::vector<WorkItem>>& phases,
               std::span<const int> node_owner, const comm::Communicator& comm);

  /// Per phase, the pieces of its items this rank computes (in the items' order).
  [[nodiscard]] const std::vector<std::vector<ItemPiece>>& pieces() const { return pieces_; }
  /// The books of every element of a block, this rank's written by its kernels, the others'
  /// received (gather_elements).
  [[nodiscard]] element::ElementBooks* books(bool shell, std::size_t block) {
    return (shell ? shell_books_ : solid_books_)[block].data();
  }
  [[nodiscard]] const element::ElementBooks* books(bool shell, std::size_t block) const {
    return (shell ? shell_books_ : solid_books_)[block].data();
  }
  /// Elements this rank computes, summed over the blocks (its own and the ones around its nodes).
  [[nodiscard]] std::size_t computed_elements() const { return computed_; }

  /// After the element loop: each owned node's values of `fields` (arrays over the nodes) from
  /// its owner to every rank.
  void gather_nodes(std::span<double* const> fields);
  /// After the element loop: every work item's books on every rank, and with `thickness` each
  /// shell's thickness (which the contact's offsets and the thermal step read every cycle), from
  /// the elements' reporting ranks. An item whose elements all report to one rank comes as that
  /// rank's piece's sums (`piece_books`, per phase and piece); the others as their elements'
  /// books, summed here in the item's order. Every rank's report of its pieces travels with
  /// them (one collective): returns the chosen step and failure (by value, then place).
  RankElementReport gather_elements(const std::vector<std::vector<RangeBooks>>& piece_books,
                                    std::vector<element::ShellBlockState>& shells, bool thickness,
                                    const RankElementReport& mine);
  /// Per phase and item, its books after gather_elements.
  [[nodiscard]] const std::vector<std::vector<RangeBooks>>& item_books() const {
    return item_books_;
  }
  /// Before the states, the element histories, the end's files and a checkpoint are written:
  /// every element's whole state from its reporting rank, so that every rank holds the state a
  /// run on one rank would.
  void gather_element_state(std::vector<element::ShellBlockState>& shells,
                            std::vector<element::SolidBlockState>& solids);

 private:
  struct ElementRef {
    bool shell;
    std::size_t block, element;
  };
  const comm::Communicator* comm_;
  std::vector<std::vector<WorkItem>> phases_;
  std::vector<std::vector<ItemPiece>> pieces_;
  std::vector<std::vector<element::ElementBooks>> shell_books_, solid_books_;
  std::size_t computed_ = 0;
  // Nodes by owner: owned_[owned_start_[r] .. owned_start_[r + 1]) are rank r's, increasing.
  std::vector<core::Index> owned_;
  std::vector<std::size_t> owned_start_;
  // Elements by reporting rank, likewise (blocks in the loop's order, elements increasing).
  std::vector<ElementRef> reported_;
  std::vector<std::size_t> reported_start_;
  // Per phase and item: the rank all its elements report to, or -1 (an item across domains).
  std::vector<std::vector<int>> item_rank_;
  // This rank's whole items: (phase, item, its piece in pieces_[phase]).
  struct WholeItem {
    std::size_t phase, item, piece;
  };
  std::vector<WholeItem> my_whole_;
  // Per rank, its whole items and its elements in items across domains (each in the loop's
  // order): what it sends of the books.
  std::vector<std::pair<std::size_t, std::size_t>> whole_;  // (phase, item), by rank
  std::vector<std::size_t> whole_start_;
  std::vector<std::size_t> reported_shells_;  // per rank, the shells among its elements
  std::vector<ElementRef> split_;             // by reporting rank, as reported_
  std::vector<std::size_t> split_start_;
  std::vector<std::vector<RangeBooks>> item_books_;
  std::vector<double> send_, receive_;
};

}  // namespace plyform::engine
