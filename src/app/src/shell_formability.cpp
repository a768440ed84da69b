#include "shell_formability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <variant>

namespace plyform::app {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// One shell's use of one edge (its nodes `lo` < `hi`), for pairing the shells across edges.
struct EdgeUse {
  core::Index part, lo, hi;
  std::int64_t shell;
  int slot;      // which of the shell's edges: node slot -> slot + 1
  bool forward;  // the shell runs from lo to hi
};

}  // namespace

ShellFormability::ShellFormability(const core::Model& model, std::size_t cells) : model_(model) {
  std::size_t shells = 0;
  for (const core::ShellBlock& b : model.shell_blocks)
    shells += b.size();
  first_shell_cell_ = cells - shells;
  for (int s = 0; s < 3; ++s) {
    major[s].assign(cells, kNan);
    minor[s].assign(cells, kNan);
  }
  thinning.assign(cells, kNan);
  connectivity_.reserve(shells);
  initial_thickness_.reserve(shells);
  deformable_.reserve(shells);
  std::vector<EdgeUse> edges;
  for (const core::ShellBlock& b : model.shell_blocks) {
    const bool rigid = std::holds_alternative<core::RigidMaterial>(
        model.materials[static_cast<std::size_t>(b.material)]);
    for (std::size_t e = 0; e < b.size(); ++e) {
      const core::Index* c = &b.connectivity[4 * e];
      const double* t0 = &b.thickness[4 * e];
      const auto s = static_cast<std::int64_t>(connectivity_.size());
      connectivity_.push_back(c);
      initial_thickness_.push_back(0.25 * (t0[0] + t0[1] + t0[2] + t0[3]));
      deformable_.push_back(rigid ? 0 : 1);
      if (rigid)
        continue;  // a tool: no strain to judge, and no neighbour of the sheet
      for (int k = 0; k < 4; ++k) {
        const core::Index a = c[k], z = c[(k + 1) % 4];
        if (a != z)  // a triangle's collapsed edge (node 3 = node 4) is none
          edges.push_back({b.part, std::min(a, z), std::max(a, z), s, k, a < z});
      }
    }
  }
  // Shells of one part that share an edge, two and only two of them (a third shell on the edge
  // makes a junction, across which the surface has no curvature to speak of).
  neighbour_.assign(4 * shells, -1);
  side_.assign(4 * shells, 1);
  const auto key = [](const EdgeUse& u) { return std::tie(u.part, u.lo, u.hi); };
  std::sort(edges.begin(), edges.end(),
            [&](const EdgeUse& l, const EdgeUse& r) { return key(l) < key(r); });
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && key(edges[j]) == key(edges[i]))
      ++j;
    if (j - i == 2) {
      const EdgeUse &u = edges[i], &v = edges[i + 1];
      // Consistently oriented neighbours run along their common edge in opposite directions.
      const signed char side = u.forward != v.forward ? 1 : -1;
      neighbour_[4 * static_cast<std::size_t>(u.shell) + static_cast<std::size_t>(u.slot)] =
          v.shell;
      neighbour_[4 * static_cast<std::size_t>(v.shell) + static_cast<std::size_t>(v.slot)] =
          u.shell;
      side_[4 * static_cast<std::size_t>(u.shell) + static_cast<std::size_t>(u.slot)] = side;
      side_[4 * static_cast<std::size_t>(v.shell) + static_cast<std::size_t>(v.slot)] = side;
    }
    i = j;
  }
  reference_.resize(shells);
  current_.resize(shells);
  reference_valid_.assign(shells, 0);
  current_valid_.assign(shells, 0);
  reference_curvature_.assign(3 * shells, 0.0);
  for (std::size_t s = 0; s < shells; ++s) {
    reference_valid_[s] = deformable_[s] && centre(s, model.x0.data(), model.y0.data(),
                                                   model.z0.data(), reference_[s]);
  }
  for (std::size_t s = 0; s < shells; ++s) {
    if (reference_valid_[s])
      curvature(s, reference_, reference_valid_, &reference_curvature_[3 * s]);
  }
}

bool ShellFormability::centre(std::size_t s, const double* x, const double* y, const double* z,
                              element::ShellCentre& out) const {
  double p[4][3];
  for (int i = 0; i < 4; ++i) {
    const auto n = static_cast<std::size_t>(connectivity_[s][i]);
    p[i][0] = x[n];
    p[i][1] = y[n];
    p[i][2] = z[n];
  }
  return element::shell_centre(p, out);
}

void ShellFormability::curvature(std::size_t s, const std::vector<element::ShellCentre>& centres,
                                 const std::vector<char>& valid, double b[3]) const {
  double c[4][3], n[4][3];
  int count = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::int64_t f = neighbour_[4 * s + k];
    if (f < 0 || !valid[static_cast<std::size_t>(f)])
      continue;
    const element::ShellCentre& other = centres[static_cast<std::size_t>(f)];
    const double side = side_[4 * s + k];
    for (int d = 0; d < 3; ++d) {
      c[count][d] = other.centre[d];
      n[count][d] = side * other.normal[d];
    }
    ++count;
  }
  element::fit_curvature(centres[s], count, c, n, b);
}

void ShellFormability::compute(const engine::NodalState& nodes,
                               const std::vector<element::ShellBlockState>& shells) {
  const std::size_t count = connectivity_.size();
  for (std::size_t s = 0; s < count; ++s) {
    current_valid_[s] = deformable_[s] && reference_valid_[s] &&
                        centre(s, nodes.x.data(), nodes.y.data(), nodes.z.data(), current_[s]);
  }
  std::size_t s = 0;
  for (std::size_t bi = 0; bi < model_.shell_blocks.size(); ++bi) {
    const std::vector<double>& thickness = shells[bi].thickness;
    for (std::size_t e = 0; e < model_.shell_blocks[bi].size(); ++e, ++s) {
      if (!deformable_[s])
        continue;  // NaN from the start
      const std::size_t cell = first_shell_cell_ + s;
      const double h = thickness[e], h0 = initial_thickness_[s];
      thinning[cell] = (h0 - h) / h0;
      element::SurfaceStrains strains{};
      double b[3] = {0.0, 0.0, 0.0};
      if (current_valid_[s])
        curvature(s, current_, current_valid_, b);
      if (!current_valid_[s] ||
          !element::shell_surface_strains(reference_[s], &reference_curvature_[3 * s], current_[s],
                                          b, h, strains)) {
        for (int k = 0; k < 3; ++k)
          strains.major[k] = strains.minor[k] = kNan;
      }
      for (int k = 0; k < 3; ++k) {
        major[k][cell] = strains.major[k];
        minor[k][cell] = strains.minor[k];
      }
    }
  }
}

bool ShellFormability::surface_strain_tensors(std::size_t s, double thickness, double bottom[6],
                                              double top[6]) const {
  if (!current_valid_[s])
    return false;
  double b[3] = {0.0, 0.0, 0.0};
  curvature(s, current_, current_valid_, b);
  return element::shell_surface_strain_tensors(
      reference_[s], &reference_curvature_[3 * s], current_[s], b, thickness,
      std::log(thickness / initial_thickness_[s]), bottom, top);
}

}  // namespace plyform::app
