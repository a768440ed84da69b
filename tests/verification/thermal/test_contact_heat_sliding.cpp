// Heat across a _THERMAL contact while the slave slides across several master segments,
// against closed forms (mm, t, s, K; heat in mJ). A 1 x 1 x 1 mm steel shell slides at constant
// speed v over a fixed plate of four 1 mm shells (x in [0, 4]), from x in [0.25, 1.25] to
// [2.75, 3.75]: each of its nodes crosses two or three segment boundaries. The thermal step is
// every mechanical step, so the heat is taken with the projection of every cycle.
// - Conduction (no friction): the plate does not conduct (no TMID) and keeps a temperature
//   that rises linearly along x, T_m = T0 + G x; the hot slave's mean temperature follows
//   C dT/dt = h A (T_m(x_c(t)) - T) (the segments' bilinear shape functions interpolate a linear
//   field exactly, and each slave node carries a quarter of the area), whose solution is
//   T = T_p + (T(0) - T_p(0)) exp(-t / tau), T_p = T0 + G x_c(t) - G v tau, tau = C / (h A); and
//   the heat the ledger books into the slave over each output interval is h A times the
//   integral of T_m(x_c) - T. The master's temperature must be read where the node is.
// - Friction (no conductance): under a load F and Coulomb friction mu the ledger's friction heat
//   grows at mu F v; FTOSA of it is stored in the slave and the rest in the plate, whose
//   columns of nodes receive it through the hat functions of the segments the slave nodes
//   cross: column i stores (1 - FTOSA) mu v sum_k integral F(t) / 4 phi_i(x_k(t)) dt.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "../contact/contact_decks.hpp"

namespace plyform {
namespace {

constexpr double kRho = 7.85e-9, kHeatCapacity = 5e8;  // steel: t/mm^3, mm^2/(s^2 K)
constexpr double kEnd = 2e-4;                          // s
constexpr double kSlide = 2.5;                         // mm
constexpr double kSpeed = kSlide / kEnd;               // 12.5 m/s
constexpr double kX0 = 0.25;                           // the slave's first x
constexpr double kOut = 2e-6;                          // output interval
// The slave's capacity (1 mm^3) and its area.
constexpr double kSlaveC = kRho * kHeatCapacity * 1.0, kSlaveA = 1.0;

struct Case {
  bool friction = false;
  double h0 = 0.0;      // conductance
  double tau = 0.0;     // for the record
  double mu = 0.0;      // FS = FD
  double load = 0.0;    // N, total on the slave (friction case)
  double ftosa = 0.5;   // FTOSA
  double gradient = 0;  // K/mm along the plate (conduction case)
};

std::string deck(const Case& c) {
  test::DeckWriter d;
  d.kw("*CONTROL_TERMINATION").card(kEnd);
  d.kw("*CONTROL_SOLUTION").card(2);
  d.kw("*CONTROL_THERMAL_SOLVER").card(1, 0, 11);
  // A fixed thermal step shorter than the mechanical one: a thermal step every cycle.
  d.kw("*CONTROL_THERMAL_TIMESTEP").card(0, 0.5, 1e-12);
  d.kw("*CONTROL_CONTACT").card(0.1).card("").card("").card(0, 1);  // FRCENG 1
  d.kw("*DATABASE_BINARY_D3PLOT").card(kOut);
  d.kw("*DATABASE_GLSTAT").card(kOut);
  // The plate conducts in the friction case only (with a negligible conductivity, so that
  // each column keeps the heat it received); in the conduction case it is a reservoir.
  if (c.friction)
    d.kw("*PART").kw("plate").card(1, 1, 1, 0, 0, 0, 0, 1);
  else
    d.kw("*PART").kw("plate").card(1, 1, 1);
  d.kw("*PART").kw("slider").card(2, 1, 1, 0, 0, 0, 0, 2);
  d.kw("*SECTION_SHELL").card(1, 2, 0.8333, 2).card(1.0, 1.0, 1.0, 1.0);
  d.kw("*MAT_ELASTIC").card(1, kRho, 2.0e5, 0.3);
  d.kw("*MAT_THERMAL_ISOTROPIC").card(1, 0.0).card(kHeatCapacity, 1e-6);
  d.kw("*MAT_THERMAL_ISOTROPIC").card(2, 0.0).card(kHeatCapacity, 5e4);
  // Plate nodes 1-5 (y = -0.5) and 6-10 (y = 1.5) at x = 0..4; slider nodes 1001-1004.
  const auto plate = d.plate(1, 1, 1, 0.0, 4.0, -0.5, 1.5, 4, 1, 0.0);
  const auto slider = d.plate(2, 1001, 1001, kX0, kX0 + 1.0, 0.0, 1.0, 1, 1, 1.0);
  d.kw("*SET_NODE_LIST").card(1).ids(plate);
  d.kw("*SET_NODE_LIST").card(2).ids(slider);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*DEFINE_CURVE").card(2).card(0.0, kSpeed).card(kEnd, kSpeed);
  d.kw("*BOUNDARY_PRESCRIBED_MOTION_SET").card(2, 1, 0, 2, 1.0);
  if (c.friction) {
    // Pressed by a load that ramps up over the first sixth, free in z.
    d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 1, 1);
    d.kw("*DEFINE_CURVE").card(1).card(0.0, 0.0).card(kEnd / 6, 1.0).card(kEnd, 1.0);
    d.kw("*LOAD_NODE_SET").card(2, 3, 1, -c.load / 4.0);
  } else {
    // Held at the plate's surface (the offsets touch: gap 0 <= LMIN, h = H0) without force.
    d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 1, 1, 1, 1);
  }
  d.kw("*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_THERMAL_ID").card(7, "sliding");
  d.card(2, 1, 3, 3).card(c.mu, c.mu, 0, 0, 20).card(1, 1);
  d.card(0, 0, c.h0, 0.01, 0.1, c.ftosa, 0, 0);  // K FRAD H0 LMIN LMAX FTOSA BC_FLG ALGO
  if (c.friction) {
    d.kw("*INITIAL_TEMPERATURE_SET").card(0, 293.0);
  } else {
    d.kw("*INITIAL_TEMPERATURE_SET").card(2, 400.0);
    d.kw("*INITIAL_TEMPERATURE_NODE");
    for (int id : plate)
      d.card(id, 300.0 + c.gradient * ((id - 1) % 5));
  }
  return d.text();
}

struct SlideRun {
  engine::RunResult result;
  std::map<int, std::size_t> index;                                 // node id -> index
  std::vector<std::pair<double, std::vector<double>>> temperature;  // at the states
  std::vector<std::pair<double, thermal::HeatLedger>> books;
};

void run(const Case& c, SlideRun& out) {
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("sliding.k", deck(c)));
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  const auto errors = setup::validate(read.model);
  ASSERT_TRUE(errors.empty()) << errors.front().to_string();
  auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  const core::Model& m = *built.model;
  for (std::size_t i = 0; i < m.node_count(); ++i)
    out.index[static_cast<int>(m.node_id[i])] = i;
  test::RecordingSink sink;
  sink.on_state = [&](const engine::Snapshot& s) {
    out.temperature.emplace_back(s.time, s.nodes->temperature);
  };
  engine::SolverOptions options;
  options.threads = 1;
  out.result = engine::run(m, sink, options);
  ASSERT_TRUE(out.result.ok) << out.result.error;
  out.books = sink.heat_books;
}

double slider_mean(const SlideRun& r, const std::vector<double>& t) {
  double sum = 0.0;
  for (int id = 1001; id <= 1004; ++id)
    sum += t[r.index.at(id)];
  return 0.25 * sum;
}

TEST(ContactHeatSliding, AHotSlaveReadsThePlateTemperatureWhereItIsAsItCrossesSegments) {
  Case c;
  c.gradient = 20.0;  // K/mm: 80 K along the plate
  const double tau = 2e-5;
  c.h0 = kSlaveC / (tau * kSlaveA);
  SlideRun r;
  run(c, r);
  ASSERT_FALSE(HasFailure());
  const double t_plate0 = 300.0 + c.gradient * (kX0 + 0.5);  // under the slave's centre at t = 0
  const auto plate_under = [&](double t) { return t_plate0 + c.gradient * kSpeed * t; };
  const auto particular = [&](double t) { return plate_under(t) - c.gradient * kSpeed * tau; };
  const auto closed = [&](double t) {
    return particular(t) + (400.0 - particular(0.0)) * std::exp(-t / tau);
  };
  ASSERT_GT(r.temperature.size(), 90u);
  double worst = 0.0, worst_t = 0.0;
  for (const auto& [t, temp] : r.temperature) {
    const double e = std::abs(slider_mean(r, temp) - closed(t));
    if (e > worst)
      worst = e, worst_t = t;
  }
  // 100 K at the start; the scheme's error (Crank-Nicolson with dt / tau = 1/120, the
  // projection of the cycle before the thermal step) is a few hundredths of a kelvin.
  EXPECT_LT(worst, 0.1) << "the slider's mean temperature is " << worst
                        << " K from the closed form at t = " << worst_t;
  // The heat over each output interval, against h A times the integral of the difference
  // (trapezoidal in the slider's temperature, exact in the plate's linear one). The books and
  // the states come at the same times.
  std::map<long, double> mean_at;
  for (const auto& [t, temp] : r.temperature)
    mean_at[std::lround(t / kOut)] = slider_mean(r, temp);
  const double ha = c.h0 * kSlaveA;
  int intervals = 0;
  double worst_flux = 0.0;
  for (std::size_t b = 1; b < r.books.size(); ++b) {
    const double ta = r.books[b - 1].first, tb = r.books[b].first;
    const auto ia = mean_at.find(std::lround(ta / kOut));
    const auto ib = mean_at.find(std::lround(tb / kOut));
    if (ia == mean_at.end() || ib == mean_at.end())
      continue;
    const double expected =
        ha * (tb - ta) *
        (0.5 * (plate_under(ta) + plate_under(tb)) - 0.5 * (ia->second + ib->second));
    const double booked = r.books[b].second.contact - r.books[b - 1].second.contact;
    // The mismatch as a temperature difference over the interval (the difference itself
    // goes from 70 K through 0 to -5 K as the slider cools and the plate warms under it).
    worst_flux = std::max(worst_flux, std::abs(booked - expected) / (ha * (tb - ta)));
    ++intervals;
  }
  EXPECT_GT(intervals, 90);
  EXPECT_LT(worst_flux, 0.1) << "the heat across the interface over an output interval, as "
                                "a temperature difference [K]";
  // The ledger: what crossed is what the slider stored (the plate is outside the system).
  const thermal::HeatLedger& last = r.books.back().second;
  EXPECT_NEAR(last.stored, kSlaveC * (slider_mean(r, r.temperature.back().second) - 400.0),
              1e-9 * last.moved);
  EXPECT_NEAR(last.stored, last.contact, 1e-9 * last.moved);
  std::printf(
      "sliding conduction: slider mean within %.3g K of the closed form, interval heat as "
      "a temperature within %.3g K of h A int(T_m - T) dt\n",
      worst, worst_flux);
}

TEST(ContactHeatSliding, FrictionHeatIsMuFvSplitByFtosaAlongThePath) {
  Case c;
  c.friction = true;
  c.mu = 0.3;
  c.load = 16.0;
  c.ftosa = 0.7;
  SlideRun r;
  run(c, r);
  ASSERT_FALSE(HasFailure());
  const double power = c.mu * c.load * kSpeed;
  // The friction heat's rate over the last third (steady load), against mu F v.
  const auto at = [&](double t) {
    return *std::lower_bound(r.books.begin(), r.books.end(), t,
                             [](const auto& b, double x) { return b.first < x; });
  };
  const auto [t0, h0] = at(2.0 * kEnd / 3.0);
  const auto [t1, h1] = r.books.back();
  const double rate = (h1.friction - h0.friction) / (t1 - t0);
  EXPECT_NEAR(rate, power, 0.01 * power);
  // FTOSA of it stored in the slider, the rest in the plate (nothing else moves heat).
  const std::vector<double>& temp = r.temperature.back().second;
  const double node_c = 0.25 * kSlaveC;
  double slider = 0.0;
  for (int id = 1001; id <= 1004; ++id)
    slider += node_c * (temp[r.index.at(id)] - 293.0);
  // Plate columns i = 0..4 (nodes i + 1 and i + 6); each element 1 x 2 x 1 mm.
  std::vector<double> column(5, 0.0);
  for (int i = 0; i < 5; ++i) {
    const double ci = (i == 0 || i == 4 ? 1.0 : 2.0) * 0.25 * kRho * kHeatCapacity * 2.0;
    for (int id : {i + 1, i + 6})
      column[static_cast<std::size_t>(i)] += ci * (temp[r.index.at(id)] - 293.0);
  }
  double plate = 0.0;
  for (double e : column)
    plate += e;
  const double friction = h1.friction;
  EXPECT_NEAR(slider, c.ftosa * friction, 1e-6 * friction);
  EXPECT_NEAR(plate, (1.0 - c.ftosa) * friction, 1e-6 * friction);
  // Column i's share: the slider nodes' friction power mu v F(t) / 4 through the hat function
  // of x_i, integrated along the path (midpoint rule, 20000 points).
  const auto load = [&](double t) { return c.load * std::min(1.0, t / (kEnd / 6)); };
  const auto hat = [](double x, int i) { return std::max(0.0, 1.0 - std::abs(x - i)); };
  const int steps = 20000;
  for (int i = 0; i < 5; ++i) {
    double e = 0.0;
    for (int s = 0; s < steps; ++s) {
      const double t = (s + 0.5) * kEnd / steps, x = kX0 + kSpeed * t;
      e += (hat(x, i) + hat(x + 1.0, i)) * 2.0 * 0.25 * load(t) * kEnd / steps;
    }
    e *= (1.0 - c.ftosa) * c.mu * kSpeed;
    EXPECT_NEAR(column[static_cast<std::size_t>(i)], e, 0.01 * (1.0 - c.ftosa) * friction)
        << "plate column x = " << i;
  }
  std::printf("sliding friction: rate %.6g (mu F v %.6g), slider %.6g and plate %.6g of %.6g\n",
              rate, power, slider, plate, friction);
}

}  // namespace
}  // namespace plyform
