// One cycle of every contact pass (ContactSet::apply): the re-search when the nodes moved
// far enough, the kinematics, the law over the batch of slave nodes, the forces and the second
// half of the step's work, and their scatter to the nodes in slave order.

#include <algorithm>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact_search.hpp"
#include "kinematics.hpp"
#include "pass_runtime.hpp"
#include "plyform/core/invariant.hpp"
#include "plyform/core/stopwatch.hpp"
#include "resting_nodes.hpp"
#include "slave_share.hpp"
#include "surface_geometry.hpp"
#include "surface_reads.hpp"

namespace plyform::contact {

// One pass's search, kinematics, law and forces (apply() runs the passes one after the other or
// side by side): what it reads and writes is its own, and this cycle's booked seconds and
// searches go to its slots of pass_shared_ and pass_searches_.
void ContactSet::apply_pass(std::size_t ip, double t, double dt, const double* packed,
                            const double* temperature) {
  PassRuntime& pr = *passes_[ip];
  // Over several ranks this rank runs the kinematics, the law and the forces of its slave
  // nodes (pr.mine); the rest runs whole.
  const unsigned char* mine = pr.mine;
  const core::ContactPass& cp = *pr.pass;
  const std::size_t ns = cp.slave_count();
  if (t < pr.iface->birth || t > pr.iface->death) {
    pr.st.resultant = {0.0, 0.0, 0.0};
    pr.st.master_resultant = {0.0, 0.0, 0.0};
    std::fill(pr.st.prev_seg.begin(), pr.st.prev_seg.end(), -1);
    pr.st.dt_last = 0.0;
    // An interface that is not there does not set the step; it searches (and votes) anew
    // once it is.
    pr.st.dt_vote = kInf;
    pr.st.searched = false;
    return;
  }
  core::Stopwatch clock;
  if (cp.offsets_follow_thickness && !shell_thickness_.empty())
    follow_thickness(pr);
  // Re-search once the contact nodes moved far enough to bring a slave node near a segment
  // outside its candidate list (or at the deck's fixed interval).
  ++pr.st.cycles_since_search;
  // The largest motion since the search, of any tracked node and of the master's (the
  // resting nodes' margin, resting_nodes.hpp).
  double moved = 0.0, master_moved = 0.0;
  const std::size_t nt = pr.tracked_nodes.size();
#pragma omp parallel for schedule(static) reduction(max : moved, master_moved) if (nt > kLightLoop)
  for (long lt = 0; lt < static_cast<long>(nt); ++lt) {
    const auto i = static_cast<std::size_t>(lt);
    const double* p = at(packed, pr.tracked_nodes[i]);
    const double dx = p[0] - pr.st.tracked_ref[3 * i], dy = p[1] - pr.st.tracked_ref[3 * i + 1],
                 dz = p[2] - pr.st.tracked_ref[3 * i + 2];
    const double d2 = dx * dx + dy * dy + dz * dz;
    moved = std::max(moved, d2);
    if (pr.tracked_master[i] != 0)
      master_moved = std::max(master_moved, d2);
  }
  const int interval = pr.iface->search_interval;
  master_moved = std::sqrt(master_moved);
  if (!pr.st.searched || 2.0 * std::sqrt(moved) >= pr.margin ||
      (interval > 0 && pr.st.cycles_since_search >= interval)) {
    search(pr, packed, mass_, rigid_, rot_, tssfac_);
    ++pass_searches_[ip];
    // New candidates, and the motion since the search starts again: every node wakes.
    std::fill(pr.st.resting.begin(), pr.st.resting.end(), 0);
    master_moved = 0.0;
  }
  pr.seconds[0] += clock.lap();

  pass_rested_[ip] = static_cast<long>(rest_or_wake(pr, packed, master_moved));
  pass_node_cycles_[ip] = static_cast<long>(pr.own_slaves);
  find_surface_reads(pr, rot_.inertia != nullptr);
  measure_surfaces(pr, dt, packed);
  double lap = clock.lap();
  pr.seconds[1] += lap;
  measure_slaves(pr, dt, packed, temperature, mass_, rigid_, rot_);
  pr.st.measured = true;
  if (!pr.st.tie_state.empty()) {
    // A tied node that lost its segment (the master's edge passed it) lets go: the energy its
    // springs held is released.
    for (std::size_t k = 0; k < ns; ++k) {
      if ((mine != nullptr && mine[k] == 0) || pr.st.seg[k] >= 0 ||
          static_cast<TieState>(pr.st.tie_state[k]) != TieState::tied)
        continue;
      pr.st.tie_state[k] = static_cast<std::int8_t>(TieState::failed);
      pr.hist.e_damage[k] += pr.st.stored[k];
      pr.hist.damping[k] = 0.0;
      pr.hist.state[k] = static_cast<std::int32_t>(law::NodeState::detached);
      pr.hist.beta[k] = 0.0;
      pr.hist.slip_x[k] = pr.hist.slip_y[k] = 0.0;
    }
  }
  lap = clock.lap();
  pr.seconds[1] += lap;
  pass_shared_[ip] += lap;
  law::BatchInput in;
  in.count = ns;
  in.gap = pr.st.gap.data();
  in.slip_x = pr.st.slip_x.data();
  in.slip_y = pr.st.slip_y.data();
  in.temperature = pr.st.temperature.data();
  in.k_normal = pr.st.k_normal.data();
  in.k_tangent = pr.st.k_tangent.data();
  in.area = cp.slave_area.data();
  in.mass = pr.st.m_eff.data();
  in.dt = dt;
  // The law is immutable and every node's update independent: chunks of the batch run in
  // parallel (same arithmetic per node, so the same bits for any thread count).
  constexpr std::size_t kLawChunk = 4096;
  const bool ties = !pr.st.tie_state.empty();
  const auto updates = [&](std::size_t k) {
    if (mine != nullptr && mine[k] == 0)
      return false;
    if (ties || pr.passed_over[k] == 0)
      return true;
    const auto state = static_cast<law::NodeState>(pr.hist.state[k]);
    return state != law::NodeState::approaching && state != law::NodeState::detached;
  };
  const std::size_t chunks = (ns + kLawChunk - 1) / kLawChunk;
#pragma omp parallel for schedule(static) if (chunks > 1)
  for (long lc = 0; lc < static_cast<long>(chunks); ++lc) {
    const std::size_t chunk_begin = static_cast<std::size_t>(lc) * kLawChunk;
    const std::size_t chunk_end = std::min(ns, chunk_begin + kLawChunk);
    for (std::size_t b = chunk_begin; b < chunk_end;) {
      // The runs of the nodes the law updates within the chunk: over several ranks this rank's;
      // not a far node passed over by the kinematics (pass_runtime.hpp) whose law is free
      // (approaching or detached): two cycles at the same stand-in gap, with no damping
      // traction, left its history as the law would and its tractions zero.
      if (!updates(b)) {
        ++b;
        continue;
      }
      std::size_t e = b + 1;
      while (e < chunk_end && updates(e))
        ++e;
      law::BatchInput ci = in;
      ci.count = e - b;
      for (const double** a : {&ci.gap, &ci.slip_x, &ci.slip_y, &ci.temperature, &ci.k_normal,
                               &ci.k_tangent, &ci.area, &ci.mass})
        *a += b;
      law::BatchHistory ch = pr.hist;
      ch.state += b;
      for (double** a :
           {&ch.beta, &ch.gap, &ch.slip_x, &ch.slip_y, &ch.opening_x, &ch.opening_y, &ch.e_damage,
            &ch.e_viscous, &ch.e_friction, &ch.e_damping, &ch.e_healing, &ch.damping})
        *a += b;
      const law::BatchOutput co{pr.st.pressure.data() + b, pr.st.tau_x.data() + b,
                                pr.st.tau_y.data() + b, pr.st.stored.data() + b};
      if (pr.st.tie_state.empty()) {
        pr.law.update_batch(ci, ch, co);
      } else {
        const TieArrays tie = pr.ties();
        tiebreak_update(pr.iface->tiebreak, pr.law, ci, ch, {tie.state + b, tie.gap0 + b}, co);
      }
      b = e;
    }
  }

  lap = clock.lap();
  pr.seconds[2] += lap;
  pass_shared_[ip] += lap;
  // Forces from the tractions, and the second half of the step's work.
#pragma omp parallel for schedule(static) if (ns > kHeavyLoop)
  for (long lk = 0; lk < static_cast<long>(ns); ++lk) {
    const auto k = static_cast<std::size_t>(lk);
    if ((mine != nullptr && mine[k] == 0) || pr.passed_over[k] != 0)
      continue;  // another rank's, or far (its force and books are zero already)
    double* f = &pr.st.force[3 * k];
    const core::Index s = pr.st.seg[k];
    pr.st.end_power[k] = 0.0;
    pr.st.surface_part[k] -= 0.5 * pr.st.pressure[k] * cp.slave_area[k] * pr.st.gap_jump[k];
    if (s < 0) {
      f[0] = f[1] = f[2] = 0.0;
      continue;
    }
    const double* fr = &pr.st.frame[9 * k];
    const double a = cp.slave_area[k];
    const double pn = pr.st.pressure[k] * a, t1 = pr.st.tau_x[k] * a, t2 = pr.st.tau_y[k] * a;
    for (int c = 0; c < 3; ++c)
      f[c] = pn * fr[c] + t1 * fr[3 + c] + t2 * fr[6 + c];
    if (f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0)
      continue;
    double du[3];
    relative_velocity(pr, k, s, &pr.st.shape[4 * k], &pr.st.rs[3 * k], pr.st.side[k], fr, packed,
                      rot_, du);
    pr.st.end_power[k] = -(f[0] * du[0] + f[1] * du[1] + f[2] * du[2]);
    pr.st.work_part[k] += 0.5 * dt * pr.st.end_power[k];
  }
  lap = clock.lap();
  pr.seconds[3] += lap;
  pass_shared_[ip] += lap;
  active_[ip] = 1;
}

void ContactSet::apply(double t, double dt, const double* packed, const double* temperature,
                       double* fx, double* fy, double* fz) {
  ++applies_;
  const std::size_t np = passes_.size();
  active_.assign(np, 0);
  pass_shared_.assign(np, 0.0);
  pass_searches_.assign(np, 0);
  pass_rested_.assign(np, 0);
  pass_node_cycles_.assign(np, 0);
  // The passes' kinematics, law and forces read and write only their own state: where there
  // are several and their costs can be shared out evenly over the threads (a sandwich's
  // interfaces and tools), each runs whole on one thread, dearest first (their own loops then
  // run on that thread alone); otherwise one after the other, each loop over the threads. Each
  // pass's numbers are the same either way (its loops give the same bits on any thread count),
  // and the scatter below stays in pass order.
  const bool concurrent = passes_in_parallel();
  // Side by side, the passes' seconds overlap: each is booked its share of the wall time they
  // took together (the timing table's shares add up to the loop).
  core::Stopwatch together;
  if (concurrent) {
    seconds_before_.resize(4 * np);
    for (std::size_t ip = 0; ip < np; ++ip)
      std::copy_n(passes_[ip]->seconds, 4, &seconds_before_[4 * ip]);
  }
  // Not a parallel region of one thread when they run one after the other: the passes' own
  // loops would then be nested regions, whose threads libgomp keeps apart from the element
  // loop's, and more threads than cores spin at its barriers (the punched plate ran 5 times
  // slower).
  if (concurrent) {
#pragma omp parallel for schedule(dynamic, 1)
    for (long li = 0; li < static_cast<long>(np); ++li)
      apply_pass(pass_order_[static_cast<std::size_t>(li)], t, dt, packed, temperature);
  } else {
    for (std::size_t ip = 0; ip < np; ++ip)
      apply_pass(ip, t, dt, packed, temperature);
  }
  if (concurrent) {
    const double wall = together.lap();
    double spent = 0.0;
    for (std::size_t ip = 0; ip < np; ++ip)
      for (std::size_t j = 0; j < 4; ++j)
        spent += passes_[ip]->seconds[j] - seconds_before_[4 * ip + j];
    const double share = spent > 0.0 ? wall / spent : 0.0;
    for (std::size_t ip = 0; ip < np; ++ip) {
      for (std::size_t j = 0; j < 4; ++j) {
        double& sec = passes_[ip]->seconds[j];
        sec = seconds_before_[4 * ip + j] + share * (sec - seconds_before_[4 * ip + j]);
      }
      pass_shared_[ip] *= share;
    }
  }
  for (std::size_t ip = 0; ip < np; ++ip) {
    shared_seconds_ += pass_shared_[ip];
    searches_ += pass_searches_[ip];
    rested_ += pass_rested_[ip];
    node_cycles_ += pass_node_cycles_[ip];
  }

  // Over several ranks: what the scatter and the books read of every pass's slave nodes, from
  // their owners to every rank, in one exchange for all the passes (nothing above reads what the
  // scatter below writes: the kinematics read positions and velocities, not forces).
  if (!shares_.empty()) {
    core::Stopwatch clock;
    SlaveShare::exchange_cycle(shares_, passes_, active_);
    exchange_seconds_ += clock.lap();
  }

  for (std::size_t ip = 0; ip < passes_.size(); ++ip) {
    if (active_[ip] == 0)
      continue;
    PassRuntime& pr = *passes_[ip];
    const core::ContactPass& cp = *pr.pass;
    const std::size_t ns = cp.slave_count();
    core::Stopwatch clock;
    pr.st.dt_last = dt;
    pr.st.work += chunked_sum(ns, pr.chunk_sums, [&](std::size_t k) { return pr.st.work_part[k]; });
    pr.st.surface +=
        chunked_sum(ns, pr.chunk_sums, [&](std::size_t k) { return pr.st.surface_part[k]; });

    // Scatter in slave order: each node receives its contributions in the same order for any
    // number of threads.
    std::array<double, 3> r{}, rm{};
    const double sign = cp.slave_side_sign;
    for (std::size_t k = 0; k < ns; ++k) {
      const core::Index s = pr.st.seg[k];
      pr.st.prev_seg[k] = s;
      if (s < 0)
        continue;
      const double* f = &pr.st.force[3 * k];
      if (f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0) {
        pr.st.prev_seg[k] = -1;
        continue;
      }
      PLYFORM_INVARIANT(std::isfinite(f[0] + f[1] + f[2]), "a finite contact force");
      PLYFORM_INVARIANT(static_cast<std::size_t>(s) < cp.segment_count(), "a segment in range");
      const auto sn = static_cast<std::size_t>(cp.slave_nodes[k]);
      fx[sn] -= f[0];
      fy[sn] -= f[1];
      fz[sn] -= f[2];
      // The force acts on the surface points: on nodes with rotations, the couples r x f of its
      // tangential part (the part relative_velocity() lets the rotations move). The engine's
      // moment arrays are internal moments, like its force arrays.
      const bool spin = rot_.inertia != nullptr;
      const double* fn = &pr.st.frame[9 * k];
      const double f_n = f[0] * fn[0] + f[1] * fn[1] + f[2] * fn[2];
      const double ft[3] = {f[0] - f_n * fn[0], f[1] - f_n * fn[1], f[2] - f_n * fn[2]};
      if (spin && rot_.inertia[sn] > 0.0) {
        const double* rs = &pr.st.rs[3 * k];
        rot_.mx[sn] -= rs[1] * ft[2] - rs[2] * ft[1];
        rot_.my[sn] -= rs[2] * ft[0] - rs[0] * ft[2];
        rot_.mz[sn] -= rs[0] * ft[1] - rs[1] * ft[0];
      }
      const auto su = static_cast<std::size_t>(s);
      const core::Index* q = &cp.segments[4 * su];
      const int nodes = q[2] == q[3] ? 3 : 4;
      const double om = pr.st.seg_offset[su];
      for (int j = 0; j < nodes; ++j) {
        const double nj = pr.st.shape[4 * k + j];
        const auto m = static_cast<std::size_t>(q[j]);
        fx[m] += nj * f[0];
        fy[m] += nj * f[1];
        fz[m] += nj * f[2];
        if (spin && om > 0.0 && rot_.inertia[m] > 0.0) {
          double rm_[3];
          corner_offset(pr, su, j, pr.st.side[k], rm_);
          rot_.mx[m] += nj * (rm_[1] * ft[2] - rm_[2] * ft[1]);
          rot_.my[m] += nj * (rm_[2] * ft[0] - rm_[0] * ft[2]);
          rot_.mz[m] += nj * (rm_[0] * ft[1] - rm_[1] * ft[0]);
        }
        for (int c = 0; c < 3; ++c)
          rm[static_cast<std::size_t>(c)] -= sign * nj * f[c];
      }
      for (int c = 0; c < 3; ++c)
        r[static_cast<std::size_t>(c)] += sign * f[c];
    }
    pr.st.resultant = r;
    pr.st.master_resultant = rm;
    std::swap(pr.st.prev_force, pr.st.force);
    std::swap(pr.st.prev_rs, pr.st.rs);
    // `shape` then holds older values: measure() rewrites it for every located node, and
    // only located nodes read it. Until the next apply(), the projection on pr.st.seg[k] is in
    // prev_shape (what the heat between cycles reads: located_shape()).
    std::swap(pr.st.prev_shape, pr.st.shape);
    pr.seconds[3] += clock.lap();
  }
}

// Whether apply() runs its passes side by side (above): two threads or more, two live passes
// or more, and no pass dearer than a thread's even share of them all (by the seconds each has
// taken so far; by slave nodes before any are measured). Orders the passes dearest first when
// it does, in their own order otherwise.
bool ContactSet::passes_in_parallel() {
  const std::size_t np = passes_.size();
  pass_order_.resize(np);
  for (std::size_t ip = 0; ip < np; ++ip)
    pass_order_[ip] = ip;
#ifdef _OPENMP
  const auto threads = static_cast<double>(omp_get_max_threads());
  const bool nested = omp_in_parallel() != 0;
#else
  const double threads = 1.0;
  const bool nested = false;
#endif
  if (threads < 2.0 || np < 2 || nested)
    return false;
  pass_cost_.assign(np, 0.0);
  double total = 0.0, largest = 0.0, measured = 0.0;
  for (std::size_t ip = 0; ip < np; ++ip)
    for (const double sec : passes_[ip]->seconds)
      measured += sec;
  for (std::size_t ip = 0; ip < np; ++ip) {
    const PassRuntime& pr = *passes_[ip];
    double cost = 0.0;
    if (measured > 0.0)
      for (const double sec : pr.seconds)
        cost += sec;
    else
      cost = static_cast<double>(pr.pass->slave_count());
    pass_cost_[ip] = cost;
    total += cost;
    largest = std::max(largest, cost);
  }
  if (!(total > 0.0) || largest > total / threads)
    return false;
  std::stable_sort(pass_order_.begin(), pass_order_.end(),
                   [&](std::size_t a, std::size_t b) { return pass_cost_[a] > pass_cost_[b]; });
  return true;
}

}  // namespace plyform::contact
