// Pressure loads (*LOAD_SEGMENT, *LOAD_SEGMENT_SET, *LOAD_SHELL_ELEMENT, *LOAD_SHELL_SET)
// against closed forms:
// - a free plate under a constant pressure takes the impulse p A t, against its normal, and its
//   kinetic energy is the external work;
// - a clamped square plate under a small pressure deflects as plate theory says (Timoshenko &
//   Woinowsky-Krieger, table 35: w = 0.00126 q a^4 / D at the centre, nu = 0.3);
// - a clamped circular membrane inflated to large deflection follows Hencky's solution of the
//   Foeppl membrane equations (w0 = 0.6534 a (p a / E h)^(1/3) for nu = 0.3; the constant
//   solved again by shooting, as in Fichter, NASA TP-3658, 1997), and the external work the
//   engine books is the integral of p dV, the volume under the membrane computed from the
//   nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "../contact/contact_decks.hpp"

namespace plyform::test {
namespace {

constexpr double kSteelE = 210000.0, kSteelRho = 7.85e-9, kNu = 0.3;

/// A rising half cosine from 0 at t = 0 to 1 at `ramp`, then 1 (a smooth start, so that the
/// quasi-static runs ring little), as a *DEFINE_CURVE of `points` segments.
void smooth_ramp(DeckWriter& w, int id, double ramp, double end, int points = 40) {
  w.kw("*DEFINE_CURVE").card(id);
  for (int k = 0; k <= points; ++k) {
    const double t = ramp * k / points;
    w.card(t, 0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp)));
  }
  w.card(2.0 * end, 1.0);
}

TEST(PressureLoads, AFreePlateTakesTheImpulseAgainstItsNormal) {
  // A free 4 x 4 mm steel plate of 2 x 2 shells (counter-clockwise seen from +z: normal +z)
  // and, beside it, a plate of two triangles loaded through a segment set whose segments run
  // clockwise (normal -z): 1 MPa pushes the first down and the second up.
  DeckWriter w;
  const double p = 1.0, t_end = 2.0e-5, h = 0.5;
  w.kw("*CONTROL_TERMINATION").card(t_end);
  w.kw("*DATABASE_GLSTAT").card(t_end / 20);
  w.kw("*PART").card("plate").card(1, 1, 1);
  w.kw("*SECTION_SHELL").card(1, 16, 0.8333, 3).card(h, h, h, h);
  w.kw("*MAT_ELASTIC").card(1, kSteelRho, kSteelE, kNu);
  w.kw("*PART").card("triangles").card(2, 2, 1);
  w.kw("*SECTION_SHELL").card(2, 2, 0.8333, 3).card(h, h, h, h);
  w.plate(1, 1, 1, 0.0, 4.0, 0.0, 4.0, 2, 2, 0.0);
  w.kw("*NODE").card(101, 10.0, 0.0, 0.0).card(102, 14.0, 0.0, 0.0).card(103, 14.0, 4.0, 0.0);
  w.card(104, 10.0, 4.0, 0.0);
  w.kw("*ELEMENT_SHELL").card(101, 2, 101, 102, 103, 103).card(102, 2, 101, 103, 104, 104);
  w.kw("*DEFINE_CURVE").card(1).card(0.0, 1.0).card(1.0, 1.0);
  w.kw("*SET_SHELL_LIST").card(1).card(1, 2, 3, 4);
  w.kw("*LOAD_SHELL_SET").card(1, 1, p);
  w.kw("*SET_SEGMENT").card(2).card(101, 103, 102).card(101, 104, 103);
  w.kw("*LOAD_SEGMENT_SET_ID").card(7, "triangles, clockwise").card(2, 1, p);
  // Momentum and mass of each plate at the last state.
  std::array<double, 2> momentum{}, lateral{}, mass{};
  double last_time = -1.0;
  DeckRun run;
  run.sink.on_state = [&](const engine::Snapshot& snap) {
    last_time = snap.time;
    momentum = lateral = mass = {};
    for (std::size_t i = 0; i < snap.model->node_count(); ++i) {
      const std::size_t k = snap.model->node_id[i] > 100 ? 1 : 0;
      const double m = snap.nodes->mass[i];
      momentum[k] += m * snap.nodes->vnz[i];
      lateral[k] += std::hypot(m * snap.nodes->vnx[i], m * snap.nodes->vny[i]);
      mass[k] += m;
    }
  };
  run_deck(w.text(), run);
  ASSERT_NEAR(last_time, t_end, 1e-12);
  const double impulse = p * 16.0 * t_end;  // both plates are 4 x 4 mm
  EXPECT_NEAR(momentum[0], -impulse, 1e-9 * impulse) << "the shells' normal is +z: pushed down";
  EXPECT_NEAR(momentum[1], impulse, 1e-9 * impulse) << "the segments run clockwise: pushed up";
  EXPECT_LT(lateral[0] + lateral[1], 1e-9 * impulse);
  // A rigid translation: kinetic energy = external work = impulse^2 / (2 m) for each plate.
  const double kinetic = impulse * impulse / (2.0 * mass[0]) + impulse * impulse / (2.0 * mass[1]);
  const engine::Energies& e = run.result.last;
  EXPECT_NEAR(e.external_work, kinetic, 1e-6 * kinetic);
  // The books' kinetic energy is 1/2 m v(n-1/2) v(n+1/2) = 1/2 m (v_n^2 - (a dt / 2)^2)
  // (docs/energy.md): (dt / 2t)^2 below, some 3e-5 here.
  EXPECT_NEAR(e.kinetic, kinetic, 1e-4 * kinetic);
  std::printf(
      "free plates under 1 MPa: momentum %.9g and %.9g against -/+ p A t = %.9g; work "
      "%.9g against the kinetic energy %.9g\n",
      momentum[0], momentum[1], impulse, e.external_work, kinetic);
}

TEST(PressureLoads, AClampedPlateDeflectsAsPlateTheory) {
  // A quarter of a clamped square steel plate (a = 100 mm, h = 1 mm, 10 x 10 ELFORM 16 shells
  // of 5 mm), symmetric about x = 0 and y = 0, under q = 0.005 MPa ramped over 12 ms (some 11
  // periods of its first mode, 1.1 ms) and held for 2 ms. Plate theory: w = 0.00126 q a^4 / D
  // (0.033 mm: w / h = 0.03, small enough for the membrane forces not to stiffen it); the
  // centre's mean deflection over the last two periods within 2 %.
  const double a = 100.0, h = 1.0, q = 0.005, ramp = 12.0e-3, end = 14.0e-3;
  const double D = kSteelE * h * h * h / (12.0 * (1.0 - kNu * kNu));
  const double w_theory = 0.00126 * q * std::pow(a, 4) / D;
  const int n = 10;
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(end);
  w.kw("*DATABASE_GLSTAT").card(end / 100);
  w.kw("*DATABASE_NODOUT").card(end / 700);
  w.kw("*DATABASE_HISTORY_NODE").card(1);
  w.kw("*PART").card("plate").card(1, 1, 1);
  w.kw("*SECTION_SHELL").card(1, 16, 0.8333, 3).card(h, h, h, h);
  w.kw("*MAT_ELASTIC").card(1, kSteelRho, kSteelE, kNu);
  const std::vector<int> nodes = w.plate(1, 1, 1, 0.0, 0.5 * a, 0.0, 0.5 * a, n, n, 0.0);
  std::vector<int> on_x0, on_y0, clamped;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int id = nodes[static_cast<std::size_t>(j * (n + 1) + i)];
      if (i == n || j == n)
        clamped.push_back(id);
      else if (i == 0)
        on_x0.push_back(id);
      else if (j == 0)
        on_y0.push_back(id);
    }
  on_x0.erase(on_x0.begin());  // the centre is on both planes: its own SPC below
  w.kw("*SET_NODE_LIST").card(1).ids(on_x0);
  w.kw("*SET_NODE_LIST").card(2).ids(on_y0);
  w.kw("*SET_NODE_LIST").card(3).ids(clamped);
  w.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 0, 0, 0, 1, 1);
  w.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 0, 1);
  w.kw("*BOUNDARY_SPC_SET").card(3, 0, 1, 1, 1, 1, 1, 1);
  w.kw("*BOUNDARY_SPC_NODE").card(1, 0, 1, 1, 0, 1, 1, 1);
  smooth_ramp(w, 1, ramp, end);
  // Every shell through *SET_SHELL_GENERATE; the pressure pushes down (normal +z).
  w.kw("*SET_SHELL_GENERATE").card(1).card(1, n * n);
  w.kw("*LOAD_SHELL_SET").card(1, 1, q);
  DeckRun run;
  run_deck(w.text(), run);
  double sum = 0.0;
  int count = 0;
  for (const auto& [time, uz] : run.uz) {
    if (time >= end - 2.2e-3) {
      sum += -uz.at(0);
      ++count;
    }
  }
  ASSERT_GT(count, 50);
  const double w_centre = sum / count;
  EXPECT_NEAR(w_centre, w_theory, 0.02 * w_theory);
  EXPECT_NEAR(run.result.last.ratio, 1.0, 1e-3);
  std::printf(
      "clamped plate under q = %g MPa: centre deflection %.5f mm against plate theory's "
      "%.5f mm (%+.2f %%)\n",
      q, w_centre, w_theory, 100.0 * (w_centre / w_theory - 1.0));
}

/// The volume on the normals' side of a surface of segments (the pressure's: it pushes
/// against the normals) closed by planes through the origin (the plane z = 0 that holds its
/// boundary, the symmetry planes): -(1/3) the integral of x . n over the surface (divergence
/// theorem; x . n vanishes on planes through the origin). x . n is quadratic in each parametric
/// coordinate on a bilinear segment: 2 x 2 Gauss points are exact.
double volume_under(const core::Model& m, const engine::NodalState& s) {
  double v = 0.0;
  const double g = 1.0 / std::sqrt(3.0);
  for (const std::array<core::Index, 4>& seg : m.pressure_segments) {
    double x[4][3];
    for (int a = 0; a < 4; ++a) {
      const auto i = static_cast<std::size_t>(seg[static_cast<std::size_t>(a)]);
      x[a][0] = m.x0[i] + s.ux[i];
      x[a][1] = m.y0[i] + s.uy[i];
      x[a][2] = m.z0[i] + s.uz[i];
    }
    for (const double xi : {-g, g})
      for (const double eta : {-g, g}) {
        const double N[4] = {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta),
                             0.25 * (1 + xi) * (1 + eta), 0.25 * (1 - xi) * (1 + eta)};
        const double dxi[4] = {-0.25 * (1 - eta), 0.25 * (1 - eta), 0.25 * (1 + eta),
                               -0.25 * (1 + eta)};
        const double deta[4] = {-0.25 * (1 - xi), -0.25 * (1 + xi), 0.25 * (1 + xi),
                                0.25 * (1 - xi)};
        double p[3] = {}, tx[3] = {}, ty[3] = {};
        for (int a = 0; a < 4; ++a)
          for (int d = 0; d < 3; ++d) {
            p[d] += N[a] * x[a][d];
            tx[d] += dxi[a] * x[a][d];
            ty[d] += deta[a] * x[a][d];
          }
        const double n[3] = {tx[1] * ty[2] - tx[2] * ty[1], tx[2] * ty[0] - tx[0] * ty[2],
                             tx[0] * ty[1] - tx[1] * ty[0]};
        v -= (p[0] * n[0] + p[1] * n[1] + p[2] * n[2]) / 3.0;
      }
  }
  return v;
}

TEST(PressureLoads, AnInflatedMembraneFollowsHenckyAndBooksPdV) {
  // A quarter of a clamped circular aluminium membrane (radius a = 50 mm, h = 0.1 mm; an
  // O-grid of ELFORM 16 shells: an 8 x 8 block inside and 8 rings out to the edge), inflated
  // from below by p = 0.257 MPa ramped over 4 ms (12 periods of its inflated first mode) and
  // held for 1 ms: p a / (E h) = 1.84e-3, so w0 / a = 0.08 by Hencky (slopes to 0.2; the
  // bending stiffness adds about (h / w0)^2). The pressure's segments run counter-clockwise
  // seen from -z: their normal points down, and the pressure pushes up.
  const double a = 50.0, h = 0.1, E = 70000.0, rho = 2.7e-9, pressure = 0.257;
  const double ramp = 4.0e-3, end = 5.0e-3;
  const double w_hencky = 0.6534 * a * std::cbrt(pressure * a / (E * h));
  const int nb = 8, nr = 8;  // block elements along a side, rings
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(end);
  w.kw("*DATABASE_GLSTAT").card(end / 250);
  w.kw("*DATABASE_NODOUT").card(end / 250);
  w.kw("*DATABASE_HISTORY_NODE").card(1);
  w.kw("*PART").card("membrane").card(1, 1, 1);
  w.kw("*SECTION_SHELL").card(1, 16, 0.8333, 3).card(h, h, h, h);
  w.kw("*MAT_ELASTIC").card(1, rho, E, kNu);
  // Nodes: the block (i, j) in [0, nb]^2 over [0, a/2]^2, numbered 1 + j (nb + 1) + i; then
  // ring r = 1..nr of 2 nb + 1 nodes from (x, 0) round to (0, y), from the block's outer
  // boundary to the circle.
  w.kw("*NODE");
  const auto block_id = [&](int i, int j) { return 1 + j * (nb + 1) + i; };
  for (int j = 0; j <= nb; ++j)
    for (int i = 0; i <= nb; ++i)
      w.card(block_id(i, j), 0.5 * a * i / nb, 0.5 * a * j / nb, 0.0);
  const int m = 2 * nb + 1;  // nodes along a ring
  std::vector<int> ring0;    // the block's outer boundary, from (a/2, 0) to (0, a/2)
  for (int j = 0; j <= nb; ++j)
    ring0.push_back(block_id(nb, j));
  for (int i = nb - 1; i >= 0; --i)
    ring0.push_back(block_id(i, nb));
  const int ring_first = 1000;
  const auto ring_id = [&](int r, int k) {
    return r == 0 ? ring0[static_cast<std::size_t>(k)] : ring_first + r * m + k;
  };
  for (int r = 1; r <= nr; ++r)
    for (int k = 0; k < m; ++k) {
      const int b = ring0[static_cast<std::size_t>(k)] - 1;
      const double bx = 0.5 * a * (b % (nb + 1)) / nb, by = 0.5 * a * (b / (nb + 1)) / nb;
      const double phi = 0.5 * std::numbers::pi * k / (m - 1);
      const double f = static_cast<double>(r) / nr;
      w.card(ring_id(r, k), bx + f * (a * std::cos(phi) - bx), by + f * (a * std::sin(phi) - by),
             0.0);
    }
  // Shells counter-clockwise seen from +z; the pressure's segments the other way round.
  std::vector<std::array<int, 4>> quads;
  for (int j = 0; j < nb; ++j)
    for (int i = 0; i < nb; ++i)
      quads.push_back(
          {block_id(i, j), block_id(i + 1, j), block_id(i + 1, j + 1), block_id(i, j + 1)});
  for (int r = 0; r < nr; ++r)
    for (int k = 0; k + 1 < m; ++k)
      quads.push_back({ring_id(r, k), ring_id(r + 1, k), ring_id(r + 1, k + 1), ring_id(r, k + 1)});
  w.kw("*ELEMENT_SHELL");
  for (std::size_t e = 0; e < quads.size(); ++e)
    w.card(e + 1, 1, quads[e][0], quads[e][1], quads[e][2], quads[e][3]);
  w.kw("*SET_SEGMENT").card(1);
  for (const auto& q : quads)
    w.card(q[0], q[3], q[2], q[1]);
  // Symmetry (x = 0: u_x and the turns about y and z; y = 0: u_y, about x and z), the edge
  // clamped; the centre on both planes.
  std::vector<int> on_x0, on_y0, edge;
  for (int j = 1; j <= nb; ++j)
    on_x0.push_back(block_id(0, j));
  for (int i = 1; i <= nb; ++i)
    on_y0.push_back(block_id(i, 0));
  for (int r = 1; r <= nr; ++r) {
    on_y0.push_back(ring_id(r, 0));
    if (r < nr)
      on_x0.push_back(ring_id(r, m - 1));
  }
  for (int k = 0; k < m; ++k)
    edge.push_back(ring_id(nr, k));
  on_y0.pop_back();  // the edge's own nodes are clamped
  w.kw("*SET_NODE_LIST").card(1).ids(on_x0);
  w.kw("*SET_NODE_LIST").card(2).ids(on_y0);
  w.kw("*SET_NODE_LIST").card(3).ids(edge);
  w.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 0, 0, 0, 1, 1);
  w.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 0, 1);
  w.kw("*BOUNDARY_SPC_SET").card(3, 0, 1, 1, 1, 1, 1, 1);
  w.kw("*BOUNDARY_SPC_NODE").card(1, 0, 1, 1, 0, 1, 1, 1);
  smooth_ramp(w, 1, ramp, end);
  w.kw("*LOAD_SEGMENT_SET").card(1, 1, pressure);
  DeckRun run;
  // The volume under the membrane at each nodout time.
  std::vector<std::array<double, 2>> volume;  // (time, volume)
  run.sink.on_nodout = [&](const engine::Snapshot& snap) {
    volume.push_back({snap.time, volume_under(*snap.model, *snap.nodes)});
  };
  run_deck(w.text(), run);
  ASSERT_GT(volume.size(), 200u);
  // Hencky: the centre's mean rise over the last 0.64 ms (two periods of the inflated
  // membrane's first mode).
  double sum = 0.0;
  int count = 0;
  for (const auto& [time, uz] : run.uz) {
    if (time >= end - 0.64e-3) {
      sum += uz.at(0);
      ++count;
    }
  }
  ASSERT_GT(count, 20);
  const double w0 = sum / count;
  EXPECT_NEAR(w0, w_hencky, 0.03 * w_hencky);
  // The external work against the integral of p dV (trapezoids over the nodout times, the
  // pressure read from the ramp), at every glstat time (the same times).
  const auto p_at = [&](double t) {
    return pressure * (t >= ramp ? 1.0 : 0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp)));
  };
  double pdv = 0.0, worst = 0.0;
  std::size_t k = 0;
  const double scale = pressure * volume.back()[1];
  for (const engine::Energies& e : run.sink.energies) {
    while (k + 1 < volume.size() && volume[k + 1][0] <= e.time + 1e-12) {
      const double t0 = volume[k][0], t1 = volume[k + 1][0];
      pdv += 0.5 * (p_at(t0) + p_at(t1)) * (volume[k + 1][1] - volume[k][1]);
      ++k;
    }
    ASSERT_NEAR(volume[k][0], e.time, 1e-12);
    worst = std::max(worst, std::abs(e.external_work - pdv));
  }
  EXPECT_LT(worst, 1e-3 * scale);
  EXPECT_NEAR(run.result.last.ratio, 1.0, 1e-3);
  std::printf(
      "membrane inflated by p a / (E h) = %.3g: centre rise %.4f mm against Hencky's "
      "%.4f mm (%+.2f %%); external work %.6g against the integral of p dV %.6g "
      "(largest difference %.2e of p V)\n",
      pressure * a / (E * h), w0, w_hencky, 100.0 * (w0 / w_hencky - 1.0),
      run.result.last.external_work, pdv, worst / scale);
}

TEST(PressureLoads, ACubeCrushedByItsModulusStopsWithADiagnosis) {
  // A unit aluminium cube (SI units, one one-point hexahedron with the default viscous
  // hourglass control), held on three faces by rollers, its top pressed by a pressure that
  // rises to Young's modulus in 1 s (a public one-element deck's load). Past half of it the
  // element's hourglass modes run away and it folds through itself. No *DATABASE_GLSTAT: the
  // books are judged only by the run's own checks. Before, the blown-apart element voted a
  // step of 3e9 s, the run took its remaining 0.44 s in that one step and reported "normal
  // termination" at an energy ratio of -10; now the step rises at most twofold a cycle and the
  // run stops where the element inverts, naming it.
  DeckWriter w;
  w.kw("*CONTROL_TERMINATION").card(1.0);
  w.kw("*PART").card("block").card(1, 1, 1);
  w.kw("*SECTION_SOLID").card(1, 1);
  w.kw("*MAT_ELASTIC").card(1, 2700.0, 70.0e9, 0.3);
  w.block(1, 1, 1, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 1, 1, 1);
  // Nodes 1-4 the bottom (z = 0), 5-8 the top; x = 0: 1, 3, 5, 7; y = 0: 1, 2, 5, 6.
  w.kw("*SET_NODE_LIST").card(1).ids({1, 2, 3, 4});
  w.kw("*BOUNDARY_SPC_SET").card(1, 0, 0, 0, 1, 0, 0, 0);
  w.kw("*SET_NODE_LIST").card(2).ids({1, 3, 5, 7});
  w.kw("*BOUNDARY_SPC_SET").card(2, 0, 1, 0, 0, 0, 0, 0);
  w.kw("*SET_NODE_LIST").card(3).ids({1, 2, 5, 6});
  w.kw("*BOUNDARY_SPC_SET").card(3, 0, 0, 1, 0, 0, 0, 0);
  w.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(1.0, 70.0e9);
  w.kw("*LOAD_SEGMENT").card(1, 1.0, 0.0, 5, 6, 8, 7);
  TempDir dir;
  const auto read = keyword::read_deck(dir.write("deck.k", w.text()));
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  ASSERT_TRUE(setup::validate(read.model).empty());
  auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty());
  RecordingSink sink;
  const engine::RunResult r = engine::run(*built.model, sink, engine::SolverOptions{});
  EXPECT_FALSE(r.ok && r.distrust.empty()) << "reported as a normal termination";
  EXPECT_FALSE(r.ok) << "stops at the instability";
  EXPECT_LT(r.time, 0.7);
  EXPECT_NE(r.error.find("element 1"), std::string::npos) << r.error;
  std::printf("crushed cube: %s\n", r.error.c_str());
}

}  // namespace
}  // namespace plyform::test
