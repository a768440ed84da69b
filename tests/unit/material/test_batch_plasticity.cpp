// The batched shell and solid plasticity kernels equal the per-point result for odd n (points
// mixing elastic and plastic steps) and write nothing past n.

#include <gtest/gtest.h>

#include <cstddef>
#include <random>
#include <vector>

#include "plasticity_helpers.hpp"

namespace plyform::material::test {
namespace {

constexpr std::size_t kGuard = 3;
constexpr double kSentinel = -12345.678;
const std::size_t kSizes[] = {0, 1, 3, 7, 17, 33, 101};

struct Arrays {
  std::vector<std::vector<double>> a;
  Arrays(std::size_t count, std::size_t n) : a(count, std::vector<double>(n + kGuard, kSentinel)) {}
};

void expect_same(double got, double ref, std::size_t p) {
  EXPECT_NEAR(got, ref, 1e-14 * (std::abs(ref) + 1e-300)) << "point " << p;
}

// Shell laws: inputs d (5), state s (5) + eps_p, outputs dzz; per point via shell_step.
template <class Call, class One>
void shell_batch(Call&& call, One&& one) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t n : kSizes) {
    Arrays d(5, n), s(5, n), ep(1, n), dz(1, n), ang(2, n);
    for (std::size_t p = 0; p < n; ++p) {
      for (auto& v : d.a)
        v[p] = (p % 3 == 0 ? 1e-4 : 4e-3) * u(rng);  // every third point stays elastic
      for (auto& v : s.a)
        v[p] = 50.0 * u(rng);
      ep.a[0][p] = 0.02 * (1.0 + u(rng));
      const double t = 3.0 * u(rng);
      ang.a[0][p] = std::cos(t);
      ang.a[1][p] = std::sin(t);
    }
    const Arrays s_in = s, ep_in = ep;
    const ShellPoints pts{d.a[0].data(), d.a[1].data(), d.a[2].data(),  d.a[3].data(),
                          d.a[4].data(), s.a[0].data(), s.a[1].data(),  s.a[2].data(),
                          s.a[3].data(), s.a[4].data(), ep.a[0].data(), dz.a[0].data()};
    call(n, pts, ang.a[0].data(), ang.a[1].data());
    for (std::size_t p = 0; p < n; ++p) {
      ShellState st;
      for (std::size_t k = 0; k < 5; ++k)
        st.s[k] = s_in.a[k][p];
      st.eps_p = ep_in.a[0][p];
      const double dzz = one(st, ShellInc{d.a[0][p], d.a[1][p], d.a[2][p], d.a[3][p], d.a[4][p]},
                             ang.a[0][p], ang.a[1][p]);
      for (std::size_t k = 0; k < 5; ++k)
        expect_same(s.a[k][p], st.s[k], p);
      expect_same(ep.a[0][p], st.eps_p, p);
      expect_same(dz.a[0][p], dzz, p);
    }
    for (const auto* arr : {&s, &ep, &dz})
      for (const auto& v : arr->a)
        for (std::size_t p = n; p < n + kGuard; ++p)
          EXPECT_EQ(v[p], kSentinel) << "written past n at " << p;
  }
}

template <class M>
void shell_law_batch(const M& m) {
  shell_batch(
      [&](std::size_t n, const ShellPoints& pts, const double*, const double*) {
        shell_update(m, n, pts);
      },
      [&](ShellState& st, const ShellInc& d, double, double) { return shell_step(m, st, d); });
}

TEST(BatchPlasticity, ShellLawsEqualPerPoint) {
  core::PiecewiseLinearPlasticity curve{7.85e-9, 210000.0, 0.3, 250.0, 1000.0, {}};
  curve.curve.plastic_strain = {0.0, 0.01, 0.03};
  curve.curve.yield_stress = {250.0, 300.0, 330.0};
  shell_law_batch(curve);
  shell_law_batch(core::PiecewiseLinearPlasticity{7.85e-9, 210000.0, 0.3, 250.0, 1000.0, {}});
  shell_law_batch(core::PowerLawPlasticity{7.85e-9, 210000.0, 0.3, 530.0, 0.26, 0.0});
  shell_law_batch(core::ElasticMaterial{7.85e-9, 210000.0, 0.3});
  core::OrthotropicElasticMaterial o;
  o.ea = 140000.0;
  o.eb = 10000.0;
  o.ec = 9000.0;
  o.prba = 0.02;
  o.prca = 0.015;
  o.prcb = 0.4;
  o.gab = 5000.0;
  o.gbc = 3500.0;
  o.gca = 4500.0;
  shell_batch([&](std::size_t n, const ShellPoints& pts, const double* c,
                  const double* s) { shell_update(o, n, pts, c, s); },
              [&](ShellState& st, const ShellInc& d, double c, double s) {
                double dzz = 0.0;
                shell_update(o, 1, shell_points(st, d, dzz), &c, &s);
                return dzz;
              });
}

template <class M>
void solid_law_batch(const M& m) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double dt = 1e-3;
  for (std::size_t n : kSizes) {
    Arrays d(6, n), s(6, n), w(3, n), ep(1, n);
    for (std::size_t p = 0; p < n; ++p) {
      for (auto& v : d.a)
        v[p] = (p % 3 == 0 ? 0.1 : 4.0) * u(rng);
      for (auto& v : s.a)
        v[p] = 50.0 * u(rng);
      for (auto& v : w.a)
        v[p] = 5.0 * u(rng);
      ep.a[0][p] = 0.02 * (1.0 + u(rng));
    }
    const Arrays s_in = s, ep_in = ep;
    solid_update(m, n,
                 ConstSymView{d.a[0].data(), d.a[1].data(), d.a[2].data(), d.a[3].data(),
                              d.a[4].data(), d.a[5].data()},
                 w.a[0].data(), w.a[1].data(), w.a[2].data(), dt,
                 SymView{s.a[0].data(), s.a[1].data(), s.a[2].data(), s.a[3].data(), s.a[4].data(),
                         s.a[5].data()},
                 ep.a[0].data());
    for (std::size_t p = 0; p < n; ++p) {
      SolidState st;
      for (std::size_t k = 0; k < 6; ++k)
        st.s[k] = s_in.a[k][p];
      st.eps_p = ep_in.a[0][p];
      solid_step(m, st, {d.a[0][p], d.a[1][p], d.a[2][p], d.a[3][p], d.a[4][p], d.a[5][p]},
                 {w.a[0][p], w.a[1][p], w.a[2][p]}, dt);
      for (std::size_t k = 0; k < 6; ++k)
        expect_same(s.a[k][p], st.s[k], p);
      expect_same(ep.a[0][p], st.eps_p, p);
    }
    for (const auto* arr : {&s, &ep})
      for (const auto& v : arr->a)
        for (std::size_t p = n; p < n + kGuard; ++p)
          EXPECT_EQ(v[p], kSentinel) << "written past n at " << p;
  }
}

TEST(BatchPlasticity, SolidLawsEqualPerPoint) {
  core::PiecewiseLinearPlasticity curve{7.85e-9, 210000.0, 0.3, 250.0, 1000.0, {}};
  curve.curve.plastic_strain = {0.0, 0.01, 0.03};
  curve.curve.yield_stress = {250.0, 300.0, 330.0};
  solid_law_batch(curve);
  solid_law_batch(core::PowerLawPlasticity{7.85e-9, 210000.0, 0.3, 530.0, 0.26, 0.0});
}

}  // namespace
}  // namespace plyform::material::test
