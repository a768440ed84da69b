#include "plyform/element/solid_kernels.hpp"
#include <algorithm>

#include <cmath>
#include <type_traits>
#include <variant>

#include "plyform/element/hex8_geometry.hpp"
#include "plyform/material/law_registry.hpp"

namespace plyform::element {
namespace {

constexpr std::size_t kChunk = 32;  // points per material call: scratch stays in L1

// The law of a material's parameters (material/law_registry.hpp): the kernels read its traits
// only, never which law it is.
template <class M>
using LawOf = material::LawOf<M>;

void gather(const core::SolidBlock& b, std::size_t e, const double* x, const double* y,
            const double* z, HexCoords& c) {
  const core::Index* n = &b.connectivity[8 * e];
  for (int i = 0; i < 8; ++i) {
    c.x[i] = x[n[i]];
    c.y[i] = y[n[i]];
    c.z[i] = z[n[i]];
  }
}

// Current coordinates and velocities of element e's nodes, from the packed copy when given.
void gather_state(const core::SolidBlock& b, std::size_t e, const NodalView& nv, HexCoords& c,
                  HexCoords& v) {
  if (nv.packed == nullptr) {
    gather(b, e, nv.x, nv.y, nv.z, c);
    gather(b, e, nv.vx, nv.vy, nv.vz, v);
    return;
  }
  const core::Index* n = &b.connectivity[8 * e];
  for (int i = 0; i < 8; ++i) {
    const double* p = nv.packed + 6 * static_cast<std::size_t>(n[i]);
    c.x[i] = p[0];
    c.y[i] = p[1];
    c.z[i] = p[2];
    v.x[i] = p[3];
    v.y[i] = p[4];
    v.z[i] = p[5];
  }
}

// Per-chunk scratch: kinematics at each point, in structure-of-arrays form for the material.
struct PointScratch {
  double d[6][kChunk];
  double jm[kChunk];  // V(x_{n+1/2}) / V(x_{n+1}) at the point (to_mid_step)
  double w[3][kChunk];
  double f[9][kChunk];
};

template <class M>
void update_material(const M& m, std::size_t n, PointScratch& s, double dt, SolidBlockState& st,
                     std::size_t first_point, const double* temperature) {
  using Law = LawOf<M>;
  const double* f[9] = {s.f[0], s.f[1], s.f[2], s.f[3], s.f[4], s.f[5], s.f[6], s.f[7], s.f[8]};
  material::SolidPoints p;
  p.n = n;
  p.d = {s.d[0], s.d[1], s.d[2], s.d[3], s.d[4], s.d[5]};
  p.w[0] = s.w[0];
  p.w[1] = s.w[1];
  p.w[2] = s.w[2];
  p.f = f;
  p.dt = dt;
  p.sigma = {&st.s[0][first_point], &st.s[1][first_point], &st.s[2][first_point],
             &st.s[3][first_point], &st.s[4][first_point], &st.s[5][first_point]};
  p.eps_p = &st.eps_p[first_point];
  constexpr std::size_t per_point = Law::history.size();
  p.history = per_point > 0 ? &st.history[per_point * first_point] : nullptr;
  p.temperature = temperature;
  Law::update_solid(m, p);
}

// The element's temperature (the mean of its nodes') and, over a step (dt > 0), the thermal
// strain increment alpha(T_mid) dT since its last update, which becomes the new one.
inline double element_temperature(const core::SolidBlock& block, SolidBlockState& st,
                                  const double* nodal, std::size_t e, double dt, bool expands,
                                  double& thermal_strain) {
  const core::Index* cn = &block.connectivity[8 * e];
  double t_new = 0.0;
  for (int i = 0; i < 8; ++i)
    t_new += nodal[static_cast<std::size_t>(cn[i])];
  t_new *= 0.125;
  thermal_strain = 0.0;
  if (dt > 0.0) {
    const double t_old = st.temperature[e];
    if (expands)
      thermal_strain = block.expansion(0.5 * (t_old + t_new)) * (t_new - t_old);
    st.temperature[e] = t_new;
  }
  return t_new;
}

// sqrt(3/2 s : s) of point p's stress.
inline double von_mises(const SolidBlockState& st, std::size_t p) {
  const double sxx = st.s[0][p], syy = st.s[1][p], szz = st.s[2][p];
  const double m = (sxx + syy + szz) / 3.0;
  const double dx = sxx - m, dy = syy - m, dz = szz - m;
  const double ss =
      dx * dx + dy * dy + dz * dz +
      2.0 * (st.s[3][p] * st.s[3][p] + st.s[4][p] * st.s[4][p] + st.s[5][p] * st.s[5][p]);
  return std::sqrt(1.5 * ss);
}

// L on the configuration at t_{n+1} mapped to the mid-step configuration:
// L_m = L (I - dt/2 L)^-1. A rigid rotation then gives an exactly skew L_m (Hughes-Winget), so
// the hypoelastic update stays objective however far an element turns. Returns
// det(I - dt/2 L) = V(x_{n+1/2}) / V(x_{n+1}), the volume the mid-step rate acts on: the stress
// work sigma : D_m dt of the step is per mid-step volume. Booked per end-of-step volume it was
// off by dt/2 tr(D) of itself every step, a first-order error that does not cancel (a block
// under a sliding tool drifted 1-3 % from its energy balance; a freely deforming block 2-5 %
// in 2000 steps).
inline double to_mid_step(double l[9], double dt) {
  const double h = 0.5 * dt;
  const double m[9] = {1.0 - h * l[0], -h * l[1], -h * l[2], -h * l[3],     1.0 - h * l[4],
                       -h * l[5],      -h * l[6], -h * l[7], 1.0 - h * l[8]};
  const double c0 = m[4] * m[8] - m[5] * m[7], c1 = m[5] * m[6] - m[3] * m[8],
               c2 = m[3] * m[7] - m[4] * m[6];
  const double inv_det = 1.0 / (m[0] * c0 + m[1] * c1 + m[2] * c2);
  const double mi[9] = {
      c0 * inv_det, (m[2] * m[7] - m[1] * m[8]) * inv_det, (m[1] * m[5] - m[2] * m[4]) * inv_det,
      c1 * inv_det, (m[0] * m[8] - m[2] * m[6]) * inv_det, (m[2] * m[3] - m[0] * m[5]) * inv_det,
      c2 * inv_det, (m[1] * m[6] - m[0] * m[7]) * inv_det, (m[0] * m[4] - m[1] * m[3]) * inv_det};
  double r[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r[3 * i + j] = l[3 * i] * mi[j] + l[3 * i + 1] * mi[3 + j] + l[3 * i + 2] * mi[6 + j];
  for (int k = 0; k < 9; ++k)
    l[k] = r[k];
  return 1.0 / inv_det;
}

// Velocity gradient L_ij = sum_I v_iI dN_I/dx_j -> D (sym) and W (w_xy, w_yz, w_zx), on the
// mid-step configuration (see to_mid_step).
inline void rates(const double* vx, const double* vy, const double* vz, const double* bx,
                  const double* by, const double* bz, PointScratch& s, std::size_t p, double dt) {
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
  double lm[9] = {l[0][0], l[0][1], l[0][2], l[1][0], l[1][1], l[1][2], l[2][0], l[2][1], l[2][2]};
  s.jm[p] = to_mid_step(lm, dt);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      l[i][j] = lm[3 * i + j];
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

// ELFORM 1, written lane-wise: each stage is a loop over the kLanes elements of a chunk with
// fixed-size inner loops, so the compiler vectorises across elements (structure of arrays).
constexpr std::size_t kLanes = 16;

using Lanes = double[kLanes];
using NodeLanes = double[8][kLanes];

// Flanagan-Belytschko hourglass forces of a chunk, lane-wise: gamma_a = h_a - (h_a . x) b is
// orthogonal to the linear velocity fields, so q = v . gamma = v . h_a - (h_a . x) . L picks
// out the hourglass modes only. Length scales from the gradient (exact for a cube):
// V^(2/3) ~ V sqrt(2 sum|b|^2 / 3) for the viscous form, V^(1/3) ~ (2/3) V sum|b|^2 for the
// stiffness form. `scale` is QM rho c (viscous) or QM (K + 4/3 G) (stiffness).
// Bulk viscosity (LS-DYNA's form): in compression, tr D < 0, the pressure
// q = rho l |tr D| (Q1 l |tr D| + Q2 c) = rho l Q |tr D| with l = V^(1/3) (bulk_length), the
// element's viscous velocity Q = Q1 l |tr D| + Q2 c, and the stable step L / (Q + sqrt(Q^2 + c^2))
// (L the step's characteristic length). Nothing in expansion. It smears a shock over a few elements
// and damps the ringing behind it; its work, q |tr D| V dt, is booked as internal energy.
struct BulkQ {
  double q = 0.0;   // pressure [stress]
  double qv = 0.0;  // viscous velocity Q [length/time]
};
// The length l: LS-DYNA's V^(1/3), but never more than sqrt(3) times the step's characteristic
// length L (equal for a cube, L = h / sqrt(3)): in a flat element (10 x 10 x 0.5 mm) V^(1/3) is
// 7 times its thickness, the viscous stress then damps the element's thickness mode 7 times more
// than the step L / (Q + sqrt(Q^2 + c^2)) allows for, and a free bar of such elements went
// unstable (tests/verification/solid/test_bulk_viscosity.cpp).
// An element's stress work over the step from its powers at the step's two ends, sigma_n : D V
// and sigma_{n+1} : D V (D the step's rate, the stresses with the bulk viscosity's pressure q,
// which the forces carry from one update to the next like the stress): the midpoint rule
// (sigma_n + sigma_{n+1}) / 2 : D V dt, and both powers for the engine's correction of the steps'
// lengths (engine/simulation.cpp, `step_power_correction`). Booked as q_{n+1} alone on the step's
// rate, the bulk viscosity's work ran a step ahead of its forces where the rate jumps: a wall
// striking a bar at rest read 1.07 at the first cycles, and a block's face heated by 200 K at
// once 1.03 at the end (tests/verification/engine/test_viscosity_books.cpp).
inline void step_powers(SolidResult& r, double start, double end, double dt, ElementBooks* books,
                        std::size_t e) {
  const double internal = 0.5 * (start + end) * dt;
  r.internal_energy += internal;
  r.start_power += start;
  r.end_power += end;
  if (books != nullptr) {
    books[e].internal = internal;
    books[e].start_power = start;
    books[e].end_power = end;
  }
}

inline double bulk_length(double volume, double step_length) {
  return std::min(std::cbrt(volume), std::sqrt(3.0) * step_length);
}
inline BulkQ bulk_viscosity(const core::BulkViscosity& b, double rho, double c, double l,
                            double trace) {
  if (!(trace < 0.0) || (b.q1 == 0.0 && b.q2 == 0.0))
    return {};
  const double rate = -trace;
  const double qv = b.q1 * l * rate + b.q2 * c;
  return {rho * l * qv * rate, qv};
}

template <bool kStiffness>
void hourglass_forces(double scale, double dt, const NodeLanes& X, const NodeLanes& Y,
                      const NodeLanes& Z, const NodeLanes& VX, const NodeLanes& VY,
                      const NodeLanes& VZ, const NodeLanes& BX, const NodeLanes& BY,
                      const NodeLanes& BZ, const double (&L)[9][kLanes], const Lanes& vol,
                      const Lanes& bsq, double (&HG)[12][kLanes], double (&F)[3][8][kLanes],
                      Lanes& power_start, Lanes& power_end) {
  // Loops are ordered with the lane index innermost, so each one vectorises across elements.
  alignas(64) double coeff[kLanes], hx[kLanes], hy[kLanes], hz[kLanes];
  alignas(64) double q[3][kLanes], r[3][kLanes];
  for (std::size_t k = 0; k < kLanes; ++k) {
    coeff[k] = kStiffness ? 0.25 * scale * (2.0 / 3.0) * vol[k] * bsq[k]
                          : 0.25 * scale * vol[k] * std::sqrt(2.0 * bsq[k] / 3.0);
    power_start[k] = power_end[k] = 0.0;
  }
  for (int a = 0; a < 4; ++a) {
    for (std::size_t k = 0; k < kLanes; ++k) {
      hx[k] = hy[k] = hz[k] = q[0][k] = q[1][k] = q[2][k] = 0.0;
    }
    for (int i = 0; i < 8; ++i) {
      const double ha = kHourglass[a][i];
      for (std::size_t k = 0; k < kLanes; ++k) {
        hx[k] += ha * X[i][k];
        hy[k] += ha * Y[i][k];
        hz[k] += ha * Z[i][k];
        q[0][k] += ha * VX[i][k];
        q[1][k] += ha * VY[i][k];
        q[2][k] += ha * VZ[i][k];
      }
    }
    for (std::size_t k = 0; k < kLanes; ++k) {
      double p0 = 0.0, p1 = 0.0;
      for (int d = 0; d < 3; ++d) {
        const double qd =
            q[d][k] - (hx[k] * L[3 * d][k] + hy[k] * L[3 * d + 1][k] + hz[k] * L[3 * d + 2][k]);
        double rd;
        if constexpr (kStiffness) {
          // Booked as the stress is, by the midpoint rule: the forces of t_n and t_{n+1} on the
          // step's rate, exactly the change of the stored k HG^2 / 2.
          double& h = HG[3 * a + d][k];
          p0 += coeff[k] * h * qd;
          h += qd * dt;
          rd = coeff[k] * h;
        } else {
          // The viscous force from the step's rate, booked on that rate (its force of t_n is not
          // kept: 12 values an element to load and store cost a tenth of the ELFORM 1 kernel's
          // speed); where the rate jumps its book runs a step ahead of its forces
          // (docs/energy.md).
          rd = coeff[k] * qd;
          p0 += rd * qd;
        }
        p1 += rd * qd;
        r[d][k] = rd;
      }
      power_start[k] += p0;
      power_end[k] += p1;
    }
    for (int i = 0; i < 8; ++i) {
      const double ha = kHourglass[a][i];
      for (std::size_t k = 0; k < kLanes; ++k) {
        const double g = ha - (hx[k] * BX[i][k] + hy[k] * BY[i][k] + hz[k] * BZ[i][k]);
        F[0][i][k] += r[0][k] * g;
        F[1][i][k] += r[1][k] * g;
        F[2][i][k] += r[2][k] * g;
      }
    }
  }
}

template <class M>
SolidResult one_point(const core::SolidBlock& block, const M& mat, SolidBlockState& st,
                      const NodalView& nv, double dt, std::size_t begin, std::size_t end,
                      const NodalForces& out) {
  SolidResult r;
  constexpr bool kTotal = LawOf<M>::needs_deformation_gradient;
  const double c_wave = material::dilatational_wave_speed(core::Material{mat});
  const double inv_c = 1.0 / c_wave, c2 = c_wave * c_wave;
  const double rho = mat.density;
  const core::BulkViscosity bv = block.bulk_viscosity;
  const bool bulk_on = bv.q1 != 0.0 || bv.q2 != 0.0;
  const double modulus = rho * c_wave * c_wave;  // K + 4/3 G
  const double qm = block.hourglass.qm;
  const bool stiffness_hg = block.hourglass.ihq == 4 || block.hourglass.ihq == 5;
  const core::Index* conn = block.connectivity.data();

  alignas(64) double X[8][kLanes], Y[8][kLanes], Z[8][kLanes];
  alignas(64) double VX[8][kLanes], VY[8][kLanes], VZ[8][kLanes];
  alignas(64) double BX[8][kLanes], BY[8][kLanes], BZ[8][kLanes];
  alignas(64) double F[3][8][kLanes];
  alignas(64) double L[9][kLanes], S[6][kLanes], HG[12][kLanes];
  alignas(64) double vol[kLanes], bsq[kLanes], hg_start[kLanes], hg_end[kLanes];
  double temp[kLanes], eth[kLanes], eps0[kLanes], heat[kLanes];
  const bool thermal = !st.temperature.empty() && nv.temperature != nullptr;
  const bool expands = thermal && !block.expansion.x.empty();
  const bool plastic_heat = out.plastic_work != nullptr;
  PointScratch s;

  for (std::size_t c0 = begin; c0 < end; c0 += kLanes) {
    const std::size_t n = std::min(kLanes, end - c0);
    // Gather (padding lanes repeat the first element, their results are dropped).
    for (std::size_t k = 0; k < kLanes; ++k) {
      const core::Index* e = conn + 8 * (c0 + (k < n ? k : 0));
      for (int i = 0; i < 8; ++i) {
        const auto node = static_cast<std::size_t>(e[i]);
        if (nv.packed != nullptr) {
          const double* p = nv.packed + 6 * node;
          X[i][k] = p[0];
          Y[i][k] = p[1];
          Z[i][k] = p[2];
          VX[i][k] = p[3];
          VY[i][k] = p[4];
          VZ[i][k] = p[5];
        } else {
          X[i][k] = nv.x[node];
          Y[i][k] = nv.y[node];
          Z[i][k] = nv.z[node];
          VX[i][k] = nv.vx[node];
          VY[i][k] = nv.vy[node];
          VZ[i][k] = nv.vz[node];
        }
      }
    }
    // Coordinates relative to node 1 (the hourglass vectors sum to zero, so h . x is unchanged).
    for (int i = 7; i >= 0; --i)
      for (std::size_t k = 0; k < kLanes; ++k) {
        X[i][k] -= X[0][k];
        Y[i][k] -= Y[0][k];
        Z[i][k] -= Z[0][k];
      }
    for (std::size_t k = 0; k < kLanes; ++k) {
#define X(j) X[j][k]
#define Y(j) Y[j][k]
#define Z(j) Z[j][k]
#define GX(i) BX[i][k]
#define GY(i) BY[i][k]
#define GZ(i) BZ[i][k]
#include "hex8_volume_gradient.inc"
#undef X
#undef Y
#undef Z
#undef GX
#undef GY
#undef GZ
    }
    for (std::size_t k = 0; k < kLanes; ++k) {
      double v12 = 0.0;
      for (int i = 0; i < 8; ++i)
        v12 += X[i][k] * BX[i][k];
      vol[k] = v12 / 12.0;
      const double inv = 1.0 / v12;  // a non-positive volume is reported below
      double sum = 0.0;
      for (int i = 0; i < 8; ++i) {
        BX[i][k] *= inv;
        BY[i][k] *= inv;
        BZ[i][k] *= inv;
        sum += BX[i][k] * BX[i][k] + BY[i][k] * BY[i][k] + BZ[i][k] * BZ[i][k];
      }
      bsq[k] = sum;
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (!(vol[k] > 0.0)) {
        r.failed = true;
        r.failed_element = c0 + k;
        return r;
      }
      st.volume[c0 + k] = vol[k];
    }
    // Velocity gradient L_ij = sum_I v_iI b_jI; D and W for the material.
    for (std::size_t k = 0; k < kLanes; ++k) {
      double l[9] = {};
      for (int i = 0; i < 8; ++i) {
        l[0] += VX[i][k] * BX[i][k];
        l[1] += VX[i][k] * BY[i][k];
        l[2] += VX[i][k] * BZ[i][k];
        l[3] += VY[i][k] * BX[i][k];
        l[4] += VY[i][k] * BY[i][k];
        l[5] += VY[i][k] * BZ[i][k];
        l[6] += VZ[i][k] * BX[i][k];
        l[7] += VZ[i][k] * BY[i][k];
        l[8] += VZ[i][k] * BZ[i][k];
      }
      for (int j = 0; j < 9; ++j)
        L[j][k] = l[j];
      s.jm[k] = to_mid_step(l, dt);
      s.d[0][k] = l[0];
      s.d[1][k] = l[4];
      s.d[2][k] = l[8];
      s.d[3][k] = 0.5 * (l[1] + l[3]);
      s.d[4][k] = 0.5 * (l[5] + l[7]);
      s.d[5][k] = 0.5 * (l[6] + l[2]);
      s.w[0][k] = 0.5 * (l[1] - l[3]);
      s.w[1][k] = 0.5 * (l[5] - l[7]);
      s.w[2][k] = 0.5 * (l[6] - l[2]);
    }
    // Bulk viscosity and the stable step: L / c, L = 1 / sqrt(2 sum |b|^2)
    // (characteristic_length), and L / (Q + sqrt(Q^2 + c^2)) where the element is compressed.
    alignas(64) double bulk_q[kLanes], dte[kLanes];
    for (std::size_t k = 0; k < kLanes; ++k) {
      bulk_q[k] = 0.0;
      dte[k] = inv_c / std::sqrt(2.0 * bsq[k]);
    }
    if (bulk_on) {
      for (std::size_t k = 0; k < n; ++k) {
        const BulkQ b =
            bulk_viscosity(bv, rho, c_wave, bulk_length(vol[k], 1.0 / std::sqrt(2.0 * bsq[k])),
                           s.d[0][k] + s.d[1][k] + s.d[2][k]);
        if (b.qv > 0.0) {
          bulk_q[k] = b.q;
          dte[k] = 1.0 / (std::sqrt(2.0 * bsq[k]) * (b.qv + std::sqrt(b.qv * b.qv + c2)));
        }
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      const double d = st.dt_factor[c0 + k] * dte[k];
      if (d < r.dt_min) {
        r.dt_min = d;
        r.dt_element = c0 + k;
      }
    }
    if constexpr (kTotal) {
      // F = sum_I x_I (x) b0_I with the uniform gradient of the reference configuration.
      for (std::size_t k = 0; k < n; ++k) {
        HexCoords ref, cur;
        gather(block, c0 + k, nv.x0, nv.y0, nv.z0, ref);
        UniformGradient g0;
        if (!uniform_gradient(ref, g0)) {
          r.failed = true;
          r.failed_element = c0 + k;
          return r;
        }
        for (int i = 0; i < 8; ++i) {
          cur.x[i] = X[i][k];
          cur.y[i] = Y[i][k];
          cur.z[i] = Z[i][k];
        }
        deformation_gradient(cur, g0.bx, g0.by, g0.bz, s, k);
      }
    }
    // Stress work of the step, midpoint rule: (sigma_n + sigma_{n+1}) / 2 : D dt V.
    // Component by component over the lanes (contiguous: vectorised).
    double power_start[kLanes] = {}, power_end[kLanes] = {};  // sigma_n : D, sigma_{n+1} : D
    const auto add_power = [&](double* into) {
      for (int c = 0; c < 6; ++c) {
        const double w = c < 3 ? 1.0 : 2.0;  // tensor shears count twice
        const double* sc = &st.s[c][c0];
        const double* dc = s.d[c];
        for (std::size_t k = 0; k < n; ++k)
          into[k] += w * sc[k] * dc[k];
      }
    };
    add_power(power_start);
    // Thermal expansion: the law sees the mechanical rate D - alpha dT/dt I; the stress work
    // counts the total rate (the forces do that work).
    if (thermal) {
      for (std::size_t k = 0; k < n; ++k) {
        temp[k] = element_temperature(block, st, nv.temperature, c0 + k, dt, expands, eth[k]);
        eth[k] = dt > 0.0 ? eth[k] / dt : 0.0;
        s.d[0][k] -= eth[k];
        s.d[1][k] -= eth[k];
        s.d[2][k] -= eth[k];
      }
    }
    if (plastic_heat)
      std::copy_n(&st.eps_p[c0], n, eps0);
    update_material(mat, n, s, dt, st, c0, thermal ? temp : nullptr);
    if (expands) {
      for (std::size_t k = 0; k < n; ++k) {
        s.d[0][k] += eth[k];
        s.d[1][k] += eth[k];
        s.d[2][k] += eth[k];
      }
    }
    add_power(power_end);
    for (std::size_t k = 0; k < n; ++k) {
      // The bulk viscosity's pressure is part of the stress the forces carry (step_powers).
      double& q_old = st.bulk_q[c0 + k];
      const double trace = s.d[0][k] + s.d[1][k] + s.d[2][k], scale = vol[k] * s.jm[k];
      step_powers(r, (power_start[k] - q_old * trace) * scale,
                  (power_end[k] - bulk_q[k] * trace) * scale, dt, out.books, c0 + k);
      q_old = bulk_q[k];
    }
    if (plastic_heat) {
      for (std::size_t k = 0; k < n; ++k) {
        const double de = st.eps_p[c0 + k] - eps0[k];
        heat[k] = de > 0.0 ? 0.125 * vol[k] * von_mises(st, c0 + k) * de : 0.0;
      }
    }

    for (int c = 0; c < 6; ++c)
      for (std::size_t k = 0; k < kLanes; ++k)
        S[c][k] = k < n ? st.s[c][c0 + k] - (c < 3 ? bulk_q[k] : 0.0) : 0.0;
    for (std::size_t k = 0; k < kLanes; ++k) {
      const double v = vol[k];
      for (int i = 0; i < 8; ++i) {
        F[0][i][k] = v * (S[0][k] * BX[i][k] + S[3][k] * BY[i][k] + S[5][k] * BZ[i][k]);
        F[1][i][k] = v * (S[3][k] * BX[i][k] + S[1][k] * BY[i][k] + S[4][k] * BZ[i][k]);
        F[2][i][k] = v * (S[5][k] * BX[i][k] + S[4][k] * BY[i][k] + S[2][k] * BZ[i][k]);
      }
      hg_start[k] = hg_end[k] = 0.0;
    }
    if (qm > 0.0) {
      if (stiffness_hg) {
        for (std::size_t k = 0; k < kLanes; ++k)
          for (int j = 0; j < 12; ++j)
            HG[j][k] = k < n ? st.hourglass[12 * (c0 + k) + static_cast<std::size_t>(j)] : 0.0;
        hourglass_forces<true>(qm * modulus, dt, X, Y, Z, VX, VY, VZ, BX, BY, BZ, L, vol, bsq, HG,
                               F, hg_start, hg_end);
      } else {
        hourglass_forces<false>(qm * rho * c_wave, dt, X, Y, Z, VX, VY, VZ, BX, BY, BZ, L, vol, bsq,
                                HG, F, hg_start, hg_end);
      }
      if (stiffness_hg) {
        for (std::size_t k = 0; k < n; ++k)
          for (int j = 0; j < 12; ++j)
            st.hourglass[12 * (c0 + k) + static_cast<std::size_t>(j)] = HG[j][k];
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      const core::Index* e = conn + 8 * (c0 + k);
      for (int i = 0; i < 8; ++i) {
        const auto node = static_cast<std::size_t>(e[i]);
        out.fx[node] += F[0][i][k];
        out.fy[node] += F[1][i][k];
        out.fz[node] += F[2][i][k];
        if (plastic_heat)
          out.plastic_work[node] += heat[k];
      }
      const double hg = 0.5 * (hg_start[k] + hg_end[k]) * dt;
      r.hourglass_energy += hg;
      r.hourglass_start_power += hg_start[k];
      r.hourglass_end_power += hg_end[k];
      if (out.books != nullptr) {
        out.books[c0 + k].hourglass = hg;
        out.books[c0 + k].hourglass_start_power = hg_start[k];
        out.books[c0 + k].hourglass_end_power = hg_end[k];
      }
    }
  }
  return r;
}

template <class M>
SolidResult selective_reduced(const core::SolidBlock& block, const M& mat, SolidBlockState& st,
                              const NodalView& nv, double dt, std::size_t begin, std::size_t end,
                              const NodalForces& out) {
  SolidResult r;
  constexpr bool kTotal = LawOf<M>::needs_deformation_gradient;
  constexpr std::size_t kElems = kChunk / 8;
  const double c_wave = material::dilatational_wave_speed(core::Material{mat});

  GaussGradients gg[kElems];
  UniformGradient mean[kElems];
  double bulk_q[kElems], bulk_trace[kElems], mean_jm[kElems];
  PointScratch s;
  double temp[kChunk], eth[kElems], eps0[kChunk];
  const bool thermal = !st.temperature.empty() && nv.temperature != nullptr;
  const bool expands = thermal && !block.expansion.x.empty();
  const bool plastic_heat = out.plastic_work != nullptr;
  for (std::size_t c0 = begin; c0 < end; c0 += kElems) {
    const std::size_t n = std::min(kElems, end - c0);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = c0 + k;
      HexCoords cur, v;
      gather_state(block, e, nv, cur, v);
      if (!gauss_gradients(cur, gg[k]) || !uniform_gradient(cur, mean[k])) {
        r.failed = true;
        r.failed_element = e;
        return r;
      }
      st.volume[e] = mean[k].volume;
      // Mean dilatation: the volumetric rate of every point is the element's mean.
      PointScratch one;
      rates(v.x, v.y, v.z, mean[k].bx, mean[k].by, mean[k].bz, one, 0, dt);
      const double mean_trace = one.d[0][0] + one.d[1][0] + one.d[2][0];
      mean_jm[k] = one.jm[0];
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
        rates(v.x, v.y, v.z, gg[k].bx[q], gg[k].by[q], gg[k].bz[q], s, p, dt);
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
      const BulkQ b =
          bulk_viscosity(block.bulk_viscosity, mat.density, c_wave,
                         bulk_length(mean[k].volume, characteristic_length(mean[k])), mean_trace);
      bulk_q[k] = b.q;
      bulk_trace[k] = mean_trace;
      const double dte = st.dt_factor[e] * characteristic_length(mean[k]) /
                         (b.qv + std::sqrt(b.qv * b.qv + c_wave * c_wave));
      if (dte < r.dt_min) {
        r.dt_min = dte;
        r.dt_element = e;
      }
    }
    double power_start[kChunk] = {}, power_end[kChunk] = {};
    const std::size_t np = 8 * n;
    const auto add_power = [&](double* into) {
      for (int c = 0; c < 6; ++c) {
        const double w = c < 3 ? 1.0 : 2.0;  // tensor shears count twice
        const double* sc = &st.s[c][8 * c0];
        const double* dc = s.d[c];
        for (std::size_t p = 0; p < np; ++p)
          into[p] += w * sc[p] * dc[p];
      }
    };
    add_power(power_start);
    if (thermal) {  // as one_point, the element's temperature at its 8 points
      for (std::size_t k = 0; k < n; ++k) {
        const double te =
            element_temperature(block, st, nv.temperature, c0 + k, dt, expands, eth[k]);
        eth[k] = dt > 0.0 ? eth[k] / dt : 0.0;
        for (std::size_t q = 0; q < 8; ++q) {
          temp[8 * k + q] = te;
          s.d[0][8 * k + q] -= eth[k];
          s.d[1][8 * k + q] -= eth[k];
          s.d[2][8 * k + q] -= eth[k];
        }
      }
    }
    if (plastic_heat)
      std::copy_n(&st.eps_p[8 * c0], np, eps0);
    update_material(mat, 8 * n, s, dt, st, 8 * c0, thermal ? temp : nullptr);
    if (expands) {
      for (std::size_t p = 0; p < np; ++p) {
        s.d[0][p] += eth[p / 8];
        s.d[1][p] += eth[p / 8];
        s.d[2][p] += eth[p / 8];
      }
    }
    add_power(power_end);
    for (std::size_t k = 0; k < n; ++k) {
      double& q_old = st.bulk_q[c0 + k];
      const double q_scale = bulk_trace[k] * mean[k].volume * mean_jm[k];
      double p_start = -q_old * q_scale, p_end = -bulk_q[k] * q_scale;
      for (std::size_t q = 0; q < 8; ++q) {
        const std::size_t p = 8 * k + q;
        const double scale = gg[k].weight_det[q] * s.jm[p];
        p_start += power_start[p] * scale;
        p_end += power_end[p] * scale;
      }
      step_powers(r, p_start, p_end, dt, out.books, c0 + k);
      q_old = bulk_q[k];
    }

    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = c0 + k;
      double f[24] = {};
      const UniformGradient& bm = mean[k];
      for (int q = 0; q < 8; ++q) {
        const std::size_t p = 8 * e + static_cast<std::size_t>(q);
        const double sxx = st.s[0][p], syy = st.s[1][p], szz = st.s[2][p];
        const double sxy = st.s[3][p], syz = st.s[4][p], szx = st.s[5][p];
        const double pm = (sxx + syy + szz) / 3.0;
        const double pq = pm - bulk_q[k];  // the mean stress with the bulk viscosity
        const double w = gg[k].weight_det[q];
        const double* bx = gg[k].bx[q];
        const double* by = gg[k].by[q];
        const double* bz = gg[k].bz[q];
        // Deviatoric stress with the point gradient, mean stress with the element's mean one.
        for (int i = 0; i < 8; ++i) {
          f[3 * i + 0] += w * ((sxx - pm) * bx[i] + sxy * by[i] + szx * bz[i] + pq * bm.bx[i]);
          f[3 * i + 1] += w * (sxy * bx[i] + (syy - pm) * by[i] + syz * bz[i] + pq * bm.by[i]);
          f[3 * i + 2] += w * (szx * bx[i] + syz * by[i] + (szz - pm) * bz[i] + pq * bm.bz[i]);
        }
      }
      double heat = 0.0;
      if (plastic_heat) {
        for (std::size_t q = 0; q < 8; ++q) {
          const double de = st.eps_p[8 * e + q] - eps0[8 * k + q];
          if (de > 0.0)
            heat += gg[k].weight_det[q] * von_mises(st, 8 * e + q) * de;
        }
        heat *= 0.125;
      }
      const core::Index* nodes = &block.connectivity[8 * e];
      for (int i = 0; i < 8; ++i) {
        const auto node = static_cast<std::size_t>(nodes[i]);
        out.fx[node] += f[3 * i];
        out.fy[node] += f[3 * i + 1];
        out.fz[node] += f[3 * i + 2];
        if (plastic_heat)
          out.plastic_work[node] += heat;
      }
    }
  }
  return r;
}

}  // namespace

void SolidBlockState::resize(const core::SolidBlock& block, std::size_t history_per_point) {
  points = block.formulation == core::SolidFormulation::one_point ? 1 : 8;
  const std::size_t n = block.size();
  for (auto& c : s)
    c.assign(n * static_cast<std::size_t>(points), 0.0);
  eps_p.assign(n * static_cast<std::size_t>(points), 0.0);
  history.assign(n * static_cast<std::size_t>(points) * history_per_point, 0.0);
  hourglass.assign(n * 12, 0.0);
  bulk_q.assign(n, 0.0);
  volume.assign(n, 0.0);
  dt_factor.assign(n, 1.0);
}

SolidResult solid_forces(const core::SolidBlock& block, const core::Material& material,
                         SolidBlockState& state, const NodalView& nodes, double dt,
                         std::size_t begin, std::size_t end, const NodalForces& forces) {
  return std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (LawOf<M>::for_solids) {
          if (block.formulation == core::SolidFormulation::one_point) {
            return one_point(block, m, state, nodes, dt, begin, end, forces);
          }
          return selective_reduced(block, m, state, nodes, dt, begin, end, forces);
        } else {
          // setup::build admits only the solid laws; reaching this is a programming error.
          SolidResult r;
          r.failed = true;
          r.unsupported_material = true;
          r.failed_element = begin;
          return r;
        }
      },
      material);
}

bool supports_solids(const core::Material& material) {
  return material::law_for_solids(material);
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
