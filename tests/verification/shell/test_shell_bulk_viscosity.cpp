// The shells' bulk viscosity (*CONTROL_BULK_VISCOSITY TYPE -1/-2) against its closed form: one
// Belytschko-Tsay (and one fully integrated, ELFORM 16) square (L0 = 2 mm, t = 0.1 mm)
// squeezed in equal biaxial strain by its edges moving in at a constant speed V:
// tr D = -2 V / L, so the pressure is
// q = rho l (2 V / L) (Q1 l 2 V / L + Q2 c) with l = sqrt(A) = L and c the plate wave speed
// sqrt(E / (rho (1 - nu^2))). The moving edge's reaction is the membrane force: the elastic
// stress of equal biaxial plane stress, E / (1 - nu) ln(L0 / L) (hypoelastic: the log strain),
// plus q, times t L, with the thickness t grown by the plane-stress eps_z. Without bulk viscosity
// (Q1 = Q2 = 0, or TYPE 1) the elastic part alone. Its work, the integral of q |tr D| t A, is
// internal energy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "recording_sink.hpp"
#include "shell_models.hpp"
#include "solid_models.hpp"

namespace plyform::engine {
namespace {

constexpr double kRho = 1.0e-9, kE = 10.0, kNu = 0.3, kSpeed = 2000.0, kL0 = 2.0, kT = 0.1;

test::ReactionSink squeeze(bool on, core::ShellFormulation formulation) {
  core::Model m = test::plate(kL0, kL0, 1, 1, kT, core::ElasticMaterial{kRho, kE, kNu}, 3);
  m.shell_blocks[0].formulation = formulation;
  m.shell_blocks[0].bulk_viscosity_on = on;
  m.shell_blocks[0].bulk_viscosity = {1.5, 0.06};
  test::ReactionSink sink;
  sink.nodes = test::nodes_where(m, [](double x, double, double) { return x > 0.5 * kL0; });
  const auto left = test::nodes_where(m, [](double x, double, double) { return x < 0.5 * kL0; });
  const auto top = test::nodes_where(m, [](double, double y, double) { return y > 0.5 * kL0; });
  const auto bottom = test::nodes_where(m, [](double, double y, double) { return y < 0.5 * kL0; });
  const unsigned still = core::dof_z | core::dof_rx | core::dof_ry | core::dof_rz;
  test::fix(m, left, core::dof_x | still);
  test::fix(m, bottom, core::dof_y | still);
  test::fix(m, sink.nodes, still);
  test::fix(m, top, still);
  const double end = 0.2 * kL0 / kSpeed;  // to 20 % compression
  const core::Index curve = test::add_curve(m, {0.0, end}, {-kSpeed, -kSpeed});
  test::prescribe(m, sink.nodes, 0, core::MotionKind::velocity, curve);
  test::prescribe(m, top, 1, core::MotionKind::velocity, curve);
  m.v0x.assign(m.node_count(), 0.0);
  m.v0y.assign(m.node_count(), 0.0);
  m.v0z.assign(m.node_count(), 0.0);
  for (core::Index n : sink.nodes)
    m.v0x[static_cast<std::size_t>(n)] = -kSpeed;
  for (core::Index n : top)
    m.v0y[static_cast<std::size_t>(n)] = -kSpeed;
  // A small step, so that the two runs' steps (the bulk viscosity shortens its run's) integrate
  // the hypoelastic stress alike to well within q's share of the reaction.
  m.controls.tssfac = 0.1;
  m.controls.end_time = end;
  m.output.bndout_dt = end / 20;
  m.output.glstat_dt = end / 20;
  const RunResult r = run(m, sink, {});
  EXPECT_TRUE(r.ok) << r.error;
  return sink;
}

void check_squeeze(core::ShellFormulation formulation, const char* name) {
  const test::ReactionSink with = squeeze(true, formulation);
  const test::ReactionSink without = squeeze(false, formulation);
  const double c = std::sqrt(kE / (kRho * (1.0 - kNu * kNu)));
  const auto length = [&](double t) { return kL0 - kSpeed * t; };
  // The reaction without bulk viscosity, interpolated to a time (the runs' steps differ):
  // sigma t L with sigma = E / (1 - nu) ln(L0 / L) exactly (in-plane hypoelasticity); it gives
  // the thickness the membrane has then (the element's own thickness update), which q acts on.
  const auto membrane = [&](double t) {
    const auto& w = without.force;
    std::size_t i = 1;
    while (i + 1 < w.size() && w[i].first < t)
      ++i;
    const double s = (t - w[i - 1].first) / (w[i].first - w[i - 1].first);
    return -(w[i - 1].second + s * (w[i].second - w[i - 1].second));
  };
  const auto thickness = [&](double t) {
    const double l = length(t);
    return membrane(t) / (kE / (1.0 - kNu) * std::log(kL0 / l) * l);
  };
  const auto bulk = [&](double t) {
    const double l = length(t), rate = 2.0 * kSpeed / l;
    return kRho * l * rate * (1.5 * l * rate + 0.06 * c) * thickness(t) * l;
  };
  ASSERT_GT(without.force.size(), 10u);
  double share = 0.0, worst = 0.0;
  for (std::size_t i = 2; i + 1 < with.force.size(); ++i) {
    const auto [t, f] = with.force[i];
    // The thickness the membrane has: grown by eps_z (plane stress), at most by 2 nu / (1 - nu)
    // ln(L0 / L).
    EXPECT_GT(thickness(t), kT);
    EXPECT_LT(thickness(t), kT * std::pow(kL0 / length(t), 2.0 * kNu / (1.0 - kNu)) * 1.001);
    // The bulk viscosity's share of the reaction (up to 17 % of it here), within 2 % of q.
    EXPECT_NEAR(-f - membrane(t), bulk(t), 0.02 * bulk(t)) << "t = " << t;
    share = std::max(share, bulk(t) / membrane(t));
    worst = std::max(worst, std::abs(-f - membrane(t) - bulk(t)) / bulk(t));
  }
  EXPECT_GT(share, 0.01);
  // Its work is internal energy: the integral of q |tr D| t A over the squeeze.
  const double end = with.energies.back().time;
  double work = 0.0;
  const int steps = 4000;
  for (int i = 0; i < steps; ++i) {
    const double t = (i + 0.5) * end / steps, l = length(t);
    const double q = bulk(t) / (thickness(t) * l);
    work += q * (2.0 * kSpeed / l) * thickness(t) * l * l * end / steps;
  }
  const double booked = with.energies.back().internal - without.energies.back().internal;
  EXPECT_NEAR(booked, work, 0.03 * work);
  std::printf(
      "shell bulk viscosity, %s: q within %.2f %% (q up to %.1f %% of the reaction), work "
      "%.2f %%\n",
      name, 100.0 * worst, 100.0 * share, 100.0 * (booked / work - 1.0));
}

TEST(ShellBulkViscosity, SqueezedMembraneCarriesTheClosedFormPressure) {
  check_squeeze(core::ShellFormulation::belytschko_tsay, "Belytschko-Tsay");
}

// ELFORM 16 takes it at each of its four points on the point's own rate; in this homogeneous
// squeeze every point has the element's rate, so the same closed form holds.
TEST(ShellBulkViscosity, FullyIntegratedShellCarriesTheSamePressure) {
  check_squeeze(core::ShellFormulation::fully_integrated, "ELFORM 16");
}

}  // namespace
}  // namespace plyform::engine
