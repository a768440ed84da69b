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
  const std::size_t ppe = 4 * unip;
  double zeta[kMaxNip], weight[kMaxNip];
  thickness_rule(block.rule, nip, zeta, weight);
  const double kappa = block.shear_factor;
  const double inv_kappa = kappa > 0.0 ? 1.0 / kappa : 0.0;
  // One element's points (4 Gauss points x NIP), in the state's order: the law runs once per
  // element over all of them. Fixed-size buffers: the loop allocates nothing.
  constexpr std::size_t kP = 4 * static_cast<std::size_t>(kMaxNip);
  double pdxx[kP], pdyy[kP], pdxy[kP], pdyz[kP], pdzx[kP], pdzz[kP];
  double pcos[kP], psin[kP], pspin[kP], ptemp[kP], peps0[kP], peth[kP];
  double pmspin[kP], pturn[kP];  // laws that keep material lines (needs_frame_turn)
  const bool thermal = !st.temperature.empty() && nv.temperature != nullptr;
  const bool expands = thermal && !block.expansion.x.empty();
  const bool plastic_heat = out.plastic_work != nullptr;
  const bool bulk_on =
      block.bulk_viscosity_on && (block.bulk_viscosity.q1 != 0.0 || block.bulk_viscosity.q2 != 0.0);
  // Stress work per unit volume of Gauss point g's column (as the BT kernel's point_work: the
  // transverse shear with the unscaled shear rate, the shear factor scaling only the stiffness).
  const auto column_work = [&](std::size_t q0, std::size_t g) {
    double w = 0.0;
    for (std::size_t k = 0; k < unip; ++k) {
      const std::size_t q = q0 + g * unip + k, at = g * unip + k;
      w +=
          weight[k] * (st.s[0][q] * pdxx[at] + st.s[1][q] * pdyy[at] + 2.0 * st.s[2][q] * pdxy[at] +
                       2.0 * inv_kappa * (st.s[3][q] * pdyz[at] + st.s[4][q] * pdzx[at]));
    }
    return w;
  };
  for (std::size_t e = begin; e < end; ++e) {
    const core::Index* cn = &block.connectivity[4 * e];
    double x[4][3], v[4][3], w[4][3];
    for (int i = 0; i < 4; ++i) {
      const auto n = static_cast<std::size_t>(cn[i]);
      const double* pk = nv.packed + 6 * n;
      for (int d = 0; d < 3; ++d) {
        x[i][d] = pk[d];
        v[i][d] = pk[3 + d];
      }
      w[i][0] = spin.wx[n];
      w[i][1] = spin.wy[n];
      w[i][2] = spin.wz[n];
    }
    Geometry g;
    const double t = st.thickness[e];
    if (!geometry(x, g) || !(t > 0.0)) {
      r.failed = true;
      r.failed_element = e;
      return r;
    }
    st.area[e] = g.area;
    const bool triangle = cn[2] == cn[3];
    const double length = characteristic_length(x, g.area, triangle);
    double vl[4][3], wl[4][2];
    for (int i = 0; i < 4; ++i) {
      vl[i][0] = v[i][0] * g.e1[0] + v[i][1] * g.e1[1] + v[i][2] * g.e1[2];
      vl[i][1] = v[i][0] * g.e2[0] + v[i][1] * g.e2[1] + v[i][2] * g.e2[2];
      vl[i][2] = v[i][0] * g.e3[0] + v[i][1] * g.e3[1] + v[i][2] * g.e3[2];
      wl[i][0] = w[i][0] * g.e1[0] + w[i][1] * g.e1[1] + w[i][2] * g.e1[2];
      wl[i][1] = w[i][0] * g.e2[0] + w[i][1] * g.e2[1] + w[i][2] * g.e2[2];
    }
    // The frame's own spin (it follows the mid-side vector s1, as in the BT kernel).
    const double s1x = 0.5 * (g.xl[1] + g.xl[2] - g.xl[0] - g.xl[3]);
    const double frame_spin = 0.5 * (vl[1][1] + vl[2][1] - vl[0][1] - vl[3][1]) / s1x;
    // The tangent of its exact turn over the step (for laws that keep material lines): s1 at t_n
    // was s1 - dt ds1/dt.
    [[maybe_unused]] const double frame_turn =
        dt * 0.5 * (vl[1][1] + vl[2][1] - vl[0][1] - vl[3][1]) /
        (s1x - dt * 0.5 * (vl[1][0] + vl[2][0] - vl[0][0] - vl[3][0]));
    // MITC4: the covariant transverse shear rate along each edge at its midpoint, from the
    // Mindlin field u_x = z theta_y, u_y = -z theta_x: gamma = (w_b - w_a) / 2 +
    // (x_b - x_a) / 2 * mean theta_y - (y_b - y_a) / 2 * mean theta_x. Edges A (1-2, eta = -1),
    // C (4-3, eta = 1) give gamma_xi; D (1-4, xi = -1), B (2-3, xi = 1) gamma_eta.
    const auto edge = [&](int a, int b) {
      return 0.5 * (vl[b][2] - vl[a][2]) + 0.25 * (g.xl[b] - g.xl[a]) * (wl[a][1] + wl[b][1]) -
             0.25 * (g.yl[b] - g.yl[a]) * (wl[a][0] + wl[b][0]);
    };
    const double gam_a = edge(0, 1), gam_c = edge(3, 2), gam_d = edge(0, 3), gam_b = edge(1, 2);
    // Per Gauss point: gradients, Jacobian, the mapped membrane rate, curvature and shear rates.
    double bx[4][4], by[4][4], jac[4][4], det[4], dil[4];
    const std::size_t q0 = ppe * e;
    for (std::size_t gp = 0; gp < 4; ++gp) {
      const double xi = kXi[gp], eta = kEta[gp];
      double dxi[4], deta[4];
      double x_xi = 0, y_xi = 0, x_eta = 0, y_eta = 0;
      for (int i = 0; i < 4; ++i) {
        dxi[i] = 0.25 * kNodeXi[i] * (1.0 + eta * kNodeEta[i]);
        deta[i] = 0.25 * kNodeEta[i] * (1.0 + xi * kNodeXi[i]);
        x_xi += dxi[i] * g.xl[i];
        y_xi += dxi[i] * g.yl[i];
        x_eta += deta[i] * g.xl[i];
        y_eta += deta[i] * g.yl[i];
      }
      const double dj = x_xi * y_eta - y_xi * x_eta;
      if (!(dj > 0.0)) {
        r.failed = true;
        r.failed_element = e;
        return r;
      }
      det[gp] = dj;
      jac[gp][0] = x_xi, jac[gp][1] = y_xi, jac[gp][2] = x_eta, jac[gp][3] = y_eta;
      double dxx = 0, dyy = 0, lxy = 0, lyx = 0, kx = 0, ky = 0, kxy = 0, sx = 0, sy = 0;
      for (int i = 0; i < 4; ++i) {
        const double nx = (y_eta * dxi[i] - y_xi * deta[i]) / dj;
        const double ny = (x_xi * deta[i] - x_eta * dxi[i]) / dj;
        bx[gp][i] = nx;
        by[gp][i] = ny;
        dxx += nx * vl[i][0];
        dyy += ny * vl[i][1];
        lxy += ny * vl[i][0];
        lyx += nx * vl[i][1];
        kx += nx * wl[i][1];
        ky -= ny * wl[i][0];
        kxy += ny * wl[i][1] - nx * wl[i][0];
        sx += nx * vl[i][2];
        sy += ny * vl[i][2];
      }
      const double gxi = 0.5 * (1.0 - eta) * gam_a + 0.5 * (1.0 + eta) * gam_c;
      const double geta = 0.5 * (1.0 - xi) * gam_d + 0.5 * (1.0 + xi) * gam_b;
      // [gamma_xi, gamma_eta] = J [gamma_xz, gamma_yz].
      const double gxz = (y_eta * gxi - y_xi * geta) / dj;
      const double gyz = (x_xi * geta - x_eta * gxi) / dj;
      // The point's mid-surface velocity gradient mapped to the mid-step configuration as a
      // whole 3 x 3 (Hughes-Winget), as in the BT kernel: no strain from a rigid rotation
      // about any axis.
      const double h2 = 0.5 * dt;
      const double l3[3][3] = {{dxx, lxy, -sx}, {lyx, dyy, -sy}, {sx, sy, 0.0}};
      double m3[3][3];
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
          m3[row][col] = (row == col ? 1.0 : 0.0) - h2 * l3[row][col];
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
          am[row][col] =
              l3[row][0] * inv[0][col] + l3[row][1] * inv[1][col] + l3[row][2] * inv[2][col];
      dil[gp] = am[0][0] + am[1][1];
      // The stresses of this point turn by the material's spin here relative to the frame's
      // (Jaumann relative to the frame; the frame is the element's, the spin the point's).
      const double phi = (0.5 * (am[1][0] - am[0][1]) - frame_spin) * dt;
      if (phi != 0.0) {
        const double half_sq = 0.25 * phi * phi, ic = 1.0 / (1.0 + half_sq);
        const double c = (1.0 - half_sq) * ic, sn = phi * ic;
        for (std::size_t k = 0; k < unip; ++k) {
          const std::size_t q = q0 + gp * unip + k;
          const double sxx = st.s[0][q], syy = st.s[1][q], sxy = st.s[2][q];
          st.s[0][q] = c * c * sxx + sn * sn * syy - 2.0 * c * sn * sxy;
          st.s[1][q] = sn * sn * sxx + c * c * syy + 2.0 * c * sn * sxy;
          st.s[2][q] = c * sn * (sxx - syy) + (c * c - sn * sn) * sxy;
          const double tzx = st.s[4][q], tyz = st.s[3][q];
          st.s[4][q] = c * tzx - sn * tyz;
          st.s[3][q] = sn * tzx + c * tyz;
        }
      }
      for (std::size_t k = 0; k < unip; ++k) {
        const double z = 0.5 * t * zeta[k];
        const std::size_t at = gp * unip + k;
        pdxx[at] = (am[0][0] + z * kx) * dt;
        pdyy[at] = (am[1][1] + z * ky) * dt;
        pdxy[at] = 0.5 * (am[0][1] + am[1][0] + z * kxy) * dt;
        pdyz[at] = 0.5 * kappa * gyz * dt;
        pdzx[at] = 0.5 * kappa * gxz * dt;
        pspin[at] = phi;
        if constexpr (material::law_needs_frame_turn<Law>()) {
          pmspin[at] = 0.5 * (am[1][0] - am[0][1]) * dt;
          pturn[at] = frame_turn;
        }
      }
    }
    // Bulk viscosity (*CONTROL_BULK_VISCOSITY TYPE -1/-2), as the BT kernel's but at each Gauss
    // point on its own in-plane compression tr D = d11 + d22 < 0 (the mapped rate), with
    // l = sqrt(A) of the element: q = rho l |tr D| (Q1 l |tr D| + Q2 c) lowers the point's
    // membrane resultants N11, N22 by q t, its work q |tr D| t dA dt is internal energy, and the
    // element's step is L / (Q + sqrt(Q^2 + c^2)) with the largest of its points' Q.
    double bulk_q[4] = {0.0, 0.0, 0.0, 0.0};
    double qv_max = 0.0;
    if (bulk_on) {
      const double l = std::sqrt(g.area);
      for (std::size_t gp = 0; gp < 4; ++gp) {
        const double rate = -dil[gp];
        if (rate > 0.0) {
          const double qv =
              block.bulk_viscosity.q1 * l * rate + block.bulk_viscosity.q2 * wave_speed;
          bulk_q[gp] = rho * l * qv * rate;
          qv_max = std::max(qv_max, qv);
        }
      }
    }
    const double dte =
        st.dt_factor[e] * length / (qv_max + std::sqrt(qv_max * qv_max + wave_speed * wave_speed));
    if (dte < r.dt_min) {
      r.dt_min = dte;
      r.dt_element = e;
    }
    double work_old[4];
    for (std::size_t gp = 0; gp < 4; ++gp)
      work_old[gp] = column_work(q0, gp);
    if (thermal) {
      // As the BT kernel: the element's mean nodal temperature (a thick thermal shell's
      // quadratic profile through the thickness), one per thickness point (the engine keeps
      // NIP temperatures per element), the same at the four Gauss points.
      const auto mean = [&](const double* tn) {
        const auto n0 = static_cast<std::size_t>(cn[0]), n1 = static_cast<std::size_t>(cn[1]),
                   n2 = static_cast<std::size_t>(cn[2]), n3 = static_cast<std::size_t>(cn[3]);
        return triangle ? (tn[n0] + tn[n1] + tn[n2]) / 3.0
                        : 0.25 * (tn[n0] + tn[n1] + tn[n2] + tn[n3]);
      };
      const double t_mid = mean(nv.temperature);
      const bool faces = nv.temperature_bottom != nullptr;
      const double t_bottom = faces ? mean(nv.temperature_bottom) : t_mid;
      const double t_top = faces ? mean(nv.temperature_top) : t_mid;
      for (std::size_t k = 0; k < unip; ++k) {
        const double z = zeta[k];
        const double t_new =
            0.5 * z * (z - 1.0) * t_bottom + (1.0 - z * z) * t_mid + 0.5 * z * (z + 1.0) * t_top;
        double eth = 0.0;
        if (dt > 0.0) {
          double& t_old = st.temperature[unip * e + k];
          if (expands)
            eth = block.expansion(0.5 * (t_old + t_new)) * (t_new - t_old);
          t_old = t_new;
        }
        for (std::size_t gp = 0; gp < 4; ++gp) {
          const std::size_t at = gp * unip + k;
          peth[at] = eth;
          pdxx[at] -= eth;
          pdyy[at] -= eth;
          ptemp[at] = t_new;
        }
      }
    }
    if constexpr (Law::needs_material_axes) {
      // The element's axes, as the BT kernel sets them (AOPT 0, 2, 3 and BETA), at every point.
      const material::MaterialAxes axes = Law::axes(mat);
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
      std::fill_n(pcos, ppe, std::cos(angle));
      std::fill_n(psin, ppe, std::sin(angle));
    }
    {
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
        std::copy_n(&st.eps_p[q0], ppe, peps0);
      Law::update_shell(mat, ppe, pts);
      if (expands) {
        for (std::size_t at = 0; at < ppe; ++at) {
          pdxx[at] += peth[at];
          pdyy[at] += peth[at];
          pdzz[at] += peth[at];
        }
      }
    }
    // The thickness follows the mean normal strain over all the element's points.
    double tz = 0.0;
    for (std::size_t gp = 0; gp < 4; ++gp)
      for (std::size_t k = 0; k < unip; ++k)
        tz += 0.125 * weight[k] * pdzz[gp * unip + k];
    double fl[4][3] = {}, ml[4][2] = {};
    double wp = 0.0;
    for (std::size_t gp = 0; gp < 4; ++gp) {
      double nxx = 0, nyy = 0, nxy = 0, mxx = 0, myy = 0, mxy = 0, qx = 0, qy = 0;
      for (std::size_t k = 0; k < unip; ++k) {
        const double wk = 0.5 * t * weight[k], z = 0.5 * t * zeta[k];
        const std::size_t q = q0 + gp * unip + k;
        nxx += wk * st.s[0][q];
        nyy += wk * st.s[1][q];
        nxy += wk * st.s[2][q];
        mxx += wk * z * st.s[0][q];
        myy += wk * z * st.s[1][q];
        mxy += wk * z * st.s[2][q];
        qy += wk * st.s[3][q];
        qx += wk * st.s[4][q];
        if (plastic_heat) {
          const double de = st.eps_p[q] - peps0[gp * unip + k];
          if (de > 0.0) {
            const double sx = st.s[0][q], sy = st.s[1][q], sxy = st.s[2][q];
            wp += weight[k] * 0.5 * t * det[gp] *
                  std::sqrt(sx * sx + sy * sy - sx * sy + 3.0 * sxy * sxy) * de;
          }
        }
      }
      const double da = det[gp];  // Gauss weights 1
      // Midpoint rule on the point's mid-step volume, as the BT kernel books its one point.
      const double mid_volume = t * (1.0 + 0.5 * tz) * da * (1.0 - 0.5 * dt * dil[gp]);
      r.internal_energy += 0.5 * (work_old[gp] + column_work(q0, gp)) * 0.5 * mid_volume;
      if (bulk_q[gp] > 0.0) {
        nxx -= bulk_q[gp] * t;
        nyy -= bulk_q[gp] * t;
        r.internal_energy += bulk_q[gp] * (-dil[gp]) * t * da * dt;
      }
      for (int i = 0; i < 4; ++i) {
        const double nx = bx[gp][i], ny = by[gp][i];
        fl[i][0] += da * (nx * nxx + ny * nxy);
        fl[i][1] += da * (ny * nyy + nx * nxy);
        ml[i][0] -= da * (ny * myy + nx * mxy);
        ml[i][1] += da * (nx * mxx + ny * mxy);
      }
      // Transverse shear: the power qx gxz + qy gyz = Q_xi gamma_xi + Q_eta gamma_eta with
      // [Q_xi, Q_eta] = J^-T [qx, qy], spread onto the edges' covariant strains.
      const double x_xi = jac[gp][0], y_xi = jac[gp][1], x_eta = jac[gp][2], y_eta = jac[gp][3];
      const double q_xi = (y_eta * qx - x_eta * qy) / da;
      const double q_eta = (x_xi * qy - y_xi * qx) / da;
      const double xi = kXi[gp], eta = kEta[gp];
      const double c_edge[4] = {da * q_xi * 0.5 * (1.0 - eta), da * q_xi * 0.5 * (1.0 + eta),
                                da * q_eta * 0.5 * (1.0 - xi), da * q_eta * 0.5 * (1.0 + xi)};
      const int ends[4][2] = {{0, 1}, {3, 2}, {0, 3}, {1, 2}};
      for (int s = 0; s < 4; ++s) {
        const int a = ends[s][0], b = ends[s][1];
        const double c = c_edge[s];
        const double dx = g.xl[b] - g.xl[a], dy = g.yl[b] - g.yl[a];
        fl[a][2] -= 0.5 * c;
        fl[b][2] += 0.5 * c;
        ml[a][1] += 0.25 * c * dx;
        ml[b][1] += 0.25 * c * dx;
        ml[a][0] -= 0.25 * c * dy;
        ml[b][0] -= 0.25 * c * dy;
      }
    }
    st.thickness[e] = t * (1.0 + tz);
    if (wp > 0.0) {
      const double share = wp / (triangle ? 3.0 : 4.0);
      for (int i = 0; i < (triangle ? 3 : 4); ++i)
        out.plastic_work[static_cast<std::size_t>(cn[i])] += share;
    }
    for (int i = 0; i < 4; ++i) {
      const auto n = static_cast<std::size_t>(cn[i]);
      for (int d = 0; d < 3; ++d) {
        const double f = g.e1[d] * fl[i][0] + g.e2[d] * fl[i][1] + g.e3[d] * fl[i][2];
        const double m = g.e1[d] * ml[i][0] + g.e2[d] * ml[i][1];
        (d == 0 ? out.fx : d == 1 ? out.fy : out.fz)[n] += f;
        (d == 0 ? mom.mx : d == 1 ? mom.my : mom.mz)[n] += m;
      }
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
