// Plane-stress J2 return of the shell updates (*MAT_024, *MAT_018) and the elastic shell law,
// against independent references: the yield curve written out, the plane-stress elasticity
// matrix, the associated flow rule, uniaxial stress paths.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "plasticity_helpers.hpp"
#include "plyform/material/thermal_plasticity.hpp"

namespace plyform::material::test {
namespace {

constexpr double kE = 210000.0;  // MPa
constexpr double kNu = 0.3;

core::PiecewiseLinearPlasticity curve_law() {
  core::PiecewiseLinearPlasticity m{7.85e-9, kE, kNu, 250.0, 1000.0, {}};
  m.curve.plastic_strain = {0.0, 0.01, 0.03, 0.06};
  m.curve.yield_stress = {250.0, 300.0, 340.0, 360.0};
  return m;
}
core::PiecewiseLinearPlasticity bilinear_law() {
  return core::PiecewiseLinearPlasticity{7.85e-9, kE, kNu, 250.0, 2100.0, {}};
}
core::PowerLawPlasticity power_law() {
  return core::PowerLawPlasticity{7.85e-9, kE, kNu, 530.0, 0.26, 0.0};
}

// Independent yield curves.
double ref_yield(const core::PiecewiseLinearPlasticity& m, double e) {
  if (!m.curve.plastic_strain.empty())
    return curve_ref(m.curve.plastic_strain, m.curve.yield_stress, e);
  return m.sigy + e * m.etan / (1.0 - m.etan / m.young);
}
double ref_yield(const core::PowerLawPlasticity& m, double e) {
  // SIGY = 0: eps_yp where k eps^n meets E eps.
  const double e0 = std::exp(std::log(m.young / m.k) / (m.n - 1.0));
  return m.k * std::pow(e0 + e, m.n);
}

TEST(YieldCurve, HelpersMatchReferences) {
  const auto c = curve_law();
  for (double e : {0.0, 0.005, 0.01, 0.02, 0.03, 0.045, 0.06, 0.1, 0.5}) {
    EXPECT_NEAR(yield_stress(c, e), ref_yield(c, e), 1e-12 * ref_yield(c, e)) << e;
  }
  EXPECT_DOUBLE_EQ(yield_slope(c, 0.005), 5000.0);
  EXPECT_DOUBLE_EQ(yield_slope(c, 0.01), 2000.0);  // segment after the point
  EXPECT_DOUBLE_EQ(yield_slope(c, 0.2), 20.0 / 0.03);
  const auto b = bilinear_law();
  EXPECT_NEAR(yield_stress(b, 0.1), 250.0 + 0.1 * kE * 2100.0 / (kE - 2100.0), 1e-10);
  EXPECT_NEAR(yield_slope(b, 0.3), kE * 2100.0 / (kE - 2100.0), 1e-9);
  const auto p = power_law();
  const double e0 = power_law_offset(p);
  EXPECT_NEAR(p.k * std::pow(e0, p.n), kE * e0, 1e-9 * kE * e0);  // meets the elastic line
  for (double e : {0.0, 0.01, 0.2})
    EXPECT_NEAR(yield_stress(p, e), ref_yield(p, e), 1e-12 * ref_yield(p, e));
  // SIGY > 0: eps_yp = (SIGY / k)^(1/n), so sigma_y(0) = SIGY.
  auto p2 = p;
  p2.sigy = 200.0;
  EXPECT_NEAR(yield_stress(p2, 0.0), 200.0, 1e-10);
  const double h = 1e-7;
  EXPECT_NEAR(yield_slope(p2, 0.05),
              (yield_stress(p2, 0.05 + h) - yield_stress(p2, 0.05 - h)) / (2 * h), 1e-5);
}

// One step from (st, d): checks the returned state against the discrete plane-stress problem.
template <class M>
void check_return(const M& m, const ShellState& st0, const ShellInc& d, double* worst) {
  ShellState st = st0;
  const double dzz = shell_step(m, st, d);
  const double g = kE / (2.0 * (1.0 + kNu));
  const double c11 = kE / (1.0 - kNu * kNu), c12 = kNu * c11;
  // Elastic trial (plane-stress matrix).
  const double tx = st0.s[0] + c11 * d[0] + c12 * d[1];
  const double ty = st0.s[1] + c12 * d[0] + c11 * d[1];
  const double txy = st0.s[2] + 2.0 * g * d[2];
  // Transverse shear elastic.
  EXPECT_NEAR(st.s[3], st0.s[3] + 2.0 * g * d[3], 1e-12 * std::abs(st.s[3]) + 1e-12);
  EXPECT_NEAR(st.s[4], st0.s[4] + 2.0 * g * d[4], 1e-12 * std::abs(st.s[4]) + 1e-12);
  const double dlam = st.eps_p - st0.eps_p;
  ASSERT_GT(dlam, 0.0);
  const double sx = st.s[0], sy = st.s[1], sxy = st.s[2];
  const double q = von_mises_ps(sx, sy, sxy);
  const double sy_ref = ref_yield(m, st.eps_p);
  // Yield function (szz = 0 by construction).
  const double f_err = std::abs(q - sy_ref) / sy_ref;
  EXPECT_LT(f_err, 1e-10);
  // Plastic strain from the stress drop: C_ps^-1 (sigma_tr - sigma).
  const double rx = tx - sx, ry = ty - sy, rxy = txy - sxy;
  const double epx = (rx - kNu * ry) / kE, epy = (ry - kNu * rx) / kE, epxy = rxy / (2.0 * g);
  // Associated flow at the end state: d eps^p = dlam 3/2 s / q, s = dev(sx, sy, sxy, 0).
  const double devx = (2.0 * sx - sy) / 3.0, devy = (2.0 * sy - sx) / 3.0;
  const double fx = dlam * 1.5 * devx / q, fy = dlam * 1.5 * devy / q, fxy = dlam * 1.5 * sxy / q;
  const double scale = std::max({std::abs(fx), std::abs(fy), std::abs(fxy), dlam});
  const double n_err =
      std::max({std::abs(epx - fx), std::abs(epy - fy), std::abs(epxy - fxy)}) / scale;
  EXPECT_LT(n_err, 1e-9);
  // Thickness strain: elastic Poisson part plus plastic incompressibility.
  const double dzz_ref = -kNu / kE * (sx - st0.s[0] + sy - st0.s[1]) - (fx + fy);
  const double z_err = std::abs(dzz - dzz_ref) / (std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]));
  EXPECT_LT(z_err, 1e-10);
  worst[0] = std::max(worst[0], f_err);
  worst[1] = std::max(worst[1], n_err);
  worst[2] = std::max(worst[2], z_err);
}

template <class M>
void check_returns(const M& m, const char* name) {
  double worst[3] = {0.0, 0.0, 0.0};
  const double mag = 6e-3;  // about five times the yield strain
  // Biaxial ratios from the zero state and from a prior plastic state.
  for (double beta : {-1.0, -0.5, 0.0, 0.3, 0.5, 1.0, 2.0}) {
    for (double e0 : {0.0, 0.02}) {
      ShellState st;
      st.eps_p = e0;
      check_return(m, st, {mag, beta * mag, 0.0, 1e-4, -2e-4}, worst);
      // Non-proportional: from a stress on the surface, load in another direction.
      ShellState st2;
      st2.eps_p = e0;
      shell_step(m, st2, {mag, 0.0, 0.0, 0.0, 0.0});
      check_return(m, st2, {beta * mag, mag, 0.5 * mag, 0.0, 0.0}, worst);
    }
  }
  // Pure shear and shear with tension; big steps (to 50 yield strains).
  for (double k : {1.0, 3.0, 10.0, 50.0}) {
    ShellState st;
    check_return(m, st, {0.0, 0.0, k * 1e-3, 0.0, 0.0}, worst);
    check_return(m, st, {k * 1e-3, -0.2 * k * 1e-3, -k * 1e-3, 0.0, 0.0}, worst);
  }
  std::printf("[%s] worst: yield function %.2e, normality %.2e, dzz %.2e\n", name, worst[0],
              worst[1], worst[2]);
}

TEST(ShellJ2, ReturnLandsOnSurfaceWithNormality) {
  check_returns(curve_law(), "MAT_024 curve");
  check_returns(bilinear_law(), "MAT_024 bilinear");
  check_returns(power_law(), "MAT_018");
}

TEST(ShellJ2, ElasticBelowYield) {
  const auto m = curve_law();
  ShellState st;
  const double dzz = shell_step(m, st, {5e-4, 1e-4, 2e-4, 1e-4, 0.0});
  EXPECT_EQ(st.eps_p, 0.0);
  const double c11 = kE / (1.0 - kNu * kNu);
  EXPECT_NEAR(st.s[0], c11 * (5e-4 + kNu * 1e-4), 1e-10);
  EXPECT_NEAR(st.s[1], c11 * (1e-4 + kNu * 5e-4), 1e-10);
  EXPECT_NEAR(st.s[2], kE / (1.0 + kNu) * 2e-4, 1e-10);
  EXPECT_NEAR(dzz, -kNu / (1.0 - kNu) * 6e-4, 1e-16);
  // The elastic law gives the same.
  ShellState se;
  const double dzz_e =
      shell_step(core::ElasticMaterial{7.85e-9, kE, kNu}, se, {5e-4, 1e-4, 2e-4, 1e-4, 0.0});
  for (int k = 0; k < 5; ++k)
    EXPECT_DOUBLE_EQ(se.s[static_cast<std::size_t>(k)], st.s[static_cast<std::size_t>(k)]);
  EXPECT_DOUBLE_EQ(dzz_e, dzz);
}

// A chunk of many points in one call: the yielding points' returns are solved together
// (plane_stress_batch.hpp). Each point must come out as it does alone (the same bits, whatever
// shares its batch), and each must satisfy the discrete plane-stress problem (check_return).
// Increments up to 1 (5000 yield strains) test the lockstep Newton far from its usual few steps.
struct ShellChunk {
  std::vector<double> d[5], s[5], eps_p, dzz, temperature;
  explicit ShellChunk(std::size_t n) : eps_p(n), dzz(n), temperature(n) {
    for (auto& v : d)
      v.assign(n, 0.0);
    for (auto& v : s)
      v.assign(n, 0.0);
  }
  ShellPoints points() {
    ShellPoints p{d[0].data(), d[1].data(), d[2].data(), d[3].data(), d[4].data(),  s[0].data(),
                  s[1].data(), s[2].data(), s[3].data(), s[4].data(), eps_p.data(), dzz.data()};
    p.temperature = temperature.data();
    return p;
  }
};

template <class M>
void check_chunk_against_single_points(const M& m, const char* name) {
  constexpr std::size_t n = 150;  // several batches, the last one partial
  ShellChunk c(n);
  std::vector<ShellState> alone(n);
  std::vector<ShellInc> inc(n);
  unsigned seed = 12345u;
  auto uniform = [&seed]() {  // in [-1, 1), a fixed sequence
    seed = seed * 1664525u + 1013904223u;
    return static_cast<double>(seed >> 8) / static_cast<double>(1u << 23) - 1.0;
  };
  for (std::size_t p = 0; p < n; ++p) {
    const double mag = p % 11 == 0  ? 1.0
                       : p % 7 == 0 ? 0.05
                                    : (p % 3 == 0 ? 2e-4 : 3e-3);  // elastic ones too
    inc[p] = {mag * uniform(), mag * uniform(), mag * uniform(), 1e-4 * uniform(), 0.0};
    alone[p].eps_p = p % 2 == 0 ? 0.0 : 0.03 * (1.0 + uniform());
    // A prior state on or inside the yield surface.
    shell_step(m, alone[p], {2e-3 * uniform(), 2e-3 * uniform(), 1e-3 * uniform(), 0.0, 0.0});
    for (std::size_t k = 0; k < 5; ++k) {
      c.d[k][p] = inc[p][k];
      c.s[k][p] = alone[p].s[k];
    }
    c.eps_p[p] = alone[p].eps_p;
  }
  const std::vector<ShellState> before = alone;
  shell_update(m, n, c.points());
  double worst[3] = {0.0, 0.0, 0.0};
  int yielded = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const double dzz = shell_step(m, alone[p], inc[p]);
    for (std::size_t k = 0; k < 5; ++k)
      ASSERT_EQ(c.s[k][p], alone[p].s[k]) << name << " point " << p << " component " << k;
    ASSERT_EQ(c.eps_p[p], alone[p].eps_p) << name << " point " << p;
    ASSERT_EQ(c.dzz[p], dzz) << name << " point " << p;
    if (alone[p].eps_p > before[p].eps_p) {
      ++yielded;
      check_return(m, before[p], inc[p], worst);
    }
  }
  EXPECT_GT(yielded, 60);
  EXPECT_LT(yielded, static_cast<int>(n));
  std::printf(
      "[%s] %d of %zu points yield in one chunk; worst: yield function %.2e, normality "
      "%.2e, dzz %.2e\n",
      name, yielded, n, worst[0], worst[1], worst[2]);
}

TEST(ShellJ2, ManyPointsInOneChunkReturnAsEachAlone) {
  check_chunk_against_single_points(bilinear_law(), "MAT_024 bilinear");
  check_chunk_against_single_points(curve_law(), "MAT_024 curve");
}

// *MAT_ELASTIC_PLASTIC_THERMAL at each point's own temperature: the same stress, plastic strain
// and thickness strain as the bilinear *MAT_024 with the constants interpolated by hand at that
// temperature, for a chunk whose points sit at different temperatures.
TEST(ShellJ2, ThermalChunkMatchesTheBilinearLawAtEachTemperature) {
  core::ElasticPlasticThermal m;
  m.density = 7.85e-9;
  m.temperature = {20.0, 300.0};
  m.young = {210000.0, 150000.0};
  m.poisson = {0.30, 0.34};
  m.alpha = {1.2e-5, 1.4e-5};
  m.sigy = {300.0, 120.0};
  m.etan = {2000.0, 500.0};
  constexpr std::size_t n = 40;
  ShellChunk c(n);
  for (std::size_t p = 0; p < n; ++p) {
    c.temperature[p] = 20.0 + 280.0 * static_cast<double>(p) / (n - 1);
    c.d[0][p] = 4e-3;
    c.d[1][p] = -1e-3 + 1e-4 * static_cast<double>(p % 5);
    c.d[2][p] = 5e-4 * static_cast<double>(p % 3);
  }
  shell_update(m, n, c.points());
  for (std::size_t p = 0; p < n; ++p) {
    const double w = (c.temperature[p] - 20.0) / 280.0;
    const auto at = [w](const std::vector<double>& v) { return v[0] + w * (v[1] - v[0]); };
    const core::PiecewiseLinearPlasticity ref{m.density,  at(m.young), at(m.poisson),
                                              at(m.sigy), at(m.etan),  {}};
    ShellState st;
    const double dzz = shell_step(ref, st, {c.d[0][p], c.d[1][p], c.d[2][p], 0.0, 0.0});
    ASSERT_GT(st.eps_p, 0.0) << p;
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(c.s[k][p], st.s[k], 1e-9 * ref.sigy) << p << " " << k;
    EXPECT_NEAR(c.eps_p[p], st.eps_p, 1e-12) << p;
    EXPECT_NEAR(c.dzz[p], dzz, 1e-12) << p;
  }
}

// Uniaxial stress along x in increments: dyy solved each step so that syy = 0 (dxy = 0 keeps
// sxy = 0). The stress follows the curve against eps_p = eps_xx - sxx / E, the thickness strain
// is -eps_p / 2 - nu sxx / E, unloading is elastic with slope E.
template <class M>
void uniaxial_path(const M& m, const char* name) {
  const double step = 2e-5;
  const int n_load = 5000;  // eps_xx = 0.1
  ShellState st;
  double exx = 0.0, ezz = 0.0;
  double worst_curve = 0.0, worst_ep = 0.0, worst_thick = 0.0, worst_unload = 0.0;
  auto advance = [&](double dxx) {
    double dzz = 0.0;
    const double dyy = secant(
        [&](double y) {
          ShellState t = st;
          shell_step(m, t, {dxx, y, 0.0, 0.0, 0.0});
          return t.s[1];
        },
        -0.5 * dxx, -0.3 * dxx, 1e-11);
    dzz = shell_step(m, st, {dxx, dyy, 0.0, 0.0, 0.0});
    exx += dxx;
    ezz += dzz;
    EXPECT_LT(std::abs(st.s[1]), 1e-9);
  };
  for (int i = 0; i < n_load; ++i) {
    advance(step);
    const double sx = st.s[0];
    if (st.eps_p > 0.0) {
      worst_curve = std::max(worst_curve, std::abs(sx - ref_yield(m, st.eps_p)) / sx);
      worst_ep = std::max(worst_ep, std::abs(st.eps_p - (exx - sx / kE)));
      worst_thick = std::max(worst_thick, std::abs(ezz - (-0.5 * st.eps_p - kNu * sx / kE)));
    }
  }
  EXPECT_LT(worst_curve, 1e-6);
  EXPECT_LT(worst_ep, 1e-9);
  EXPECT_LT(worst_thick, 1e-9);
  EXPECT_GT(st.eps_p, 0.09);
  // Unloading by 1.6 sigma / E: elastic, slope E, into compression but short of reverse yield.
  const double s_top = st.s[0], e_top = exx, ep_top = st.eps_p;
  const int n_un = 100;
  const double un = -1.6 * s_top / kE / n_un;
  for (int i = 0; i < n_un; ++i) {
    advance(un);
    worst_unload = std::max(worst_unload, std::abs(st.s[0] - (s_top + kE * (exx - e_top))) / s_top);
  }
  EXPECT_EQ(st.eps_p, ep_top);
  EXPECT_LT(worst_unload, 1e-9);
  std::printf(
      "[%s] uniaxial to eps 0.1: |s - s_y(eps_p)|/s %.2e, eps_p %.2e, thickness %.2e, "
      "unloading slope %.2e\n",
      name, worst_curve, worst_ep, worst_thick, worst_unload);
}

TEST(ShellJ2, UniaxialFollowsCurve) {
  uniaxial_path(curve_law(), "MAT_024 curve");
  uniaxial_path(bilinear_law(), "MAT_024 bilinear");
  uniaxial_path(power_law(), "MAT_018");
}

// Equibiaxial: by symmetry sxx = syy = sigma_y(eps_p) and d eps^p_xx = d eps^p_yy = d eps_p / 2,
// so the plastic thickness strain equals -eps_p.
TEST(ShellJ2, EquibiaxialThinning) {
  const auto m = curve_law();
  ShellState st;
  double ezz = 0.0, exx = 0.0;
  for (int i = 0; i < 1000; ++i) {
    ezz += shell_step(m, st, {5e-5, 5e-5, 0.0, 0.0, 0.0});
    exx += 5e-5;
  }
  EXPECT_NEAR(st.s[0], st.s[1], 1e-10);
  EXPECT_NEAR(st.s[0], ref_yield(m, st.eps_p), 1e-8);
  const double e_el = st.s[0] * (1.0 - kNu) / kE;
  EXPECT_NEAR(st.eps_p, 2.0 * (exx - e_el), 1e-12);
  EXPECT_NEAR(ezz, -st.eps_p - 2.0 * kNu * st.s[0] / kE, 1e-12);
}

}  // namespace
}  // namespace plyform::material::test
