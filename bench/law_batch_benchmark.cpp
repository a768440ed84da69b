// Throughput of the batched contact-law update (the solver's hot loop): node-updates per
// second over host-owned arrays of 1e6 nodes in mixed states, single thread.
//
//   build/bench/bench_law_batch --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "plyform/law/law.hpp"

namespace {

using namespace plyform::law;

struct Nodes {
  std::size_t n;
  std::vector<double> gap, sx, sy, temp, kn, kt, area, mass, pressure, tx, ty, stored;
  HistoryStore history;

  Nodes(const Law& law, std::size_t count, bool damping)
      : n(count),
        gap(count),
        sx(count),
        sy(count),
        temp(count),
        kn(count, 2000.0),
        kt(count, 1000.0),
        area(count, 0.04),
        mass(count, damping ? 1e-7 : 0.0),
        pressure(count),
        tx(count),
        ty(count),
        stored(count),
        history(count) {
    // A quarter each: approaching, in contact and sliding, bonded and opening, detached;
    // shuffled so that the branches are unpredictable, as in a real contact surface.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double gc = 0.01;
    for (std::size_t i = 0; i < n; ++i) {
      const int kind = static_cast<int>(rng() % 4);
      temp[i] = 300.0 + 200.0 * u(rng);
      sx[i] = 1e-5 * (u(rng) - 0.5);
      sy[i] = 1e-5 * (u(rng) - 0.5);
      NodeHistory h = law.initial_history(0.0);
      switch (kind) {
        case 0:
          h = law.initial_history(1.0);
          gap[i] = 0.5 + u(rng);
          break;
        case 1:
          gap[i] = -1e-4 * u(rng);
          h.state = NodeState::contact;
          break;
        case 2:
          gap[i] = gc * (0.5 + 3.0 * u(rng));
          h.state = NodeState::separating;
          h.gap = gap[i];
          break;
        default:
          gap[i] = 0.1 + u(rng);
          h.state = NodeState::detached;
          h.beta = 0.0;
          break;
      }
      history.set(i, h);
    }
  }
};

Parameters parameters() {
  Parameters p;
  p.cn = 30.0;
  p.sigma_max = {0.5, 0.1, -1};
  p.t_lo = 300.0;
  p.t_hi = 500.0;
  p.eta = 1e-3;
  p.zeta = {2.0, 8.0, -1};
  p.mu = {0.3, 0.15, -1};
  p.vdc = 10.0;
  return p;
}

void run(benchmark::State& state, bool damping) {
  const Law law(parameters());
  Nodes nodes(law, static_cast<std::size_t>(state.range(0)), damping);
  const BatchInput in{
      nodes.n,         nodes.gap.data(), nodes.sx.data(),   nodes.sy.data(),   nodes.temp.data(),
      nodes.kn.data(), nodes.kt.data(),  nodes.area.data(), nodes.mass.data(), 1e-7};
  const BatchOutput out{nodes.pressure.data(), nodes.tx.data(), nodes.ty.data(),
                        nodes.stored.data()};
  const BatchHistory h = nodes.history.view();
  for (auto _ : state) {
    law.update_batch(in, h, out);
    benchmark::DoNotOptimize(nodes.pressure.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["node_updates_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * state.range(0)), benchmark::Counter::kIsRate);
}

void BM_LawBatch(benchmark::State& state) {
  run(state, false);
}
void BM_LawBatchDamped(benchmark::State& state) {
  run(state, true);
}

BENCHMARK(BM_LawBatch)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LawBatchDamped)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LawBatch)->Arg(10'000)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
