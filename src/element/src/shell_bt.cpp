#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "plyform/element/shell_kernels.hpp"
#include "plyform/material/constitutive.hpp"
#include "plyform/material/law_registry.hpp"
#include "plyform/material/shell.hpp"
#include "shell_common.hpp"

namespace plyform::element {
namespace {

using namespace shell_detail;

template <class M>
ShellResult bt(const core::ShellBlock& block, const M& mat, ShellBlockState& st,
               const NodalView& nv, const NodalSpin& spin, double dt, std::size_t begin,
               std::size_t end, const NodalForces& out, const NodalMoments& mom, double wave_speed,
               double rho) {
  ShellResult r;
  const int nip = st.nip;
  double zeta[kMaxNip], weight[kMaxNip];
  thickness_rule(block.rule, nip, zeta, weight);
  const double kappa = block.shear_factor;
  const double qm = block.hourglass.qm;
  const bool stiffness_hg = block.hourglass.ihq >= 4;
  const double e_plate = rho * wave_speed * wave_speed;  // E / (1 - nu^2)
  const double h[4] = {1.0, -1.0, 1.0, -1.0};
  // Elements go in chunks: the kinematics of each element first, then one material call for
  // all the chunk's points (the law's loops then run over many points), then the forces.
  constexpr std::size_t kChunk = 16;
  constexpr std::size_t kPoints = kChunk * static_cast<std::size_t>(kMaxNip);
  double pdxx[kPoints], pdyy[kPoints], pdxy[kPoints], pdyz[kPoints], pdzx[kPoints];
  double pdzz[kPoints], pcos[kPoints], psin[kPoints], pspin[kPoints];
  double pmspin[kPoints], pturn[kPoints];  // laws that keep material lines (needs_frame_turn)
  // Temperature (thermal blocks) and the plastic strain before the law (plastic work heat).
  double ptemp[kPoints], peps0[kPoints], peth[kPoints];
  const bool thermal = !st.temperature.empty() && nv.temperature != nullptr;
  const bool expands = thermal && !block.expansion.x.empty();
  const bool plastic_heat = out.plastic_work != nullptr;
  Geometry gk[kChunk];
  double vlk[kChunk][4][3], wlk[kChunk][4][3], tk[kChunk];
  // Bulk viscosity of the membrane (TYPE -1/-2): its pressure and the compression rate.
  const bool bulk_on =
      block.bulk_viscosity_on && (block.bulk_viscosity.q1 != 0.0 || block.bulk_viscosity.q2 != 0.0);
  double bulk_q[kChunk], bulk_rate[kChunk];
  const auto unip = static_cast<std::size_t>(nip);
  alignas(64) double LX[4][kChunk], LY[4][kChunk], LZ[4][kChunk];
  alignas(64) double LVX[4][kChunk], LVY[4][kChunk], LVZ[4][kChunk];
  alignas(64) double LWX[4][kChunk], LWY[4][kChunk], LWZ[4][kChunk];
  alignas(64) double E[9][kChunk], XL[4][kChunk], YL[4][kChunk], B1[4][kChunk], B2[4][kChunk];
  alignas(64) double VL[12][kChunk], WL[12][kChunk], RATE[9][kChunk];
  alignas(64) double MSPIN[kChunk], FTURN[kChunk];
  alignas(64) double AREA[kChunk], LEN[kChunk], TRI[kChunk];
  double work_old[kChunk];
  // Stress work of an element's thickness points over the step per unit area, for stresses
  // q0.. and strain increments at0..: sigma : d_eps with the transverse shear as the element's
  // forces see it (the resultant times the unscaled shear rate: the shear factor only scales
  // the stiffness).
  const double inv_kappa = kappa > 0.0 ? 1.0 / kappa : 0.0;
  const auto point_work = [&](const ShellBlockState& sb, std::size_t q0, std::size_t at0) {
    double w = 0.0;
    for (int k = 0; k < nip; ++k) {
      const std::size_t q = q0 + static_cast<std::size_t>(k),
                        at = at0 + static_cast<std::size_t>(k);
      w +=
          weight[k] * (sb.s[0][q] * pdxx[at] + sb.s[1][q] * pdyy[at] + 2.0 * sb.s[2][q] * pdxy[at] +
                       2.0 * inv_kappa * (sb.s[3][q] * pdyz[at] + sb.s[4][q] * pdzx[at]));
    }
    return w;
  };
  for (std::size_t c0 = begin; c0 < end; c0 += kChunk) {
    const std::size_t chunk = std::min(kChunk, end - c0);
    // Stage A, lane-wise over the chunk (vectorised across elements): gather, co-rotational
    // frame, local coordinates and gradients, local velocities, rates. Padding lanes repeat
    // the chunk's first element; their results are dropped.
    for (std::size_t k = 0; k < kChunk; ++k) {
      const core::Index* cn = &block.connectivity[4 * (c0 + (k < chunk ? k : 0))];
      for (int i = 0; i < 4; ++i) {
        const auto n = static_cast<std::size_t>(cn[i]);
        const double* pk = nv.packed + 6 * n;
        LX[i][k] = pk[0];
        LY[i][k] = pk[1];
        LZ[i][k] = pk[2];
        LVX[i][k] = pk[3];
        LVY[i][k] = pk[4];
        LVZ[i][k] = pk[5];
        LWX[i][k] = spin.wx[n];
        LWY[i][k] = spin.wy[n];
        LWZ[i][k] = spin.wz[n];
      }
      TRI[k] = cn[2] == cn[3] ? 2.0 : 1.0;
    }
    for (std::size_t k = 0; k < kChunk; ++k) {
      const double r31x = LX[2][k] - LX[0][k], r31y = LY[2][k] - LY[0][k],
                   r31z = LZ[2][k] - LZ[0][k];
      const double r42x = LX[3][k] - LX[1][k], r42y = LY[3][k] - LY[1][k],
                   r42z = LZ[3][k] - LZ[1][k];
      double nx = r31y * r42z - r31z * r42y, ny = r31z * r42x - r31x * r42z,
             nz = r31x * r42y - r31y * r42x;
      const double ninv = 1.0 / std::sqrt(nx * nx + ny * ny + nz * nz);
      nx *= ninv, ny *= ninv, nz *= ninv;
      double sx = 0.5 * (LX[1][k] + LX[2][k] - LX[0][k] - LX[3][k]);
      double sy = 0.5 * (LY[1][k] + LY[2][k] - LY[0][k] - LY[3][k]);
      double sz = 0.5 * (LZ[1][k] + LZ[2][k] - LZ[0][k] - LZ[3][k]);
      const double sn = sx * nx + sy * ny + sz * nz;
      sx -= sn * nx, sy -= sn * ny, sz -= sn * nz;
      const double sinv = 1.0 / std::sqrt(sx * sx + sy * sy + sz * sz);
      const double e1x = sx * sinv, e1y = sy * sinv, e1z = sz * sinv;
      const double e2x = ny * e1z - nz * e1y, e2y = nz * e1x - nx * e1z, e2z = nx * e1y - ny * e1x;
      E[0][k] = e1x, E[1][k] = e1y, E[2][k] = e1z;
      E[3][k] = e2x, E[4][k] = e2y, E[5][k] = e2z;
      E[6][k] = nx, E[7][k] = ny, E[8][k] = nz;
      const double cx = 0.25 * (LX[0][k] + LX[1][k] + LX[2][k] + LX[3][k]);
      const double cy = 0.25 * (LY[0][k] + LY[1][k] + LY[2][k] + LY[3][k]);
      const double cz = 0.25 * (LZ[0][k] + LZ[1][k] + LZ[2][k] + LZ[3][k]);
      double xl[4], yl[4], lmax2 = 0.0;
      for (int i = 0; i < 4; ++i) {
        const double rx = LX[i][k] - cx, ry = LY[i][k] - cy, rz = LZ[i][k] - cz;
        xl[i] = rx * e1x + ry * e1y + rz * e1z;
        yl[i] = rx * e2x + ry * e2y + rz * e2z;
        XL[i][k] = xl[i];
        YL[i][k] = yl[i];
        const int j = (i + 1) % 4;
        const double dx = LX[j][k] - LX[i][k], dy = LY[j][k] - LY[i][k], dz = LZ[j][k] - LZ[i][k];
        lmax2 = std::max(lmax2, dx * dx + dy * dy + dz * dz);
      }
      const double area =
          0.5 * ((xl[2] - xl[0]) * (yl[3] - yl[1]) + (xl[1] - xl[3]) * (yl[2] - yl[0]));
      AREA[k] = area;
      LEN[k] = TRI[k] * area / std::sqrt(lmax2);
      const double inv2a = 0.5 / area;
      double b1[4], b2[4];
      b1[0] = (yl[1] - yl[3]) * inv2a;
      b1[1] = (yl[2] - yl[0]) * inv2a;
      b1[2] = (yl[3] - yl[1]) * inv2a;
      b1[3] = (yl[0] - yl[2]) * inv2a;
      b2[0] = (xl[3] - xl[1]) * inv2a;
      b2[1] = (xl[0] - xl[2]) * inv2a;
      b2[2] = (xl[1] - xl[3]) * inv2a;
      b2[3] = (xl[2] - xl[0]) * inv2a;
      double dxx = 0, dyy = 0, lxy = 0, lyx = 0, kx = 0, ky = 0, kxy = 0, gxz = 0, gyz = 0;
      double thx = 0, thy = 0;
      double vx_loc[4], vy_loc[4];
      for (int i = 0; i < 4; ++i) {
        B1[i][k] = b1[i];
        B2[i][k] = b2[i];
        const double vxl = LVX[i][k] * e1x + LVY[i][k] * e1y + LVZ[i][k] * e1z;
        const double vyl = LVX[i][k] * e2x + LVY[i][k] * e2y + LVZ[i][k] * e2z;
        const double vzl = LVX[i][k] * nx + LVY[i][k] * ny + LVZ[i][k] * nz;
        const double wxl = LWX[i][k] * e1x + LWY[i][k] * e1y + LWZ[i][k] * e1z;
        const double wyl = LWX[i][k] * e2x + LWY[i][k] * e2y + LWZ[i][k] * e2z;
        const double wzl = LWX[i][k] * nx + LWY[i][k] * ny + LWZ[i][k] * nz;
        VL[3 * i][k] = vxl, VL[3 * i + 1][k] = vyl, VL[3 * i + 2][k] = vzl;
        WL[3 * i][k] = wxl, WL[3 * i + 1][k] = wyl, WL[3 * i + 2][k] = wzl;
        vx_loc[i] = vxl;
        vy_loc[i] = vyl;
        // Membrane, bending and transverse shear rates at the centre (Mindlin kinematics:
        // u_x = u + z theta_y, u_y = v - z theta_x).
        dxx += b1[i] * vxl;
        dyy += b2[i] * vyl;
        lxy += b2[i] * vxl;
        lyx += b1[i] * vyl;
        kx += b1[i] * wyl;
        ky -= b2[i] * wxl;
        kxy += b2[i] * wyl - b1[i] * wxl;
        gxz += b1[i] * vzl;
        gyz += b2[i] * vzl;
        thx += 0.25 * wxl;
        thy += 0.25 * wyl;
      }
      // The mid-surface's velocity gradient in the frame, taken on the configuration at
      // t_{n+1}, is mapped to the mid-step configuration, L_m = L (I - dt/2 L)^-1, as a whole
      // 3 x 3 (Hughes-Winget): its third column is the turning of the normal (the nodes' mean
      // spin: dv_x/dz = theta_y, dv_y/dz = -theta_x), its third row the out-of-plane slopes.
      // A rigid rotation about any axis then gives an exactly skew L_m: no spurious membrane
      // strain however far and fast the shell turns. (The in-plane 2 x 2 block alone is exact
      // for turning in the plane only: a shell tumbling about an in-plane axis saw a stretch
      // rate of omega^2 dt / 2 and gained energy.)
      const double h2 = 0.5 * dt;
      const double l3[3][3] = {{dxx, lxy, -gxz}, {lyx, dyy, -gyz}, {gxz, gyz, 0.0}};
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
      // The in-plane block of L_m (its first two columns suffice).
      double am[2][2];
      for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 2; ++col)
          am[row][col] =
              l3[row][0] * inv[0][col] + l3[row][1] * inv[1][col] + l3[row][2] * inv[2][col];
      const double a00 = am[0][0], a01 = am[0][1], a10 = am[1][0], a11 = am[1][1];
      // The stored stresses turn with the frame (they are its components); the material's spin
      // W = (L_yx - L_xy) / 2 differs from the frame's own spin, that of the mid-side vector
      // s1 = (x2 + x3 - x1 - x4) / 2 it follows. The difference turns the stresses back
      // (Jaumann relative to the frame), so the result does not depend on which edges the
      // frame follows, i.e. on the node numbering.
      const double s1x = 0.5 * (xl[1] + xl[2] - xl[0] - xl[3]);
      const double s1v = 0.5 * (vy_loc[1] + vy_loc[2] - vy_loc[0] - vy_loc[3]);
      RATE[0][k] = a00;
      RATE[1][k] = a11;
      RATE[2][k] = a01 + a10;
      RATE[3][k] = kx;
      RATE[4][k] = ky;
      RATE[5][k] = kxy;
      RATE[6][k] = gxz + thy;
      RATE[7][k] = gyz - thx;
      RATE[8][k] = (0.5 * (a10 - a01) - s1v / s1x) * dt;
      if constexpr (material::law_needs_frame_turn<LawOf<M>>()) {
        // s1 at t_n was s1 - dt ds1/dt: the frame turned through atan of this, exactly.
        const double s1u = 0.5 * (vx_loc[1] + vx_loc[2] - vx_loc[0] - vx_loc[3]);
        MSPIN[k] = 0.5 * (a10 - a01) * dt;
        FTURN[k] = dt * s1v / (s1x - dt * s1u);
      }
    }
    // Per element: checks, the stable step, the stresses turned by the relative spin, the
    // strain increments at the thickness points, and the data the force stage needs.
    for (std::size_t e = c0; e < c0 + chunk; ++e) {
      const std::size_t k_el = e - c0;
      const double t = tk[k_el] = st.thickness[e];
      const double area = AREA[k_el];
      if (!(area > 0.0) || !(t > 0.0) || !std::isfinite(E[0][k_el] + E[6][k_el])) {
        r.failed = true;
        r.failed_element = e;
        return r;
      }
      st.area[e] = area;
      double dte = st.dt_factor[e] * LEN[k_el] / wave_speed;
      bulk_q[k_el] = 0.0;
      if (bulk_on) {
        // The solids' form on the mid-surface's in-plane compression, tr D = d11 + d22 < 0,
        // with l = sqrt(A): q = rho l |tr D| (Q1 l |tr D| + Q2 c); the step L / (Q + sqrt(Q^2 +
        // c^2)) with the viscous velocity Q = Q1 l |tr D| + Q2 c.
        const double rate = -(RATE[0][k_el] + RATE[1][k_el]);
        if (rate > 0.0) {
          const double l = std::sqrt(area);
          const double qv =
              block.bulk_viscosity.q1 * l * rate + block.bulk_viscosity.q2 * wave_speed;
          bulk_q[k_el] = rho * l * qv * rate;
          bulk_rate[k_el] = rate;
          dte = st.dt_factor[e] * LEN[k_el] / (qv + std::sqrt(qv * qv + wave_speed * wave_speed));
        }
      }
      if (dte < r.dt_min) {
        r.dt_min = dte;
        r.dt_element = e;
      }
      Geometry& g = gk[k_el];
      for (int d = 0; d < 3; ++d) {
        g.e1[d] = E[d][k_el];
        g.e2[d] = E[3 + d][k_el];
        g.e3[d] = E[6 + d][k_el];
      }
      for (int i = 0; i < 4; ++i) {
        g.xl[i] = XL[i][k_el];
        g.yl[i] = YL[i][k_el];
        g.b1[i] = B1[i][k_el];
        g.b2[i] = B2[i][k_el];
        for (int d = 0; d < 3; ++d) {
          vlk[k_el][i][d] = VL[3 * i + d][k_el];
          wlk[k_el][i][d] = WL[3 * i + d][k_el];
        }
      }
      g.area = area;
      const double phi = RATE[8][k_el];
      if (phi != 0.0) {
        // Cayley form of the rotation by phi: exactly orthogonal, no trigonometry.
        const double half_sq = 0.25 * phi * phi, inv = 1.0 / (1.0 + half_sq);
        const double c = (1.0 - half_sq) * inv, sn = phi * inv;
        const std::size_t q0 = unip * e;
        for (int k = 0; k < nip; ++k) {
          const std::size_t q = q0 + static_cast<std::size_t>(k);
          const double sx = st.s[0][q], sy = st.s[1][q], sxy = st.s[2][q];
          st.s[0][q] = c * c * sx + sn * sn * sy - 2.0 * c * sn * sxy;
          st.s[1][q] = sn * sn * sx + c * c * sy + 2.0 * c * sn * sxy;
          st.s[2][q] = c * sn * (sx - sy) + (c * c - sn * sn) * sxy;
          const double tzx = st.s[4][q], tyz = st.s[3][q];
          st.s[4][q] = c * tzx - sn * tyz;
          st.s[3][q] = sn * tzx + c * tyz;
        }
      }
      // Strain increments at the thickness points (tensor shears; the shear factor scales the
      // transverse shear).
      for (int k = 0; k < nip; ++k) {
        const double z = 0.5 * t * zeta[k];
        const std::size_t at = k_el * unip + static_cast<std::size_t>(k);
        pdxx[at] = (RATE[0][k_el] + z * RATE[3][k_el]) * dt;
        pdyy[at] = (RATE[1][k_el] + z * RATE[4][k_el]) * dt;
        pdxy[at] = 0.5 * (RATE[2][k_el] + z * RATE[5][k_el]) * dt;
        pdyz[at] = 0.5 * kappa * RATE[7][k_el] * dt;
        pdzx[at] = 0.5 * kappa * RATE[6][k_el] * dt;
      }
      work_old[k_el] = point_work(st, unip * e, k_el * unip);
      if (thermal) {
        // The temperature of each thickness point: the element's mean of its nodes' (a
        // triangle's three), through the thickness the quadratic profile of a thick thermal
        // shell's bottom, middle and top (uniform for a thin one). Thermal expansion takes
        // alpha(T_mid) dT off the in-plane increments the law sees (the stress work above and
        // below counts the total strain: the forces do that work).
        const core::Index* cn = &block.connectivity[4 * e];
        const bool tri = cn[2] == cn[3];
        const auto mean = [&](const double* tn) {
          const auto n0 = static_cast<std::size_t>(cn[0]), n1 = static_cast<std::size_t>(cn[1]),
                     n2 = static_cast<std::size_t>(cn[2]), n3 = static_cast<std::size_t>(cn[3]);
          return tri ? (tn[n0] + tn[n1] + tn[n2]) / 3.0
                     : 0.25 * (tn[n0] + tn[n1] + tn[n2] + tn[n3]);
        };
        const double t_mid = mean(nv.temperature);
        const bool faces = nv.temperature_bottom != nullptr;
        const double t_bottom = faces ? mean(nv.temperature_bottom) : t_mid;
        const double t_top = faces ? mean(nv.temperature_top) : t_mid;
        for (int k = 0; k < nip; ++k) {
          const std::size_t at = k_el * unip + static_cast<std::size_t>(k);
          const std::size_t q = unip * e + static_cast<std::size_t>(k);
          const double z = zeta[k];
          const double t_new =
              0.5 * z * (z - 1.0) * t_bottom + (1.0 - z * z) * t_mid + 0.5 * z * (z + 1.0) * t_top;
          peth[at] = 0.0;
          if (dt > 0.0) {
            const double t_old = st.temperature[q];
            if (expands)
              peth[at] = block.expansion(0.5 * (t_old + t_new)) * (t_new - t_old);
            st.temperature[q] = t_new;
          }
          pdxx[at] -= peth[at];
          pdyy[at] -= peth[at];
          ptemp[at] = t_new;
        }
      }
      const double x[4][3] = {{LX[0][k_el], LY[0][k_el], LZ[0][k_el]},
                              {LX[1][k_el], LY[1][k_el], LZ[1][k_el]},
                              {LX[2][k_el], LY[2][k_el], LZ[2][k_el]},
                              {LX[3][k_el], LY[3][k_el], LZ[3][k_el]}};
      if constexpr (LawOf<M>::needs_material_axes) {
        // AOPT 0: axis a along the edge from node 1 to node 2; AOPT 2: the global vector a;
        // AOPT 3: v x n; all projected on the shell. AOPT 0 and 3 then turn about the normal by
        // the element card's BETA where it is not zero, else by the material's angle (MANGL).
        const material::MaterialAxes axes = LawOf<M>::axes(mat);
        double a3[3];
        for (int d = 0; d < 3; ++d)
          a3[d] = axes.aopt == 2 ? axes.a[d] : x[1][d] - x[0][d];
        if (axes.aopt == 3) {
          a3[0] = axes.v[1] * g.e3[2] - axes.v[2] * g.e3[1];
          a3[1] = axes.v[2] * g.e3[0] - axes.v[0] * g.e3[2];
          a3[2] = axes.v[0] * g.e3[1] - axes.v[1] * g.e3[0];
        }
        const double ax = a3[0] * g.e1[0] + a3[1] * g.e1[1] + a3[2] * g.e1[2];
        const double ay = a3[0] * g.e2[0] + a3[1] * g.e2[1] + a3[2] * g.e2[2];
        double angle = std::atan2(ay, ax);
        if (axes.aopt != 2) {
          const double beta = block.material_angle.empty() ? 0.0 : block.material_angle[e];
          angle += beta != 0.0 ? beta : axes.angle;
        }
        for (std::size_t k = 0; k < unip; ++k) {
          pcos[k_el * unip + k] = std::cos(angle);
          psin[k_el * unip + k] = std::sin(angle);
        }
      }
      if constexpr (material::law_needs_spin<LawOf<M>>()) {
        for (std::size_t k = 0; k < unip; ++k)
          pspin[k_el * unip + k] = phi;
      }
      if constexpr (material::law_needs_frame_turn<LawOf<M>>()) {
        for (std::size_t k = 0; k < unip; ++k) {
          pmspin[k_el * unip + k] = MSPIN[k_el];
          pturn[k_el * unip + k] = FTURN[k_el];
        }
      }
    }
    {
      const std::size_t q0 = unip * c0;
      using Law = LawOf<M>;
      constexpr std::size_t per_point = Law::history.size();
      material::ShellPoints pts{pdxx,         pdyy,         pdxy,          pdyz,
                                pdzx,         &st.s[0][q0], &st.s[1][q0],  &st.s[2][q0],
                                &st.s[3][q0], &st.s[4][q0], &st.eps_p[q0], pdzz};
      if constexpr (Law::needs_material_axes) {
        pts.cos_t = pcos;
        pts.sin_t = psin;
      }
      if constexpr (per_point > 0)
        pts.history = &st.history[per_point * q0];
      if (thermal)
        pts.temperature = ptemp;
      if constexpr (material::law_needs_spin<Law>())
        pts.spin = pspin;
      if constexpr (material::law_needs_frame_turn<Law>()) {
        pts.material_spin = pmspin;
        pts.frame_turn = pturn;
      }
      if (plastic_heat)
        std::copy_n(&st.eps_p[q0], unip * chunk, peps0);
      Law::update_shell(mat, unip * chunk, pts);
      if (expands) {
        // Back to the total increments (stress work), and the free thermal thickness strain.
        for (std::size_t at = 0; at < unip * chunk; ++at) {
          const double eth = peth[at];
          pdxx[at] += eth;
          pdyy[at] += eth;
          pdzz[at] += eth;
        }
      }
    }
    for (std::size_t e = c0; e < c0 + chunk; ++e) {
      const std::size_t k_el = e - c0;
      const core::Index* conn = &block.connectivity[4 * e];
      const Geometry& g = gk[k_el];
      const auto& vl = vlk[k_el];
      const auto& wl = wlk[k_el];
      const double t = tk[k_el];
      const std::size_t q0 = unip * e;
      const double* dzz = &pdzz[unip * k_el];
      // Resultants over the thickness, and the thickness update from the mean normal strain.
      double nxx = 0, nyy = 0, nxy = 0, mxx = 0, myy = 0, mxy = 0, qx = 0, qy = 0, tz = 0;
      for (int k = 0; k < nip; ++k) {
        const double wk = 0.5 * t * weight[k], z = 0.5 * t * zeta[k];
        const std::size_t q = q0 + static_cast<std::size_t>(k);
        nxx += wk * st.s[0][q];
        nyy += wk * st.s[1][q];
        nxy += wk * st.s[2][q];
        mxx += wk * z * st.s[0][q];
        myy += wk * z * st.s[1][q];
        mxy += wk * z * st.s[2][q];
        qy += wk * st.s[3][q];
        qx += wk * st.s[4][q];
        tz += 0.5 * weight[k] * dzz[k];
      }
      const double a = g.area;
      // The step's stress work counts on the mid-step volume: the thickness halfway through
      // its update, the area back half the step's in-plane dilatation from t_{n+1} (on the
      // end-of-step volume the books drift at first order in the step when the sheet
      // stretches and thins).
      const double mid_volume =
          t * (1.0 + 0.5 * tz) * a * (1.0 - 0.5 * dt * (RATE[0][k_el] + RATE[1][k_el]));
      r.internal_energy +=
          0.5 * (work_old[k_el] + point_work(st, q0, k_el * unip)) * 0.5 * mid_volume;
      if (bulk_q[k_el] > 0.0) {
        // The pressure over the thickness acts on the membrane only (not stored in the
        // stresses); its work q |tr D| t A dt is internal energy.
        nxx -= bulk_q[k_el] * t;
        nyy -= bulk_q[k_el] * t;
        r.internal_energy += bulk_q[k_el] * bulk_rate[k_el] * t * a * dt;
      }
      st.thickness[e] = t * (1.0 + tz);
      if (plastic_heat) {
        // Plastic dissipation sigma_eq d eps_p (the backward-Euler return: sigma : d eps^p),
        // plane-stress von Mises on the in-plane stress (the transverse shear stays elastic).
        double wp = 0.0;
        for (int k = 0; k < nip; ++k) {
          const std::size_t q = q0 + static_cast<std::size_t>(k);
          const double de = st.eps_p[q] - peps0[k_el * unip + static_cast<std::size_t>(k)];
          if (de > 0.0) {
            const double x = st.s[0][q], y = st.s[1][q], xy = st.s[2][q];
            wp += weight[k] * std::sqrt(x * x + y * y - x * y + 3.0 * xy * xy) * de;
          }
        }
        wp *= 0.5 * t * a;
        if (wp > 0.0) {
          const bool tri = conn[2] == conn[3];
          const double share = wp / (tri ? 3.0 : 4.0);
          for (int i = 0; i < (tri ? 3 : 4); ++i)
            out.plastic_work[static_cast<std::size_t>(conn[i])] += share;
        }
      }
      double fl[4][3], ml[4][2];
      for (int i = 0; i < 4; ++i) {
        fl[i][0] = a * (g.b1[i] * nxx + g.b2[i] * nxy);
        fl[i][1] = a * (g.b2[i] * nyy + g.b1[i] * nxy);
        fl[i][2] = a * (g.b1[i] * qx + g.b2[i] * qy);
        ml[i][0] = -a * (g.b2[i] * myy + g.b1[i] * mxy) - 0.25 * a * qy;
        ml[i][1] = a * (g.b1[i] * mxx + g.b2[i] * mxy) + 0.25 * a * qx;
      }
      if (qm > 0.0) {
        // Hourglass control of the four modes h = (1, -1, 1, -1): membrane, out of plane and the
        // two rotations, with gamma = h - (h . x) b1 - (h . y) b2 orthogonal to the linear
        // fields; viscous (IHQ 1-3) or stiffness (IHQ 4-5).
        double hx = 0, hy = 0;
        for (int i = 0; i < 4; ++i) {
          hx += h[i] * g.xl[i];
          hy += h[i] * g.yl[i];
        }
        double gam[4];
        for (int i = 0; i < 4; ++i)
          gam[i] = h[i] - hx * g.b1[i] - hy * g.b2[i];
        double qv[5] = {0, 0, 0, 0, 0};
        for (int i = 0; i < 4; ++i) {
          qv[0] += gam[i] * vl[i][0];
          qv[1] += gam[i] * vl[i][1];
          qv[2] += gam[i] * vl[i][2];
          qv[3] += gam[i] * wl[i][0];
          qv[4] += gam[i] * wl[i][1];
        }
        const double sa = std::sqrt(a);
        double coef[5];
        if (stiffness_hg) {
          // Stiffness form (Belytschko-Tsay): the generalised forces grow with the modes'
          // displacements, Q += k q_rate dt, with k from the modes' elastic scale
          // (membrane E t, out of plane E t^3 / L^2, rotations E t^3) times QM, L^2 = 2 / (b . b)
          // (the area for a square, the short side squared for an elongated element).
          double bb = 0.0;
          for (int i = 0; i < 4; ++i)
            bb += g.b1[i] * g.b1[i] + g.b2[i] * g.b2[i];
          const double km = qm * e_plate * t * a * bb / 8.0;
          const double kw = qm * e_plate * t * t * t * bb / 24.0;
          const double kr = qm * e_plate * t * t * t * a * bb / 192.0;
          const double k[5] = {km, km, kw, kr, kr};
          double power = 0.0;
          for (int j = 0; j < 5; ++j) {
            double& qj = st.hourglass[j][e];
            const double q_new = qj + k[j] * qv[j] * dt;
            power += 0.5 * (qj + q_new) * qv[j];
            qj = q_new;
            coef[j] = q_new;
          }
          r.hourglass_energy += power * dt;
          for (int i = 0; i < 4; ++i) {
            fl[i][0] += coef[0] * gam[i];
            fl[i][1] += coef[1] * gam[i];
            fl[i][2] += coef[2] * gam[i];
            ml[i][0] += coef[3] * gam[i];
            ml[i][1] += coef[4] * gam[i];
          }
        } else {
          coef[0] = coef[1] = 0.25 * qm * rho * wave_speed * t * sa;
          coef[2] = qm * rho * wave_speed * t * t * t / (12.0 * sa);
          coef[3] = coef[4] = qm * rho * wave_speed * t * t * t * sa / 48.0;
          double power = 0.0;
          for (int j = 0; j < 5; ++j)
            power += coef[j] * qv[j] * qv[j];
          r.hourglass_energy += power * dt;
          for (int i = 0; i < 4; ++i) {
            fl[i][0] += coef[0] * qv[0] * gam[i];
            fl[i][1] += coef[1] * qv[1] * gam[i];
            fl[i][2] += coef[2] * qv[2] * gam[i];
            ml[i][0] += coef[3] * qv[3] * gam[i];
            ml[i][1] += coef[4] * qv[4] * gam[i];
          }
        }
      }
      // Back to global axes, added to the nodes (a triangle's fourth node is its third).
      for (int i = 0; i < 4; ++i) {
        const auto n = static_cast<std::size_t>(conn[i]);
        for (int d = 0; d < 3; ++d) {
          const double f = g.e1[d] * fl[i][0] + g.e2[d] * fl[i][1] + g.e3[d] * fl[i][2];
          const double m = g.e1[d] * ml[i][0] + g.e2[d] * ml[i][1];
          (d == 0 ? out.fx : d == 1 ? out.fy : out.fz)[n] += f;
          (d == 0 ? mom.mx : d == 1 ? mom.my : mom.mz)[n] += m;
        }
      }
    }
  }
  return r;
}

}  // namespace

void thickness_rule(core::ThicknessRule rule, int nip, double* zeta, double* weight) {
  if (rule == core::ThicknessRule::lobatto && nip >= 2) {
    // Lobatto: the surfaces are integration points.
    static const double kZ[6][6] = {{0},
                                    {0},
                                    {-1, 1},
                                    {-1, 0, 1},
                                    {-1, -0.447213595499958, 0.447213595499958, 1},
                                    {-1, -0.654653670707977, 0, 0.654653670707977, 1}};
    static const double kW[6][6] = {{0},
                                    {0},
                                    {1, 1},
                                    {1.0 / 3, 4.0 / 3, 1.0 / 3},
                                    {1.0 / 6, 5.0 / 6, 5.0 / 6, 1.0 / 6},
                                    {0.1, 49.0 / 90, 32.0 / 45, 49.0 / 90, 0.1}};
    for (int k = 0; k < nip; ++k) {
      zeta[k] = kZ[nip][k];
      weight[k] = kW[nip][k];
    }
    return;
  }
  static const double kZ[6][5] = {
      {0},
      {0},
      {-0.577350269189626, 0.577350269189626},
      {-0.774596669241483, 0, 0.774596669241483},
      {-0.861136311594053, -0.339981043584856, 0.339981043584856, 0.861136311594053},
      {-0.906179845938664, -0.538469310105683, 0, 0.538469310105683, 0.906179845938664}};
  static const double kW[6][5] = {
      {0},
      {2},
      {1, 1},
      {5.0 / 9, 8.0 / 9, 5.0 / 9},
      {0.347854845137454, 0.652145154862546, 0.652145154862546, 0.347854845137454},
      {0.236926885056189, 0.478628670499366, 0.568888888888889, 0.478628670499366,
       0.236926885056189}};
  for (int k = 0; k < nip; ++k) {
    zeta[k] = kZ[nip][k];
    weight[k] = kW[nip][k];
  }
}

void ShellBlockState::resize(const core::ShellBlock& block, std::size_t history_per_point) {
  nip = block.nip;
  inplane = block.formulation == core::ShellFormulation::fully_integrated ? 4 : 1;
  const std::size_t n = block.size();
  for (auto& c : s)
    c.assign(n * points_per_element(), 0.0);
  eps_p.assign(n * points_per_element(), 0.0);
  history.assign(n * points_per_element() * history_per_point, 0.0);
  thickness.resize(n);
  for (std::size_t e = 0; e < n; ++e) {
    const double* t = &block.thickness[4 * e];
    thickness[e] = 0.25 * (t[0] + t[1] + t[2] + t[3]);
  }
  dt_factor.assign(n, 1.0);
  area.assign(n, 0.0);
  for (auto& q : hourglass)
    q.assign(block.hourglass.ihq >= 4 && inplane == 1 ? n : 0, 0.0);
}

ShellResult shell_forces(const core::ShellBlock& block, const core::Material& material,
                         ShellBlockState& state, const NodalView& nodes, const NodalSpin& spin,
                         double dt, std::size_t begin, std::size_t end, const NodalForces& forces,
                         const NodalMoments& moments) {
  if (block.formulation == core::ShellFormulation::fully_integrated)
    return shell_full_forces(block, material, state, nodes, spin, dt, begin, end, forces, moments);
  const double c = plate_wave_speed(material);
  const double rho = material::density(material);
  return std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (LawOf<M>::for_shells) {
          return bt(block, m, state, nodes, spin, dt, begin, end, forces, moments, c, rho);
        } else {
          ShellResult r;  // setup::build admits only the shell laws
          r.failed = true;
          r.unsupported_material = true;
          r.failed_element = begin;
          return r;
        }
      },
      material);
}

bool shell_frame(const core::ShellBlock& block, const double* x, const double* y, const double* z,
                 std::size_t e, double e1[3], double e2[3], double e3[3]) {
  double c[4][3];
  for (int i = 0; i < 4; ++i) {
    const auto n =
        static_cast<std::size_t>(block.connectivity[4 * e + static_cast<std::size_t>(i)]);
    c[i][0] = x[n];
    c[i][1] = y[n];
    c[i][2] = z[n];
  }
  Geometry g;
  if (!geometry(c, g))
    return false;
  for (int d = 0; d < 3; ++d) {
    e1[d] = g.e1[d];
    e2[d] = g.e2[d];
    e3[d] = g.e3[d];
  }
  return true;
}

bool supports_shells(const core::Material& material) {
  return material::law_for_shells(material);
}

double shell_reference_area(const core::ShellBlock& block, const NodalView& nodes, std::size_t e) {
  double x[4][3];
  for (int i = 0; i < 4; ++i) {
    const auto n =
        static_cast<std::size_t>(block.connectivity[4 * e + static_cast<std::size_t>(i)]);
    x[i][0] = nodes.x0[n];
    x[i][1] = nodes.y0[n];
    x[i][2] = nodes.z0[n];
  }
  Geometry g;
  return geometry(x, g) ? g.area : 0.0;
}

double shell_stable_dt(const core::ShellBlock& block, const core::Material& material,
                       const NodalView& nodes, std::size_t e) {
  double x[4][3];
  for (int i = 0; i < 4; ++i) {
    const auto n =
        static_cast<std::size_t>(block.connectivity[4 * e + static_cast<std::size_t>(i)]);
    x[i][0] = nodes.x0[n];
    x[i][1] = nodes.y0[n];
    x[i][2] = nodes.z0[n];
  }
  Geometry g;
  if (!geometry(x, g))
    return 0.0;
  const bool triangle = block.connectivity[4 * e + 2] == block.connectivity[4 * e + 3];
  return characteristic_length(x, g.area, triangle) / plate_wave_speed(material);
}

}  // namespace plyform::element
