// Element-cycles per second of the explicit engine on an elastic hex8 block of about 100k
// elements (ELFORM 1, viscous hourglass control), with 1 and 2 OpenMP threads. A timed run of
// the whole cycle (elements, assembly, time integration, energies), outputs disabled.
//
//   build/bench/bench_solid_block [cycles]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "engine_timing.hpp"

namespace {

using namespace plyform;

core::Model block(int nx, int ny, int nz, core::SolidFormulation form) {
  core::Model m;
  const auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        m.node_id.push_back(id(i, j, k) + 1);
        m.x0.push_back(i * 1.0);
        m.y0.push_back(j * 1.0);
        m.z0.push_back(k * 1.0);
      }
  core::SolidBlock b;
  b.formulation = form;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        b.element_id.push_back(static_cast<core::GlobalId>(b.element_id.size() + 1));
        const int c[8] = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        for (int n : c)
          b.connectivity.push_back(n);
      }
  m.materials.push_back(core::ElasticMaterial{7.85e-9, 210000.0, 0.3});
  m.parts.push_back(core::Part{1, "block", 0});
  m.solid_blocks.push_back(std::move(b));
  core::colour_element_blocks(m);
  // A velocity field that deforms the block (not a rigid motion).
  const std::size_t n = m.node_count();
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    m.v0z[i] = 100.0 * m.x0[i] / nx;
  m.controls.end_time = 1.0;
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const long cycles = argc > 1 ? std::atol(argv[1]) : 200;
  const bool only_one = argc > 2;  // "1": ELFORM 1 only (for profiling)
  for (auto form : {core::SolidFormulation::one_point, core::SolidFormulation::selective_reduced}) {
    if (only_one && form != core::SolidFormulation::one_point)
      continue;
    const core::Model m = block(50, 50, 40, form);
    const double one = bench::element_cycles_per_second(m, cycles, 1);
    const double two = bench::element_cycles_per_second(m, cycles, 2);
    std::printf(
        "ELFORM %d, %zu hex8 elements, %ld cycles: 1 thread %.2f M element-cycles/s, "
        "2 threads %.2f M (speed-up %.2f)\n",
        static_cast<int>(form), m.solid_count(), cycles, one * 1e-6, two * 1e-6, two / one);
  }
  return 0;
}
