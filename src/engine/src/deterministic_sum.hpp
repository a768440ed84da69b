#pragma once
// Sums over large index ranges whose value does not depend on the number of threads: the range
// is cut into fixed chunks, each summed in order (in parallel), then the chunk sums in order.

#include <cstddef>
#include <vector>

namespace plyform::engine {

template <class F>
double deterministic_sum(std::size_t n, F&& term) {
  constexpr std::size_t kChunk = 4096;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<double> partial(chunks, 0.0);
#pragma omp parallel for schedule(static)
  for (long c = 0; c < static_cast<long>(chunks); ++c) {
    const std::size_t b = static_cast<std::size_t>(c) * kChunk;
    const std::size_t e = b + kChunk < n ? b + kChunk : n;
    double s = 0.0;
    for (std::size_t i = b; i < e; ++i)
      s += term(i);
    partial[static_cast<std::size_t>(c)] = s;
  }
  double total = 0.0;
  for (double p : partial)
    total += p;
  return total;
}

}  // namespace plyform::engine
