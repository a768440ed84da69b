// *MAT_ELASTIC with the Jaumann rate against plain-matrix references.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "tensor_helpers.hpp"

namespace plyform::material::test {
namespace {

const core::ElasticMaterial kSteel{7.85e-9, 210000.0, 0.3};  // t/mm^3, MPa

// Rate of the brief's update, sigma_dot = C : D + W sigma - sigma W, with matrices.
Mat3 jaumann_rate(const core::ElasticMaterial& m, const Mat3& sigma, const Mat3& d,
                  const std::array<double, 3>& w) {
  const double mu = m.young / (2.0 * (1.0 + m.poisson));
  const double lambda = m.young * m.poisson / ((1.0 + m.poisson) * (1.0 - 2.0 * m.poisson));
  const Mat3 wm = spin(w);
  Mat3 r = add(mul(wm, sigma), mul(sigma, wm), -1.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r[i][j] += 2.0 * mu * d[i][j] + (i == j ? lambda * trace(d) : 0.0);
  return r;
}

TEST(ElasticJaumann, UniaxialSmallStrainIncrements) {
  const double rate = 10.0;  // 1/s
  const double dt = 1e-6;
  const int steps = 200;  // total strain 2e-3
  const double nu = kSteel.poisson;
  const Mat3 d{{{rate, 0.0, 0.0}, {0.0, -nu * rate, 0.0}, {0.0, 0.0, -nu * rate}}};
  Mat3 s{};
  for (int i = 0; i < steps; ++i)
    s = jaumann_step(kSteel, s, d, {0.0, 0.0, 0.0}, dt);
  const double eps = rate * dt * steps;
  EXPECT_NEAR(s[0][0], kSteel.young * eps, 1e-10 * kSteel.young * eps);
  EXPECT_NEAR(s[1][1], 0.0, 1e-10 * kSteel.young * eps);
  EXPECT_NEAR(s[2][2], 0.0, 1e-10 * kSteel.young * eps);
  EXPECT_EQ(s[0][1], 0.0);
  EXPECT_EQ(s[1][2], 0.0);
  EXPECT_EQ(s[2][0], 0.0);
  std::printf("uniaxial: sigma_xx = %.12g (E eps = %.12g), lateral %.3g %.3g\n", s[0][0],
              kSteel.young * eps, s[1][1], s[2][2]);
}

TEST(ElasticJaumann, PureShearIncrement) {
  // D_12 = gdot / 2 gives tau = G gamma.
  const double gdot = 1.0, dt = 1e-4;
  const Mat3 d{{{0.0, 0.5 * gdot, 0.0}, {0.5 * gdot, 0.0, 0.0}, {0.0, 0.0, 0.0}}};
  const Mat3 s = jaumann_step(kSteel, Mat3{}, d, {0.0, 0.0, 0.0}, dt);
  const double g = kSteel.young / (2.0 * (1.0 + kSteel.poisson));
  EXPECT_NEAR(s[0][1], g * gdot * dt, 1e-12 * g * gdot * dt);
}

TEST(ElasticJaumann, PureRotationKeepsInvariants) {
  const Mat3 s0{{{120.0, 35.0, -20.0}, {35.0, -40.0, 15.0}, {-20.0, 15.0, 60.0}}};
  const std::array<double, 3> w{0.7, -0.4, 1.1};  // rad/s
  const double omega = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const int steps = 20000;
  const double period = 2.0 * std::numbers::pi / omega;
  const double dt = period / steps;
  const Mat3 zero{};
  Mat3 s = s0;
  double worst_tr = 0.0, worst_vm = 0.0, worst_det = 0.0;
  for (int i = 1; i <= steps; ++i) {
    s = jaumann_step(kSteel, s, zero, w, dt);
    worst_tr = std::max(worst_tr, std::abs(trace(s) - trace(s0)) / std::abs(trace(s0)));
    worst_vm = std::max(worst_vm, std::abs(von_mises(s) - von_mises(s0)) / von_mises(s0));
    worst_det = std::max(worst_det, std::abs(det(s) - det(s0)) / std::abs(det(s0)));
    if (i == steps / 4) {
      // A quarter turn: the exact rotation R = exp(t W) applied to s0.
      const Mat3 wt = [&] {
        Mat3 a = spin(w);
        for (auto& row : a)
          for (double& v : row)
            v *= dt * i;
        return a;
      }();
      const Mat3 r = expm(wt);
      const Mat3 ref = mul(mul(r, s0), transpose(r));
      EXPECT_LT(norm(add(s, ref, -1.0)), 1e-6 * norm(s0));
    }
  }
  EXPECT_LT(worst_tr, 1e-6);
  EXPECT_LT(worst_vm, 1e-6);
  EXPECT_LT(worst_det, 1e-6);
  // After the full turn the stress is back (the Cayley angle per step is 2 atan(omega dt / 2)).
  EXPECT_LT(norm(add(s, s0, -1.0)), 1e-6 * norm(s0));
  std::printf(
      "rotation, %d steps: max rel. drift trace %.2e, von Mises %.2e, det %.2e; "
      "|s - s0| / |s0| after a turn %.2e\n",
      steps, worst_tr, worst_vm, worst_det, norm(add(s, s0, -1.0)) / norm(s0));
}

TEST(ElasticJaumann, LinearInDtForSmallSteps) {
  const Mat3 s0{{{120.0, 35.0, -20.0}, {35.0, -40.0, 15.0}, {-20.0, 15.0, 60.0}}};
  const Mat3 d{{{1e-3, 2e-4, -3e-4}, {2e-4, -5e-4, 1e-4}, {-3e-4, 1e-4, 2e-4}}};
  const std::array<double, 3> w{0.7, -0.4, 1.1};
  const Mat3 rate = jaumann_rate(kSteel, s0, d, w);
  double previous = 0.0;
  for (double dt : {1e-2, 1e-3, 1e-4, 1e-5}) {
    const Mat3 inc = add(jaumann_step(kSteel, s0, d, w, dt), s0, -1.0);
    Mat3 per_dt = inc;
    for (auto& row : per_dt)
      for (double& v : row)
        v /= dt;
    const double err = norm(add(per_dt, rate, -1.0)) / norm(rate);
    // First order: the increment / dt tends to the rate with an error O(dt).
    EXPECT_LT(err, 2.0 * dt) << "dt " << dt;
    if (previous > 0.0) {
      EXPECT_NEAR(previous / err, 10.0, 1.0) << "dt " << dt;  // error ~ dt
    }
    previous = err;
    std::printf("dt %.0e: |dsigma/dt - rate| / |rate| = %.3e\n", dt, err);
  }
}

}  // namespace
}  // namespace plyform::material::test
