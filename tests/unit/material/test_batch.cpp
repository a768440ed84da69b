// The batched kernels equal the per-point result for n = 1 and odd n, write nothing past n.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "tensor_helpers.hpp"

namespace plyform::material::test {
namespace {

constexpr std::size_t kGuard = 5;  // sentinel slots after the n points
constexpr double kSentinel = -12345.678;

struct Soa {
  std::vector<double> c[6];
  explicit Soa(std::size_t n) {
    for (auto& v : c)
      v.assign(n + kGuard, kSentinel);
  }
  SymView view() {
    return {c[0].data(), c[1].data(), c[2].data(), c[3].data(), c[4].data(), c[5].data()};
  }
  ConstSymView cview() const {
    return {c[0].data(), c[1].data(), c[2].data(), c[3].data(), c[4].data(), c[5].data()};
  }
  Mat3 at(std::size_t p) const {
    return from_voigt({c[0][p], c[1][p], c[2][p], c[3][p], c[4][p], c[5][p]});
  }
};

void expect_same(const Mat3& a, const Mat3& b, std::size_t p) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(a[i][j], b[i][j], 1e-14 * (std::abs(b[i][j]) + 1e-300))
          << "point " << p << " component " << i << j;
}

void expect_guard(const Soa& s, std::size_t n) {
  for (const auto& v : s.c)
    for (std::size_t p = n; p < n + kGuard; ++p)
      EXPECT_EQ(v[p], kSentinel) << "written past n at " << p;
}

const std::size_t kSizes[] = {0, 1, 3, 7, 17, 33, 101};

TEST(Batch, MooneyRivlinEqualsPerPoint) {
  const core::MooneyRivlinMaterial m{1.1e-9, 0.495, 0.4, 0.1};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (std::size_t n : kSizes) {
    std::vector<double> fv[9];
    for (int k = 0; k < 9; ++k) {
      fv[k].resize(n + kGuard);
      for (std::size_t p = 0; p < n; ++p)
        fv[k][p] = (k % 4 == 0 ? 1.0 : 0.0) + u(rng);
    }
    const double* fp[9];
    for (int k = 0; k < 9; ++k)
      fp[k] = fv[k].data();
    Soa s(n);
    mooney_rivlin_cauchy(m, n, fp, s.view());
    for (std::size_t p = 0; p < n; ++p) {
      Mat3 f{};
      for (int k = 0; k < 9; ++k)
        f[k / 3][k % 3] = fv[k][p];
      expect_same(s.at(p), mooney_rivlin(m, f), p);
    }
    expect_guard(s, n);
  }
}

TEST(Batch, ElasticJaumannEqualsPerPoint) {
  const core::ElasticMaterial m{7.85e-9, 210000.0, 0.3};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double dt = 1e-3;
  for (std::size_t n : kSizes) {
    Soa d(n), s(n);
    std::vector<double> w[3];
    for (auto& v : w)
      v.assign(n + kGuard, kSentinel);
    for (std::size_t p = 0; p < n; ++p) {
      for (int k = 0; k < 6; ++k) {
        d.c[k][p] = 1e-2 * u(rng);
        s.c[k][p] = 100.0 * u(rng);
      }
      for (auto& v : w)
        v[p] = 5.0 * u(rng);
    }
    const Soa s_in = s;
    elastic_jaumann(m, n, d.cview(), w[0].data(), w[1].data(), w[2].data(), dt, s.view());
    for (std::size_t p = 0; p < n; ++p)
      expect_same(s.at(p), jaumann_step(m, s_in.at(p), d.at(p), {w[0][p], w[1][p], w[2][p]}, dt),
                  p);
    expect_guard(s, n);
  }
}

}  // namespace
}  // namespace plyform::material::test
