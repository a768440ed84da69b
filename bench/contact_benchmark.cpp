// Contact pass throughput (contact::ContactSet::apply): a slave plate of N x N shells lying on a
// fixed master plate of N x N shells, the two meshes offset by half an element in x and y (no
// node faces a node), surfaces touching (offsets t / 2 on both sides). Penalty + Coulomb law
// (mu 0.2), stiffness as setup builds it (0.1 K A / d_max per segment, each slave node its
// share). Every cycle the slave plate sinks a little (penetration 0.5e-4 t .. 1.5e-4 t over the
// run) and slides sideways at 10 m/s along (1, 0.3), so the re-search triggers on its own once
// the plate has moved a quarter of a diagonal since the last one (about every 200 cycles at the
// shells' stable step). The plate starts that far behind, less a few cycles, so that even a
// short timed window holds a natural re-search.
//
// Timed: apply() alone (the positions are the engine's part). Reported per slave node: a cycle
// without a search ("track"), the extra cost of a cycle that searched ("re-search"), their
// blend at the natural interval ("amortised" = track + re-search / interval), the mean of all
// timed cycles ("mean", searches as they fell in the window), and one bare search
// (BucketSearch build + query, "search"); on 1 and 2 OpenMP threads.
//
//   build/bench/bench_contact [largest N (default 1000)] [cycle scale (default 1)]
//                             [most threads (default 2)]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "plyform/contact/bucket_search.hpp"
#include "plyform/contact/contact_set.hpp"
#include "plyform/core/model.hpp"

namespace {

using namespace plyform;
using Clock = std::chrono::steady_clock;

// Steel sheet, mm / tonne / s.
constexpr double kH = 1.0;  // element size [mm]
constexpr double kT = 1.0;  // thickness [mm]
constexpr double kYoung = 210000.0, kPoisson = 0.3, kRho = 7.85e-9;
constexpr double kBulk = kYoung / (3.0 * (1.0 - 2.0 * kPoisson));
constexpr double kSpeed = 10000.0;  // sliding speed [mm/s]

// The shells' stable step.
double shell_dt() {
  return 0.9 * kH / std::sqrt(kYoung / (kRho * (1.0 - kPoisson * kPoisson)));
}

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

struct Plates {
  core::Model model;
  std::vector<double> mass;
  std::vector<double> packed;  // x y z vx vy vz per node, at t = 0
  std::vector<double> radius;  // the search radius ContactSet gives each segment
  std::size_t master_nodes = 0;
  double dt = 0.0;
};

// Nodes of an (n + 1) x (n + 1) grid plate at (x0 + i h, y0 + j h, z); returns the first index.
core::Index add_plate(core::Model& m, int n, double x0, double y0, double z) {
  const auto first = static_cast<core::Index>(m.node_count());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.node_id.push_back(static_cast<core::GlobalId>(m.node_count() + 1));
      m.x0.push_back(x0 + kH * i);
      m.y0.push_back(y0 + kH * j);
      m.z0.push_back(z);
    }
  return first;
}

Plates build(int n) {
  Plates p;
  core::Model& m = p.model;
  const core::Index master = add_plate(m, n, 0.0, 0.0, 0.0);
  const core::Index slave = add_plate(m, n, 0.5 * kH, 0.5 * kH, kT);
  p.master_nodes = static_cast<std::size_t>(slave);
  const std::size_t nn = m.node_count();
  const auto id = [&](core::Index first, int i, int j) {
    return static_cast<core::Index>(first + j * (n + 1) + i);
  };
  // Per quad: area h^2, longest diagonal sqrt(2) h; k = SLSFAC K A / d_max.
  const double area = kH * kH;
  const double k_seg = 0.1 * kBulk * area / (std::sqrt(2.0) * kH);
  std::vector<double> node_area(nn, 0.0), node_k(nn, 0.0);
  core::ContactPass cp;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      for (core::Index q :
           {id(master, i, j), id(master, i + 1, j), id(master, i + 1, j + 1), id(master, i, j + 1)})
        cp.segments.push_back(q);
      cp.segment_offset.push_back(0.5 * kT);
      cp.segment_stiffness.push_back(k_seg);
      for (core::Index first : {master, slave})
        for (core::Index q :
             {id(first, i, j), id(first, i + 1, j), id(first, i + 1, j + 1), id(first, i, j + 1)}) {
          node_area[static_cast<std::size_t>(q)] += 0.25 * area;
          node_k[static_cast<std::size_t>(q)] += 0.25 * k_seg;
        }
    }
  for (std::size_t i = p.master_nodes; i < nn; ++i) {
    cp.slave_nodes.push_back(static_cast<core::Index>(i));
    cp.slave_offset.push_back(0.5 * kT);
    cp.slave_area.push_back(node_area[i]);
    cp.slave_stiffness.push_back(node_k[i]);
  }
  p.mass.resize(nn);
  for (std::size_t i = 0; i < nn; ++i)
    p.mass[i] = kRho * kT * node_area[i];
  // As ContactSet sets it: offsets on both sides twice, and the margin (half a diagonal).
  const double margin = 0.5 * std::sqrt(2.0) * kH;
  p.radius.assign(cp.segment_count(), (0.5 * kT + 0.5 * kT) + margin);

  core::ContactInterface ci;
  ci.id = 1;
  ci.keyword = "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE";
  ci.kind = core::ContactKind::forming;
  ci.law.cn = 1.0;  // the plain penalty-Coulomb law of setup (no adhesion)
  ci.law.sigma_max = {1.0, 1.0, -1};
  ci.law.eta = 1.0;
  ci.law.beta0 = 0.0;
  ci.law.mu = {0.2, 0.2, -1};
  ci.passes.push_back(std::move(cp));
  m.contacts.push_back(std::move(ci));

  p.packed.resize(6 * nn);
  for (std::size_t i = 0; i < nn; ++i) {
    double* q = &p.packed[6 * i];
    q[0] = m.x0[i];
    q[1] = m.y0[i];
    q[2] = m.z0[i];
    q[3] = q[4] = q[5] = 0.0;
  }
  p.dt = shell_dt();
  return p;
}

// Cycles between natural re-searches: the trigger is a motion of half the margin (a quarter of
// the mean diagonal) since the last search.
double search_interval() {
  return 0.25 * std::sqrt(2.0) * kH / (kSpeed * std::sqrt(1.09) * shell_dt());
}

// The slave plate at cycle c (c < 0 before the timed window): sunk by 0.5e-4 t .. 1.5e-4 t over
// the window, slid by v t along (1, 0.3).
void move_slaves(const Plates& p, std::vector<double>& packed, long c, long cycles) {
  const double t = p.dt * static_cast<double>(c);
  const double f = static_cast<double>(std::max(0L, c)) / static_cast<double>(cycles);
  const double sink = 1e-4 * kT * (0.5 + f);
  const double vz = -1e-4 * kT / (static_cast<double>(cycles) * p.dt);
  const double vx = kSpeed, vy = 0.3 * kSpeed;
  const core::Model& m = p.model;
  const auto nn = static_cast<long>(m.node_count());
#pragma omp parallel for schedule(static)
  for (long li = static_cast<long>(p.master_nodes); li < nn; ++li) {
    const auto i = static_cast<std::size_t>(li);
    double* q = &packed[6 * i];
    q[0] = m.x0[i] + vx * t;
    q[1] = m.y0[i] + vy * t;
    q[2] = m.z0[i] - sink;
    q[3] = vx;
    q[4] = vy;
    q[5] = vz;
  }
}

struct Result {
  long cycles = 0;
  long searches = 0;      // re-searches during the timed cycles
  double track = 0.0;     // ns per slave per cycle, cycles without a search
  double research = 0.0;  // ns per slave, extra time of a cycle with a search (0: none)
  double mean = 0.0;      // ns per slave per cycle, all timed cycles
  double search = 0.0;    // ns per slave, one BucketSearch build + query
  double contact = 0.0;   // fraction of slave nodes in compressive contact at the end
  double force = 0.0;     // normal resultant / (k penetration) per node in contact: about 1
};

Result run(const Plates& p, long cycles, int threads) {
  omp_set_num_threads(threads);
  const core::ContactPass& cp = p.model.contacts.front().passes.front();
  const auto ns = static_cast<double>(cp.slave_count());
  Result r;
  r.cycles = cycles;

  // One bare search (the start configuration), best of a few.
  {
    contact::BucketSearch grid;
    std::vector<std::size_t> start;
    std::vector<core::Index> cand;
    const int reps = std::max(2, static_cast<int>(3e5 / ns));
    double best = 1e300;
    for (int k = 0; k < reps; ++k) {
      const auto a = Clock::now();
      grid.build(cp.segments, p.packed.data(), 6, p.radius);
      grid.query(cp.slave_nodes, p.packed.data(), 6, start, cand);
      best = std::min(best, seconds(a, Clock::now()));
    }
    r.search = best * 1e9 / ns;
  }

  std::vector<double> packed = p.packed;
  const std::size_t nn = p.model.node_count();
  std::vector<double> fx(nn, 0.0), fy(nn, 0.0), fz(nn, 0.0);
  contact::ContactSet cs(p.model, p.mass, nullptr, p.dt, 0.9);
  // Start a little less than one search interval behind; cycle 0 (untimed) catches up.
  const long lead = static_cast<long>(search_interval()) - 5;
  move_slaves(p, packed, -lead, cycles);
  cs.start(packed.data());
  move_slaves(p, packed, 0, cycles);
  cs.apply(0.0, p.dt, packed.data(), nullptr, fx.data(), fy.data(), fz.data());
  double t_all = 0.0, t_track = 0.0, t_search = 0.0;
  long track_cycles = 0;
  const long searches0 = cs.searches();
  for (long c = 1; c <= cycles; ++c) {
    move_slaves(p, packed, c, cycles);
    const long before = cs.searches();
    const auto a = Clock::now();
    cs.apply(p.dt * static_cast<double>(c), p.dt, packed.data(), nullptr, fx.data(), fy.data(),
             fz.data());
    const double s = seconds(a, Clock::now());
    t_all += s;
    if (cs.searches() == before) {
      t_track += s;
      ++track_cycles;
    } else {
      t_search += s;
    }
  }
  r.searches = cs.searches() - searches0;
  r.mean = t_all * 1e9 / (ns * static_cast<double>(cycles));
  r.track = track_cycles > 0 ? t_track * 1e9 / (ns * static_cast<double>(track_cycles)) : 0.0;
  if (r.searches > 0)
    r.research = t_search * 1e9 / (ns * static_cast<double>(r.searches)) - r.track;
  const contact::InterfaceReport rep = cs.report().front();
  r.contact = static_cast<double>(rep.in_contact) / ns;
  const double k_node = 0.1 * kBulk * kH * kH / (std::sqrt(2.0) * kH);
  r.force = rep.force[2] / (k_node * 1.5e-4 * kT * static_cast<double>(rep.in_contact));
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const int largest = argc > 1 ? std::atoi(argv[1]) : 1000;
  const double scale = argc > 2 ? std::atof(argv[2]) : 1.0;
  const int most_threads = argc > 3 ? std::atoi(argv[3]) : 2;
  struct Size {
    int n;
    long cycles;
  };
  const double interval = search_interval();
  std::printf(
      "Contact pass: slave plate on a fixed master plate, N x N shells each, meshes offset by "
      "half an element;\npenalty + Coulomb (mu 0.2), penetration ~1e-4 t, sliding at %.0f m/s: "
      "a natural re-search every %.0f cycles.\n"
      "ns per slave node: track = cycle without search, re-search = extra of a cycle that "
      "searched,\namortised = track + re-search / %.0f, mean = all timed cycles, search = one "
      "BucketSearch build + query.\n\n",
      kSpeed * 1e-3, interval, interval);
  std::printf("%6s %9s %7s %6s %8s %8s %9s %9s %8s %8s %8s\n", "N", "slaves", "threads", "cycles",
              "searches", "track", "re-search", "amortised", "mean", "search", "contact");
  for (const Size s : {Size{100, 1000}, Size{316, 200}, Size{1000, 30}}) {
    if (s.n > largest)
      break;
    const Plates p = build(s.n);
    const long cycles = std::max(1L, static_cast<long>(static_cast<double>(s.cycles) * scale));
    for (int threads = 1; threads <= most_threads; ++threads) {
      const Result r = run(p, cycles, threads);
      std::printf("%6d %9zu %7d %6ld %8ld %8.1f %9.1f %9.1f %8.1f %8.1f %7.1f%%\n", s.n,
                  p.model.contacts.front().passes.front().slave_count(), threads, r.cycles,
                  r.searches, r.track, r.research, r.track + r.research / interval, r.mean,
                  r.search, 100.0 * r.contact);
      std::fflush(stdout);
      if (std::fabs(r.force - 1.0) > 0.5)
        std::fprintf(stderr, "  (normal force %.2f of k * penetration per node in contact)\n",
                     r.force);
    }
  }
  return 0;
}
