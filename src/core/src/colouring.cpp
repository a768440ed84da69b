#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <numeric>

#include "plyform/core/model.hpp"

namespace plyform::core {
namespace {

// A per-element array of a block: `per_element` values for each element.
struct PerElement {
  std::vector<double>* values;
  int per_element;
};

// Greedy colouring in element order, then a stable reorder by colour of the block's per-element
// arrays (`extras`; empty ones are left alone), filling colour_start.
template <int kNodes, class Block>
bool colour_block(Block& b, std::size_t node_count, std::initializer_list<PerElement> extras) {
  constexpr int kWords = 2;  // up to 128 colours
  const std::size_t n = b.size();
  std::vector<std::array<std::uint64_t, kWords>> used(node_count, {0, 0});
  std::vector<int> colour(n, 0);
  int colours = 0;
  for (std::size_t e = 0; e < n; ++e) {
    std::array<std::uint64_t, kWords> taken{0, 0};
    for (int i = 0; i < kNodes; ++i) {
      const auto node =
          static_cast<std::size_t>(b.connectivity[kNodes * e + static_cast<std::size_t>(i)]);
      for (int w = 0; w < kWords; ++w)
        taken[static_cast<std::size_t>(w)] |= used[node][static_cast<std::size_t>(w)];
    }
    int c = 0;
    while (c < 64 * kWords && ((taken[static_cast<std::size_t>(c / 64)] >> (c % 64)) & 1u))
      ++c;
    if (c == 64 * kWords)
      return false;
    colour[e] = c;
    colours = std::max(colours, c + 1);
    for (int i = 0; i < kNodes; ++i) {
      const auto node =
          static_cast<std::size_t>(b.connectivity[kNodes * e + static_cast<std::size_t>(i)]);
      used[node][static_cast<std::size_t>(c / 64)] |= std::uint64_t{1} << (c % 64);
    }
  }
  // Stable reorder by colour (element order kept inside a colour, for locality).
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t c) { return colour[a] < colour[c]; });
  std::vector<GlobalId> ids(n);
  std::vector<Index> conn(kNodes * n);
  for (const PerElement& x : extras) {
    if (x.values->empty())
      continue;
    const auto per = static_cast<std::size_t>(x.per_element);
    std::vector<double> values(x.values->size());
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t j = 0; j < per; ++j)
        values[per * k + j] = (*x.values)[per * order[k] + j];
    }
    *x.values = std::move(values);
  }
  for (std::size_t k = 0; k < n; ++k) {
    ids[k] = b.element_id[order[k]];
    for (int i = 0; i < kNodes; ++i) {
      conn[kNodes * k + static_cast<std::size_t>(i)] =
          b.connectivity[kNodes * order[k] + static_cast<std::size_t>(i)];
    }
  }
  b.element_id = std::move(ids);
  b.connectivity = std::move(conn);
  b.colour_start.assign(static_cast<std::size_t>(colours) + 1, 0);
  for (std::size_t e = 0; e < n; ++e)
    ++b.colour_start[static_cast<std::size_t>(colour[e]) + 1];
  for (std::size_t c = 1; c < b.colour_start.size(); ++c)
    b.colour_start[c] += b.colour_start[c - 1];
  return true;
}

}  // namespace

bool colour_element_blocks(Model& model) {
  for (SolidBlock& b : model.solid_blocks) {
    if (!colour_block<8>(b, model.node_count(), {}))
      return false;
  }
  for (ShellBlock& b : model.shell_blocks) {
    if (!colour_block<4>(b, model.node_count(), {{&b.thickness, 4}, {&b.material_angle, 1}}))
      return false;
  }
  return true;
}

namespace {

template <std::size_t kNodes, class Block>
bool block_is_independent(const Block& b, std::size_t node_count, std::vector<std::size_t>& seen) {
  const std::size_t n = b.size();
  if (b.colour_start.empty())
    return n == 0;
  if (b.colour_start.front() != 0 || b.colour_start.back() != n ||
      !std::is_sorted(b.colour_start.begin(), b.colour_start.end()))
    return false;
  for (std::size_t c = 0; c + 1 < b.colour_start.size(); ++c) {
    for (std::size_t e = b.colour_start[c]; e < b.colour_start[c + 1]; ++e) {
      for (std::size_t i = 0; i < kNodes; ++i) {
        const Index node = b.connectivity[kNodes * e + i];
        if (node < 0 || static_cast<std::size_t>(node) >= node_count)
          return false;
        // A triangle repeats its third node within the element: only other elements count.
        std::size_t& mark = seen[static_cast<std::size_t>(node)];
        if (mark == e + 1)
          continue;
        if (mark > b.colour_start[c])  // an earlier element of this colour (marks are e + 1)
          return false;
        mark = e + 1;
      }
    }
  }
  return true;
}

}  // namespace

bool colouring_is_independent(const Model& model) {
  std::vector<std::size_t> seen;
  for (const SolidBlock& b : model.solid_blocks) {
    seen.assign(model.node_count(), 0);
    if (!block_is_independent<8>(b, model.node_count(), seen))
      return false;
  }
  for (const ShellBlock& b : model.shell_blocks) {
    seen.assign(model.node_count(), 0);
    if (!block_is_independent<4>(b, model.node_count(), seen))
      return false;
  }
  return true;
}

}  // namespace plyform::core
