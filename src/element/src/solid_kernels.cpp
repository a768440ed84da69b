#include "plyform/element/solid_kernels.hpp"

#include <cmath>
#include <type_traits>
#include <variant>

#include "plyform/element/hex8_geometry.hpp"
#include "plyform/material/constitutive.hpp"

namespace plyform::element {
namespace {

constexpr std::size_t kChunk = 32;  // points per material call: scratch stays in L1

using core::ElasticMaterial;
using core::MooneyRivlinMaterial;

void gather(const core::SolidBlock& b, std::size_t e, const double* x, const double* y,
            const double* z, HexCoords& c) {
  const core::Index* n = &b.connectivity[8 * e];
  for (int i = 0; i < 8; ++i) {
    c.x[i] = x[n[i]];
    c.y[i] = y[n[i]];
    c.z[i] = z[n[i]];
  }
}

// Per-chunk scratch: kinematics at each point, in structure-of-arrays form for the material.
struct PointScratch {
  double d[6][kChunk];
  double w[3][kChunk];
  double f[9][kChunk];
};

template <class M>
void update_material(const M& m, std::size_t n, PointScratch& s, double dt, SolidBlockState& st,
                     std::size_t first_point) {
  const material::SymView sigma{&st.s[0][first_point], &st.s[1][first_point],
                                &st.s[2][first_point], &st.s[3][first_point],
                                &st.s[4][first_point], &st.s[5][first_point]};
  if constexpr (std::is_same_v<M, ElasticMaterial>) {
    const material::ConstSymView d{s.d[0], s.d[1], s.d[2], s.d[3], s.d[4], s.d[5]};
    material::elastic_jaumann(m, n, d, s.w[0], s.w[1], s.w[2], dt, sigma);
  } else {
    const double* f[9] = {s.f[0], s.f[1], s.f[2], s.f[3], s.f[4], s.f[5], s.f[6], s.f[7], s.f[8]};
    material::mooney_rivlin_cauchy(m, n, f, sigma);
  }
}

// Velocity gradient L_ij = sum_I v_iI dN_I/dx_j -> D (sym) and W (w_xy, w_yz, w_zx).
inline void rates(const double* vx, const double* vy, const double* vz, const double* bx,
                  const double* by, const double* bz, PointScratch& s, std::size_t p) {
  double l[3][3] = {};
  for (int i = 0; i < 8; ++i) {
    l[0][0] += vx[i] * bx[i];
    l[0][1] += vx[i] * by[i];
    l[0][2] += vx[i] * bz[i];
    l[1][0] += vy[i] * bx[i];
    l[1][1] += vy[i] * by[i];
    l[1][2] += vy[i] * bz[i];
    l[2][0] += vz[i] * bx[i];
    l[2][1] += vz[i] * by[i];
    l[2][2] += vz[i] * bz[i];
  }
  s.d[0][p] = l[0][0];
  s.d[1][p] = l[1][1];
  s.d[2][p] = l[2][2];
  s.d[3][p] = 0.5 * (l[0][1] + l[1][0]);
  s.d[4][p] = 0.5 * (l[1][2] + l[2][1]);
  s.d[5][p] = 0.5 * (l[2][0] + l[0][2]);
  s.w[0][p] = 0.5 * (l[0][1] - l[1][0]);
  s.w[1][p] = 0.5 * (l[1][2] - l[2][1]);
  s.w[2][p] = 0.5 * (l[2][0] - l[0][2]);
}

// Deformation gradient F_ij = sum_I x_iI dN_I/dX_j (row-major into s.f).
inline void deformation_gradient(const HexCoords& c, const double* bx, const double* by,
                                 const double* bz, PointScratch& s, std::size_t p,
                                 double scale = 1.0) {
  double f[9] = {};
  for (int i = 0; i < 8; ++i) {
    f[0] += c.x[i] * bx[i];
    f[1] += c.x[i] * by[i];
    f[2] += c.x[i] * bz[i];
    f[3] += c.y[i] * bx[i];
    f[4] += c.y[i] * by[i];
    f[5] += c.y[i] * bz[i];
    f[6] += c.z[i] * bx[i];
    f[7] += c.z[i] * by[i];
    f[8] += c.z[i] * bz[i];
  }
  for (int k = 0; k < 9; ++k)
    s.f[k][p] = scale * f[k];
}

inline double det3(const double* f) {
  return f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
         f[2] * (f[3] * f[7] - f[4] * f[6]);
}

template <class M>
SolidResult one_point(const core::SolidBlock& block, const M& mat, SolidBlockState& st,
                      const NodalView& nv, double dt, std::size_t begin, std::size_t end) {
  SolidResult r;
  constexpr bool kTotal = std::is_same_v<M, MooneyRivlinMaterial>;
  const double c_wave = material::dilatational_wave_speed(core::Material{mat});
  const double rho = mat.density;
  const double modulus = rho * c_wave * c_wave;  // K + 4/3 G
  const auto& h = hourglass_base();
  const int ihq = block.hourglass.ihq;
  const double qm = block.hourglass.qm;
  const bool stiffness_hg = ihq == 4 || ihq == 5;

  UniformGradient g[kChunk];
  HexCoords cur[kChunk];
  double vel[kChunk][3][8];
  PointScratch s;
  for (std::size_t c0 = begin; c0 < end; c0 += kChunk) {
    const std::size_t n = std::min(kChunk, end - c0);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = c0 + k;
      gather(block, e, nv.x, nv.y, nv.z, cur[k]);
      HexCoords v;
      gather(block, e, nv.vx, nv.vy, nv.vz, v);
      for (int i = 0; i < 8; ++i) {
        vel[k][0][i] = v.x[i];
        vel[k][1][i] = v.y[i];
        vel[k][2][i] = v.z[i];
      }
      if (!uniform_gradient(cur[k], g[k])) {
        r.failed = true;
        r.failed_element = e;
        return r;
      }
      st.volume[e] = g[k].volume;
      rates(vel[k][0], vel[k][1], vel[k][2], g[k].bx, g[k].by, g[k].bz, s, k);
      if constexpr (kTotal) {
        HexCoords ref;
        gather(block, e, nv.x0, nv.y0, nv.z0, ref);
        UniformGradient g0;
        if (!uniform_gradient(ref, g0)) {
          r.failed = true;
          r.failed_element = e;
          return r;
        }
        deformation_gradient(cur[k], g0.bx, g0.by, g0.bz, s, k);
      }
      const double dte = characteristic_length(g[k]) / c_wave;
      if (dte < r.dt_min) {
        r.dt_min = dte;
        r.dt_element = e;
      }
    }
    update_material(mat, n, s, dt, st, c0);

    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = c0 + k;
      const UniformGradient& b = g[k];
      const double sxx = st.s[0][e], syy = st.s[1][e], szz = st.s[2][e];
      const double sxy = st.s[3][e], syz = st.s[4][e], szx = st.s[5][e];
      double* f = &st.force[24 * e];
      const double vol = b.volume;
      for (int i = 0; i < 8; ++i) {
        f[3 * i + 0] = vol * (sxx * b.bx[i] + sxy * b.by[i] + szx * b.bz[i]);
        f[3 * i + 1] = vol * (sxy * b.bx[i] + syy * b.by[i] + syz * b.bz[i]);
        f[3 * i + 2] = vol * (szx * b.bx[i] + syz * b.by[i] + szz * b.bz[i]);
      }
      if (qm <= 0.0)
        continue;
      // Flanagan-Belytschko hourglass: gamma_a = h_a - (h_a . x) b, orthogonal to the linear
      // velocity fields, so it resists only the hourglass modes.
      const HexCoords& xc = cur[k];
      double hg_coeff;
      if (stiffness_hg) {
        hg_coeff = qm * modulus * std::cbrt(vol) * 0.25;
      } else {
        hg_coeff = qm * rho * c_wave * std::cbrt(vol * vol) * 0.25;
      }
      double power = 0.0;
      for (int a = 0; a < 4; ++a) {
        double hx = 0.0, hy = 0.0, hz = 0.0;
        for (int i = 0; i < 8; ++i) {
          hx += h[a][i] * xc.x[i];
          hy += h[a][i] * xc.y[i];
          hz += h[a][i] * xc.z[i];
        }
        double gamma[8];
        for (int i = 0; i < 8; ++i)
          gamma[i] = h[a][i] - (hx * b.bx[i] + hy * b.by[i] + hz * b.bz[i]);
        double q[3] = {0.0, 0.0, 0.0};
        for (int d = 0; d < 3; ++d)
          for (int i = 0; i < 8; ++i)
            q[d] += vel[k][d][i] * gamma[i];
        double res[3];
        if (stiffness_hg) {
          double* sh = &st.hourglass[12 * e + 3 * static_cast<std::size_t>(a)];
          for (int d = 0; d < 3; ++d) {
            sh[d] += q[d] * dt;
            res[d] = hg_coeff * sh[d];
          }
        } else {
          for (int d = 0; d < 3; ++d)
            res[d] = hg_coeff * q[d];
        }
        for (int i = 0; i < 8; ++i)
          for (int d = 0; d < 3; ++d)
            f[3 * i + d] += res[d] * gamma[i];
        power += res[0] * q[0] + res[1] * q[1] + res[2] * q[2];
      }
      r.hourglass_energy += power * dt;
    }
  }
  return r;
}

template <class M>
SolidResult selective_reduced(const core::SolidBlock& block, const M& mat, SolidBlockState& st,
                              const NodalView& nv, double dt, std::size_t begin, std::size_t end) {
  SolidResult r;
  constexpr bool kTotal = std::is_same_v<M, MooneyRivlinMaterial>;
  constexpr std::size_t kElems = kChunk / 8;
  const double c_wave = material::dilatational_wave_speed(core::Material{mat});

  GaussGradients gg[kElems];
  UniformGradient mean[kElems];
  PointScratch s;
  for (std::size_t c0 = begin; c0 < end; c0 += kElems) {
    const std::size_t n = std::min(kElems, end - c0);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = c0 + k;
      HexCoords cur, v;
      gather(block, e, nv.x, nv.y, nv.z, cur);
      gather(block, e, nv.vx, nv.vy, nv.vz, v);
      if (!gauss_gradients(cur, gg[k]) || !uniform_gradient(cur, mean[k])) {
        r.failed = true;
        r.failed_element = e;
        return r;
      }
      st.volume[e] = mean[k].volume;
      // Mean dilatation: the volumetric rate of every point is the element's mean.
      PointScratch one;
      rates(v.x, v.y, v.z, mean[k].bx, mean[k].by, mean[k].bz, one, 0);
      const double mean_trace = one.d[0][0] + one.d[1][0] + one.d[2][0];
      GaussGradients g0;
      double ref_volume = 0.0;
      if constexpr (kTotal) {
        HexCoords ref;
        gather(block, e, nv.x0, nv.y0, nv.z0, ref);
        if (!gauss_gradients(ref, g0)) {
          r.failed = true;
          r.failed_element = e;
          return r;
        }
        for (int q = 0; q < 8; ++q)
          ref_volume += g0.weight_det[q];
      }
      for (int q = 0; q < 8; ++q) {
        const std::size_t p = 8 * k + static_cast<std::size_t>(q);
        rates(v.x, v.y, v.z, gg[k].bx[q], gg[k].by[q], gg[k].bz[q], s, p);
        const double shift = (mean_trace - (s.d[0][p] + s.d[1][p] + s.d[2][p])) / 3.0;
        s.d[0][p] += shift;
        s.d[1][p] += shift;
        s.d[2][p] += shift;
        if constexpr (kTotal) {
          // F-bar: the point's F scaled to the element's mean volume ratio.
          deformation_gradient(cur, g0.bx[q], g0.by[q], g0.bz[q], s, p);
          double f[9];
          for (int j = 0; j < 9; ++j)
            f[j] = s.f[j][p];
          const double scale = std::cbrt((mean[k].volume / ref_volume) / det3(f));
          for (int j = 0; j < 9; ++j)
            s.f[j][p] = scale * f[j];
        }
      }
      const double dte = characteristic_length(mean[k]) / c_wave;
      if (dte < r.dt_min) {
        r.dt_min = dte;
        r.dt_element = e;
      }
    }
    update_material(mat, 8 * n, s, dt, st, 8 * c0);

    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = c0 + k;
      double* f = &st.force[24 * e];
      for (int i = 0; i < 24; ++i)
        f[i] = 0.0;
      const UniformGradient& bm = mean[k];
      for (int q = 0; q < 8; ++q) {
        const std::size_t p = 8 * e + static_cast<std::size_t>(q);
        const double sxx = st.s[0][p], syy = st.s[1][p], szz = st.s[2][p];
        const double sxy = st.s[3][p], syz = st.s[4][p], szx = st.s[5][p];
        const double pm = (sxx + syy + szz) / 3.0;
        const double w = gg[k].weight_det[q];
        const double* bx = gg[k].bx[q];
        const double* by = gg[k].by[q];
        const double* bz = gg[k].bz[q];
        // Deviatoric stress with the point gradient, mean stress with the element's mean one.
        for (int i = 0; i < 8; ++i) {
          f[3 * i + 0] += w * ((sxx - pm) * bx[i] + sxy * by[i] + szx * bz[i] + pm * bm.bx[i]);
          f[3 * i + 1] += w * (sxy * bx[i] + (syy - pm) * by[i] + syz * bz[i] + pm * bm.by[i]);
          f[3 * i + 2] += w * (szx * bx[i] + syz * by[i] + (szz - pm) * bz[i] + pm * bm.bz[i]);
        }
      }
    }
  }
  return r;
}

}  // namespace

void SolidBlockState::resize(const core::SolidBlock& block) {
  points = block.formulation == core::SolidFormulation::one_point ? 1 : 8;
  const std::size_t n = block.size();
  for (auto& c : s)
    c.assign(n * static_cast<std::size_t>(points), 0.0);
  hourglass.assign(n * 12, 0.0);
  force.assign(n * 24, 0.0);
  volume.assign(n, 0.0);
}

SolidResult solid_forces(const core::SolidBlock& block, const core::Material& material,
                         SolidBlockState& state, const NodalView& nodes, double dt,
                         std::size_t begin, std::size_t end) {
  return std::visit(
      [&](const auto& m) {
        if (block.formulation == core::SolidFormulation::one_point) {
          return one_point(block, m, state, nodes, dt, begin, end);
        }
        return selective_reduced(block, m, state, nodes, dt, begin, end);
      },
      material);
}

double solid_stable_dt(const core::SolidBlock& block, const core::Material& material,
                       const NodalView& nodes, std::size_t e) {
  HexCoords c;
  gather(block, e, nodes.x, nodes.y, nodes.z, c);
  UniformGradient g;
  if (!uniform_gradient(c, g))
    return 0.0;
  return characteristic_length(g) / material::dilatational_wave_speed(material);
}

double solid_reference_volume(const core::SolidBlock& block, const NodalView& nodes,
                              std::size_t e) {
  HexCoords c;
  gather(block, e, nodes.x0, nodes.y0, nodes.z0, c);
  UniformGradient g;
  uniform_gradient(c, g);
  return g.volume;
}

}  // namespace plyform::element
