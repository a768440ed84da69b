#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "plyform/element/shell_kernels.hpp"
#include "plyform/material/constitutive.hpp"
#include "plyform/material/law_registry.hpp"
#include "plyform/material/shell.hpp"
#include "shell_common.hpp"
#include "shell_stages.hpp"

namespace plyform::element {
namespace {

using namespace shell_detail;

template <class M>
ShellResult bt(const core::ShellBlock& block, const M& mat, ShellBlockState& st,
               const NodalView& nv, const NodalSpin& spin, double dt, std::size_t begin,
               std::size_t end, const NodalForces& out, const NodalMoments& mom, double wave_speed,
               double rho) {
  using Law = LawOf<M>;
  ShellResult r;
  const int nip = st.nip;
  const auto unip = static_cast<std::size_t>(nip);
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
  ChunkFrames<kChunk> f;
  PointBuffers<kChunk* static_cast<std::size_t>(kMaxNip)> b;
  const bool thermal = !st.temperature.empty() && nv.temperature != nullptr;
  const bool expands = thermal && !block.expansion.x.empty();
  const bool plastic_heat = out.plastic_work != nullptr;
  // Bulk viscosity of the membrane (TYPE -1/-2): its pressure and the compression rate.
  const bool bulk_on =
      block.bulk_viscosity_on && (block.bulk_viscosity.q1 != 0.0 || block.bulk_viscosity.q2 != 0.0);
  double bulk_q[kChunk], tk[kChunk], work_old[kChunk];
  alignas(64) double B1[4][kChunk], B2[4][kChunk], RATE[9][kChunk];
  alignas(64) double MSPIN[kChunk], FTURN[kChunk];
  for (std::size_t c0 = begin; c0 < end; c0 += kChunk) {
    const std::size_t chunk = std::min(kChunk, end - c0);
    // Stage A, lane-wise over the chunk (vectorised across elements): the frames, then the
    // gradients at the centre and the rates.
    chunk_frames(block, nv, spin, c0, chunk, f);
    for (std::size_t k = 0; k < kChunk; ++k) {
      double xl[4], yl[4];
      for (int i = 0; i < 4; ++i) {
        xl[i] = f.xl[i][k];
        yl[i] = f.yl[i][k];
      }
      const double inv2a = 0.5 / f.area[k];
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
      for (int i = 0; i < 4; ++i) {
        B1[i][k] = b1[i];
        B2[i][k] = b2[i];
        const double vxl = f.vl[3 * i][k], vyl = f.vl[3 * i + 1][k], vzl = f.vl[3 * i + 2][k];
        const double wxl = f.wl[3 * i][k], wyl = f.wl[3 * i + 1][k];
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
      // The mid-surface's velocity gradient at the centre (its third column the nodes' mean
      // spin: dv_x/dz = theta_y, dv_y/dz = -theta_x) on the mid-step configuration.
      const InPlaneRate am = mid_step_rate(dxx, lxy, lyx, dyy, gxz, gyz, dt);
      // The stored stresses turn with the frame (they are its components); the material's spin
      // W = (L_yx - L_xy) / 2 differs from the frame's own spin, that of the mid-side vector
      // s1 = (x2 + x3 - x1 - x4) / 2 it follows. The difference turns the stresses back.
      const double s1x = 0.5 * (xl[1] + xl[2] - xl[0] - xl[3]);
      const double s1v = 0.5 * (f.vl[4][k] + f.vl[7][k] - f.vl[1][k] - f.vl[10][k]);
      RATE[0][k] = am.a00;
      RATE[1][k] = am.a11;
      RATE[2][k] = am.a01 + am.a10;
      RATE[3][k] = kx;
      RATE[4][k] = ky;
      RATE[5][k] = kxy;
      RATE[6][k] = gxz + thy;
      RATE[7][k] = gyz - thx;
      RATE[8][k] = (0.5 * (am.a10 - am.a01) - s1v / s1x) * dt;
      if constexpr (material::law_needs_frame_turn<Law>()) {
        // s1 at t_n was s1 - dt ds1/dt: the frame turned through atan of this, exactly.
        const double s1u = 0.5 * (f.vl[3][k] + f.vl[6][k] - f.vl[0][k] - f.vl[9][k]);
        MSPIN[k] = 0.5 * (am.a10 - am.a01) * dt;
        FTURN[k] = dt * s1v / (s1x - dt * s1u);
      }
    }
    // Per element: checks, the stable step, the stresses turned by the relative spin, the
    // strain increments at the thickness points, and the data the force stage needs.
    for (std::size_t e = c0; e < c0 + chunk; ++e) {
      const std::size_t k_el = e - c0;
      const double t = tk[k_el] = st.thickness[e];
      const double area = f.area[k_el];
      if (!frame_usable(f, k_el, t)) {
        r.failed = true;
        r.failed_element = e;
        return r;
      }
      st.area[e] = area;
      double dte = st.dt_factor[e] * f.length[k_el] / wave_speed;
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
          dte = st.dt_factor[e] * f.length[k_el] /
                (qv + std::sqrt(qv * qv + wave_speed * wave_speed));
        }
      }
      if (dte < r.dt_min) {
        r.dt_min = dte;
        r.dt_element = e;
      }
      const double phi = RATE[8][k_el];
      const std::size_t at0 = k_el * unip;
      {
        double rate[kColumnRates][1], turn[1] = {phi}, w_old[1];
        for (int c = 0; c < kColumnRates; ++c)
          rate[c][0] = RATE[c][k_el];
        prepare_columns<1>(st, b, unip * e, at0, unip, t, zeta, weight, kappa, dt, rate, turn,
                           w_old);
        work_old[k_el] = w_old[0];
      }
      if (thermal) {
        // Thermal expansion takes alpha(T_mid) dT off the in-plane increments the law sees.
        double t_point[kMaxNip], eth_point[kMaxNip];
        thickness_temperatures(block, nv, st, e, zeta, unip, dt, expands, t_point, eth_point);
        spread_temperatures<1>(b, at0, unip, t_point, eth_point);
      }
      if constexpr (Law::needs_material_axes) {
        set_material_axes<Law>(mat, block, e, f, k_el, b, at0, unip);
      }
      if constexpr (material::law_needs_spin<Law>())
        std::fill_n(&b.spin[at0], unip, phi);
      if constexpr (material::law_needs_frame_turn<Law>()) {
        std::fill_n(&b.material_spin[at0], unip, MSPIN[k_el]);
        std::fill_n(&b.frame_turn[at0], unip, FTURN[k_el]);
      }
    }
    update_points<Law>(mat, st, unip * c0, unip * chunk, b, thermal, plastic_heat, expands, dt);
    for (std::size_t e = c0; e < c0 + chunk; ++e) {
      const std::size_t k_el = e - c0;
      const core::Index* conn = &block.connectivity[4 * e];
      const double t = tk[k_el];
      const std::size_t q0 = unip * e, at0 = k_el * unip;
      // Resultants over the thickness, the stress work and the thickness update from the mean
      // normal strain.
      ColumnSums<1> cs;
      sum_columns<1>(st, b, q0, at0, unip, t, zeta, weight, kappa, plastic_heat, cs);
      // The resultants on the end-of-step thickness t (1 + tz), where the stresses sigma_{n+1}
      // belong (shell_stages.hpp, thickness_resultants).
      const double tz = cs.tz;
      const ThicknessScale grow(tz);
      double nxx = grow.n * cs.nxx[0], nyy = grow.n * cs.nyy[0];
      const double nxy = grow.n * cs.nxy[0], mxx = grow.m * cs.mxx[0], myy = grow.m * cs.myy[0];
      const double mxy = grow.m * cs.mxy[0], qx = grow.n * cs.qx[0], qy = grow.n * cs.qy[0];
      const double a = f.area[k_el];
      // The step's stress work counts on the mid-step volume: the thickness halfway through
      // its update, the area back half the step's in-plane dilatation from t_{n+1} (on the
      // end-of-step volume the books drift at first order in the step when the sheet
      // stretches and thins).
      const double mid_volume =
          t * (1.0 + 0.5 * tz) * a * (1.0 - 0.5 * dt * (RATE[0][k_el] + RATE[1][k_el]));
      // The element's books, summed into the range's in element order (ElementBooks).
      double internal = 0.5 * (work_old[k_el] + cs.work[0]) * 0.5 * mid_volume;
      double hg = 0.0, hg_start = 0.0, hg_end = 0.0;
      const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
      double p_start = work_old[k_el] * 0.5 * mid_volume * inv_dt;
      double p_end = cs.work[0] * 0.5 * mid_volume * inv_dt;
      if (bulk_on) {
        // The pressure over the thickness acts on the membrane only (not stored in the
        // stresses); its work is internal energy, by the stresses' midpoint rule: the pressures
        // of t_n and t_{n+1} on the step's rate |tr D| t A (element/solid_kernels.cpp says why).
        double& q_old = st.bulk_q[e];
        const double rate = -(RATE[0][k_el] + RATE[1][k_el]);
        const double w0 = q_old * rate * t * a, w1 = bulk_q[k_el] * rate * t * a;
        internal += 0.5 * (w0 + w1) * dt;
        p_start += w0;
        p_end += w1;
        q_old = bulk_q[k_el];
        nxx -= bulk_q[k_el] * t;
        nyy -= bulk_q[k_el] * t;
      }
      st.thickness[e] = t * (1.0 + tz);
      if (plastic_heat)
        spread_plastic_work(conn, cs.plastic[0] * 0.5 * t * a, out);
      double fl[4][3], ml[4][2];
      for (int i = 0; i < 4; ++i) {
        const double b1 = B1[i][k_el], b2 = B2[i][k_el];
        fl[i][0] = a * (b1 * nxx + b2 * nxy);
        fl[i][1] = a * (b2 * nyy + b1 * nxy);
        fl[i][2] = a * (b1 * qx + b2 * qy);
        ml[i][0] = -a * (b2 * myy + b1 * mxy) - 0.25 * a * qy;
        ml[i][1] = a * (b1 * mxx + b2 * mxy) + 0.25 * a * qx;
      }
      if (qm > 0.0) {
        // Hourglass control of the four modes h = (1, -1, 1, -1): membrane, out of plane and the
        // two rotations, with gamma = h - (h . x) b1 - (h . y) b2 orthogonal to the linear
        // fields; viscous (IHQ 1-3) or stiffness (IHQ 4-5).
        double hx = 0, hy = 0;
        for (int i = 0; i < 4; ++i) {
          hx += h[i] * f.xl[i][k_el];
          hy += h[i] * f.yl[i][k_el];
        }
        double gam[4];
        for (int i = 0; i < 4; ++i)
          gam[i] = h[i] - hx * B1[i][k_el] - hy * B2[i][k_el];
        double qv[5] = {0, 0, 0, 0, 0};
        for (int i = 0; i < 4; ++i) {
          qv[0] += gam[i] * f.vl[3 * i][k_el];
          qv[1] += gam[i] * f.vl[3 * i + 1][k_el];
          qv[2] += gam[i] * f.vl[3 * i + 2][k_el];
          qv[3] += gam[i] * f.wl[3 * i][k_el];
          qv[4] += gam[i] * f.wl[3 * i + 1][k_el];
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
            bb += B1[i][k_el] * B1[i][k_el] + B2[i][k_el] * B2[i][k_el];
          const double km = qm * e_plate * t * a * bb / 8.0;
          const double kw = qm * e_plate * t * t * t * bb / 24.0;
          const double kr = qm * e_plate * t * t * t * a * bb / 192.0;
          const double k[5] = {km, km, kw, kr, kr};
          double p0 = 0.0, p1 = 0.0;
          for (int j = 0; j < 5; ++j) {
            double& qj = st.hourglass[j][e];
            const double q_new = qj + k[j] * qv[j] * dt;
            p0 += qj * qv[j];
            p1 += q_new * qv[j];
            qj = q_new;
            coef[j] = q_new;
          }
          hg = 0.5 * (p0 + p1) * dt;
          hg_start = p0;
          hg_end = p1;
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
          // The modes' last forces are kept for the midpoint rule of their work, as the
          // stiffness form's (a viscous force from the step's rate acts at t_{n+1}).
          double p0 = 0.0, p1 = 0.0;
          for (int j = 0; j < 5; ++j) {
            double& qj = st.hourglass[j][e];
            p0 += qj * qv[j];
            qj = coef[j] * qv[j];
            p1 += qj * qv[j];
          }
          hg = 0.5 * (p0 + p1) * dt;
          hg_start = p0;
          hg_end = p1;
          for (int i = 0; i < 4; ++i) {
            fl[i][0] += coef[0] * qv[0] * gam[i];
            fl[i][1] += coef[1] * qv[1] * gam[i];
            fl[i][2] += coef[2] * qv[2] * gam[i];
            ml[i][0] += coef[3] * qv[3] * gam[i];
            ml[i][1] += coef[4] * qv[4] * gam[i];
          }
        }
      }
      scatter(conn, f, k_el, fl, ml, out, mom);
      r.internal_energy += internal;
      r.start_power += p_start;
      r.end_power += p_end;
      r.hourglass_energy += hg;
      r.hourglass_start_power += hg_start;
      r.hourglass_end_power += hg_end;
      if (out.books != nullptr)
        out.books[e] = {internal, hg, p_start, p_end, hg_start, hg_end};
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
    q.assign(inplane == 1 ? n : 0, 0.0);
  bulk_q.assign(n * inplane, 0.0);
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
