// Patch tests of the 8-node solids on a distorted mesh: a linear displacement (or velocity)
// field gives the exact uniform stress in every element and at every integration point, and
// the forces on an interior node cancel (both formulations).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "plyform/element/solid_kernels.hpp"
#include "plyform/material/constitutive.hpp"
#include "solid_models.hpp"

namespace plyform::element {
namespace {

struct Patch {
  core::Model model;
  std::vector<double> x, y, z, vx, vy, vz;
  core::Index centre = 0;

  Patch(core::Material mat, core::SolidFormulation form) {
    model = test::box(2.0, 2.0, 2.0, 2, 2, 2, mat, form);
    // Distort every node (the centre one most), keeping elements valid.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.15, 0.15);
    for (std::size_t i = 0; i < model.node_count(); ++i) {
      const bool mid =
          test::near(model.x0[i], 1) && test::near(model.y0[i], 1) && test::near(model.z0[i], 1);
      if (mid)
        centre = static_cast<core::Index>(i);
      const double s = mid ? 2.0 : 1.0;
      model.x0[i] += s * u(rng);
      model.y0[i] += s * u(rng);
      model.z0[i] += s * u(rng);
    }
  }
  // x = F X, v = Fdot X.
  void deform(const double f[9], const double fdot[9]) {
    const std::size_t n = model.node_count();
    x.resize(n), y.resize(n), z.resize(n), vx.resize(n), vy.resize(n), vz.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double p[3] = {model.x0[i], model.y0[i], model.z0[i]};
      x[i] = f[0] * p[0] + f[1] * p[1] + f[2] * p[2];
      y[i] = f[3] * p[0] + f[4] * p[1] + f[5] * p[2];
      z[i] = f[6] * p[0] + f[7] * p[1] + f[8] * p[2];
      vx[i] = fdot[0] * p[0] + fdot[1] * p[1] + fdot[2] * p[2];
      vy[i] = fdot[3] * p[0] + fdot[4] * p[1] + fdot[5] * p[2];
      vz[i] = fdot[6] * p[0] + fdot[7] * p[1] + fdot[8] * p[2];
    }
  }
  NodalView view() const {
    return {x.data(),        y.data(),  z.data(),  model.x0.data(), model.y0.data(),
            model.z0.data(), vx.data(), vy.data(), vz.data()};
  }
  // Nodal internal forces of the last kernel call.
  std::vector<double> fx, fy, fz;
  NodalForces forces() {
    const std::size_t n = model.node_count();
    fx.assign(n, 0.0);
    fy.assign(n, 0.0);
    fz.assign(n, 0.0);
    return {fx.data(), fy.data(), fz.data()};
  }
  // Sum of the element forces on the centre node.
  std::array<double, 3> centre_force() const {
    const auto c = static_cast<std::size_t>(centre);
    return {fx[c], fy[c], fz[c]};
  }
};

class PatchTest : public ::testing::TestWithParam<core::SolidFormulation> {};

TEST_P(PatchTest, HypoelasticStressIsExactAndInteriorForcesCancel) {
  const core::ElasticMaterial mat{7.8e-9, 210000.0, 0.3};
  Patch p(mat, GetParam());
  const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  // A general velocity gradient (stretch, shear and spin).
  const double l[9] = {1.0, 0.4, -0.3, -0.2, -0.5, 0.6, 0.7, 0.1, 0.25};
  p.deform(identity, l);
  SolidBlockState st;
  st.resize(p.model.solid_blocks[0]);
  const double dt = 1e-6;
  const SolidResult r = solid_forces(p.model.solid_blocks[0], p.model.materials[0], st, p.view(),
                                     dt, 0, 8, p.forces());
  ASSERT_FALSE(r.failed);
  const double lambda = 210000.0 * 0.3 / (1.3 * 0.4), mu = 210000.0 / 2.6;
  // The rate of deformation on the mid-step configuration x_m = (I - dt/2 L) X, where the
  // element evaluates it: L_m = L (I - dt/2 L)^-1 (Hughes-Winget; objective under rotation).
  double lm[9];
  {
    const double h = 0.5 * dt;
    const double a[9] = {1 - h * l[0], -h * l[1], -h * l[2], -h * l[3],   1 - h * l[4],
                         -h * l[5],    -h * l[6], -h * l[7], 1 - h * l[8]};
    const double det = a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
                       a[2] * (a[3] * a[7] - a[4] * a[6]);
    const double inv[9] = {(a[4] * a[8] - a[5] * a[7]) / det, (a[2] * a[7] - a[1] * a[8]) / det,
                           (a[1] * a[5] - a[2] * a[4]) / det, (a[5] * a[6] - a[3] * a[8]) / det,
                           (a[0] * a[8] - a[2] * a[6]) / det, (a[2] * a[3] - a[0] * a[5]) / det,
                           (a[3] * a[7] - a[4] * a[6]) / det, (a[1] * a[6] - a[0] * a[7]) / det,
                           (a[0] * a[4] - a[1] * a[3]) / det};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        lm[3 * i + j] = l[3 * i] * inv[j] + l[3 * i + 1] * inv[3 + j] + l[3 * i + 2] * inv[6 + j];
  }
  const double d[6] = {
      lm[0], lm[4], lm[8], 0.5 * (lm[1] + lm[3]), 0.5 * (lm[5] + lm[7]), 0.5 * (lm[6] + lm[2])};
  const double tr = d[0] + d[1] + d[2];
  double expected[6];
  for (int c = 0; c < 6; ++c)
    expected[c] = dt * (2 * mu * d[c] + (c < 3 ? lambda * tr : 0.0));
  const double scale = std::abs(expected[0]);
  for (std::size_t q = 0; q < st.s[0].size(); ++q)
    for (int c = 0; c < 6; ++c)
      ASSERT_NEAR(st.s[c][q], expected[c], 1e-12 * scale) << q << c;
  const auto f = p.centre_force();
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(f[c], 0.0, 1e-12 * scale);
}

TEST_P(PatchTest, MooneyRivlinStressIsTheMaterialsAtTheHomogeneousF) {
  const core::MooneyRivlinMaterial mat{1e-9, 0.49, 0.1, 0.05};
  Patch p(mat, GetParam());
  const double f[9] = {1.3, 0.2, 0.0, -0.1, 0.9, 0.15, 0.05, 0.0, 0.95};
  const double zero[9] = {};
  p.deform(f, zero);
  SolidBlockState st;
  st.resize(p.model.solid_blocks[0]);
  const SolidResult r = solid_forces(p.model.solid_blocks[0], p.model.materials[0], st, p.view(),
                                     1e-6, 0, 8, p.forces());
  ASSERT_FALSE(r.failed);
  double s[6];
  double* out[6] = {&s[0], &s[1], &s[2], &s[3], &s[4], &s[5]};
  const double* fp[9] = {&f[0], &f[1], &f[2], &f[3], &f[4], &f[5], &f[6], &f[7], &f[8]};
  material::mooney_rivlin_cauchy(mat, 1, fp, {out[0], out[1], out[2], out[3], out[4], out[5]});
  for (std::size_t q = 0; q < st.s[0].size(); ++q)
    for (int c = 0; c < 6; ++c)
      ASSERT_NEAR(st.s[c][q], s[c], 1e-10 * std::abs(s[0])) << q << c;
  const auto fc = p.centre_force();
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(fc[c], 0.0, 1e-12 * std::abs(s[0]));
}

TEST_P(PatchTest, InvertedElementIsReported) {
  const core::ElasticMaterial mat{7.8e-9, 210000.0, 0.3};
  Patch p(mat, GetParam());
  const double mirror[9] = {-1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double zero[9] = {};
  p.deform(mirror, zero);
  SolidBlockState st;
  st.resize(p.model.solid_blocks[0]);
  const SolidResult r = solid_forces(p.model.solid_blocks[0], p.model.materials[0], st, p.view(),
                                     1e-6, 0, 8, p.forces());
  EXPECT_TRUE(r.failed);
  EXPECT_EQ(r.failed_element, 0u);
}

INSTANTIATE_TEST_SUITE_P(BothFormulations, PatchTest,
                         ::testing::Values(core::SolidFormulation::one_point,
                                           core::SolidFormulation::selective_reduced));

}  // namespace
}  // namespace plyform::element
