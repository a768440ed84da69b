#include "state_strain.hpp"

#include "plyform/element/element_strain.hpp"

namespace plyform::app {

void element_log_strains(const core::Model& model, const engine::NodalState& nodes,
                         const std::vector<element::ShellBlockState>& shells,
                         std::vector<double>& out) {
  std::size_t cell = 0;
  for (const core::SolidBlock& b : model.solid_blocks) {
    for (std::size_t e = 0; e < b.size(); ++e, ++cell) {
      element::HexCoords ref{}, cur{};
      for (std::size_t i = 0; i < 8; ++i) {
        const auto n = static_cast<std::size_t>(b.connectivity[8 * e + i]);
        ref.x[i] = model.x0[n];
        ref.y[i] = model.y0[n];
        ref.z[i] = model.z0[n];
        cur.x[i] = nodes.x[n];
        cur.y[i] = nodes.y[n];
        cur.z[i] = nodes.z[n];
      }
      (void)element::hex8_log_strain(ref, cur, &out[6 * cell]);
    }
  }
  for (std::size_t bi = 0; bi < model.shell_blocks.size(); ++bi) {
    const core::ShellBlock& b = model.shell_blocks[bi];
    for (std::size_t e = 0; e < b.size(); ++e, ++cell) {
      double ref[4][3], cur[4][3];
      for (std::size_t i = 0; i < 4; ++i) {
        const auto n = static_cast<std::size_t>(b.connectivity[4 * e + i]);
        ref[i][0] = model.x0[n];
        ref[i][1] = model.y0[n];
        ref[i][2] = model.z0[n];
        cur[i][0] = nodes.x[n];
        cur[i][1] = nodes.y[n];
        cur[i][2] = nodes.z[n];
      }
      const double* t0 = &b.thickness[4 * e];
      const double h0 = 0.25 * (t0[0] + t0[1] + t0[2] + t0[3]);
      (void)element::shell_log_strain(ref, cur, shells[bi].thickness[e] / h0, &out[6 * cell]);
    }
  }
}

}  // namespace plyform::app
