#pragma once
// The element loop's units of parallel work: each block's colours cut into ranges of elements
// (simulation.cpp runs them; rank_exchange.hpp shares them out over the ranks of a run).

#include <algorithm>
#include <cstddef>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::engine {

/// The nodes of element e of a block (a triangle repeats its third node).
template <class Block>
std::span<const core::Index> element_nodes(const Block& block, std::size_t e) {
  constexpr std::size_t k = std::is_same_v<Block, core::ShellBlock> ? 4 : 8;
  return {&block.connectivity[k * e], k};
}

// A range of elements of one colour of one block: the unit of parallel work in the element
// loop. Items of one phase (block, colour) share no node and run in parallel; phases run in
// order, so each node sums its forces in the same order for any number of threads.
struct WorkItem {
  bool shell;  ///< a shell block (else a solid block)
  std::size_t block, begin, end;
};

/// The nodes of element e of a work item's block.
inline std::span<const core::Index> element_nodes(const core::Model& model, const WorkItem& it,
                                                  std::size_t e) {
  return it.shell ? element_nodes(model.shell_blocks[it.block], e)
                  : element_nodes(model.solid_blocks[it.block], e);
}

template <class Block>
void add_phases(const core::Model& model, const std::vector<Block>& blocks, bool shell,
                std::vector<std::vector<WorkItem>>& phases) {
  // Items of up to 64 elements, but at least 8 per colour where the colour allows (in steps
  // of 16, the kernels' lane width): the colours of a small part (a few hundred shells: four
  // colours of some 80) would otherwise make one or two items each, and one thread would run
  // the whole element loop while the others wait. The item size depends on the colour's size
  // only, never on the thread count, so the books sum in the same order on any thread count.
  static constexpr std::size_t kLanes = 16, kMaxItem = 64, kItemsWanted = 8;
  const auto item_size = [](std::size_t colour_size) {
    const std::size_t even = (colour_size + kItemsWanted - 1) / kItemsWanted;
    return std::clamp((even + kLanes - 1) / kLanes * kLanes, kLanes, kMaxItem);
  };
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    // Rigid parts move with their body: no internal forces, no stable step.
    if (std::holds_alternative<core::RigidMaterial>(
            model.materials[static_cast<std::size_t>(blocks[b].material)])) {
      continue;
    }
    const std::vector<std::size_t>& start = blocks[b].colour_start;
    for (std::size_t c = 0; c + 1 < start.size(); ++c) {
      std::vector<WorkItem> phase;
      const std::size_t item = item_size(start[c + 1] - start[c]);
      for (std::size_t e = start[c]; e < start[c + 1]; e += item) {
        phase.push_back({shell, b, e, std::min(start[c + 1], e + item)});
      }
      if (!phase.empty())
        phases.push_back(std::move(phase));
    }
  }
}

inline std::vector<std::vector<WorkItem>> make_phases(const core::Model& model) {
  std::vector<std::vector<WorkItem>> phases;
  add_phases(model, model.solid_blocks, false, phases);
  add_phases(model, model.shell_blocks, true, phases);
  return phases;
}

}  // namespace plyform::engine
