#pragma once
// Sums over large index ranges whose value does not depend on the number of threads: the range
// is cut into fixed chunks, each summed in order (in parallel), then the chunk sums in order.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "plyform/core/types.hpp"

namespace plyform::engine {

/// The nodes of one chunk of a sum: many chunks balance the threads on small models too.
inline constexpr std::size_t kSumChunk = 1024;

/// N sums in `chunks` chunks: chunk(c, acc) adds chunk c's contributions to acc in order; the
/// chunks run in parallel, then their sums are added in order.
template <std::size_t N, class Chunk>
std::array<double, N> sum_chunks(std::size_t chunks, Chunk&& chunk) {
  // The chunks' sums, kept between calls (each instantiation its own; called outside parallel
  // regions) so that the cycle does not allocate.
  thread_local std::vector<std::array<double, N>> scratch;
  if (scratch.size() < chunks)
    scratch.resize(chunks);
  // The calling thread's buffer, by pointer: inside the parallel loop the name `scratch` would
  // be each worker's own (empty) copy.
  std::array<double, N>* const partial = scratch.data();
  // One chunk: the team would have nothing to share (its start and join cost microseconds).
#pragma omp parallel for schedule(static) proc_bind(close) if (chunks > 1)
  for (long c = 0; c < static_cast<long>(chunks); ++c) {
    std::array<double, N> acc{};
    chunk(static_cast<std::size_t>(c), acc);
    partial[c] = acc;
  }
  std::array<double, N> total{};
  for (std::size_t c = 0; c < chunks; ++c)
    for (std::size_t k = 0; k < N; ++k)
      total[k] += partial[c][k];
  return total;
}

/// N sums at once: term(i, acc) adds node i's contributions to acc[0..N-1]. The loop body may
/// also update per-node state (each i is visited exactly once), which lets one pass over the
/// nodes both advance them and accumulate energies.
template <std::size_t N, class F>
std::array<double, N> deterministic_sums(std::size_t n, F&& term) {
  return sum_chunks<N>((n + kSumChunk - 1) / kSumChunk,
                       [&](std::size_t c, std::array<double, N>& acc) {
                         const std::size_t b = c * kSumChunk;
                         const std::size_t e = b + kSumChunk < n ? b + kSumChunk : n;
                         for (std::size_t i = b; i < e; ++i)
                           term(i, acc);
                       });
}

/// The same sums over some of the nodes: `nodes` increasing, chunk_start[c] the place in `nodes`
/// of the first node of chunk c (nodes c * kSumChunk onwards), chunk_start.back() = its size.
/// Each chunk sums its listed nodes in order, then the chunks in order: where the nodes left
/// out add only zeros (+0 or -0), the sums are bit for bit those over every node.
template <std::size_t N, class F>
std::array<double, N> deterministic_sums_over(std::span<const core::Index> nodes,
                                              std::span<const std::size_t> chunk_start, F&& term) {
  return sum_chunks<N>(chunk_start.size() - 1, [&](std::size_t c, std::array<double, N>& acc) {
    for (std::size_t j = chunk_start[c]; j < chunk_start[c + 1]; ++j)
      term(static_cast<std::size_t>(nodes[j]), acc);
  });
}

template <class F>
double deterministic_sum(std::size_t n, F&& term) {
  return deterministic_sums<1>(
      n, [&](std::size_t i, std::array<double, 1>& acc) { acc[0] += term(i); })[0];
}

}  // namespace plyform::engine
