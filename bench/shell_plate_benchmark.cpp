// Element-cycles per second of the explicit engine on a 100 x 100 Belytschko-Tsay plate with
// 5 through-thickness points and J2 plasticity (*MAT_024), clamped, pushed by an initial
// velocity field large enough to yield it; 1 and 2 OpenMP threads, outputs disabled. Then the
// same plate with the fully integrated shell (ELFORM 16, four in-plane points: about four times
// the law calls) on one thread, and its cost per element-cycle against the BT element's.
//
//   build/bench/bench_shell_plate [cycles]
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "engine_timing.hpp"

namespace {

using namespace plyform;

core::Model plate(int nx, core::ShellFormulation formulation) {
  core::Model m;
  const double a = 100.0;
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= nx; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.node_id.push_back(id(i, j) + 1);
      m.x0.push_back(a * i / nx);
      m.y0.push_back(a * j / nx);
      m.z0.push_back(0.0);
    }
  core::ShellBlock b;
  b.formulation = formulation;
  b.nip = 5;
  for (int j = 0; j < nx; ++j)
    for (int i = 0; i < nx; ++i) {
      b.element_id.push_back(static_cast<core::GlobalId>(b.element_id.size() + 1));
      for (int n : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) {
        b.connectivity.push_back(n);
        b.thickness.push_back(1.0);
      }
    }
  core::PiecewiseLinearPlasticity steel;
  steel.density = 7.85e-9;
  steel.young = 210000.0;
  steel.poisson = 0.3;
  steel.sigy = 200.0;
  steel.etan = 1000.0;
  m.materials.push_back(steel);
  m.parts.push_back(core::Part{1, "plate", 0});
  m.shell_blocks.push_back(std::move(b));
  core::colour_element_blocks(m);
  const std::size_t n = m.node_count();
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = m.x0[i], y = m.y0[i];
    m.v0z[i] = 20000.0 * std::sin(M_PI * x / a) * std::sin(M_PI * y / a);
    if (x < 1e-9 || y < 1e-9 || x > a - 1e-9 || y > a - 1e-9) {
      m.fixed.push_back({static_cast<core::Index>(i), 63u});
    }
  }
  m.controls.end_time = 1.0;
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const long cycles = argc > 1 ? std::atol(argv[1]) : 500;
  const core::Model m = plate(100, core::ShellFormulation::belytschko_tsay);
  const double one = bench::element_cycles_per_second(m, cycles, 1);
  const double two = bench::element_cycles_per_second(m, cycles, 2);
  std::printf(
      "Belytschko-Tsay, 100 x 100 shells, NIP 5, J2 (*MAT_024), %ld cycles: 1 thread "
      "%.2f M element-cycles/s, 2 threads %.2f M (speed-up %.2f)\n",
      cycles, one * 1e-6, two * 1e-6, two / one);
  const core::Model full = plate(100, core::ShellFormulation::fully_integrated);
  const double full_one = bench::element_cycles_per_second(full, cycles, 1);
  std::printf(
      "Fully integrated (ELFORM 16), the same plate, %ld cycles: 1 thread %.2f M "
      "element-cycles/s, %.2f x the cost of Belytschko-Tsay\n",
      cycles, full_one * 1e-6, one / full_one);
  return 0;
}
