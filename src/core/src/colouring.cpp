#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>

#include "plyform/core/model.hpp"

namespace plyform::core {

bool colour_solid_blocks(Model& model) {
  constexpr int kWords = 2;  // up to 128 colours
  for (SolidBlock& b : model.solid_blocks) {
    const std::size_t n = b.size();
    std::vector<std::array<std::uint64_t, kWords>> used(model.node_count(), {0, 0});
    std::vector<int> colour(n, 0);
    int colours = 0;
    for (std::size_t e = 0; e < n; ++e) {
      std::array<std::uint64_t, kWords> taken{0, 0};
      for (int i = 0; i < 8; ++i) {
        const auto node =
            static_cast<std::size_t>(b.connectivity[8 * e + static_cast<std::size_t>(i)]);
        for (int w = 0; w < kWords; ++w)
          taken[w] |= used[node][w];
      }
      int c = 0;
      while (c < 64 * kWords && (taken[c / 64] >> (c % 64) & 1u))
        ++c;
      if (c == 64 * kWords)
        return false;
      colour[e] = c;
      colours = std::max(colours, c + 1);
      for (int i = 0; i < 8; ++i) {
        const auto node =
            static_cast<std::size_t>(b.connectivity[8 * e + static_cast<std::size_t>(i)]);
        used[node][c / 64] |= std::uint64_t{1} << (c % 64);
      }
    }
    // Stable reorder by colour (element order kept inside a colour, for locality).
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t c) { return colour[a] < colour[c]; });
    std::vector<GlobalId> ids(n);
    std::vector<Index> conn(8 * n);
    for (std::size_t k = 0; k < n; ++k) {
      ids[k] = b.element_id[order[k]];
      for (int i = 0; i < 8; ++i) {
        conn[8 * k + static_cast<std::size_t>(i)] =
            b.connectivity[8 * order[k] + static_cast<std::size_t>(i)];
      }
    }
    b.element_id = std::move(ids);
    b.connectivity = std::move(conn);
    b.colour_start.assign(static_cast<std::size_t>(colours) + 1, 0);
    for (std::size_t e = 0; e < n; ++e)
      ++b.colour_start[static_cast<std::size_t>(colour[e]) + 1];
    for (std::size_t c = 1; c < b.colour_start.size(); ++c)
      b.colour_start[c] += b.colour_start[c - 1];
  }
  return true;
}

}  // namespace plyform::core
