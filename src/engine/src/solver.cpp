#include "plyform/engine/solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "boundary_conditions.hpp"
#include "deterministic_sum.hpp"
#include "mass.hpp"

namespace plyform::engine {
namespace {

// A range of elements of one colour of one block: the unit of parallel work in the element
// loop. Items of one phase (block, colour) share no node and run in parallel; phases run in
// order, so each node sums its forces in the same order for any number of threads.
struct WorkItem {
  std::size_t block, begin, end;
};

std::vector<std::vector<WorkItem>> make_phases(const core::Model& model) {
  constexpr std::size_t kItem = 256;
  std::vector<std::vector<WorkItem>> phases;
  for (std::size_t b = 0; b < model.solid_blocks.size(); ++b) {
    const std::vector<std::size_t>& start = model.solid_blocks[b].colour_start;
    for (std::size_t c = 0; c + 1 < start.size(); ++c) {
      std::vector<WorkItem> phase;
      for (std::size_t e = start[c]; e < start[c + 1]; e += kItem) {
        phase.push_back({b, e, std::min(start[c + 1], e + kItem)});
      }
      if (!phase.empty())
        phases.push_back(std::move(phase));
    }
  }
  return phases;
}

struct InternalResult {
  double dt_min = 1e300;
  std::size_t dt_block = 0, dt_element = 0;
  double hourglass = 0.0;
  bool failed = false;
  std::size_t failed_block = 0, failed_element = 0;
};

std::string time_text(double t) {
  std::ostringstream os;
  os.precision(6);
  os << t;
  return os.str();
}

}  // namespace

RunResult run(const core::Model& model, OutputSink& sink, const SolverOptions& options) {
#ifdef _OPENMP
  omp_set_num_threads(std::max(1, options.threads));
#endif
  const auto wall_start = std::chrono::steady_clock::now();
  const auto wall = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  };
  RunResult res;
  const std::size_t n = model.node_count();
  NodalState s;
  s.resize(n);
  s.x = model.x0;
  s.y = model.y0;
  s.z = model.z0;
  if (!model.v0x.empty()) {
    s.vx = model.v0x;
    s.vy = model.v0y;
    s.vz = model.v0z;
  }
  // Packed copy of x, y, z, vx, vy, vz per node for the element gathers (one cache line).
  std::vector<double> packed(6 * n);
  const auto pack = [&] {
#pragma omp parallel for schedule(static)
    for (long li = 0; li < static_cast<long>(n); ++li) {
      const auto i = static_cast<std::size_t>(li);
      double* p = &packed[6 * i];
      p[0] = s.x[i];
      p[1] = s.y[i];
      p[2] = s.z[i];
      p[3] = s.vx[i];
      p[4] = s.vy[i];
      p[5] = s.vz[i];
    }
  };
  element::NodalView view{s.x.data(),      s.y.data(),      s.z.data(),
                          model.x0.data(), model.y0.data(), model.z0.data(),
                          s.vx.data(),     s.vy.data(),     s.vz.data()};
  view.packed = packed.data();
  std::vector<element::SolidBlockState> solids(model.solid_blocks.size());
  for (std::size_t b = 0; b < solids.size(); ++b)
    solids[b].resize(model.solid_blocks[b]);

  const MassResult mass = lumped_mass(model, view, s.mass, solids);
  res.physical_mass = mass.physical;
  res.added_mass = mass.added;
  std::vector<double> inv_mass(n, 0.0);
  std::size_t massless = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (s.mass[i] > 0.0) {
      inv_mass[i] = 1.0 / s.mass[i];
    } else {
      ++massless;
    }
  }
  if (massless > 0) {
    res.warnings.push_back(std::to_string(massless) +
                           " nodes belong to no element: they carry no mass and do not move");
  }

  const BoundaryConditions bc(model);
  for (const core::SolidBlock& b : model.solid_blocks) {
    if (b.colour_start.empty() || b.colour_start.back() != b.size()) {
      res.ok = false;
      res.error = "internal error: solid blocks must be coloured (core::colour_solid_blocks)";
      return res;
    }
  }
  const std::vector<std::vector<WorkItem>> phases = make_phases(model);
  std::vector<std::size_t> phase_offset(phases.size() + 1, 0);
  for (std::size_t p = 0; p < phases.size(); ++p) {
    phase_offset[p + 1] = phase_offset[p] + phases[p].size();
  }
  std::vector<element::SolidResult> item_results(phase_offset.back());
  std::size_t element_count = model.solid_count();
  const element::NodalForces forces{s.fx.data(), s.fy.data(), s.fz.data()};

  // Element forces at the current positions; the nodal force arrays must be zero and the packed
  // copy current (the node pass of the time loop does both).
  double bad_velocities = 0.0;
  const auto internal = [&](double dt) {
#pragma omp parallel
    {
      for (std::size_t p = 0; p < phases.size(); ++p) {
        const std::vector<WorkItem>& phase = phases[p];
#pragma omp for schedule(dynamic, 2)
        for (long w = 0; w < static_cast<long>(phase.size()); ++w) {
          const WorkItem& it = phase[static_cast<std::size_t>(w)];
          const core::SolidBlock& blk = model.solid_blocks[it.block];
          item_results[phase_offset[p] + static_cast<std::size_t>(w)] =
              element::solid_forces(blk, model.materials[static_cast<std::size_t>(blk.material)],
                                    solids[it.block], view, dt, it.begin, it.end, forces);
        }
      }
    }
    InternalResult r;
    for (std::size_t p = 0; p < phases.size(); ++p) {  // in order: deterministic
      for (std::size_t w = 0; w < phases[p].size(); ++w) {
        const element::SolidResult& x = item_results[phase_offset[p] + w];
        if (x.failed && !r.failed) {
          r.failed = true;
          r.failed_block = phases[p][w].block;
          r.failed_element = x.failed_element;
        }
        if (x.dt_min < r.dt_min) {
          r.dt_min = x.dt_min;
          r.dt_block = phases[p][w].block;
          r.dt_element = x.dt_element;
        }
        r.hourglass += x.hourglass_energy;
      }
    }
    return r;
  };
  const auto element_name = [&](std::size_t b, std::size_t e) {
    const core::SolidBlock& blk = model.solid_blocks[b];
    return "solid element " + std::to_string(blk.element_id[e]) + " (part " +
           std::to_string(model.parts[static_cast<std::size_t>(blk.part)].id) + ")";
  };

  double t = 0.0;
  long cycle = 0;
  const Snapshot snap{0.0, 0, &model, &s, &solids};
  const auto snapshot = [&] {
    Snapshot x = snap;
    x.time = t;
    x.cycle = cycle;
    return x;
  };
  const auto fail = [&](const std::string& why) {
    res.ok = false;
    res.error = why;
    sink.state(snapshot());  // keep the last state for the diagnosis
  };

  pack();
  InternalResult ir = internal(0.0);
  if (ir.failed) {
    fail("non-positive volume in " + element_name(ir.failed_block, ir.failed_element) +
         " in the initial mesh");
    return res;
  }
  if (element_count == 0 || !(ir.dt_min < 1e300)) {
    res.ok = false;
    res.error = "the model has no elements to integrate";
    return res;
  }
  const double tssfac = model.controls.tssfac > 0.0 ? model.controls.tssfac : 0.9;
  double dt = tssfac * ir.dt_min;
  if (model.controls.dt_init > 0.0)
    dt = std::min(dt, model.controls.dt_init);
  const double end_time = model.controls.end_time;
  if (end_time > 0.0)
    dt = std::min(dt, end_time);
  res.dt_first = dt;
  const double floor_ratio =
      model.controls.dt_min_ratio > 0.0 ? model.controls.dt_min_ratio : options.dt_floor_ratio;
  const double dt_floor = floor_ratio * dt;

  bc.loads(0.0, s);
  std::vector<double> old_x(n), old_y(n), old_z(n);
  const double* const old[3] = {old_x.data(), old_y.data(), old_z.data()};
  const std::vector<unsigned char>& constrained = bc.constrained();
  const std::vector<core::Index>& constrained_nodes = bc.constrained_nodes();

  // Velocity update of the step [t, t + dt_next] with its half-step interval dt_avg, in one
  // pass over the nodes: the work of the forces at t over the step just taken (second half of
  // the trapezoid, `dt_prev`), v_{n+1/2} kept in old, v_{n+3/2} = old + a dt_avg, v_{n+1}, and
  // a count of non-finite velocities. Then constraints and reactions on the constrained nodes.
  // Returns {internal work, external work} of that half.
  const auto advance_velocity = [&](double t_now, double dt_prev, double dt_next,
                                    double dt_avg) -> std::array<double, 2> {
    const double w = dt_prev / (2.0 * dt_avg);
    const auto sums = deterministic_sums<3>(n, [&](std::size_t i, std::array<double, 3>& acc) {
      const double vx = s.vx[i], vy = s.vy[i], vz = s.vz[i];
      acc[0] += vx * s.fx[i] + vy * s.fy[i] + vz * s.fz[i];
      acc[1] += vx * s.ex[i] + vy * s.ey[i] + vz * s.ez[i];
      old_x[i] = vx;
      old_y[i] = vy;
      old_z[i] = vz;
      const double nx = vx + (s.ex[i] - s.fx[i]) * inv_mass[i] * dt_avg;
      const double ny = vy + (s.ey[i] - s.fy[i]) * inv_mass[i] * dt_avg;
      const double nz = vz + (s.ez[i] - s.fz[i]) * inv_mass[i] * dt_avg;
      s.vx[i] = nx;
      s.vy[i] = ny;
      s.vz[i] = nz;
      s.vnx[i] = vx + (nx - vx) * w;
      s.vny[i] = vy + (ny - vy) * w;
      s.vnz[i] = vz + (nz - vz) * w;
      if (!std::isfinite(nx + ny + nz))
        acc[2] += 1.0;
    });
    bad_velocities = sums[2];
    bc.constrain(t_now, dt_next, dt_avg, old, s);
    double reaction_work = 0.0;  // in node order: deterministic
    for (core::Index ci : constrained_nodes) {
      const auto i = static_cast<std::size_t>(ci);
      const unsigned char* c = &constrained[3 * i];
      s.rx[i] = c[0] ? s.mass[i] * (s.vx[i] - old_x[i]) / dt_avg - (s.ex[i] - s.fx[i]) : 0.0;
      s.ry[i] = c[1] ? s.mass[i] * (s.vy[i] - old_y[i]) / dt_avg - (s.ey[i] - s.fy[i]) : 0.0;
      s.rz[i] = c[2] ? s.mass[i] * (s.vz[i] - old_z[i]) / dt_avg - (s.ez[i] - s.fz[i]) : 0.0;
      reaction_work += old_x[i] * s.rx[i] + old_y[i] * s.ry[i] + old_z[i] * s.rz[i];
      s.vnx[i] = old_x[i] + (s.vx[i] - old_x[i]) * w;
      s.vny[i] = old_y[i] + (s.vy[i] - old_y[i]) * w;
      s.vnz[i] = old_z[i] + (s.vz[i] - old_z[i]) * w;
    }
    return {0.5 * dt_prev * sums[0], 0.5 * dt_prev * (sums[1] + reaction_work)};
  };
  const auto kinetic = [&] {
    return 0.5 * deterministic_sum(n, [&](std::size_t i) {
             return s.mass[i] * (s.vnx[i] * s.vnx[i] + s.vny[i] * s.vny[i] + s.vnz[i] * s.vnz[i]);
           });
  };

  // t = 0: the first half step is dt/2 and the velocities at t_0 are the initial ones.
  advance_velocity(0.0, 0.0, dt, 0.5 * dt);
  s.vnx = old_x;
  s.vny = old_y;
  s.vnz = old_z;
  const double kinetic0 = kinetic();
  double work_internal = 0.0;  // stress + hourglass work, from nodal forces (trapezoid)
  double hourglass = 0.0;
  double work_external = 0.0;
  Energies en;
  const auto energies = [&] {
    en.time = t;
    en.dt = dt;
    en.kinetic = kinetic();
    en.hourglass = hourglass;
    en.internal = work_internal - hourglass;
    en.external_work = work_external;
    en.total = en.kinetic + en.internal + en.hourglass + en.contact;
    const double reference = kinetic0 + work_external;
    en.ratio = std::abs(reference) > 0.0 ? en.total / reference : 1.0;
    return en;
  };

  const core::OutputRequests& out = model.output;
  const double eps_t = 1e-9 * std::max(end_time, dt);
  double next_state = 0.0, next_glstat = 0.0, next_nodout = 0.0;
  bool state_written = false;
  const auto write_outputs = [&](bool last) {
    state_written = false;
    if (t + eps_t >= next_state || last) {
      sink.state(snapshot());
      state_written = true;
      if (out.d3plot_dt > 0.0) {
        while (next_state <= t + eps_t)
          next_state += out.d3plot_dt;
      } else {
        next_state = end_time;  // first and last only
      }
    }
    if (out.glstat_dt > 0.0 && (t + eps_t >= next_glstat || last)) {
      sink.glstat(energies());
      while (next_glstat <= t + eps_t)
        next_glstat += out.glstat_dt;
    }
    if (out.nodout_dt > 0.0 && !out.history_nodes.empty() && (t + eps_t >= next_nodout || last)) {
      sink.nodout(snapshot());
      while (next_nodout <= t + eps_t)
        next_nodout += out.nodout_dt;
    }
  };
  write_outputs(false);

  while (true) {
    if (end_time > 0.0 && t + eps_t >= end_time)
      break;
    if (model.controls.end_cycle > 0 && cycle >= model.controls.end_cycle)
      break;
    // One pass over the nodes: work of the forces at t_n over the step (first half of the
    // trapezoid), positions at t_{n+1}, the packed copy for the elements, zeroed forces.
    const auto work = deterministic_sums<2>(n, [&](std::size_t i, std::array<double, 2>& acc) {
      const double vx = s.vx[i], vy = s.vy[i], vz = s.vz[i];
      acc[0] += vx * s.fx[i] + vy * s.fy[i] + vz * s.fz[i];
      acc[1] += vx * (s.ex[i] + s.rx[i]) + vy * (s.ey[i] + s.ry[i]) + vz * (s.ez[i] + s.rz[i]);
      s.fx[i] = s.fy[i] = s.fz[i] = 0.0;
      s.ux[i] += vx * dt;
      s.uy[i] += vy * dt;
      s.uz[i] += vz * dt;
      double* p = &packed[6 * i];
      p[0] = s.x[i] = model.x0[i] + s.ux[i];
      p[1] = s.y[i] = model.y0[i] + s.uy[i];
      p[2] = s.z[i] = model.z0[i] + s.uz[i];
      p[3] = vx;
      p[4] = vy;
      p[5] = vz;
    });
    work_internal += 0.5 * dt * work[0];
    work_external += 0.5 * dt * work[1];
    t += dt;
    ++cycle;

    ir = internal(dt);
    if (ir.failed) {
      fail("non-positive volume in " + element_name(ir.failed_block, ir.failed_element) +
           " at t = " + time_text(t) + " (cycle " + std::to_string(cycle) + ")");
      break;
    }
    hourglass += ir.hourglass;
    bc.loads(t, s);

    double dt_next = tssfac * ir.dt_min;
    if (dt_next < dt_floor) {
      fail("time step " + time_text(dt_next) + " fell below the floor " + time_text(dt_floor) +
           " at t = " + time_text(t) + ", set by " + element_name(ir.dt_block, ir.dt_element));
      break;
    }
    if (end_time > 0.0 && t + dt_next > end_time)
      dt_next = std::max(end_time - t, 1e-3 * dt_next);
    const auto half = advance_velocity(t, dt, dt_next, 0.5 * (dt + dt_next));
    work_internal += half[0];
    work_external += half[1];
    if (bad_velocities > 0.0) {
      std::size_t bad = 0;
      while (bad < n && std::isfinite(s.vx[bad] + s.vy[bad] + s.vz[bad]))
        ++bad;
      fail("non-finite velocity at node " + std::to_string(model.node_id[std::min(bad, n - 1)]) +
           " at t = " + time_text(t) + " (cycle " + std::to_string(cycle) + ")");
      break;
    }
    res.dt_last = dt;
    dt = dt_next;
    write_outputs(false);
    sink.progress(t, end_time, cycle, dt, wall());
  }
  if (res.ok && !state_written)
    write_outputs(true);
  if (res.ok) {
    if (out.glstat_dt > 0.0 && en.time != t)
      sink.glstat(energies());
  }
  res.cycles = cycle;
  res.time = t;
  res.wall_seconds = wall();
  res.last = energies();
  if (res.wall_seconds > 0.0) {
    res.element_cycles_per_second =
        static_cast<double>(element_count) * static_cast<double>(cycle) / res.wall_seconds;
  }
  return res;
}

}  // namespace plyform::engine
