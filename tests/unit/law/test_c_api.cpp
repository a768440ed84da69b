// The C ABI gives the C++ results, reports errors as status codes and messages.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "law_fixtures.hpp"
#include "plyform/law/plyform_law.h"

extern "C" double c_header_open_once(double gap);

namespace plyform::law {
namespace {

constexpr double kBlank = std::numeric_limits<double>::quiet_NaN();

// CN SMAX ... with healing, Coulomb friction and damping switched on.
std::vector<double> constants() {
  return {1,   30.0, 0.3, 0.2, 300, 500,    1e-4,   2.0,    1.0,
          1.0, 1e-6, 0,   0.3, 0.2, kBlank, kBlank, kBlank, 5.0};
}

TEST(CApi, PlainCCallerGetsTheCohesiveTension) {
  EXPECT_DOUBLE_EQ(c_header_open_once(0.005), -30.0 * 0.005);
}

TEST(CApi, NodeUpdatesEqualTheCppLaw) {
  const std::vector<double> uc = constants();
  plyform_law* claw = nullptr;
  char msg[512];
  ASSERT_EQ(plyform_law_create(uc.data(), int32_t(uc.size()), nullptr, 0, &claw, msg, sizeof msg),
            PLYFORM_LAW_OK)
      << msg;
  std::vector<std::optional<double>> ucx;
  for (double v : uc)
    ucx.push_back(std::isnan(v) ? std::nullopt : std::optional<double>(v));
  const Law law(from_user_constants(ucx, {}).parameters);

  plyform_law_history ch;
  ASSERT_EQ(plyform_law_initial_history(claw, 0.0, &ch), PLYFORM_LAW_OK);
  NodeHistory h = law.initial_history(0.0);
  for (int i = 1; i <= 400; ++i) {
    const double t = i * 1e-3;
    plyform_law_increment in{};
    in.gap = 0.03 * std::sin(12.0 * t) - 0.005;
    in.slip[0] = 1e-4;
    in.slip[1] = -2e-5;
    in.dt = 1e-3;
    in.temperature = 300 + 500 * t;
    in.k_normal = 900;
    in.k_tangent = 300;
    in.area = 0.2;
    in.mass = 1e-6;
    plyform_law_response cr;
    ASSERT_EQ(plyform_law_update_node(claw, &in, &ch, &cr), PLYFORM_LAW_OK);
    Increment inc;
    inc.gap = in.gap;
    inc.slip[0] = in.slip[0];
    inc.slip[1] = in.slip[1];
    inc.dt = in.dt;
    inc.temperature = in.temperature;
    inc.k_normal = in.k_normal;
    inc.k_tangent = in.k_tangent;
    inc.area = in.area;
    inc.mass = in.mass;
    const Response r = law.update(inc, h);
    ASSERT_EQ(cr.pressure, r.pressure);
    ASSERT_EQ(cr.tau[0], r.tau[0]);
    ASSERT_EQ(ch.beta, h.beta);
    ASSERT_EQ(ch.state, static_cast<int32_t>(h.state));
    ASSERT_EQ(ch.e_healing, h.e_healing);
  }
  EXPECT_GT(h.e_damage, 0.0);
  EXPECT_GT(h.e_healing, 0.0);
  EXPECT_GT(h.e_friction, 0.0);
  plyform_law_destroy(claw);
}

TEST(CApi, Mode1HistoryGivesTheSameNormalPressure) {
  std::vector<double> uc = constants();
  uc[11] = 0.0;
  uc[12] = 0.0;  // no friction: the full law is then mode I only
  uc[13] = 0.0;
  uc[17] = 0.0;  // no damping
  plyform_law* claw = nullptr;
  ASSERT_EQ(plyform_law_create(uc.data(), int32_t(uc.size()), nullptr, 0, &claw, nullptr, 0),
            PLYFORM_LAW_OK);
  plyform_law_history full;
  ASSERT_EQ(plyform_law_initial_history(claw, 0.0, &full), PLYFORM_LAW_OK);
  double hist[3] = {double(full.state), full.beta, full.gap};
  for (int i = 1; i <= 300; ++i) {
    const double g = 0.05 * std::sin(0.05 * i) - 0.01;
    plyform_law_increment in{};
    in.gap = g;
    in.dt = 1e-3;
    in.temperature = 400;
    in.k_normal = 500;
    in.area = 1;
    plyform_law_response r;
    ASSERT_EQ(plyform_law_update_node(claw, &in, &full, &r), PLYFORM_LAW_OK);
    double p = 0;
    ASSERT_EQ(plyform_law_update_mode1(claw, g, 1e-3, 400, 500, hist, &p), PLYFORM_LAW_OK);
    ASSERT_EQ(p, r.pressure);
    ASSERT_EQ(hist[1], full.beta);
  }
  plyform_law_destroy(claw);
}

TEST(CApi, InvalidConstantsReturnTheMessages) {
  const double uc[] = {1, -30.0, 0.3};
  plyform_law* claw = reinterpret_cast<plyform_law*>(0x1);
  char msg[512];
  EXPECT_EQ(plyform_law_create(uc, 3, nullptr, 0, &claw, msg, sizeof msg),
            PLYFORM_LAW_INVALID_PARAMETER);
  EXPECT_EQ(claw, nullptr);
  const std::string text(msg);
  EXPECT_NE(text.find("constant UC2 CN = -30: expected greater than 0"), std::string::npos);
  EXPECT_NE(text.find("constant UC7 ETA is required"), std::string::npos);
  // A short buffer is truncated, still NUL-terminated.
  char tiny[8];
  EXPECT_EQ(plyform_law_create(uc, 3, nullptr, 0, &claw, tiny, sizeof tiny),
            PLYFORM_LAW_INVALID_PARAMETER);
  EXPECT_EQ(std::string(tiny), "constan");
}

TEST(CApi, CurvesAndBadArguments) {
  const double x[] = {300, 500}, y[] = {0.5, 0.1};
  const plyform_law_curve curve{4, 2, x, y};
  const double uc[] = {1, 30, -4, kBlank, 300, 500, 1e-3};
  plyform_law* claw = nullptr;
  ASSERT_EQ(plyform_law_create(uc, 7, &curve, 1, &claw, nullptr, 0), PLYFORM_LAW_OK);
  plyform_law_history h;
  ASSERT_EQ(plyform_law_initial_history(claw, 0.0, &h), PLYFORM_LAW_OK);
  plyform_law_increment in{};
  plyform_law_response r;
  in.dt = 0.0;
  EXPECT_EQ(plyform_law_update_node(claw, &in, &h, &r), PLYFORM_LAW_INVALID_ARGUMENT);
  in.dt = 1e-3;
  h.state = 9;
  EXPECT_EQ(plyform_law_update_node(claw, &in, &h, &r), PLYFORM_LAW_INVALID_ARGUMENT);
  EXPECT_EQ(plyform_law_update_node(nullptr, &in, &h, &r), PLYFORM_LAW_INVALID_ARGUMENT);
  plyform_law_batch b{};
  b.n = 3;
  b.dt = 1e-3;
  EXPECT_EQ(plyform_law_update_batch(claw, &b), PLYFORM_LAW_INVALID_ARGUMENT);
  EXPECT_STREQ(plyform_law_state_name(2), "SEPARATING");
  EXPECT_STREQ(plyform_law_state_name(7), "UNKNOWN");
  plyform_law_destroy(claw);
}

}  // namespace
}  // namespace plyform::law
