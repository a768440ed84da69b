// Viscous regime: the response depends on Lambda = eta v / (omega g_c) only, and the peak and
// the work of separation rise with the opening rate and with eta (paper fig. 4).
#include <gtest/gtest.h>

#include <cmath>

#include "law_fixtures.hpp"

namespace plyform::law {
namespace {

using test::critical_gap;
using test::omega;

struct Outcome {
  double peak;
  double work;
  std::vector<PathSample> run;
};

// Opens to 300 g_c at rate v with 2000 steps per g_c.
Outcome pull(double eta, double v) {
  const Parameters p = test::probe_parameters(eta);
  const Law law(p);
  const double gc = critical_gap(p);
  auto run = drive(law, test::opening_path(v, 300 * gc, 300 * 2000), {1000.0});
  EXPECT_EQ(run.back().history.state, NodeState::detached) << "eta " << eta << " v " << v;
  const double peak = test::peak_tension(run).tension;
  const double work = interface_work(run);
  return {peak, work, std::move(run)};
}

TEST(RateDependence, PeakAndWorkRiseStrictlyWithTheOpeningRate) {
  const double eta = 3e-6;  // Lambda = 0.1 v
  double last_peak = 0.3, last_work = 0.0;
  for (double v : {0.1, 1.0, 10.0, 100.0}) {
    const Outcome o = pull(eta, v);
    EXPECT_GT(o.peak, last_peak) << "v = " << v;
    EXPECT_GT(o.work, last_work) << "v = " << v;
    EXPECT_GT(o.work, omega(test::probe_parameters()));  // viscous dissipation on top of omega
    last_peak = o.peak;
    last_work = o.work;
  }
}

TEST(RateDependence, PeakAndWorkRiseStrictlyWithEta) {
  double last_peak = 0.3, last_work = 0.0;
  for (double eta : {3e-7, 3e-6, 3e-5, 3e-4}) {
    const Outcome o = pull(eta, 1.0);
    EXPECT_GT(o.peak, last_peak) << "eta = " << eta;
    EXPECT_GT(o.work, last_work) << "eta = " << eta;
    last_peak = o.peak;
    last_work = o.work;
  }
}

TEST(RateDependence, EqualLambdaGivesTheSameCurveInGOverGc) {
  // Lambda = 1 twice: (eta, v) = (3e-5, 1) and (3e-7, 100).
  const Outcome a = pull(3e-5, 1.0);
  const Outcome b = pull(3e-7, 100.0);
  ASSERT_EQ(a.run.size(), b.run.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.run.size(); ++i) {
    ASSERT_NEAR(a.run[i].at.gap, b.run[i].at.gap, 1e-12);
    worst = std::max(worst, std::abs(a.run[i].response.pressure - b.run[i].response.pressure));
  }
  EXPECT_LT(worst, 1e-9 * 0.3);
  EXPECT_NEAR(a.peak, b.peak, 1e-9 * a.peak);
  // The viscous peak sits beyond g_c, and above sigma_max.
  EXPECT_GT(a.peak, 0.3 * 1.05);
}

}  // namespace
}  // namespace plyform::law
