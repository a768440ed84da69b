#pragma once
// The stages both shell formulations run on a chunk of elements (Belytschko-Tsay,
// shell_bt.cpp; fully integrated, shell_full.cpp), one copy of each: the co-rotational frames
// lane-wise across the chunk's elements, the stress turn by the material's spin, the
// temperatures of the thickness points, the material axes, the one law call for all the
// chunk's points, the resultants and the plastic dissipation of a column of thickness points,
// and the scatter of an element's local forces and moments to its nodes. A formulation adds
// only what differs: where its in-plane points are and how its forces come from them.

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "plyform/element/shell_kernels.hpp"
#include "plyform/material/shell.hpp"
#include "shell_common.hpp"

namespace plyform::element::shell_detail {

// The co-rotational frames of a chunk of N elements, one lane per element (structure of
// arrays, so that the loops over lanes vectorise across elements).
template <std::size_t N>
struct ChunkFrames {
  alignas(64) double x[4][N], y[4][N], z[4][N];  // nodal coordinates, global
  alignas(64) double vx[4][N], vy[4][N], vz[4][N], wx[4][N], wy[4][N], wz[4][N];
  alignas(64) double e[9][N];               // e1, e2, e3 (the normal)
  alignas(64) double xl[4][N], yl[4][N];    // local in-plane coordinates about the centroid
  alignas(64) double vl[12][N], wl[12][N];  // nodal velocities and spins in the frame
  alignas(64) double area[N], length[N];    // current area; the shell length of the step
};

// Gathers elements c0 .. c0 + chunk - 1 into the lanes and computes their frames: e3 along
// the diagonals' cross product, e1 along the mid-side vector from edge 4-1 to edge 2-3
// projected on the plane, e2 = e3 x e1 (as geometry() in shell_common.hpp). Padding lanes
// repeat the chunk's first element; their results are never read. A collapsed element gives a
// zero or non-finite area or frame, which the caller checks.
template <std::size_t N>
inline void chunk_frames(const core::ShellBlock& block, const NodalView& nv, const NodalSpin& spin,
                         std::size_t c0, std::size_t chunk, ChunkFrames<N>& f) {
  for (std::size_t k = 0; k < N; ++k) {
    const core::Index* cn = &block.connectivity[4 * (c0 + (k < chunk ? k : 0))];
    for (int i = 0; i < 4; ++i) {
      const auto n = static_cast<std::size_t>(cn[i]);
      const double* pk = nv.packed + 6 * n;
      f.x[i][k] = pk[0];
      f.y[i][k] = pk[1];
      f.z[i][k] = pk[2];
      f.vx[i][k] = pk[3];
      f.vy[i][k] = pk[4];
      f.vz[i][k] = pk[5];
      f.wx[i][k] = spin.wx[n];
      f.wy[i][k] = spin.wy[n];
      f.wz[i][k] = spin.wz[n];
    }
    f.length[k] = cn[2] == cn[3] ? 2.0 : 1.0;  // a triangle's shell length is twice A / side
  }
  for (std::size_t k = 0; k < N; ++k) {
    const double r31x = f.x[2][k] - f.x[0][k], r31y = f.y[2][k] - f.y[0][k],
                 r31z = f.z[2][k] - f.z[0][k];
    const double r42x = f.x[3][k] - f.x[1][k], r42y = f.y[3][k] - f.y[1][k],
                 r42z = f.z[3][k] - f.z[1][k];
    double nx = r31y * r42z - r31z * r42y, ny = r31z * r42x - r31x * r42z,
           nz = r31x * r42y - r31y * r42x;
    const double ninv = 1.0 / std::sqrt(nx * nx + ny * ny + nz * nz);
    nx *= ninv, ny *= ninv, nz *= ninv;
    double sx = 0.5 * (f.x[1][k] + f.x[2][k] - f.x[0][k] - f.x[3][k]);
    double sy = 0.5 * (f.y[1][k] + f.y[2][k] - f.y[0][k] - f.y[3][k]);
    double sz = 0.5 * (f.z[1][k] + f.z[2][k] - f.z[0][k] - f.z[3][k]);
    const double sn = sx * nx + sy * ny + sz * nz;
    sx -= sn * nx, sy -= sn * ny, sz -= sn * nz;
    const double sinv = 1.0 / std::sqrt(sx * sx + sy * sy + sz * sz);
    const double e1x = sx * sinv, e1y = sy * sinv, e1z = sz * sinv;
    const double e2x = ny * e1z - nz * e1y, e2y = nz * e1x - nx * e1z, e2z = nx * e1y - ny * e1x;
    f.e[0][k] = e1x, f.e[1][k] = e1y, f.e[2][k] = e1z;
    f.e[3][k] = e2x, f.e[4][k] = e2y, f.e[5][k] = e2z;
    f.e[6][k] = nx, f.e[7][k] = ny, f.e[8][k] = nz;
    const double cx = 0.25 * (f.x[0][k] + f.x[1][k] + f.x[2][k] + f.x[3][k]);
    const double cy = 0.25 * (f.y[0][k] + f.y[1][k] + f.y[2][k] + f.y[3][k]);
    const double cz = 0.25 * (f.z[0][k] + f.z[1][k] + f.z[2][k] + f.z[3][k]);
    double xl[4], yl[4], lmax2 = 0.0;
    for (int i = 0; i < 4; ++i) {
      const double rx = f.x[i][k] - cx, ry = f.y[i][k] - cy, rz = f.z[i][k] - cz;
      xl[i] = rx * e1x + ry * e1y + rz * e1z;
      yl[i] = rx * e2x + ry * e2y + rz * e2z;
      f.xl[i][k] = xl[i];
      f.yl[i][k] = yl[i];
      const int j = (i + 1) % 4;
      const double dx = f.x[j][k] - f.x[i][k], dy = f.y[j][k] - f.y[i][k],
                   dz = f.z[j][k] - f.z[i][k];
      lmax2 = std::max(lmax2, dx * dx + dy * dy + dz * dz);
    }
    const double area =
        0.5 * ((xl[2] - xl[0]) * (yl[3] - yl[1]) + (xl[1] - xl[3]) * (yl[2] - yl[0]));
    f.area[k] = area;
    f.length[k] *= area / std::sqrt(lmax2);
    for (int i = 0; i < 4; ++i) {
      const double vx = f.vx[i][k], vy = f.vy[i][k], vz = f.vz[i][k];
      const double wx = f.wx[i][k], wy = f.wy[i][k], wz = f.wz[i][k];
      f.vl[3 * i][k] = vx * e1x + vy * e1y + vz * e1z;
      f.vl[3 * i + 1][k] = vx * e2x + vy * e2y + vz * e2z;
      f.vl[3 * i + 2][k] = vx * nx + vy * ny + vz * nz;
      f.wl[3 * i][k] = wx * e1x + wy * e1y + wz * e1z;
      f.wl[3 * i + 1][k] = wx * e2x + wy * e2y + wz * e2z;
      f.wl[3 * i + 2][k] = wx * nx + wy * ny + wz * nz;
    }
  }
}

// Whether lane k holds a usable element of thickness t: a positive area and a finite frame.
template <std::size_t N>
inline bool frame_usable(const ChunkFrames<N>& f, std::size_t k, double t) {
  return f.area[k] > 0.0 && t > 0.0 && std::isfinite(f.e[0][k] + f.e[6][k]);
}

// The mid-surface velocity gradient of an in-plane point, l3 = [[dxx, lxy, -sx], [lyx, dyy, -sy],
// [sx, sy, 0]] in the frame at t_{n+1}, mapped to the mid-step configuration as a whole 3 x 3,
// L_m = L (I - dt/2 L)^-1 (Hughes-Winget): its third column is the turning of the normal, its
// third row the out-of-plane slopes, so that a rigid rotation about any axis gives an exactly
// skew L_m and no strain however far and fast the shell turns. Returns L_m's in-plane block.
// (The in-plane 2 x 2 block alone is exact for turning in the plane only: a shell tumbling
// about an in-plane axis saw a stretch rate of omega^2 dt / 2 and gained energy.)
struct InPlaneRate {
  double a00, a01, a10, a11;
};
inline InPlaneRate mid_step_rate(double dxx, double lxy, double lyx, double dyy, double sx,
                                 double sy, double dt) {
  const double h2 = 0.5 * dt;
  const double l3[3][3] = {{dxx, lxy, -sx}, {lyx, dyy, -sy}, {sx, sy, 0.0}};
  double m3[3][3];
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col)
      m3[row][col] = (row == col ? 1.0 : 0.0) - h2 * l3[row][col];
  // Inverse by cofactors (m3 is within dt |L| of the identity: never singular).
  const double c00 = m3[1][1] * m3[2][2] - m3[1][2] * m3[2][1];
  const double c01 = m3[1][2] * m3[2][0] - m3[1][0] * m3[2][2];
  const double c02 = m3[1][0] * m3[2][1] - m3[1][1] * m3[2][0];
  const double idet = 1.0 / (m3[0][0] * c00 + m3[0][1] * c01 + m3[0][2] * c02);
  const double inv[3][2] = {{c00 * idet, (m3[0][2] * m3[2][1] - m3[0][1] * m3[2][2]) * idet},
                            {c01 * idet, (m3[0][0] * m3[2][2] - m3[0][2] * m3[2][0]) * idet},
                            {c02 * idet, (m3[0][1] * m3[2][0] - m3[0][0] * m3[2][1]) * idet}};
  double am[2][2];
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 2; ++col)
      am[row][col] = l3[row][0] * inv[0][col] + l3[row][1] * inv[1][col] + l3[row][2] * inv[2][col];
  return {am[0][0], am[0][1], am[1][0], am[1][1]};
}

// The inputs and scratch of one law call over P points (a chunk's thickness points).
template <std::size_t P>
struct PointBuffers {
  double dxx[P], dyy[P], dxy[P], dyz[P], dzx[P], dzz[P];
  double cos_t[P], sin_t[P], spin[P];
  double material_spin[P], frame_turn[P];    // laws that keep material lines (needs_frame_turn)
  double temperature[P], eps_p0[P], eth[P];  // thermal blocks; the plastic strain before the law
};

// The temperatures of element e's thickness points at t_{n+1}: the mean of its nodes' (a
// triangle's three), through the thickness the quadratic profile of a thick thermal shell's
// bottom, middle and top (uniform for a thin one); and the free thermal strain of the step,
// alpha(T_mid) dT, where the block expands. Stores the new temperatures in the state (one per
// thickness point; every in-plane point of the element shares them).
inline void thickness_temperatures(const core::ShellBlock& block, const NodalView& nv,
                                   ShellBlockState& st, std::size_t e, const double* zeta,
                                   std::size_t nip, double dt, bool expands, double* t_point,
                                   double* eth_point) {
  const core::Index* cn = &block.connectivity[4 * e];
  const bool tri = cn[2] == cn[3];
  const auto mean = [&](const double* tn) {
    const auto n0 = static_cast<std::size_t>(cn[0]), n1 = static_cast<std::size_t>(cn[1]),
               n2 = static_cast<std::size_t>(cn[2]), n3 = static_cast<std::size_t>(cn[3]);
    return tri ? (tn[n0] + tn[n1] + tn[n2]) / 3.0 : 0.25 * (tn[n0] + tn[n1] + tn[n2] + tn[n3]);
  };
  const double t_mid = mean(nv.temperature);
  const bool faces = nv.temperature_bottom != nullptr;
  const double t_bottom = faces ? mean(nv.temperature_bottom) : t_mid;
  const double t_top = faces ? mean(nv.temperature_top) : t_mid;
  for (std::size_t k = 0; k < nip; ++k) {
    const double z = zeta[k];
    const double t_new =
        0.5 * z * (z - 1.0) * t_bottom + (1.0 - z * z) * t_mid + 0.5 * z * (z + 1.0) * t_top;
    eth_point[k] = 0.0;
    if (dt > 0.0) {
      double& t_old = st.temperature[nip * e + k];
      if (expands)
        eth_point[k] = block.expansion(0.5 * (t_old + t_new)) * (t_new - t_old);
      t_old = t_new;
    }
    t_point[k] = t_new;
  }
}

// The material axes of lane k's element (element e) at its n points from at0, as the angle's
// cosine and sine: AOPT 0 along the edge from node 1 to node 2, AOPT 2 the global vector a,
// AOPT 3 v x n, all projected on the shell; AOPT 0 and 3 then turn about the normal by the
// element card's BETA where it is not zero, else by the material's angle (MANGL).
template <class Law, class M, std::size_t N, std::size_t P>
inline void set_material_axes(const M& mat, const core::ShellBlock& block, std::size_t e,
                              const ChunkFrames<N>& f, std::size_t k, PointBuffers<P>& b,
                              std::size_t at0, std::size_t n) {
  const material::MaterialAxes axes = Law::axes(mat);
  double a3[3] = {f.x[1][k] - f.x[0][k], f.y[1][k] - f.y[0][k], f.z[1][k] - f.z[0][k]};
  if (axes.aopt == 2) {
    for (int d = 0; d < 3; ++d)
      a3[d] = axes.a[d];
  }
  if (axes.aopt == 3) {
    a3[0] = axes.v[1] * f.e[8][k] - axes.v[2] * f.e[7][k];
    a3[1] = axes.v[2] * f.e[6][k] - axes.v[0] * f.e[8][k];
    a3[2] = axes.v[0] * f.e[7][k] - axes.v[1] * f.e[6][k];
  }
  const double ax = a3[0] * f.e[0][k] + a3[1] * f.e[1][k] + a3[2] * f.e[2][k];
  const double ay = a3[0] * f.e[3][k] + a3[1] * f.e[4][k] + a3[2] * f.e[5][k];
  double angle = std::atan2(ay, ax);
  if (axes.aopt != 2) {
    const double beta = block.material_angle.empty() ? 0.0 : block.material_angle[e];
    angle += beta != 0.0 ? beta : axes.angle;
  }
  std::fill_n(&b.cos_t[at0], n, std::cos(angle));
  std::fill_n(&b.sin_t[at0], n, std::sin(angle));
}

// One law call over the n points from q0 (the chunk's), with what the law reads; then the
// thermal strain added back to the increments (the stress work counts the total strain: the
// forces do that work) and to the thickness strain (free expansion).
template <class Law, class M, std::size_t P>
inline void update_points(const M& mat, ShellBlockState& st, std::size_t q0, std::size_t n,
                          PointBuffers<P>& b, bool thermal, bool plastic_heat, bool expands,
                          double dt) {
  constexpr std::size_t per_point = Law::history.size();
  material::ShellPoints pts{b.dxx,        b.dyy,        b.dxy,         b.dyz,
                            b.dzx,        &st.s[0][q0], &st.s[1][q0],  &st.s[2][q0],
                            &st.s[3][q0], &st.s[4][q0], &st.eps_p[q0], b.dzz};
  if constexpr (Law::needs_material_axes) {
    pts.cos_t = b.cos_t;
    pts.sin_t = b.sin_t;
  }
  pts.dt = dt;
  if constexpr (per_point > 0)
    pts.history = &st.history[per_point * q0];
  if (thermal)
    pts.temperature = b.temperature;
  if constexpr (material::law_needs_spin<Law>())
    pts.spin = b.spin;
  if constexpr (material::law_needs_frame_turn<Law>()) {
    pts.material_spin = b.material_spin;
    pts.frame_turn = b.frame_turn;
  }
  if (plastic_heat)
    std::copy_n(&st.eps_p[q0], n, b.eps_p0);
  Law::update_shell(mat, n, pts);
  if (expands) {
    for (std::size_t at = 0; at < n; ++at) {
      const double eth = b.eth[at];
      b.dxx[at] += eth;
      b.dyy[at] += eth;
      b.dzz[at] += eth;
    }
  }
}

// The columns of an element's G in-plane points (G = 1 for BT, 4 for ELFORM 16): thickness
// point k of in-plane point g at q0 + g nip + k in the state (at0 + g nip + k in the chunk's
// buffers).
//
// The rates of in-plane point g over the step, rate[r][g]: the mapped membrane rate (dxx, dyy,
// dxy + dyx), the curvature rates (kx, ky, kxy), the transverse shear strains (gxz, gyz).
constexpr int kColumnRates = 8;

// Turns the stored stresses of each column by phi[g] about the normal (the material's spin
// relative to the frame's: Jaumann relative to the frame, so the result does not depend on
// which edges the frame follows; Cayley form, exactly orthogonal, no trigonometry); sets the
// strain increments of the points (tensor shears; the shear factor kappa scales the transverse
// shear); returns each column's stress work per unit volume before the law (work_old), weighted
// by the thickness rule: sigma : d_eps with the transverse shear as the element's forces see it
// (the resultant times the unscaled shear rate: the shear factor scales only the stiffness).
template <std::size_t G, std::size_t P>
inline void prepare_columns(ShellBlockState& st, PointBuffers<P>& b, std::size_t q0,
                            std::size_t at0, std::size_t nip, double t, const double* zeta,
                            const double* weight, double kappa, double dt,
                            const double (&rate)[kColumnRates][G], const double (&phi)[G],
                            double (&work_old)[G]) {
  const double inv_kappa = kappa > 0.0 ? 1.0 / kappa : 0.0;
  double c[G], sn[G];
  for (std::size_t g = 0; g < G; ++g) {
    const double half_sq = 0.25 * phi[g] * phi[g], inv = 1.0 / (1.0 + half_sq);
    c[g] = (1.0 - half_sq) * inv;
    sn[g] = phi[g] * inv;
  }
  // The arrays through restrict pointers: they never overlap, and the loop over a column
  // vectorises.
  double* __restrict sxx = st.s[0].data() + q0;
  double* __restrict syy = st.s[1].data() + q0;
  double* __restrict sxy = st.s[2].data() + q0;
  double* __restrict syz = st.s[3].data() + q0;
  double* __restrict szx = st.s[4].data() + q0;
  double* __restrict dxx = b.dxx + at0;
  double* __restrict dyy = b.dyy + at0;
  double* __restrict dxy = b.dxy + at0;
  double* __restrict dyz = b.dyz + at0;
  double* __restrict dzx = b.dzx + at0;
  for (std::size_t g = 0; g < G; ++g) {
    const double cg = c[g], sg = sn[g];
    double w = 0.0;
    for (std::size_t k = 0; k < nip; ++k) {
      const double z = 0.5 * t * zeta[k];
      const std::size_t i = g * nip + k;
      const double sx = sxx[i], sy = syy[i], txy = sxy[i], tzx = szx[i], tyz = syz[i];
      const double s0 = cg * cg * sx + sg * sg * sy - 2.0 * cg * sg * txy;
      const double s1 = sg * sg * sx + cg * cg * sy + 2.0 * cg * sg * txy;
      const double s2 = cg * sg * (sx - sy) + (cg * cg - sg * sg) * txy;
      const double s4 = cg * tzx - sg * tyz;
      const double s3 = sg * tzx + cg * tyz;
      sxx[i] = s0, syy[i] = s1, sxy[i] = s2, syz[i] = s3, szx[i] = s4;
      const double exx = (rate[0][g] + z * rate[3][g]) * dt;
      const double eyy = (rate[1][g] + z * rate[4][g]) * dt;
      const double exy = 0.5 * (rate[2][g] + z * rate[5][g]) * dt;
      const double eyz = 0.5 * kappa * rate[7][g] * dt;
      const double ezx = 0.5 * kappa * rate[6][g] * dt;
      dxx[i] = exx, dyy[i] = eyy, dxy[i] = exy, dyz[i] = eyz, dzx[i] = ezx;
      w += weight[k] *
           (s0 * exx + s1 * eyy + 2.0 * s2 * exy + 2.0 * inv_kappa * (s3 * eyz + s4 * ezx));
    }
    work_old[g] = w;
  }
}

// Each point's temperature and thermal strain (one per thickness point, the same in every
// column) into the buffers; the thermal strain off the in-plane increments the law sees.
template <std::size_t G, std::size_t P>
inline void spread_temperatures(PointBuffers<P>& b, std::size_t at0, std::size_t nip,
                                const double* t_point, const double* eth_point) {
  for (std::size_t g = 0; g < G; ++g)
    for (std::size_t k = 0; k < nip; ++k) {
      const std::size_t at = at0 + g * nip + k;
      b.eth[at] = eth_point[k];
      b.dxx[at] -= eth_point[k];
      b.dyy[at] -= eth_point[k];
      b.temperature[at] = t_point[k];
    }
}

// A value per column (value[g]) at every point of the columns.
template <std::size_t G>
inline void spread_columns(double* out, std::size_t nip, const double (&value)[G]) {
  for (std::size_t g = 0; g < G; ++g)
    for (std::size_t k = 0; k < nip; ++k)
      out[g * nip + k] = value[g];
}

// What the force stage needs of the columns after the law: the resultants of each column of a
// shell of thickness t (membrane forces N, moments M, transverse shear forces Q per unit
// length), its stress work per unit volume after the law, its plastic dissipation per unit
// volume (sigma_eq d eps_p, the backward-Euler return's sigma : d eps^p, the plane-stress von
// Mises stress of the in-plane components; the transverse shear stays elastic), and the
// thickness strain of the step, the mean over all the points.
template <std::size_t G>
struct ColumnSums {
  double nxx[G], nyy[G], nxy[G], mxx[G], myy[G], mxy[G], qx[G], qy[G];
  double work[G], plastic[G];
  double tz;
};
// The factors that put a column's resultants, summed over the thickness t_n of the step's start
// (sum_columns), on the end-of-step thickness t_{n+1} = t_n (1 + tz): the stresses sigma_{n+1}
// are the end configuration's, and so must be the thickness they act over (membrane and
// transverse shear forces scale with t, moments with t^2). On t_n the thickness lagged its
// stresses by a step: in a membrane under in-plane compression the Poisson thickening that
// follows each oscillation of the in-plane strain then worked on the oscillation, and an
// elastic sheet compressed by 1.4 % with its nodes held in z gained energy until it blew up
// (ELFORM 2 and 16 alike, at any step; a soft core compressed at its free edge in the square
// cup's frictionless sandwich did the same: examples/square_cup/README.md).
struct ThicknessScale {
  explicit ThicknessScale(double tz) : n(1.0 + tz), m((1.0 + tz) * (1.0 + tz)) {}
  double n, m;  // forces, moments
};

template <std::size_t G, std::size_t P>
[[gnu::always_inline]] inline void sum_columns(const ShellBlockState& st, const PointBuffers<P>& b,
                                               std::size_t q0, std::size_t at0, std::size_t nip,
                                               double t, const double* zeta, const double* weight,
                                               double kappa, bool plastic, ColumnSums<G>& r) {
  const double inv_kappa = kappa > 0.0 ? 1.0 / kappa : 0.0;
  constexpr double kMean = 0.5 / static_cast<double>(G);  // the weights sum to 2 per column
  const double* __restrict sxx = st.s[0].data() + q0;
  const double* __restrict syy = st.s[1].data() + q0;
  const double* __restrict sxy = st.s[2].data() + q0;
  const double* __restrict syz = st.s[3].data() + q0;
  const double* __restrict szx = st.s[4].data() + q0;
  const double* __restrict eps = st.eps_p.data() + q0;
  const double* __restrict eps0 = b.eps_p0 + at0;
  const double* __restrict dxx = b.dxx + at0;
  const double* __restrict dyy = b.dyy + at0;
  const double* __restrict dxy = b.dxy + at0;
  const double* __restrict dyz = b.dyz + at0;
  const double* __restrict dzx = b.dzx + at0;
  const double* __restrict dzz = b.dzz + at0;
  double tz = 0.0;
  // With four columns (ELFORM 16) the plastic work's branch is taken outside the loops: inside,
  // GCC turned its loads into masked vector loads, after which this project's AMD EPYC stalled
  // depending on where the stack lay (ASLR): the ELFORM 16 plate benchmark ran at 1.0-3.5 M
  // element-cycles/s from run to run, and at 3.55-3.66 M with the branch outside. With one
  // column (Belytschko-Tsay) the branch stays inside: outside, that plate ran 5 % slower.
  enum class Plastic { inside, always, never };
  const auto columns = [&]<Plastic kPlastic>() __attribute__((always_inline)) {
    for (std::size_t g = 0; g < G; ++g) {
      double nxx = 0, nyy = 0, nxy = 0, mxx = 0, myy = 0, mxy = 0, qx = 0, qy = 0, w = 0, wp = 0;
      for (std::size_t k = 0; k < nip; ++k) {
        const double wk = 0.5 * t * weight[k], z = 0.5 * t * zeta[k];
        const std::size_t i = g * nip + k;
        const double s0 = sxx[i], s1 = syy[i], s2 = sxy[i], s3 = syz[i], s4 = szx[i];
        nxx += wk * s0;
        nyy += wk * s1;
        nxy += wk * s2;
        mxx += wk * z * s0;
        myy += wk * z * s1;
        mxy += wk * z * s2;
        qy += wk * s3;
        qx += wk * s4;
        tz += kMean * weight[k] * dzz[i];
        w += weight[k] * (s0 * dxx[i] + s1 * dyy[i] + 2.0 * s2 * dxy[i] +
                          2.0 * inv_kappa * (s3 * dyz[i] + s4 * dzx[i]));
        if (kPlastic == Plastic::always || (kPlastic == Plastic::inside && plastic)) {
          const double de = eps[i] - eps0[i];
          const double eq = std::sqrt(s0 * s0 + s1 * s1 - s0 * s1 + 3.0 * s2 * s2);
          wp += de > 0.0 ? weight[k] * eq * de : 0.0;
        }
      }
      r.nxx[g] = nxx, r.nyy[g] = nyy, r.nxy[g] = nxy, r.mxx[g] = mxx, r.myy[g] = myy;
      r.mxy[g] = mxy, r.qx[g] = qx, r.qy[g] = qy, r.work[g] = w, r.plastic[g] = wp;
    }
  };
  if constexpr (G == 1)
    columns.template operator()<Plastic::inside>();
  else if (plastic)
    columns.template operator()<Plastic::always>();
  else
    columns.template operator()<Plastic::never>();
  r.tz = tz;
}

// Plastic work wp of element e shared among its nodes (a triangle's three), as heat.
inline void spread_plastic_work(const core::Index* conn, double wp, const NodalForces& out) {
  if (!(wp > 0.0))
    return;
  const bool tri = conn[2] == conn[3];
  const double share = wp / (tri ? 3.0 : 4.0);
  for (int i = 0; i < (tri ? 3 : 4); ++i)
    out.plastic_work[static_cast<std::size_t>(conn[i])] += share;
}

// An element's local nodal forces fl and moments ml (about e1, e2) turned to global axes and
// added to its nodes (a triangle's fourth node is its third). e: lane k of the frames.
template <std::size_t N>
inline void scatter(const core::Index* conn, const ChunkFrames<N>& f, std::size_t k,
                    const double fl[4][3], const double ml[4][2], const NodalForces& out,
                    const NodalMoments& mom) {
  const double e1[3] = {f.e[0][k], f.e[1][k], f.e[2][k]};
  const double e2[3] = {f.e[3][k], f.e[4][k], f.e[5][k]};
  const double e3[3] = {f.e[6][k], f.e[7][k], f.e[8][k]};
  for (int i = 0; i < 4; ++i) {
    const auto n = static_cast<std::size_t>(conn[i]);
    for (int d = 0; d < 3; ++d) {
      const double fo = e1[d] * fl[i][0] + e2[d] * fl[i][1] + e3[d] * fl[i][2];
      const double mo = e1[d] * ml[i][0] + e2[d] * ml[i][1];
      (d == 0 ? out.fx : d == 1 ? out.fy : out.fz)[n] += fo;
      (d == 0 ? mom.mx : d == 1 ? mom.my : mom.mz)[n] += mo;
    }
  }
}

}  // namespace plyform::element::shell_detail
