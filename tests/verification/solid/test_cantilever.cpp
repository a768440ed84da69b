// Cantilevers of hexahedra against beam theory (steel, E 210 GPa, nu 0.3; mm, t, s, MPa).
//
// 1. Free vibration: a clamped beam 100 x 5 x 5 mm (L/h = 20) starts with the velocity field of
//    its first Euler-Bernoulli mode (tip amplitude ~ h / 130); the half period between two
//    zero crossings of the mean tip deflection gives the first bending frequency, checked
//    against f1 = (1.8751^2 / (2 pi L^2)) sqrt(E I / (rho A)) = 417.76 Hz: within 3 % on the
//    finer of two meshes, and closer than on the coarser one. ELFORM 1 with stiffness hourglass
//    control (IHQ 5, QM 0.1) converges from the stiff side (2 -> 4 elements through the
//    thickness); ELFORM 2 is soft with one element through the thickness (mean dilatation drops
//    the volumetric part of the element's own bending) and within 3 % with two. Shear and
//    rotary inertia lower the exact frequency by ~0.3 % at L/h = 20.
// 2. Quasi-static tip load on ELFORM 1 with the default viscous hourglass control (IHQ 1,
//    QM 0.1), 50 x 5 x 5 mm, 8 elements through the thickness: the hourglass energy stays below
//    5 % of the internal energy, and the mean tip deflection over one period after a slow ramp
//    matches Timoshenko's P L^3 / (3 E I) + P L / (k G A) within 3 %. Justification: one-point
//    elements whose hourglass resistance is viscous carry static bending only by the constant
//    strain of each layer, EI_h = EI (1 - 1/n^2): 1.6 % soft for n = 8; the fully clamped root
//    (Poisson contraction held) and the load spread over the tip face add a few tenths of %.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "recording_sink.hpp"
#include "solid_models.hpp"

namespace plyform::engine {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kRho = 7.85e-9;  // MPa, t/mm^3

/// A beam along x: [0, L] x [0, b] x [0, h], clamped at x = 0 (all translations).
core::Model beam(double length, double width, double height, int nx, int ny, int nz,
                 core::SolidFormulation form, int ihq, double qm) {
  core::Model m =
      test::box(length, width, height, nx, ny, nz, core::ElasticMaterial{kRho, kE, kNu}, form);
  m.solid_blocks[0].hourglass.ihq = ihq;
  m.solid_blocks[0].hourglass.qm = qm;
  test::fix(m, test::nodes_where(m, [](double x, double, double) { return x < 1e-9; }),
            core::dof_x | core::dof_y | core::dof_z);
  return m;
}

// ---------------------------------------------------------------------------------------------
// 1. First bending frequency.

constexpr double kBetaL = 1.8751040687;  // first root of cos(bL) cosh(bL) = -1

/// First cantilever mode shape of Euler-Bernoulli theory, normalised to 1 at the tip.
double mode_shape(double x, double length) {
  const double bl = kBetaL, b = bl / length;
  const double sigma = (std::cosh(bl) + std::cos(bl)) / (std::sinh(bl) + std::sin(bl));
  const auto phi = [&](double s) {
    return std::cosh(b * s) - std::cos(b * s) - sigma * (std::sinh(b * s) - std::sin(b * s));
  };
  return phi(x) / phi(length);
}

struct FrequencyCase {
  const char* name;
  core::SolidFormulation form;
  int ihq;
  double qm;
  int coarse_nz, fine_nz;  // elements through the thickness (nx = 20 nz: square in x-z)
  bool cubes;              // ny = nz / 2 (cubes in y too), else one element across the width
};

struct FrequencyResult {
  double frequency = 0.0;
  double seconds = 0.0;
};

constexpr double kLength = 100.0, kHeight = 5.0, kWidth = 5.0;  // mm: L / h = 20

double reference_frequency() {
  const double area = kWidth * kHeight;
  const double inertia = kWidth * kHeight * kHeight * kHeight / 12.0;
  return kBetaL * kBetaL / (2.0 * M_PI * kLength * kLength) *
         std::sqrt(kE * inertia / (kRho * area));
}

FrequencyResult measure_frequency(const FrequencyCase& c, int nz) {
  const int nx = 20 * nz;
  const int ny = c.cubes ? std::max(1, nz / 2) : 1;
  core::Model m = beam(kLength, kWidth, kHeight, nx, ny, nz, c.form, c.ihq, c.qm);
  const std::size_t n = m.node_count();
  const double v_tip = 100.0;  // mm/s: tip amplitude v / omega ~ 0.04 mm = h / 130
  m.v0x.assign(n, 0.0);
  m.v0y.assign(n, 0.0);
  m.v0z.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    m.v0z[i] = v_tip * mode_shape(m.x0[i], kLength);
  const double period = 1.0 / reference_frequency();
  m.controls.end_time = 1.15 * period;
  m.output.nodout_dt = period / 2000.0;
  m.output.history_nodes =
      test::nodes_where(m, [&](double x, double, double) { return test::near(x, kLength); });
  const std::vector<core::Index>& tip = m.output.history_nodes;

  // Downward zero crossings of the tip displacement (after the first half period) by linear
  // interpolation between samples: u = a sin(omega t) crosses zero at T/2, T, ...
  std::vector<double> crossings;
  double t_prev = 0.0, u_prev = 0.0;
  test::RecordingSink sink;
  sink.on_nodout = [&](const Snapshot& s) {
    double u = 0.0;  // mean over the tip face
    for (core::Index i : tip)
      u += s.nodes->uz[static_cast<std::size_t>(i)];
    if (s.time > 0.25 * period && ((u_prev > 0.0) != (u > 0.0)))
      crossings.push_back(t_prev + (s.time - t_prev) * u_prev / (u_prev - u));
    t_prev = s.time;
    u_prev = u;
  };
  const RunResult r = run(m, sink, {});
  EXPECT_TRUE(r.ok) << r.error;
  EXPECT_EQ(crossings.size(), 2u);
  FrequencyResult out;
  out.seconds = r.wall_seconds;
  if (crossings.size() >= 2)
    out.frequency = 1.0 / (2.0 * (crossings[1] - crossings[0]));
  std::cout << c.name << " nz=" << nz << " elements=" << m.solid_count() << " cycles=" << r.cycles
            << " f=" << out.frequency << " ref=" << reference_frequency()
            << " err=" << 100 * (out.frequency / reference_frequency() - 1) << "% wall "
            << r.wall_seconds << " s\n";
  return out;
}

class CantileverFrequency : public ::testing::TestWithParam<FrequencyCase> {};

TEST_P(CantileverFrequency, FirstBendingModeMatchesEulerBernoulli) {
  const FrequencyCase& c = GetParam();
  const double f_ref = reference_frequency();
  const FrequencyResult coarse = measure_frequency(c, c.coarse_nz);
  const FrequencyResult fine = measure_frequency(c, c.fine_nz);
  const double err_coarse = coarse.frequency / f_ref - 1.0;
  const double err_fine = fine.frequency / f_ref - 1.0;
  RecordProperty("f_reference_hz", std::to_string(f_ref));
  RecordProperty("f_coarse_hz", std::to_string(coarse.frequency));
  RecordProperty("f_fine_hz", std::to_string(fine.frequency));
  EXPECT_NEAR(err_fine, 0.0, 0.03) << "fine mesh: f = " << fine.frequency << " Hz";
  EXPECT_LT(std::abs(err_fine), std::abs(err_coarse)) << "refinement does not converge";
}

INSTANTIATE_TEST_SUITE_P(
    Formulations, CantileverFrequency,
    ::testing::Values(
        FrequencyCase{"elform1_ihq5", core::SolidFormulation::one_point, 5, 0.1, 2, 4, true},
        FrequencyCase{"elform2", core::SolidFormulation::selective_reduced, 1, 0.1, 1, 2, false}),
    [](const ::testing::TestParamInfo<FrequencyCase>& i) { return std::string(i.param.name); });

// ---------------------------------------------------------------------------------------------
// 2. Quasi-static tip load, ELFORM 1 with viscous hourglass control.

TEST(CantileverTipLoad, HourglassEnergySmallAndDeflectionMatchesBeamTheory) {
  constexpr double length = 50.0, height = 5.0, width = 5.0;  // mm: L / h = 10
  constexpr int nz = 8, nx = 10 * nz, ny = 1;
  core::Model m =
      beam(length, width, height, nx, ny, nz, core::SolidFormulation::one_point, 1, 0.1);
  const double area = width * height, inertia = width * height * height * height / 12.0;
  const double f1 =
      kBetaL * kBetaL / (2.0 * M_PI * length * length) * std::sqrt(kE * inertia / (kRho * area));
  const double period = 1.0 / f1;

  // Tip load P in z, ramped smoothly (3 s^2 - 2 s^3) over three periods of the first mode and
  // then held for one more: the residual oscillation is a few % of the static deflection and
  // its mean over the last period is the static deflection. The load is spread over the tip
  // face as the consistent nodal forces of a uniform shear traction (weights 1/4 at the
  // corners, 1/2 on the edges, 1 inside), which excites no hourglass mode.
  constexpr double load = 10.0;  // N: beam theory deflection ~ 0.04 mm = h / 130
  const double ramp = 3.0 * period, hold = period;
  std::vector<double> ct, cv;
  for (int i = 0; i <= 60; ++i) {
    const double s = i / 60.0;
    ct.push_back(s * ramp);
    cv.push_back(3.0 * s * s - 2.0 * s * s * s);
  }
  ct.push_back(10.0 * (ramp + hold));
  cv.push_back(1.0);
  const core::Index curve = test::add_curve(m, ct, cv);
  const std::vector<core::Index> tip =
      test::nodes_where(m, [&](double x, double, double) { return test::near(x, length); });
  ASSERT_EQ(tip.size(), static_cast<std::size_t>((ny + 1) * (nz + 1)));
  double weight_sum = 0.0;
  std::vector<double> weights;
  for (core::Index i : tip) {
    const auto k = static_cast<std::size_t>(i);
    const bool edge_y = test::near(m.y0[k], 0.0) || test::near(m.y0[k], width);
    const bool edge_z = test::near(m.z0[k], 0.0) || test::near(m.z0[k], height);
    weights.push_back((edge_y ? 0.5 : 1.0) * (edge_z ? 0.5 : 1.0));
    weight_sum += weights.back();
  }
  for (std::size_t j = 0; j < tip.size(); ++j)
    m.loads.push_back(core::NodalLoad{tip[j], 2, curve, load * weights[j] / weight_sum});

  m.controls.end_time = ramp + hold;
  m.output.glstat_dt = period / 100.0;
  m.output.nodout_dt = period / 400.0;
  m.output.history_nodes = tip;

  // Time average of the mean tip deflection over the held period.
  double sum = 0.0;
  long samples = 0;
  test::RecordingSink sink;
  sink.on_nodout = [&](const Snapshot& s) {
    if (s.time < ramp + 1e-3 * period || s.time > ramp + hold - 1e-3 * period)
      return;  // half-open window of exactly one period
    double u = 0.0;
    for (core::Index i : tip)
      u += s.nodes->uz[static_cast<std::size_t>(i)];
    sum += u / static_cast<double>(tip.size());
    ++samples;
  };
  const RunResult r = run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_GT(samples, 300);
  const double deflection = sum / static_cast<double>(samples);

  // Timoshenko: bending P L^3 / (3 E I) plus shear P L / (k G A), k = 5/6.
  const double shear_modulus = kE / (2.0 * (1.0 + kNu));
  const double reference = load * length * length * length / (3.0 * kE * inertia) +
                           load * length / (5.0 / 6.0 * shear_modulus * area);
  double max_ratio = 0.0;
  const double final_internal = sink.energies.back().internal;
  for (const Energies& e : sink.energies) {
    if (e.internal > 0.01 * final_internal)
      max_ratio = std::max(max_ratio, e.hourglass / e.internal);
  }
  std::cout << "tip deflection " << deflection << " reference " << reference << " err "
            << 100 * (deflection / reference - 1) << " %, max hg/internal " << max_ratio
            << ", final hg " << sink.energies.back().hourglass << " internal " << final_internal
            << " wall " << r.wall_seconds << " s cycles " << r.cycles << "\n";
  RecordProperty("tip_deflection_mm", std::to_string(deflection));
  RecordProperty("reference_mm", std::to_string(reference));
  RecordProperty("max_hourglass_over_internal", std::to_string(max_ratio));
  EXPECT_LT(max_ratio, 0.05);
  EXPECT_NEAR(deflection, reference, 0.03 * reference);
}

}  // namespace
}  // namespace plyform::engine
