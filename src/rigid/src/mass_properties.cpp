#include "plyform/rigid/mass_properties.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace plyform::rigid {
namespace {

// 3-point Gauss rule on [-1, 1].
constexpr double kGp[3] = {-0.77459666924148337704, 0.0, 0.77459666924148337704};
constexpr double kGw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

constexpr double kHexXi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr double kQuadXi[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

// Visits every Gauss point of the part's elements: f(element id, node indices, N, dm, x, nn)
// with dm = rho dV (or rho t dA) of the point, x its position, nn the thin-plate term
// rho t^3/12 dA n n^T (zero for hexahedra; 6 entries xx, yy, zz, xy, yz, zx).
template <typename F>
void for_each_point(const core::Model& model, core::Index part, double rho, F&& f) {
  const auto& X = model.x0;
  const auto& Y = model.y0;
  const auto& Z = model.z0;
  for (const core::SolidBlock& b : model.solid_blocks) {
    if (b.part != part)
      continue;
    for (std::size_t e = 0; e < b.size(); ++e) {
      const core::Index* c = &b.connectivity[8 * e];
      double xn[8][3];
      for (int a = 0; a < 8; ++a) {
        const auto i = static_cast<std::size_t>(c[a]);
        xn[a][0] = X[i];
        xn[a][1] = Y[i];
        xn[a][2] = Z[i];
      }
      for (int gi = 0; gi < 3; ++gi)
        for (int gj = 0; gj < 3; ++gj)
          for (int gk = 0; gk < 3; ++gk) {
            const double p[3] = {kGp[gi], kGp[gj], kGp[gk]};
            double n[8], dn[8][3];
            for (int a = 0; a < 8; ++a) {
              const double s[3] = {1.0 + kHexXi[a][0] * p[0], 1.0 + kHexXi[a][1] * p[1],
                                   1.0 + kHexXi[a][2] * p[2]};
              n[a] = 0.125 * s[0] * s[1] * s[2];
              dn[a][0] = 0.125 * kHexXi[a][0] * s[1] * s[2];
              dn[a][1] = 0.125 * kHexXi[a][1] * s[0] * s[2];
              dn[a][2] = 0.125 * kHexXi[a][2] * s[0] * s[1];
            }
            double j[3][3] = {};  // j[i][k] = d x_i / d xi_k
            double x[3] = {};
            for (int a = 0; a < 8; ++a)
              for (int i = 0; i < 3; ++i) {
                x[i] += n[a] * xn[a][i];
                for (int k = 0; k < 3; ++k)
                  j[i][k] += dn[a][k] * xn[a][i];
              }
            const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                               j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                               j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
            if (!(det > 0.0)) {
              throw std::invalid_argument(
                  "rigid part " + std::to_string(model.parts[static_cast<std::size_t>(part)].id) +
                  ": solid element " + std::to_string(b.element_id[e]) +
                  " has a non-positive Jacobian (inverted or degenerate)");
            }
            const double nn[6] = {};
            f(c, 8, n, rho * det * kGw[gi] * kGw[gj] * kGw[gk], x, nn);
          }
    }
  }
  for (const core::ShellBlock& b : model.shell_blocks) {
    if (b.part != part)
      continue;
    for (std::size_t e = 0; e < b.size(); ++e) {
      const core::Index* c = &b.connectivity[4 * e];
      const double* th = &b.thickness[4 * e];
      double xn[4][3];
      for (int a = 0; a < 4; ++a) {
        const auto i = static_cast<std::size_t>(c[a]);
        xn[a][0] = X[i];
        xn[a][1] = Y[i];
        xn[a][2] = Z[i];
      }
      double area = 0.0;
      for (int gi = 0; gi < 3; ++gi)
        for (int gj = 0; gj < 3; ++gj) {
          const double p[2] = {kGp[gi], kGp[gj]};
          double n[4], dn[4][2];
          for (int a = 0; a < 4; ++a) {
            const double s[2] = {1.0 + kQuadXi[a][0] * p[0], 1.0 + kQuadXi[a][1] * p[1]};
            n[a] = 0.25 * s[0] * s[1];
            dn[a][0] = 0.25 * kQuadXi[a][0] * s[1];
            dn[a][1] = 0.25 * kQuadXi[a][1] * s[0];
          }
          double x[3] = {}, g1[3] = {}, g2[3] = {};
          double t = 0.0;
          for (int a = 0; a < 4; ++a) {
            t += n[a] * th[a];
            for (int i = 0; i < 3; ++i) {
              x[i] += n[a] * xn[a][i];
              g1[i] += dn[a][0] * xn[a][i];
              g2[i] += dn[a][1] * xn[a][i];
            }
          }
          const double nv[3] = {g1[1] * g2[2] - g1[2] * g2[1], g1[2] * g2[0] - g1[0] * g2[2],
                                g1[0] * g2[1] - g1[1] * g2[0]};
          const double da = std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
          const double w = kGw[gi] * kGw[gj] * da;
          area += w;
          double nn[6] = {};
          if (da > 0.0) {
            const double u[3] = {nv[0] / da, nv[1] / da, nv[2] / da};
            const double k = rho * t * t * t / 12.0 * w;
            nn[0] = k * u[0] * u[0];
            nn[1] = k * u[1] * u[1];
            nn[2] = k * u[2] * u[2];
            nn[3] = k * u[0] * u[1];
            nn[4] = k * u[1] * u[2];
            nn[5] = k * u[2] * u[0];
          }
          f(c, 4, n, rho * t * w, x, nn);
        }
      if (!(area > 0.0)) {
        throw std::invalid_argument(
            "rigid part " + std::to_string(model.parts[static_cast<std::size_t>(part)].id) +
            ": shell element " + std::to_string(b.element_id[e]) + " has no area");
      }
    }
  }
}

}  // namespace

MassProperties part_mass_properties(const core::Model& model, core::Index part, double rho) {
  MassProperties mp;
  std::vector<int> local(model.node_count(), -1);
  // Pass 1: mass, first moment, nodal masses (positions relative to a first node, so that a
  // body far from the origin keeps its digits).
  double origin[3] = {0.0, 0.0, 0.0};
  bool have_origin = false;
  double s[3] = {0.0, 0.0, 0.0};
  std::vector<double> nodal(model.node_count(), 0.0);
  for_each_point(model, part, rho,
                 [&](const core::Index* c, int nc, const double* n, double dm, const double* x,
                     const double*) {
                   if (!have_origin) {
                     origin[0] = x[0];
                     origin[1] = x[1];
                     origin[2] = x[2];
                     have_origin = true;
                   }
                   mp.mass += dm;
                   for (int i = 0; i < 3; ++i)
                     s[i] += dm * (x[i] - origin[i]);
                   for (int a = 0; a < nc; ++a) {
                     const auto i = static_cast<std::size_t>(c[a]);
                     nodal[i] += n[a] * dm;
                     local[i] = 0;
                   }
                 });
  for (std::size_t i = 0; i < model.node_count(); ++i) {
    if (local[i] == 0) {
      mp.nodes.push_back(static_cast<core::Index>(i));
      mp.nodal_mass.push_back(nodal[i]);
    }
  }
  if (!(mp.mass > 0.0))
    return mp;
  for (int i = 0; i < 3; ++i)
    mp.centre[static_cast<std::size_t>(i)] = origin[i] + s[i] / mp.mass;
  // Pass 2: second moments about the centre.
  double q[6] = {};  // xx, yy, zz, xy, yz, zx
  const auto& c0 = mp.centre;
  for_each_point(
      model, part, rho,
      [&](const core::Index*, int, const double*, double dm, const double* x, const double* nn) {
        const double r[3] = {x[0] - c0[0], x[1] - c0[1], x[2] - c0[2]};
        q[0] += dm * r[0] * r[0] + nn[0];
        q[1] += dm * r[1] * r[1] + nn[1];
        q[2] += dm * r[2] * r[2] + nn[2];
        q[3] += dm * r[0] * r[1] + nn[3];
        q[4] += dm * r[1] * r[2] + nn[4];
        q[5] += dm * r[2] * r[0] + nn[5];
      });
  const double tr = q[0] + q[1] + q[2];
  mp.inertia = {tr - q[0], -q[3], -q[5], -q[3], tr - q[1], -q[4], -q[5], -q[4], tr - q[2]};
  return mp;
}

}  // namespace plyform::rigid
