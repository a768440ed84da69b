// The fully integrated shell (LS-DYNA ELFORM 16): the Belytschko-Tsay element's co-rotational
// frame and flat local geometry (shell_common.hpp), but 2 x 2 in-plane Gauss points with the
// material law at each (NIP points through the thickness at each), so the element has no
// zero-energy modes and needs no hourglass control: a differential stretch across the element
// (the fibres of a woven ply) is real strain at the points, not hourglass energy. Transverse
// shear by the assumed natural strain interpolation of Bathe and Dvorkin (MITC4) from the
// covariant shear strains at the edge midpoints, which keeps thin plates free of shear locking.

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "plyform/element/shell_kernels.hpp"
#include "plyform/material/shell.hpp"
#include "shell_common.hpp"
#include "shell_stages.hpp"

namespace plyform::element {
namespace {

using namespace shell_detail;

constexpr double kGp = 0.577350269189626;  // 1 / sqrt(3)
constexpr double kXi[4] = {-kGp, kGp, kGp, -kGp};
constexpr double kEta[4] = {-kGp, -kGp, kGp, kGp};
constexpr double kNodeXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kNodeEta[4] = {-1.0, -1.0, 1.0, 1.0};

template <class M>
ShellResult full(const core::ShellBlock& block, const M& mat, ShellBlockState& st,
                 const NodalView& nv, const NodalSpin& spin, double dt, std::size_t begin,
                 std::size_t end, const NodalForces& out, const NodalMoments& mom,
                 double wave_speed, double rho) {
  using Law = LawOf<M>;
  ShellResult r;
  const int nip = st.nip;
  const auto unip = static_cast<std::size_t>(nip);
  const std::size_t ppe = 4 * unip;  // an element's points: 4 Gauss points x NIP, in that order
  double zeta[kMaxNip], weight[kMaxNip];
  thickness_rule(block.rule, nip, zeta, weight);
  const double kappa = block.shear_factor;
  // Elements go in chunks, as in the BT kernel: the frames lane-wise across the chunk's
  // elements, the Gauss points' kinematics lane-wise too, then one law call for all the
  // chunk's 4 x NIP x kChunk points, then the forces. Fixed-size buffers: nothing allocates.
  constexpr std::size_t kChunk = 8;
  ChunkFrames<kChunk> f;
  PointBuffers<4 * kChunk* static_cast<std::size_t>(kMaxNip)> b;
  const bool thermal = !st.temperature.empty() && nv.temperature != nullptr;
  const bool expands = thermal && !block.expansion.x.empty();
  const bool plastic_heat = out.plastic_work != nullptr;
  const bool bulk_on =
      block.bulk_viscosity_on && (block.bulk_viscosity.q1 != 0.0 || block.bulk_viscosity.q2 != 0.0);
  // Per Gauss point g and lane k: the gradients in the frame (BX, BY per node), the Jacobian
  // (x_xi, y_xi, x_eta, y_eta) and its determinant, the mapped in-plane rate (dxx, dyy, 2 dxy),
  // the curvature rates, the assumed transverse shear strains, the dilatation rate, the
  // stresses' turn relative to the frame and the material's own spin over the step.
  alignas(64) double BX[4][4][kChunk], BY[4][4][kChunk], JAC[4][4][kChunk], DET[4][kChunk];
  alignas(64) double RATE[8][4][kChunk], DIL[4][kChunk], PHI[4][kChunk], MSPIN[4][kChunk];
  alignas(64) double FTURN[kChunk];
  double tk[kChunk], work_old[kChunk][4], bulk_q[kChunk][4];
  for (std::size_t c0 = begin; c0 < end; c0 += kChunk) {
    const std::size_t chunk = std::min(kChunk, end - c0);
    chunk_frames(block, nv, spin, c0, chunk, f);
    for (std::size_t gp = 0; gp < 4; ++gp) {
      const double xi = kXi[gp], eta = kEta[gp];
      double dxi[4], deta[4];
      for (int i = 0; i < 4; ++i) {
        dxi[i] = 0.25 * kNodeXi[i] * (1.0 + eta * kNodeEta[i]);
        deta[i] = 0.25 * kNodeEta[i] * (1.0 + xi * kNodeXi[i]);
      }
      for (std::size_t k = 0; k < kChunk; ++k) {
        double x_xi = 0, y_xi = 0, x_eta = 0, y_eta = 0;
        for (int i = 0; i < 4; ++i) {
          x_xi += dxi[i] * f.xl[i][k];
          y_xi += dxi[i] * f.yl[i][k];
          x_eta += deta[i] * f.xl[i][k];
          y_eta += deta[i] * f.yl[i][k];
        }
        const double dj = x_xi * y_eta - y_xi * x_eta;
        const double inv_dj = 1.0 / dj;
        DET[gp][k] = dj;
        JAC[0][gp][k] = x_xi, JAC[1][gp][k] = y_xi, JAC[2][gp][k] = x_eta, JAC[3][gp][k] = y_eta;
        double dxx = 0, dyy = 0, lxy = 0, lyx = 0, kx = 0, ky = 0, kxy = 0, sx = 0, sy = 0;
        for (int i = 0; i < 4; ++i) {
          const double nx = (y_eta * dxi[i] - y_xi * deta[i]) * inv_dj;
          const double ny = (x_xi * deta[i] - x_eta * dxi[i]) * inv_dj;
          BX[i][gp][k] = nx;
          BY[i][gp][k] = ny;
          const double vxl = f.vl[3 * i][k], vyl = f.vl[3 * i + 1][k], vzl = f.vl[3 * i + 2][k];
          const double wxl = f.wl[3 * i][k], wyl = f.wl[3 * i + 1][k];
          dxx += nx * vxl;
          dyy += ny * vyl;
          lxy += ny * vxl;
          lyx += nx * vyl;
          kx += nx * wyl;
          ky -= ny * wxl;
          kxy += ny * wyl - nx * wxl;
          sx += nx * vzl;
          sy += ny * vzl;
        }
        // MITC4: the covariant transverse shear rate along each edge at its midpoint, from the
        // Mindlin field u_x = z theta_y, u_y = -z theta_x: gamma = (w_b - w_a) / 2 +
        // (x_b - x_a) / 2 * mean theta_y - (y_b - y_a) / 2 * mean theta_x. Edges A (1-2,
        // eta = -1), C (4-3, eta = 1) give gamma_xi; D (1-4, xi = -1), B (2-3, xi = 1)
        // gamma_eta; interpolated to the point, [gamma_xi, gamma_eta] = J [gamma_xz, gamma_yz].
        const auto edge = [&](int a, int c) {
          return 0.5 * (f.vl[3 * c + 2][k] - f.vl[3 * a + 2][k]) +
                 0.25 * (f.xl[c][k] - f.xl[a][k]) * (f.wl[3 * a + 1][k] + f.wl[3 * c + 1][k]) -
                 0.25 * (f.yl[c][k] - f.yl[a][k]) * (f.wl[3 * a][k] + f.wl[3 * c][k]);
        };
        const double gxi = 0.5 * (1.0 - eta) * edge(0, 1) + 0.5 * (1.0 + eta) * edge(3, 2);
        const double geta = 0.5 * (1.0 - xi) * edge(0, 3) + 0.5 * (1.0 + xi) * edge(1, 2);
        // The point's mid-surface velocity gradient on the mid-step configuration, as in the
        // BT kernel: no strain from a rigid rotation about any axis.
        const InPlaneRate am = mid_step_rate(dxx, lxy, lyx, dyy, sx, sy, dt);
        RATE[0][gp][k] = am.a00;
        RATE[1][gp][k] = am.a11;
        RATE[2][gp][k] = am.a01 + am.a10;
        RATE[3][gp][k] = kx;
        RATE[4][gp][k] = ky;
        RATE[5][gp][k] = kxy;
        RATE[6][gp][k] = (y_eta * gxi - y_xi * geta) * inv_dj;  // gamma_xz
        RATE[7][gp][k] = (x_xi * geta - x_eta * gxi) * inv_dj;  // gamma_yz
        DIL[gp][k] = am.a00 + am.a11;
        // The stresses of this point turn by the material's spin here relative to the frame's
        // own (that of the mid-side vector s1, as in the BT kernel).
        const double s1x = 0.5 * (f.xl[1][k] + f.xl[2][k] - f.xl[0][k] - f.xl[3][k]);
        const double s1v = 0.5 * (f.vl[4][k] + f.vl[7][k] - f.vl[1][k] - f.vl[10][k]);
        MSPIN[gp][k] = 0.5 * (am.a10 - am.a01) * dt;
        PHI[gp][k] = (0.5 * (am.a10 - am.a01) - s1v / s1x) * dt;
      }
    }
    if constexpr (material::law_needs_frame_turn<Law>()) {
      // The tangent of the frame's exact turn over the step: s1 at t_n was s1 - dt ds1/dt.
      for (std::size_t k = 0; k < kChunk; ++k) {
        const double s1x = 0.5 * (f.xl[1][k] + f.xl[2][k] - f.xl[0][k] - f.xl[3][k]);
        const double s1v = 0.5 * (f.vl[4][k] + f.vl[7][k] - f.vl[1][k] - f.vl[10][k]);
        const double s1u = 0.5 * (f.vl[3][k] + f.vl[6][k] - f.vl[0][k] - f.vl[9][k]);
        FTURN[k] = dt * s1v / (s1x - dt * s1u);
      }
    }
    // Per element: checks, the stable step, the stresses turned, the strain increments at the
    // points, the temperatures and axes.
    for (std::size_t e = c0; e < c0 + chunk; ++e) {
      const std::size_t k_el = e - c0;
      const double t = tk[k_el] = st.thickness[e];
      bool usable = frame_usable(f, k_el, t);
      for (std::size_t gp = 0; gp < 4; ++gp)
        usable = usable && DET[gp][k_el] > 0.0;
      if (!usable) {
        r.failed = true;
        r.failed_element = e;
        return r;
      }
      st.area[e] = f.area[k_el];
      // Bulk viscosity (*CONTROL_BULK_VISCOSITY TYPE -1/-2), as the BT kernel's but at each
      // Gauss point on its own in-plane compression tr D = d11 + d22 < 0 (the mapped rate),
      // with l = sqrt(A) of the element: q = rho l |tr D| (Q1 l |tr D| + Q2 c) lowers the
      // point's membrane resultants N11, N22 by q t, its work q |tr D| t dA dt is internal
      // energy, and the element's step is L / (Q + sqrt(Q^2 + c^2)) with the largest of its
      // points' Q.
      double qv_max = 0.0;
      for (std::size_t gp = 0; gp < 4; ++gp) {
        bulk_q[k_el][gp] = 0.0;
        const double rate = -DIL[gp][k_el];
        if (bulk_on && rate > 0.0) {
          const double l = std::sqrt(f.area[k_el]);
          const double qv =
              block.bulk_viscosity.q1 * l * rate + block.bulk_viscosity.q2 * wave_speed;
          bulk_q[k_el][gp] = rho * l * qv * rate;
          qv_max = std::max(qv_max, qv);
        }
      }
      const double dte = st.dt_factor[e] * f.length[k_el] /
                         (qv_max + std::sqrt(qv_max * qv_max + wave_speed * wave_speed));
      if (dte < r.dt_min) {
        r.dt_min = dte;
        r.dt_element = e;
      }
      const std::size_t q0 = ppe * e, at_el = ppe * k_el;
      {
        double rate[kColumnRates][4], phi[4];
        for (std::size_t gp = 0; gp < 4; ++gp) {
          for (int c = 0; c < kColumnRates; ++c)
            rate[c][gp] = RATE[c][gp][k_el];
          phi[gp] = PHI[gp][k_el];
        }
        prepare_columns<4>(st, b, q0, at_el, unip, t, zeta, weight, kappa, dt, rate, phi,
                           work_old[k_el]);
        if constexpr (material::law_needs_spin<Law>())
          spread_columns<4>(&b.spin[at_el], unip, phi);
      }
      if constexpr (material::law_needs_frame_turn<Law>()) {
        double spin_g[4], turn_g[4];
        for (std::size_t gp = 0; gp < 4; ++gp) {
          spin_g[gp] = MSPIN[gp][k_el];
          turn_g[gp] = FTURN[k_el];
        }
        spread_columns<4>(&b.material_spin[at_el], unip, spin_g);
        spread_columns<4>(&b.frame_turn[at_el], unip, turn_g);
      }
      if (thermal) {
        // As the BT kernel: one temperature per thickness point (the engine keeps NIP per
        // element), the same at the four Gauss points; thermal expansion off the increments.
        double t_point[kMaxNip], eth_point[kMaxNip];
        thickness_temperatures(block, nv, st, e, zeta, unip, dt, expands, t_point, eth_point);
        spread_temperatures<4>(b, at_el, unip, t_point, eth_point);
      }
      if constexpr (Law::needs_material_axes) {
        set_material_axes<Law>(mat, block, e, f, k_el, b, at_el, ppe);
      }
    }
    update_points<Law>(mat, st, ppe * c0, ppe * chunk, b, thermal, plastic_heat, expands, dt);
    for (std::size_t e = c0; e < c0 + chunk; ++e) {
      const std::size_t k_el = e - c0;
      const core::Index* conn = &block.connectivity[4 * e];
      const double t = tk[k_el];
      const std::size_t q0 = ppe * e, at_el = ppe * k_el;
      // The columns' resultants and stress work; the thickness follows the mean normal strain
      // over all the element's points.
      ColumnSums<4> cs;
      sum_columns<4>(st, b, q0, at_el, unip, t, zeta, weight, kappa, plastic_heat, cs);
      const double tz = cs.tz;
      // The resultants on the end-of-step thickness t (1 + tz), where the stresses sigma_{n+1}
      // belong (shell_stages.hpp, ThicknessScale).
      const ThicknessScale grow(tz);
      double fl[4][3] = {}, ml[4][2] = {};
      double wp = 0.0;
      const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
      // The element's books, summed into the range's in element order (ElementBooks).
      double internal = 0.0, p_start = 0.0, p_end = 0.0;
      for (std::size_t gp = 0; gp < 4; ++gp) {
        double nxx = grow.n * cs.nxx[gp], nyy = grow.n * cs.nyy[gp];
        const double nxy = grow.n * cs.nxy[gp], mxx = grow.m * cs.mxx[gp];
        const double myy = grow.m * cs.myy[gp], mxy = grow.m * cs.mxy[gp];
        const double qx = grow.n * cs.qx[gp], qy = grow.n * cs.qy[gp];
        const double da = DET[gp][k_el];  // Gauss weights 1
        wp += cs.plastic[gp] * 0.5 * t * da;
        // Midpoint rule on the point's mid-step volume, as the BT kernel books its one point.
        const double mid_volume = t * (1.0 + 0.5 * tz) * da * (1.0 - 0.5 * dt * DIL[gp][k_el]);
        internal += 0.5 * (work_old[k_el][gp] + cs.work[gp]) * 0.5 * mid_volume;
        p_start += work_old[k_el][gp] * 0.5 * mid_volume * inv_dt;
        p_end += cs.work[gp] * 0.5 * mid_volume * inv_dt;
        if (bulk_on) {
          // The midpoint rule of the BT kernel's bulk viscosity, at each point.
          double& q_old = st.bulk_q[4 * e + gp];
          const double rate = -DIL[gp][k_el];
          const double w0 = q_old * rate * t * da, w1 = bulk_q[k_el][gp] * rate * t * da;
          internal += 0.5 * (w0 + w1) * dt;
          p_start += w0;
          p_end += w1;
          q_old = bulk_q[k_el][gp];
          nxx -= bulk_q[k_el][gp] * t;
          nyy -= bulk_q[k_el][gp] * t;
        }
        for (int i = 0; i < 4; ++i) {
          const double nx = BX[i][gp][k_el], ny = BY[i][gp][k_el];
          fl[i][0] += da * (nx * nxx + ny * nxy);
          fl[i][1] += da * (ny * nyy + nx * nxy);
          ml[i][0] -= da * (ny * myy + nx * mxy);
          ml[i][1] += da * (nx * mxx + ny * mxy);
        }
        // Transverse shear: the power qx gxz + qy gyz = Q_xi gamma_xi + Q_eta gamma_eta with
        // [Q_xi, Q_eta] = J^-T [qx, qy], spread onto the edges' covariant strains.
        const double x_xi = JAC[0][gp][k_el], y_xi = JAC[1][gp][k_el];
        const double x_eta = JAC[2][gp][k_el], y_eta = JAC[3][gp][k_el];
        const double q_xi = (y_eta * qx - x_eta * qy) / da;
        const double q_eta = (x_xi * qy - y_xi * qx) / da;
        const double xi = kXi[gp], eta = kEta[gp];
        const double c_edge[4] = {da * q_xi * 0.5 * (1.0 - eta), da * q_xi * 0.5 * (1.0 + eta),
                                  da * q_eta * 0.5 * (1.0 - xi), da * q_eta * 0.5 * (1.0 + xi)};
        constexpr int kEnds[4][2] = {{0, 1}, {3, 2}, {0, 3}, {1, 2}};
        for (int s = 0; s < 4; ++s) {
          const int a = kEnds[s][0], c = kEnds[s][1];
          const double ce = c_edge[s];
          const double dx = f.xl[c][k_el] - f.xl[a][k_el], dy = f.yl[c][k_el] - f.yl[a][k_el];
          fl[a][2] -= 0.5 * ce;
          fl[c][2] += 0.5 * ce;
          ml[a][1] += 0.25 * ce * dx;
          ml[c][1] += 0.25 * ce * dx;
          ml[a][0] -= 0.25 * ce * dy;
          ml[c][0] -= 0.25 * ce * dy;
        }
      }
      st.thickness[e] = t * (1.0 + tz);
      if (plastic_heat)
        spread_plastic_work(conn, wp, out);
      scatter(conn, f, k_el, fl, ml, out, mom);
      r.internal_energy += internal;
      r.start_power += p_start;
      r.end_power += p_end;
      if (out.books != nullptr)
        out.books[e] = {internal, 0.0, p_start, p_end, 0.0, 0.0};
    }
  }
  return r;
}

}  // namespace

ShellResult shell_full_forces(const core::ShellBlock& block, const core::Material& material,
                              ShellBlockState& state, const NodalView& nodes, const NodalSpin& spin,
                              double dt, std::size_t begin, std::size_t end,
                              const NodalForces& forces, const NodalMoments& moments) {
  const double c = plate_wave_speed(material);
  const double rho = material::density(material);
  return std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (LawOf<M>::for_shells) {
          return full(block, m, state, nodes, spin, dt, begin, end, forces, moments, c, rho);
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

}  // namespace plyform::element
