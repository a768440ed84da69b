// The element loop's phases (work_items.hpp): the items of one phase run in parallel and add
// their forces straight to the nodes, so no two of them may share a node; every element of every
// deformable block is computed once a cycle; a rigid block not at all. Blocks that share no node
// (each layer of a sandwich its own mesh) run their colours in the same phases, so a cycle waits
// for its threads as many times as one block has colours, not their sum; blocks that share
// nodes keep apart.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "layered_models.hpp"
#include "plyform/core/model.hpp"
#include "work_items.hpp"

namespace plyform::engine {
namespace {

std::size_t colours_of(const core::ShellBlock& b) {
  return b.colour_start.empty() ? 0 : b.colour_start.size() - 1;
}

// What every phase list must be: each element of each deformable block once, none of a rigid
// one, no node shared by two items of a phase, and within a phase the items in block order.
void expect_sound(const core::Model& model, const std::vector<std::vector<WorkItem>>& phases) {
  std::map<std::pair<std::size_t, std::size_t>, int> computed;  // (block, element) -> times
  for (const auto& phase : phases) {
    std::map<core::Index, std::pair<std::size_t, std::size_t>> user;  // node -> (item, block)
    std::size_t last_block = 0;
    for (std::size_t w = 0; w < phase.size(); ++w) {
      const WorkItem& it = phase[w];
      ASSERT_TRUE(it.shell);
      EXPECT_GE(it.block, last_block) << "items in block order";
      last_block = it.block;
      for (std::size_t e = it.begin; e < it.end; ++e) {
        ++computed[{it.block, e}];
        for (const core::Index n : element_nodes(model, it, e)) {
          const auto [at, fresh] = user.emplace(n, std::make_pair(w, it.block));
          EXPECT_TRUE(fresh || at->second.first == w)
              << "node " << n << " in items " << at->second.first << " and " << w;
        }
      }
    }
  }
  for (std::size_t b = 0; b < model.shell_blocks.size(); ++b) {
    const core::ShellBlock& blk = model.shell_blocks[b];
    const bool rigid = std::holds_alternative<core::RigidMaterial>(
        model.materials[static_cast<std::size_t>(blk.material)]);
    for (std::size_t e = 0; e < blk.element_id.size(); ++e) {
      const auto at = computed.find({b, e});
      EXPECT_EQ(at == computed.end() ? 0 : at->second, rigid ? 0 : 1)
          << "block " << b << " element " << e;
    }
  }
}

TEST(ElementLoopPhases, LayersOfASandwichShareTheirPhases) {
  core::Model model = test::layered_blank({.nx = 12, .ny = 10});  // three layers and a tool
  ASSERT_TRUE(core::colour_element_blocks(model));
  const auto phases = make_phases(model);
  expect_sound(model, phases);
  std::size_t most = 0;
  for (std::size_t b = 0; b < 3; ++b)
    most = std::max(most, colours_of(model.shell_blocks[b]));
  EXPECT_EQ(phases.size(), most);  // not the sum of the layers' colours
  std::set<std::size_t> blocks;
  for (const WorkItem& it : phases.front())
    blocks.insert(it.block);
  EXPECT_EQ(blocks, (std::set<std::size_t>{0, 1, 2}));
}

TEST(ElementLoopPhases, BlocksThatShareNodesKeepApart) {
  // One mesh cut into two blocks along a row of nodes (A, B), and a mesh of its own (C).
  core::Model model;
  model.materials.push_back(core::ElasticMaterial{});
  core::ShellBlock whole;
  test::add_layer_mesh(model, whole, 8, 6, 1.0, 0.0, 0.0, 0.0, 1.0);
  core::ShellBlock a, b, c;
  const std::size_t half = whole.element_id.size() / 2;  // rows 0-2 and rows 3-5
  for (std::size_t e = 0; e < whole.element_id.size(); ++e) {
    core::ShellBlock& to = e < half ? a : b;
    to.element_id.push_back(whole.element_id[e]);
    for (std::size_t k = 0; k < 4; ++k) {
      to.connectivity.push_back(whole.connectivity[4 * e + k]);
      to.thickness.push_back(whole.thickness[4 * e + k]);
    }
  }
  test::add_layer_mesh(model, c, 5, 5, 1.0, 3.0, 0.0, 0.0, 1.0);
  for (core::ShellBlock* blk : {&a, &b, &c}) {
    blk->material = 0;
    model.shell_blocks.push_back(std::move(*blk));
  }
  ASSERT_TRUE(core::colour_element_blocks(model));
  const auto phases = make_phases(model);
  expect_sound(model, phases);
  // A and C together, B on its own.
  EXPECT_EQ(phases.size(),
            std::max(colours_of(model.shell_blocks[0]), colours_of(model.shell_blocks[2])) +
                colours_of(model.shell_blocks[1]));
  for (const auto& phase : phases) {
    std::set<std::size_t> blocks;
    for (const WorkItem& it : phase)
      blocks.insert(it.block);
    EXPECT_FALSE(blocks.count(0) != 0 && blocks.count(1) != 0) << "blocks 0 and 1 share nodes";
  }
}

}  // namespace
}  // namespace plyform::engine
