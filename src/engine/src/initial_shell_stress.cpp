#include "initial_shell_stress.hpp"

#include <algorithm>

#include "plyform/material/law_registry.hpp"

namespace plyform::engine {
namespace {

/// The value at `zeta` of the card's points (thickness point k, in-plane point g, component c
/// of `width` per point): linear between the neighbouring T, constant beyond the ends.
double through_thickness(const core::InitialShellStress& s, const std::vector<double>& values,
                         std::size_t width, std::size_t g, std::size_t c, double zeta) {
  const std::size_t n = s.t.size();
  const auto in_plane = static_cast<std::size_t>(s.in_plane);
  const auto at = [&](std::size_t k) { return values[(k * in_plane + g) * width + c]; };
  if (zeta <= s.t.front())
    return at(0);
  if (zeta >= s.t.back())
    return at(n - 1);
  const auto hi =
      static_cast<std::size_t>(std::upper_bound(s.t.begin(), s.t.end(), zeta) - s.t.begin());
  const std::size_t lo = hi - 1;
  const double w = (zeta - s.t[lo]) / (s.t[hi] - s.t[lo]);
  return at(lo) + w * (at(hi) - at(lo));
}

/// The card's value for the block's in-plane point g (see the header).
double in_plane_value(const core::InitialShellStress& s, const std::vector<double>& values,
                      std::size_t width, std::size_t block_in_plane, std::size_t g, std::size_t c,
                      double zeta) {
  if (s.in_plane == 1)
    return through_thickness(s, values, width, 0, c, zeta);
  if (block_in_plane == 4)
    return through_thickness(s, values, width, g, c, zeta);
  double sum = 0.0;
  for (std::size_t q = 0; q < 4; ++q)
    sum += through_thickness(s, values, width, q, c, zeta);
  return 0.25 * sum;
}

}  // namespace

void apply_initial_shell_stresses(const core::Model& model,
                                  std::vector<element::ShellBlockState>& shells) {
  static constexpr int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (const core::InitialShellStress& s : model.initial_shell_stresses) {
    const auto b = static_cast<std::size_t>(s.shell.block);
    const auto e = static_cast<std::size_t>(s.shell.element);
    const core::ShellBlock& blk = model.shell_blocks[b];
    element::ShellBlockState& st = shells[b];
    const auto nip = static_cast<std::size_t>(st.nip);
    const auto inplane = static_cast<std::size_t>(st.inplane);
    std::vector<double> zeta(nip), weight(nip);
    element::thickness_rule(blk.rule, st.nip, zeta.data(), weight.data());
    double axes[3][3];
    if (!element::shell_frame(blk, model.x0.data(), model.y0.data(), model.z0.data(), e, axes[0],
                              axes[1], axes[2]))
      continue;  // a collapsed element: the first element pass reports it
    for (std::size_t g = 0; g < inplane; ++g) {
      for (std::size_t k = 0; k < nip; ++k) {
        // The global tensor at this point, then its components in the frame:
        // l_ab = e_a . sigma . e_b.
        double sigma[3][3];
        for (std::size_t c = 0; c < 6; ++c) {
          const double v = in_plane_value(s, s.stress, 6, inplane, g, c, zeta[k]);
          sigma[kPair[c][0]][kPair[c][1]] = sigma[kPair[c][1]][kPair[c][0]] = v;
        }
        const auto local = [&](int a, int bb) {
          double v = 0.0;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              v += axes[a][i] * sigma[i][j] * axes[bb][j];
          return v;
        };
        const std::size_t q = e * st.points_per_element() + g * nip + k;
        st.s[0][q] = local(0, 0);
        st.s[1][q] = local(1, 1);
        st.s[2][q] = local(0, 1);
        st.s[3][q] = local(1, 2);
        st.s[4][q] = local(2, 0);
        st.eps_p[q] = in_plane_value(s, s.plastic_strain, 1, inplane, g, 0, zeta[k]);
      }
    }
  }
}

std::vector<double> initial_stress_energy(const core::Model& model,
                                          const std::vector<element::ShellBlockState>& shells) {
  std::vector<double> energy(model.shell_blocks.size(), 0.0);
  for (const core::InitialShellStress& s : model.initial_shell_stresses) {
    const auto b = static_cast<std::size_t>(s.shell.block);
    const auto e = static_cast<std::size_t>(s.shell.element);
    const core::ShellBlock& blk = model.shell_blocks[b];
    const element::ShellBlockState& st = shells[b];
    const core::Material& m = model.materials[static_cast<std::size_t>(blk.material)];
    const double k = material::bulk_modulus(m), g = material::shear_modulus(m);
    const double young = 9.0 * k * g / (3.0 * k + g),
                 nu = (3.0 * k - 2.0 * g) / (2.0 * (3.0 * k + g));
    const auto nip = static_cast<std::size_t>(st.nip);
    std::vector<double> zeta(nip), weight(nip);
    element::thickness_rule(blk.rule, st.nip, zeta.data(), weight.data());
    // Each point's share of the volume: the weights sum to 2 through the thickness, and the
    // in-plane points share the area equally.
    const double volume = st.area[e] * st.thickness[e] / (2.0 * st.inplane);
    for (std::size_t gp = 0; gp < static_cast<std::size_t>(st.inplane); ++gp)
      for (std::size_t kp = 0; kp < nip; ++kp) {
        const std::size_t q = e * st.points_per_element() + gp * nip + kp;
        const double sxx = st.s[0][q], syy = st.s[1][q], sxy = st.s[2][q];
        const double in_plane =
            (sxx * sxx + syy * syy - 2.0 * nu * sxx * syy + 2.0 * (1.0 + nu) * sxy * sxy) /
            (2.0 * young);
        const double shear = (st.s[3][q] * st.s[3][q] + st.s[4][q] * st.s[4][q]) / (2.0 * g);
        energy[b] += weight[kp] * volume * (in_plane + shear);
      }
  }
  return energy;
}

}  // namespace plyform::engine
