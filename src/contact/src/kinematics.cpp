#include "kinematics.hpp"

#include <algorithm>
#include <cmath>

#include "penalty.hpp"
#include "projection.hpp"
#include "surface_geometry.hpp"
#include "surface_normals.hpp"

namespace plyform::contact {

namespace {

// The law's tangential history of a slave node (its stick slip and its adhesive opening) is
// written in the node's tangent axes. Those axes come from the global x axis (y where the normal
// is close to x), so they jump by up to 90 degrees when the normal passes near x, and they turn
// with the surface. Before the axes are replaced, each history vector is taken back to global
// components, turned by the smallest rotation that takes the old normal to the new one (the
// surface carries it along), and written in the new axes: its direction and length stay what
// they were on the surface, whatever the axes do.
inline void carry_tangential_history(const law::BatchHistory& h, std::size_t k,
                                     const double* old_frame, const double* n, const double* e1,
                                     const double* e2) {
  const double* n0 = old_frame;
  const double c = n0[0] * n[0] + n0[1] * n[1] + n0[2] * n[2];
  if (!(c > -0.5))  // no frame yet (zeros), or the node turned onto a far side: start afresh
    return;
  const double* a1 = old_frame + 3;
  const double* a2 = old_frame + 6;
  const auto carry = [&](double& x, double& y) {
    if (x == 0.0 && y == 0.0)
      return;
    double v[3] = {x * a1[0] + y * a2[0], x * a1[1] + y * a2[1], x * a1[2] + y * a2[2]};
    // R v = v - (v . n) (n0 + n) / (1 + c) for v normal to n0 (Rodrigues, the rotation about
    // n0 x n that takes n0 to n).
    const double vn = (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / (1.0 + c);
    for (int d = 0; d < 3; ++d)
      v[d] -= vn * (n0[d] + n[d]);
    x = v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2];
    y = v[0] * e2[0] + v[1] * e2[1] + v[2] * e2[2];
  };
  carry(h.slip_x[k], h.slip_y[k]);
  carry(h.opening_x[k], h.opening_y[k]);
}

// A bonded slave node that left the master surface (a skin's edge sliding past the core's edge)
// lets go of its bond without any work: the energy its springs held goes to damage, as a
// release does, and so does the adhesion omega(T) beta it takes with it, which no work paid
// for: the surface book takes that as the surfaces' own doing, and the interface's books still
// close. Before, the law released it at the stand-in gap and booked omega beta as damage
// against nothing (the coarse hot draw's lower interface: books 33 % above work + surface at
// 2.2 ms, twelve edge nodes of 1.4 mJ each).
void leave_master_bonded(PassRuntime& pr, std::size_t k) {
  const law::BatchHistory& h = pr.hist;
  const law::Parameters& p = pr.law.parameters();
  const double smax = law::evaluate(p.sigma_max, p, pr.st.temperature[k]);
  const double area = pr.pass->slave_area[k];
  const double adhesion = smax * smax / p.cn * h.beta[k] * area;
  // The stick spring's share is friction's, as when the law lets a node out of contact (it
  // turns to heat with the friction).
  const double stick =
      0.5 * pr.st.k_tangent[k] * (h.slip_x[k] * h.slip_x[k] + h.slip_y[k] * h.slip_y[k]) * area;
  h.e_friction[k] += stick;
  h.e_damage[k] += pr.st.stored[k] - stick + adhesion;
  pr.st.surface_part[k] += adhesion;
  h.state[k] = static_cast<std::int32_t>(law::NodeState::detached);
  h.beta[k] = 0.0;
  h.slip_x[k] = h.slip_y[k] = 0.0;
  h.opening_x[k] = h.opening_y[k] = 0.0;
}

// A node pressed on the master that left it (a sheet sliding off a holder's inner edge) takes
// its normal spring's energy with it: no work unloaded that spring, so the surface book pays it
// out (the law turns the stick spring's to friction as the node detaches). Unbooked, the
// coarse hot draw's holder contact fell 1.6 % below its work by such steps of 5-15 mJ.
void leave_master_pressed(PassRuntime& pr, std::size_t k) {
  const law::BatchHistory& h = pr.hist;
  const double stick = 0.5 * pr.st.k_tangent[k] *
                       (h.slip_x[k] * h.slip_x[k] + h.slip_y[k] * h.slip_y[k]) *
                       pr.pass->slave_area[k];
  pr.st.surface_part[k] -= pr.st.stored[k] - stick;
}

}  // namespace

// Geometry and law inputs of every slave node of a pass at the current positions; the first
// half of the step's contact work with last cycle's forces. Fills the arrays.
void measure(PassRuntime& pr, double dt, const double* packed, const double* temperature,
             const std::vector<double>& mass, const unsigned char* rigid, const Rotations& rot) {
  pr.reads.all_master = pr.reads.all_slaves = true;  // at t = 0 (initial_contacts.cpp): all
  measure_surfaces(pr, dt, packed);
  measure_slaves(pr, dt, packed, temperature, mass, rigid, rot);
}

void measure_surfaces(PassRuntime& pr, double dt, const double* packed) {
  pr.st.seg_normal_current = pr.master_offsets && dt > 0.0;
  if (pr.st.seg_normal_current)
    update_master_normals(pr, packed);
  if (!pr.pass->slave_face_start.empty() && dt > 0.0)
    update_slave_normals(pr, packed);
  update_folds(pr, packed);
}

void measure_slaves(PassRuntime& pr, double dt, const double* packed, const double* temperature,
                    const std::vector<double>& mass, const unsigned char* rigid,
                    const Rotations& rot) {
  const core::ContactPass& cp = *pr.pass;
  const std::size_t ns = cp.slave_count();
  const law::BatchHistory& h = pr.hist;
  pr.far_cycles.resize(ns, 0);
  pr.passed_over.resize(ns, 0);
#pragma omp parallel for schedule(static) if (ns > kHeavyLoop)
  for (long lk = 0; lk < static_cast<long>(ns); ++lk) {
    const auto k = static_cast<std::size_t>(lk);
    if (pr.mine != nullptr && pr.mine[k] == 0)
      continue;  // another rank's slave node (slave_share.hpp)
    const core::Index node = cp.slave_nodes[k];
    // Far (pass_runtime.hpp): two cycles measured it so already; only its temperature moves.
    const bool far =
        pr.st.seg[k] < 0 && pr.st.prev_seg[k] < 0 && pr.st.cand_start[k] == pr.st.cand_start[k + 1];
    // Resting (resting_nodes.hpp): clear of the master, with no force, until its margin is spent.
    pr.passed_over[k] = (far && pr.far_cycles[k] >= 2) || pr.st.resting[k] != 0 ? 1 : 0;
    if (pr.passed_over[k] != 0) {
      pr.st.temperature[k] =
          temperature != nullptr ? temperature[static_cast<std::size_t>(node)] : 0.0;
      continue;
    }
    pr.far_cycles[k] = far ? static_cast<std::uint8_t>(std::min(pr.far_cycles[k] + 1, 2)) : 0;
    // First half of the trapezoidal work of the step just taken, with last cycle's force (and
    // last cycle's frame and surface point, still in the arrays). Where the step changed, that
    // force moved the nodes over dt_avg / 2 on each side of its time: (dt - dt_last) / 4 times
    // its power on the last step less its power on this one (docs/energy.md).
    double w = 0.0;
    double moved_before = 0.0;  // the step's normal motion at last cycle's point and normal
    // Last cycle's tangential traction (global axes), its work on the step's motion at last
    // cycle's point, and last cycle's normal: the surface book's tangential half below.
    double tau_before[3] = {0.0, 0.0, 0.0}, n_before[3] = {0.0, 0.0, 0.0};
    double slid_before = 0.0;
    if (pr.st.prev_seg[k] >= 0) {
      const double* f = &pr.st.prev_force[3 * k];
      double du[3];
      relative_velocity(pr, k, pr.st.prev_seg[k], &pr.st.prev_shape[4 * k], &pr.st.prev_rs[3 * k],
                        pr.st.side[k], &pr.st.frame[9 * k], packed, rot, du);
      const double* fr0 = &pr.st.frame[9 * k];
      for (int d = 0; d < 3; ++d) {
        n_before[d] = fr0[d];
        tau_before[d] = pr.st.tau_x[k] * fr0[3 + d] + pr.st.tau_y[k] * fr0[6 + d];
      }
      moved_before = dt * (du[0] * n_before[0] + du[1] * n_before[1] + du[2] * n_before[2]);
      slid_before = dt * (du[0] * tau_before[0] + du[1] * tau_before[1] + du[2] * tau_before[2]);
      const double start_power = -(f[0] * du[0] + f[1] * du[1] + f[2] * du[2]);
      w += 0.5 * dt * start_power;
      if (pr.st.dt_last > 0.0)
        w += 0.25 * (dt - pr.st.dt_last) * (pr.st.end_power[k] - start_power);
    }
    pr.st.work_part[k] = w;
    pr.st.gap_jump[k] = 0.0;
    pr.st.temperature[k] =
        temperature != nullptr ? temperature[static_cast<std::size_t>(node)] : 0.0;
    const auto state = static_cast<law::NodeState>(h.state[k]);
    const bool free = state == law::NodeState::approaching || state == law::NodeState::detached;
    const bool was_located = pr.st.seg[k] >= 0;
    Located L;
    const core::Index s = locate(pr, k, free, was_located, packed, L);
    pr.st.seg[k] = s;
    double* rs = &pr.st.rs[3 * k];
    if (s < 0) {
      pr.st.surface_part[k] = 0.0;
      // The law sees the stand-in gap: its last damping traction's second half (half a step's
      // work of it) is not booked against that jump.
      h.damping[k] = 0.0;
      if (was_located && !free) {
        if (pr.bonds && h.beta[k] > 0.0)
          leave_master_bonded(pr, k);
        else if (pr.st.tie_state.empty() ||
                 static_cast<TieState>(pr.st.tie_state[k]) != TieState::tied)
          leave_master_pressed(pr, k);
      }
      pr.st.gap[k] = pr.far_gap;
      pr.st.arrival_depth[k] = 0.0;
      pr.st.slip_x[k] = pr.st.slip_y[k] = 0.0;
      pr.st.m_eff[k] = 0.0;
      rs[0] = rs[1] = rs[2] = 0.0;
      continue;
    }
    const core::Index* q = &cp.segments[4 * static_cast<std::size_t>(s)];
    for (int j = 0; j < 4; ++j)
      pr.st.shape[4 * k + j] = L.sp.shape[j];
    pr.st.side[k] = L.side;
    rs[0] = L.rs[0], rs[1] = L.rs[1], rs[2] = L.rs[2];
    // A node that comes onto the master from beyond its edge (a layer's edge sliding back over
    // the layer below, a sheet coming round a tool's edge) may arrive inside the band of the
    // offsets: a penetration it never made. Pushing it out would give the model energy that
    // never entered it. Beyond a shallow first part (1 % of the band, an interference of
    // meshes the penalty should remove, as before), the depth it arrived at is tolerated, and
    // the tolerance shrinks to the node's depth whenever it comes out (there is no force then,
    // so nothing is stored): the penalty acts on penetration beyond the arrival depth only, and
    // the usual rule resumes once the node is clear. Penetrations at t = 0 are pushed out, as
    // LS-DYNA does with IGNORE = 0.
    const double g = L.side * L.sp.distance;
    double& tol = pr.st.arrival_depth[k];
    const double band = pr.st.slave_offset[k] + pr.st.seg_offset[static_cast<std::size_t>(s)];
    const double push = 0.01 * band;
    // A located node arrives too when its depth jumps by half the band or more in one cycle,
    // which no motion does: it took another surface's segment (an intersecting part) whose
    // band it was inside already, or its segment turned over (a crushed fold's quadrilateral
    // flips its normal); the penalty would fire the node out (the crush box deck: 1.3 mm deep
    // at once, 150 mm/ms; a segment flipped under a node 9 mm above it, 12 mm deep, 17 kJ).
    const double g_before = pr.st.gap[k] + tol;
    const bool jumped = was_located && band > 0.0 && g < g_before - 0.5 * band;
    if (((!was_located && pr.st.measured) || jumped) && g < -push)
      tol = std::min(tol, g + push);
    else if (tol < 0.0 && g > tol)
      tol = g < 0.0 ? g : 0.0;
    pr.st.gap[k] = g - tol;
    // A guard acts only beyond kGuardDepth of the two offsets' depth.
    if (pr.guard)
      pr.st.gap[k] +=
          kGuardDepth * (pr.st.slave_offset[k] + pr.st.seg_offset[static_cast<std::size_t>(s)]);
    // Its last gap was the stand-in `far_gap`: start the gap rate (normal damping) afresh.
    if (!was_located)
      h.gap[k] = pr.st.gap[k];
    double* fr = &pr.st.frame[9 * k];
    const double n[3] = {L.side * L.sp.normal[0], L.side * L.sp.normal[1], L.side * L.sp.normal[2]};
    // Tangent axes from the global x axis (y where the normal is close to x): continuous as
    // the node moves from segment to segment, so the stick spring keeps its meaning.
    double e1[3] = {1.0 - n[0] * n[0], -n[0] * n[1], -n[0] * n[2]};
    double len = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    if (len < 0.1) {
      e1[0] = -n[1] * n[0];
      e1[1] = 1.0 - n[1] * n[1];
      e1[2] = -n[1] * n[2];
      len = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    }
    const double inv_len = 1.0 / len;
    e1[0] *= inv_len;
    e1[1] *= inv_len;
    e1[2] *= inv_len;
    const double e2[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2],
                          n[0] * e1[1] - n[1] * e1[0]};
    carry_tangential_history(h, k, fr, n, e1, e2);
    for (int c = 0; c < 3; ++c) {
      fr[c] = n[c];
      fr[3 + c] = e1[c];
      fr[6 + c] = e2[c];
    }
    // Relative displacement of the step: the slave's surface point minus the segment's
    // surface point (same shape functions as the force distribution).
    double du[3];
    relative_velocity(pr, k, s, L.sp.shape, rs, L.side, fr, packed, rot, du);
    // The effective mass, which every pass needs: damping (VDC), SOFT = 1, a layer interface's
    // penalty, the cap on any other penalty (kToolPenaltyScale), friction's stick spring.
    double mm = 0.0;
    for (int j = 0; j < 4; ++j) {
      const double nj = L.sp.shape[j];
      if (nj > 0.0)
        mm += nj * node_mass(mass, rigid, q[j]);
    }
    pr.st.slip_x[k] = dt * (du[0] * e1[0] + du[1] * e1[1] + du[2] * e1[2]);
    pr.st.slip_y[k] = dt * (du[0] * e2[0] + du[1] * e2[1] + du[2] * e2[2]);
    // The surface book: the law's gap changed by pr.st.gap - h.gap over the step, the nodes'
    // motion moved it by dt du . n; the rest no work of the nodes paid for. Each half of the
    // step's work is measured as the work is: last cycle's pressure with last cycle's point and
    // normal (the pressure still last cycle's here), this cycle's with this cycle's (the force
    // loop). A node found again starts afresh.
    pr.st.surface_part[k] = 0.0;
    if (!was_located && pr.st.measured) {
      // A node that finds a segment (again) already inside it: the spring the law gives it
      // stores energy that no work put in (the shallow first part of an arrival's depth, which
      // the penalty pushes out, above). The whole gap counts as the surface's doing: the
      // force loop books -p A g / 2, the linear spring's stored energy. Unbooked, a skin's
      // nodes that kept leaving and finding the core's receding edge each made 0.05 mJ out of
      // nothing in the frictionless square cup, 0.2 % of that interface's work.
      pr.st.gap_jump[k] = pr.st.gap[k];
    } else if (was_located) {
      const double changed = pr.st.gap[k] - h.gap[k];
      pr.st.gap_jump[k] = changed - dt * (du[0] * n[0] + du[1] * n[1] + du[2] * n[2]);
      pr.st.surface_part[k] =
          -0.5 * pr.st.pressure[k] * cp.slave_area[k] * (changed - moved_before);
      // Tangential: the law works last cycle's traction, carried into this cycle's frame (as
      // carry_tangential_history carries its springs), on this cycle's slip; the nodes moved
      // under it at last cycle's point and frame. Where a node passes between facets at an
      // angle, the two differ (a node switching facets every cycle under 21 MPa in the
      // three-layer square cup: 2.5 % of its interface's work).
      double slid = 0.0;
      const double c = n_before[0] * n[0] + n_before[1] * n[1] + n_before[2] * n[2];
      if (c > -0.5) {
        double v[3] = {tau_before[0], tau_before[1], tau_before[2]};
        const double vn = (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / (1.0 + c);
        for (int d = 0; d < 3; ++d)
          v[d] -= vn * (n_before[d] + n[d]);
        slid = dt * (v[0] * du[0] + v[1] * du[1] + v[2] * du[2]);
      }
      pr.st.surface_part[k] -= 0.5 * cp.slave_area[k] * (slid - slid_before);
    }
    const double me = effective_mass(node_mass(mass, rigid, node), mm);
    pr.st.m_eff[k] = me;
    const double kk = penalty(pr, k, s, me);
    pr.st.k_normal[k] = kk / cp.slave_area[k];
    pr.st.k_tangent[k] = pr.st.k_normal[k];
    if (pr.dt0 > 0.0 && me > 0.0)
      pr.st.k_tangent[k] =
          std::min(pr.st.k_tangent[k], kStickScale * me / (pr.dt0 * pr.dt0) / cp.slave_area[k]);
  }
}

}  // namespace plyform::contact
