// The nodes each rank moves over several ranks (node_share.hpp), checked against what the run's
// bit-identity needs, recomputed here by brute force from METIS's split of a three-layer blank:
// every node of every element a rank computes is moved by that rank; the nodes no element
// touches and the nodes every pass reads are moved by every rank; what a rank sends a neighbour
// is exactly what the neighbour expects from it, node for node; a rank receives every node it
// moves and does not own, from its owner; the chunks of the sums hold their own nodes.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "layered_models.hpp"
#include "node_share.hpp"
#include "plyform/core/model.hpp"
#include "plyform/domain/decomposition.hpp"
#include "work_items.hpp"

namespace plyform::engine {
namespace {

class NodeListsOfASplit : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    ASSERT_TRUE(core::colour_element_blocks(model));
    phases = make_phases(model);
    const domain::DecomposeResult r = domain::decompose(model, GetParam());
    ASSERT_TRUE(r.error.empty()) << r.error;
    owner = r.decomposition.node_owner;
    // A loose node (no element) and two nodes the whole passes read.
    model.node_id.push_back(static_cast<core::GlobalId>(model.node_count() + 1));
    model.x0.push_back(0.0);
    model.y0.push_back(0.0);
    model.z0.push_back(-5.0);
    owner.push_back(-1);
    everywhere = {0, static_cast<core::Index>(owner.size() / 2), 0};
    for (int rank = 0; rank < GetParam(); ++rank)
      lists.push_back(node_lists(model, phases, owner, everywhere, rank, GetParam()));
  }
  core::Model model = test::layered_blank({.nx = 12, .ny = 10});
  std::vector<std::vector<WorkItem>> phases;
  std::vector<int> owner;
  std::vector<core::Index> everywhere;
  std::vector<NodeLists> lists;
};

TEST_P(NodeListsOfASplit, EachRankMovesTheNodesOfEveryElementItComputes) {
  const int ranks = GetParam();
  for (int r = 0; r < ranks; ++r) {
    const std::set<core::Index> moved(lists[r].nodes.begin(), lists[r].nodes.end());
    EXPECT_TRUE(std::is_sorted(lists[r].nodes.begin(), lists[r].nodes.end()));
    EXPECT_EQ(moved.size(), lists[r].nodes.size()) << "a node listed twice";
    std::size_t computed = 0;
    for (const auto& phase : phases) {
      for (const WorkItem& it : phase) {
        for (std::size_t e = it.begin; e < it.end; ++e) {
          const auto nodes = element_nodes(model, it, e);
          const bool mine = std::any_of(nodes.begin(), nodes.end(), [&](core::Index i) {
            return owner[static_cast<std::size_t>(i)] == r;
          });
          if (!mine)
            continue;
          ++computed;
          for (const core::Index i : nodes)
            EXPECT_TRUE(moved.count(i)) << "rank " << r << " computes an element of node " << i;
        }
      }
    }
    EXPECT_GT(computed, 0u);
    for (std::size_t i = 0; i < owner.size(); ++i) {
      if (owner[i] < 0 ||
          std::count(everywhere.begin(), everywhere.end(), static_cast<core::Index>(i)) > 0) {
        EXPECT_TRUE(moved.count(static_cast<core::Index>(i))) << "rank " << r << ", node " << i;
      }
    }
    if (ranks > 1) {
      EXPECT_LT(lists[r].nodes.size(), owner.size()) << "rank " << r << " moves every node";
    }
  }
}

TEST_P(NodeListsOfASplit, WhatARankSendsIsWhatItsNeighbourExpects) {
  const auto ranks = static_cast<std::size_t>(GetParam());
  for (std::size_t r = 0; r < ranks; ++r) {
    const NodeLists& a = lists[r];
    // What r receives: every node it moves that another rank owns, from that owner.
    std::vector<std::vector<core::Index>> expected(ranks);
    for (const core::Index i : a.nodes) {
      const int o = owner[static_cast<std::size_t>(i)];
      if (o >= 0 && static_cast<std::size_t>(o) != r)
        expected[static_cast<std::size_t>(o)].push_back(i);
    }
    for (std::size_t q = 0; q < ranks; ++q) {
      const std::vector<core::Index> from(a.received.begin() + a.receive_start[q],
                                          a.received.begin() + a.receive_start[q + 1]);
      EXPECT_EQ(from, expected[q]) << "rank " << r << " from " << q;
      const NodeLists& b = lists[q];
      const std::vector<core::Index> sent(b.sent.begin() + b.send_start[r],
                                          b.sent.begin() + b.send_start[r + 1]);
      EXPECT_EQ(sent, from) << "rank " << q << " to " << r;
    }
    EXPECT_EQ(a.send_start[r + 1], a.send_start[r]) << "rank " << r << " sends to itself";
  }
}

TEST_P(NodeListsOfASplit, EveryOwnedNodeIsGatheredOnceAndTheChunksHoldTheirNodes) {
  const auto ranks = static_cast<std::size_t>(GetParam());
  for (std::size_t r = 0; r < ranks; ++r) {
    const NodeLists& a = lists[r];
    for (std::size_t q = 0; q < ranks; ++q) {
      for (std::size_t j = a.owned_start[q]; j < a.owned_start[q + 1]; ++j) {
        EXPECT_EQ(owner[static_cast<std::size_t>(a.owned[j])], static_cast<int>(q));
      }
    }
    const auto owned = static_cast<std::size_t>(
        std::count_if(owner.begin(), owner.end(), [](int o) { return o >= 0; }));
    EXPECT_EQ(a.owned.size(), owned);
    ASSERT_EQ(a.chunk_start.size(), (owner.size() + a.chunk - 1) / a.chunk + 1);
    EXPECT_EQ(a.chunk_start.back(), a.nodes.size());
    for (std::size_t c = 0; c + 1 < a.chunk_start.size(); ++c) {
      for (std::size_t j = a.chunk_start[c]; j < a.chunk_start[c + 1]; ++j) {
        EXPECT_GE(static_cast<std::size_t>(a.nodes[j]), c * a.chunk);
        EXPECT_LT(static_cast<std::size_t>(a.nodes[j]), (c + 1) * a.chunk);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Ranks, NodeListsOfASplit, ::testing::Values(1, 2, 3, 4));

}  // namespace
}  // namespace plyform::engine
