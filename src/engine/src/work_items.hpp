#pragma once
// The element loop's units of parallel work: each block's colours cut into ranges of elements
// (simulation.cpp runs them; rank_exchange.hpp shares them out over the ranks of a run).

#include <algorithm>
#include <cstddef>
#include <cstdint>
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

// The items of each colour of each deformable block, in block order: colours[b][c] the items of
// colour c of the b-th block listed (solids first, then shells).
template <class Block>
void add_block_colours(const core::Model& model, const std::vector<Block>& blocks, bool shell,
                       std::vector<std::vector<std::vector<WorkItem>>>& colours) {
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
    std::vector<std::vector<WorkItem>> block_colours;
    const std::vector<std::size_t>& start = blocks[b].colour_start;
    for (std::size_t c = 0; c + 1 < start.size(); ++c) {
      std::vector<WorkItem> items;
      const std::size_t item = item_size(start[c + 1] - start[c]);
      for (std::size_t e = start[c]; e < start[c + 1]; e += item)
        items.push_back({shell, b, e, std::min(start[c + 1], e + item)});
      if (!items.empty())
        block_colours.push_back(std::move(items));
    }
    colours.push_back(std::move(block_colours));
  }
}

/// The element loop's phases. Blocks that share no node (each layer of a sandwich its own mesh,
/// a blank and a tool) run their colours in the same phases: colour c of every such block
/// together, so that a cycle has as many phases (each ending where the threads wait for one
/// another) as the most colours of one block, not their sum, and each phase has the items of
/// every block to share out (the hot deep drawing's three layers: 4 phases of 17-18 items
/// instead of 12 of 3-7). A block that shares nodes with an earlier one starts a group of its
/// own. Within a phase the items stay in block order, so each block's books sum as before, and
/// the order depends on the model only, never on the thread or rank count.
inline std::vector<std::vector<WorkItem>> make_phases(const core::Model& model) {
  std::vector<std::vector<std::vector<WorkItem>>> colours;  // per block listed, per colour
  add_block_colours(model, model.solid_blocks, false, colours);
  add_block_colours(model, model.shell_blocks, true, colours);
  // Groups of blocks that share no node. Each node carries the groups whose blocks use it, one
  // bit each, for the first 64 groups; a block that touches all of those (a model of more than
  // 64 parts that all share nodes) makes a group of its own (from the 65th on) that no later
  // block joins.
  constexpr std::size_t kMarked = 64;
  std::vector<std::uint64_t> node_groups(model.node_count(), 0);
  std::vector<std::vector<std::size_t>> groups;  // indices into colours
  for (std::size_t i = 0; i < colours.size(); ++i) {
    if (colours[i].empty())
      continue;
    const WorkItem& any = colours[i].front().front();
    const std::vector<core::Index>& connectivity = any.shell
                                                       ? model.shell_blocks[any.block].connectivity
                                                       : model.solid_blocks[any.block].connectivity;
    std::uint64_t touched = 0;
    for (const core::Index n : connectivity)
      touched |= node_groups[static_cast<std::size_t>(n)];
    std::size_t g = 0;
    while (g < groups.size() && (g >= kMarked || (touched >> g & 1u) != 0))
      ++g;
    if (g == groups.size())
      groups.emplace_back();
    groups[g].push_back(i);
    if (g < kMarked)
      for (const core::Index n : connectivity)
        node_groups[static_cast<std::size_t>(n)] |= std::uint64_t{1} << g;
  }
  std::vector<std::vector<WorkItem>> phases;
  for (const std::vector<std::size_t>& group : groups) {
    std::size_t most = 0;
    for (const std::size_t i : group)
      most = std::max(most, colours[i].size());
    for (std::size_t c = 0; c < most; ++c) {
      std::vector<WorkItem> phase;
      for (const std::size_t i : group)
        if (c < colours[i].size())
          phase.insert(phase.end(), colours[i][c].begin(), colours[i][c].end());
      phases.push_back(std::move(phase));
    }
  }
  return phases;
}

}  // namespace plyform::engine
