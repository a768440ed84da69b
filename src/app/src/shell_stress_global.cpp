#include "shell_stress_global.hpp"

#include "plyform/element/shell_kernels.hpp"

namespace plyform::app {

void shell_stress_to_global(const double* const axes[3], const double l[3][3], double* out) {
  static constexpr int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (int c = 0; c < 6; ++c) {
    double v = 0.0;
    for (int a = 0; a < 3; ++a)
      for (int bb = 0; bb < 3; ++bb)
        v += axes[a][kPair[c][0]] * l[a][bb] * axes[bb][kPair[c][1]];
    out[c] = v;
  }
}

void current_shell_frame(const core::ShellBlock& blk, const engine::NodalState& ns, std::size_t e,
                         double e1[3], double e2[3], double e3[3]) {
  if (!element::shell_frame(blk, ns.x.data(), ns.y.data(), ns.z.data(), e, e1, e2, e3)) {
    e1[0] = e2[1] = e3[2] = 1.0;
    e1[1] = e1[2] = e2[0] = e2[2] = e3[0] = e3[1] = 0.0;
  }
}

}  // namespace plyform::app
