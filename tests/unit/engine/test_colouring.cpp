// The element colouring's invariant (core::colouring_is_independent): after setup's greedy
// colouring of a plate no two elements of a colour share a node; two elements of a colour on
// the same nodes, a node index out of range or colour ranges that miss an element break it.
#include <gtest/gtest.h>

#include "plyform/core/model.hpp"
#include "shell_models.hpp"

namespace plyform {
namespace {

TEST(Colouring, GreedyColouringIsIndependentAndBreakagesAreFound) {
  core::Model m = test::plate(4.0, 3.0, 4, 3, 0.1, core::ElasticMaterial{7.85e-9, 2.1e5, 0.3});
  ASSERT_TRUE(core::colouring_is_independent(m));
  core::ShellBlock& b = m.shell_blocks[0];
  ASSERT_GE(b.colour_start.size(), 3u);  // at least two colours
  ASSERT_GE(b.colour_start[1], 2u);      // colour 0 holds at least two elements
  // The second element of colour 0 on the first one's nodes: two elements of a colour share
  // nodes.
  {
    core::Model broken = m;
    core::ShellBlock& c = broken.shell_blocks[0];
    for (std::size_t i = 0; i < 4; ++i)
      c.connectivity[4 + i] = c.connectivity[i];
    EXPECT_FALSE(core::colouring_is_independent(broken));
  }
  {
    core::Model broken = m;
    broken.shell_blocks[0].connectivity[0] = static_cast<core::Index>(m.node_count());
    EXPECT_FALSE(core::colouring_is_independent(broken));
  }
  {
    core::Model broken = m;
    broken.shell_blocks[0].colour_start.back() -= 1;  // the ranges no longer cover the block
    EXPECT_FALSE(core::colouring_is_independent(broken));
  }
}

}  // namespace
}  // namespace plyform
