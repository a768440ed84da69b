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

// Spreads the low 21 bits of v over every third bit (a Morton code's one axis).
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

// Each element's tile on a Morton curve through the block's box (by its nodes' mean position).
template <int kNodes, class Block>
std::vector<std::uint64_t> morton_keys(const Block& b, const Model& m) {
  const std::size_t n = b.size();
  std::vector<std::array<double, 3>> centre(n);
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (std::size_t e = 0; e < n; ++e) {
    std::array<double, 3> c{0.0, 0.0, 0.0};
    for (int i = 0; i < kNodes; ++i) {
      const auto node =
          static_cast<std::size_t>(b.connectivity[kNodes * e + static_cast<std::size_t>(i)]);
      c[0] += m.x0[node];
      c[1] += m.y0[node];
      c[2] += m.z0[node];
    }
    for (std::size_t d = 0; d < 3; ++d) {
      c[d] /= kNodes;
      lo[d] = std::min(lo[d], c[d]);
      hi[d] = std::max(hi[d], c[d]);
    }
    centre[e] = c;
  }
  // One scale for the three axes, so that the curve's cells are cubes.
  const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
  const double cells = static_cast<double>((1u << 21) - 1);
  std::vector<std::uint64_t> key(n);
  for (std::size_t e = 0; e < n; ++e) {
    std::uint64_t k = 0;
    for (std::size_t d = 0; d < 3; ++d) {
      const auto cell = static_cast<std::uint64_t>((centre[e][d] - lo[d]) / span * cells);
      k |= spread_bits(cell) << d;
    }
    key[e] = k;
  }
  // Coarsened to tiles of about kTile elements (of every colour): within a tile the elements
  // keep the mesher's order, whose neighbours share nodes (a finer curve cost the 100 x 100 plate
  // 1.5-2 % on one thread).
  constexpr std::size_t kTile = 256;
  std::vector<std::uint64_t> sorted = key;
  std::sort(sorted.begin(), sorted.end());
  int shift = 0;
  for (; shift < 63; shift += 3) {
    std::size_t tiles = 0;
    for (std::size_t e = 0; e < n; ++e)
      tiles += e == 0 || (sorted[e] >> shift) != (sorted[e - 1] >> shift) ? 1 : 0;
    if (tiles * kTile <= n)
      break;
  }
  for (std::uint64_t& k : key)
    k >>= shift;
  return key;
}

// Greedy colouring in element order, then a reorder by colour of the block's per-element arrays
// (`extras`; empty ones are left alone), filling colour_start. Within a colour the elements go
// tile by tile along a Morton curve through the block (in element order within a tile): a run
// of a colour's elements is then a compact patch of the part, which keeps a work item's nodes close
// together and lets a domain of a run over MPI ranks take whole items (docs/parallel.md). The
// colours themselves, and with them the order in which each node sums its elements' forces,
// follow from the element order alone.
template <int kNodes, class Block>
bool colour_block(Block& b, const Model& m, std::initializer_list<PerElement> extras) {
  const std::size_t node_count = m.node_count();
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
  const std::vector<std::uint64_t> key = morton_keys<kNodes>(b, m);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) {
    return colour[a] != colour[c] ? colour[a] < colour[c] : key[a] < key[c];
  });
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
    if (!colour_block<8>(b, model, {}))
      return false;
  }
  for (ShellBlock& b : model.shell_blocks) {
    if (!colour_block<4>(b, model, {{&b.thickness, 4}, {&b.material_angle, 1}}))
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
