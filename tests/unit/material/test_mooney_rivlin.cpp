// *MAT_MOONEY-RIVLIN_RUBBER against the closed forms of the incompressible Mooney-Rivlin solid
// (C10 = A, C01 = B), sigma = -p I + 2 C10 b - 2 C01 b^-1:
//   uniaxial      sigma = 2 (l^2 - 1/l) (C10 + C01 / l)
//   equibiaxial   sigma = 2 (l^2 - 1/l^4) (C10 + C01 l^2)
//   simple shear  tau = 2 (C10 + C01) g, N1 = 2 (C10 + C01) g^2, N2 = -2 C01 g^2.
// The compressible law approaches them as nu -> 1/2 (the volume change is O(sigma / K)).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "plyform/material/law_registry.hpp"
#include "tensor_helpers.hpp"

namespace plyform::material::test {
namespace {

struct Case {
  double nu;
  double a;
  double b;
};

// C10 = 0.4, C01 = 0.1 MPa (a typical filled rubber) and C01 > C10 to exercise N2.
const Case kCases[] = {
    {0.49, 0.4, 0.1},  {0.49, 0.1, 0.3},   {0.499, 0.4, 0.1},
    {0.499, 0.1, 0.3}, {0.4999, 0.4, 0.1}, {0.4999, 0.1, 0.3},
};

// The compressible law departs from the incompressible closed forms by O(1 - 2 nu): already at
// small strain, uniaxial E = 2 G (1 + nu) against 3 G (-0.67 % at nu = 0.49) and equibiaxial
// E / (1 - nu) = 2 G (1 + nu) / (1 - nu) against 6 G (-2.6 % at nu = 0.49). The tolerances are
// k (1 - 2 nu): uniaxial k = 1 (2 % at 0.49, 0.2 % at 0.499), equibiaxial k = 4 (8 %, 0.8 %).
double tolerance(const Case& c, double k) {
  return k * (1.0 - 2.0 * c.nu);
}

const double kStretches[] = {0.7, 0.75, 0.8, 0.9, 0.95, 1.05, 1.1, 1.25, 1.5, 1.75, 2.0};

core::MooneyRivlinMaterial material(const Case& c) {
  return core::MooneyRivlinMaterial{1.1e-9, c.nu, c.a, c.b};
}

Mat3 diag(double x, double y, double z) {
  return Mat3{{{x, 0.0, 0.0}, {0.0, y, 0.0}, {0.0, 0.0, z}}};
}

// Newton loop (finite-difference slope) for the free stretch s with residual(s) = 0.
double solve_free_stretch(const std::function<double(double)>& residual, double s0) {
  double s = s0;
  for (int it = 0; it < 50; ++it) {
    const double h = 1e-7 * s;
    const double slope = (residual(s + h) - residual(s - h)) / (2.0 * h);
    const double step = residual(s) / slope;
    s -= step;
    if (std::abs(step) < 1e-15 * s)
      return s;
  }
  ADD_FAILURE() << "Newton loop for the free stretch did not converge";
  return s;
}

double rel_err(double value, double ref) {
  return std::abs(value - ref) / std::abs(ref);
}

TEST(MooneyRivlin, StressFreeAtIdentity) {
  for (const Case& c : kCases) {
    const Mat3 s = mooney_rivlin(material(c), identity());
    EXPECT_LT(norm(s), 1e-12 * (c.a + c.b)) << "nu " << c.nu;
  }
}

TEST(MooneyRivlin, UniaxialTensionCompression) {
  for (const Case& c : kCases) {
    const auto m = material(c);
    double worst = 0.0;
    for (double l : kStretches) {
      const double lat = solve_free_stretch(
          [&](double s) { return mooney_rivlin(m, diag(l, s, s))[1][1]; }, 1.0 / std::sqrt(l));
      const Mat3 s = mooney_rivlin(m, diag(l, lat, lat));
      const double ref = 2.0 * (l * l - 1.0 / l) * (c.a + c.b / l);
      EXPECT_NEAR(s[2][2], 0.0, 1e-10 * (c.a + c.b));  // the other lateral stress, by symmetry
      EXPECT_EQ(std::signbit(s[0][0]), std::signbit(ref)) << "lambda " << l;
      EXPECT_LT(rel_err(s[0][0], ref), tolerance(c, 1.0)) << "nu " << c.nu << " lambda " << l;
      worst = std::max(worst, rel_err(s[0][0], ref));
      std::printf(" %.2f:%.2e", l, rel_err(s[0][0], ref));
    }
    std::printf("\nuniaxial     nu=%.4f A=%.2f B=%.2f: max rel. error %.3e\n", c.nu, c.a, c.b,
                worst);
  }
}

TEST(MooneyRivlin, EquibiaxialTension) {
  for (const Case& c : kCases) {
    const auto m = material(c);
    double worst = 0.0;
    for (double l : kStretches) {
      const double thick = solve_free_stretch(
          [&](double s) { return mooney_rivlin(m, diag(l, l, s))[2][2]; }, 1.0 / (l * l));
      const Mat3 s = mooney_rivlin(m, diag(l, l, thick));
      const double ref = 2.0 * (l * l - std::pow(l, -4.0)) * (c.a + c.b * l * l);
      EXPECT_NEAR(s[0][0], s[1][1], 1e-12 * std::abs(ref));
      EXPECT_EQ(std::signbit(s[0][0]), std::signbit(ref)) << "lambda " << l;
      EXPECT_LT(rel_err(s[0][0], ref), tolerance(c, 4.0)) << "nu " << c.nu << " lambda " << l;
      worst = std::max(worst, rel_err(s[0][0], ref));
      std::printf(" %.2f:%.2e", l, rel_err(s[0][0], ref));
    }
    std::printf("\nequibiaxial  nu=%.4f A=%.2f B=%.2f: max rel. error %.3e\n", c.nu, c.a, c.b,
                worst);
  }
}

TEST(MooneyRivlin, SimpleShear) {
  const double shears[] = {-1.0, -0.3, 0.05, 0.1, 0.3, 0.5, 1.0, 1.5, 2.0};
  for (const Case& c : kCases) {
    const auto m = material(c);
    double worst = 0.0;
    for (double g : shears) {
      const Mat3 f{{{1.0, g, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
      const Mat3 s = mooney_rivlin(m, f);
      const double tau = 2.0 * (c.a + c.b) * g;
      const double n1 = 2.0 * (c.a + c.b) * g * g;
      const double n2 = -2.0 * c.b * g * g;
      EXPECT_LT(rel_err(s[0][1], tau), 1e-10) << "gamma " << g;
      EXPECT_LT(rel_err(s[0][0] - s[1][1], n1), 1e-10) << "gamma " << g;
      EXPECT_LT(rel_err(s[1][1] - s[2][2], n2), 1e-10) << "gamma " << g;
      EXPECT_EQ(std::signbit(s[0][1]), std::signbit(g));
      EXPECT_GT(s[0][0] - s[1][1], 0.0);  // N1 > 0
      EXPECT_LT(s[1][1] - s[2][2], 0.0);  // N2 < 0 (B > 0)
      EXPECT_NEAR(s[1][2], 0.0, 1e-14);
      EXPECT_NEAR(s[2][0], 0.0, 1e-14);
      worst = std::max({worst, rel_err(s[0][1], tau), rel_err(s[0][0] - s[1][1], n1),
                        rel_err(s[1][1] - s[2][2], n2)});
    }
    std::printf("simple shear nu=%.4f A=%.2f B=%.2f: max rel. error %.3e\n", c.nu, c.a, c.b, worst);
  }
}

TEST(MooneyRivlin, Objectivity) {
  const core::MooneyRivlinMaterial m{1e-9, 0.49, 0.4, 0.1};
  const Mat3 f{{{1.3, 0.2, -0.1}, {0.05, 0.8, 0.3}, {-0.2, 0.1, 1.1}}};
  ASSERT_GT(det(f), 0.0);
  const Mat3 s = mooney_rivlin(m, f);
  for (double angle : {0.3, 1.7, -2.5, 3.1}) {
    const Mat3 r = rotation(0.3, -1.0, 0.7, angle);
    const Mat3 sr = mooney_rivlin(m, mul(r, f));
    const Mat3 ref = mul(mul(r, s), transpose(r));
    EXPECT_LT(norm(add(sr, ref, -1.0)), 1e-12 * norm(s)) << "angle " << angle;
    // Rotation of the reference frame (F -> F R) leaves the Cauchy stress unchanged.
    const Mat3 sl = mooney_rivlin(m, mul(f, r));
    EXPECT_LT(norm(add(sl, s, -1.0)), 1e-12 * norm(s)) << "angle " << angle;
  }
}

// The stress formula against the energy itself: sigma = (1/J) (dW/dF) F^T with dW/dF by central
// differences of W = A (I1 - 3) + B (I2 - 3) + C (III^-2 - 1) + D (III - 1)^2 (LS-DYNA MAT_027),
// for general deformation gradients with large volume changes (nu = 0.3, 0.45, 0.49).
double energy(const core::MooneyRivlinMaterial& m, const Mat3& f) {
  const Mat3 cr = mul(transpose(f), f);
  const double i1 = trace(cr);
  const double i2 = 0.5 * (i1 * i1 - trace(mul(cr, cr)));
  const double i3 = det(cr);
  const double c = 0.5 * m.a + m.b;
  const double d = (m.a * (5.0 * m.poisson - 2.0) + m.b * (11.0 * m.poisson - 5.0)) /
                   (2.0 * (1.0 - 2.0 * m.poisson));
  return m.a * (i1 - 3.0) + m.b * (i2 - 3.0) + c * (1.0 / (i3 * i3) - 1.0) +
         d * (i3 - 1.0) * (i3 - 1.0);
}

TEST(MooneyRivlin, StressIsTheDerivativeOfTheEnergy) {
  const Mat3 fs[] = {
      Mat3{{{1.3, 0.2, -0.1}, {0.05, 0.8, 0.3}, {-0.2, 0.1, 1.1}}},
      Mat3{{{0.75, -0.3, 0.0}, {0.1, 1.6, 0.2}, {0.0, -0.4, 0.9}}},
      Mat3{{{1.1, 0.0, 0.0}, {0.0, 1.1, 0.0}, {0.0, 0.0, 1.1}}},  // pure dilatation
      Mat3{{{0.9, 0.1, 0.0}, {0.0, 0.9, 0.0}, {0.1, 0.0, 0.92}}},
  };
  for (double nu : {0.3, 0.45, 0.49}) {
    const core::MooneyRivlinMaterial m{1e-9, nu, 0.4, 0.1};
    for (const Mat3& f : fs) {
      Mat3 p{};
      const double h = 1e-6;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Mat3 fp = f, fm = f;
          fp[i][j] += h;
          fm[i][j] -= h;
          p[i][j] = (energy(m, fp) - energy(m, fm)) / (2.0 * h);
        }
      Mat3 ref = mul(p, transpose(f));
      const double jac = det(f);
      for (auto& row : ref)
        for (double& v : row)
          v /= jac;
      const Mat3 s = mooney_rivlin(m, f);
      EXPECT_LT(norm(add(s, ref, -1.0)), 1e-7 * (norm(ref) + 1.0)) << "nu " << nu;
    }
  }
}

// Small strain: sigma = K tr(eps) I + 2 G dev(eps) with G = 2 (A + B), K from nu.
TEST(MooneyRivlin, SmallStrainModuli) {
  for (const Case& c : kCases) {
    const auto m = material(c);
    const double g = 2.0 * (c.a + c.b);
    const double k = 2.0 * g * (1.0 + c.nu) / (3.0 * (1.0 - 2.0 * c.nu));
    EXPECT_NEAR(material::shear_modulus(core::Material{m}), g, 1e-14 * g);
    EXPECT_NEAR(material::bulk_modulus(core::Material{m}), k, 1e-12 * k);
    const double h = 1e-7;
    const Mat3 eps{
        {{0.3 * h, 0.5 * h, -0.2 * h}, {0.5 * h, -0.7 * h, 0.1 * h}, {-0.2 * h, 0.1 * h, 0.2 * h}}};
    const Mat3 s = mooney_rivlin(m, add(identity(), eps));
    const double tr = trace(eps);
    Mat3 ref{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        ref[i][j] = 2.0 * g * eps[i][j] + (i == j ? (k - 2.0 * g / 3.0) * tr : 0.0);
    EXPECT_LT(norm(add(s, ref, -1.0)), 1e-5 * norm(ref)) << "nu " << c.nu;
  }
}

}  // namespace
}  // namespace plyform::material::test
