// The decomposition at scale, on paper (docs/parallel.md): a three-layer blank of about a million
// shells (two skins and a core, each its own mesh, two layer interfaces and a rigid tool) split by
// METIS into 8, 64 and 512 domains; what each domain then exchanges, and a strong-scaling estimate
// from a latency-bandwidth model with this machine's measured cost per element.
//
// Run: build/bench/decomposition_scale [elements along a layer's side, default 578] [domains...]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "layered_models.hpp"
#include "plyform/domain/decomposition.hpp"

namespace {

using plyform::domain::Decomposition;
using plyform::domain::DomainSummary;

// A BT shell with NIP 5 and J2 takes about 150 ns a cycle on one core of this machine (README,
// Speed); the decomposition's costs are in those units.
constexpr double kUnitSeconds = 150e-9;
// Per shared node and cycle: the nodal force and moment (6 doubles) out and in.
constexpr double kSharedNodeBytes = 2 * 6 * 8;
// Per ghost segment and cycle: its 4 nodes' positions and velocities in (some shared with the
// neighbouring ghosts: counted whole, an upper bound) and their contact forces out.
constexpr double kGhostSegmentBytes = 4 * (6 + 3) * 8;

struct Network {
  const char* name;
  double latency;    // s per message
  double bandwidth;  // bytes/s per rank
};

template <class F>
double largest(const std::vector<DomainSummary>& s, F f) {
  double m = 0.0;
  for (const DomainSummary& d : s)
    m = std::max(m, static_cast<double>(f(d)));
  return m;
}
template <class F>
double mean(const std::vector<DomainSummary>& s, F f) {
  double m = 0.0;
  for (const DomainSummary& d : s)
    m += static_cast<double>(f(d));
  return m / static_cast<double>(s.size());
}

}  // namespace

int main(int argc, char** argv) {
  plyform::test::LayeredBlankOptions o;
  o.nx = o.ny = argc > 1 ? std::atoi(argv[1]) : 578;
  std::vector<int> counts;
  for (int i = 2; i < argc; ++i)
    counts.push_back(std::atoi(argv[i]));
  if (counts.empty())
    counts = {8, 64, 512};
  const plyform::core::Model model = plyform::test::layered_blank(o);
  std::printf("three-layer blank: %zu shells (%d x %d a skin), %zu nodes, %zu interfaces\n",
              model.deformable_element_count(), o.nx, o.ny, model.node_count(),
              model.contacts.size());
  const Network networks[] = {{"shared memory", 0.5e-6, 5e9}, {"InfiniBand HDR", 1.5e-6, 12e9}};
  std::printf("%8s %8s %10s %22s %16s %20s %9s %8s\n", "domains", "METIS s", "elements",
              "shared nodes mean/max", "neighbours m/max", "ghost segments m/max", "imbalance",
              "cut %");
  std::vector<Decomposition> splits;
  for (int n : counts) {
    const auto t0 = std::chrono::steady_clock::now();
    plyform::domain::DecomposeResult r = plyform::domain::decompose(model, n);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!r.error.empty()) {
      std::fprintf(stderr, "%d domains: %s\n", n, r.error.c_str());
      return 1;
    }
    const Decomposition& d = r.decomposition;
    const auto& s = d.summary;
    std::printf("%8d %8.1f %10.0f %10.0f / %9.0f %7.1f / %6.0f %9.0f / %8.0f %9.3f %8.2f\n", n,
                seconds, mean(s, [](auto& x) { return x.elements; }),
                mean(s, [](auto& x) { return x.shared_nodes; }),
                largest(s, [](auto& x) { return x.shared_nodes; }),
                mean(s, [](auto& x) { return x.neighbours; }),
                largest(s, [](auto& x) { return x.neighbours; }),
                mean(s, [](auto& x) { return x.ghost_segments; }),
                largest(s, [](auto& x) { return x.ghost_segments; }), d.imbalance,
                100.0 * static_cast<double>(d.interface_edges_cut) /
                    static_cast<double>(std::max<std::size_t>(1, d.interface_edges)));
    splits.push_back(std::move(r.decomposition));
  }
  double total_cost = 0.0;
  for (const DomainSummary& x : splits.front().summary)
    total_cost += x.cost;
  const double serial = total_cost * kUnitSeconds;
  std::printf(
      "\nstrong scaling, one rank per core: a cycle takes %.1f ms on one core "
      "(%.3g cost units x %.0f ns)\n",
      1e3 * serial, total_cost, kUnitSeconds * 1e9);
  for (const Network& net : networks) {
    std::printf("%s (latency %.1f us, %.0f GB/s):\n", net.name, net.latency * 1e6,
                net.bandwidth * 1e-9);
    std::printf("  %8s %12s %12s %12s %9s %11s\n", "domains", "compute us", "exchange us",
                "reduce us", "speed-up", "efficiency");
    for (const Decomposition& d : splits) {
      // The slowest domain sets the cycle: its compute, its messages (one to each neighbour for
      // the nodal sums, one each way for the ghosts) and two reductions a cycle (the step vote
      // and the energy books), each log2(P) latencies deep.
      double worst = 0.0, worst_compute = 0.0, worst_exchange = 0.0;
      for (const DomainSummary& x : d.summary) {
        const double compute = x.cost * kUnitSeconds;
        const double bytes = kSharedNodeBytes * static_cast<double>(x.shared_nodes) +
                             kGhostSegmentBytes * static_cast<double>(x.ghost_segments);
        const double exchange =
            3.0 * static_cast<double>(x.neighbours) * net.latency + bytes / net.bandwidth;
        if (compute + exchange > worst) {
          worst = compute + exchange;
          worst_compute = compute;
          worst_exchange = exchange;
        }
      }
      const double reduce =
          2.0 * std::ceil(std::log2(static_cast<double>(d.domains))) * net.latency;
      const double cycle = worst + reduce;
      std::printf("  %8d %12.1f %12.1f %12.1f %9.1f %10.0f%%\n", d.domains, worst_compute * 1e6,
                  worst_exchange * 1e6, reduce * 1e6, serial / cycle,
                  100.0 * serial / cycle / d.domains);
    }
  }
  return 0;
}
