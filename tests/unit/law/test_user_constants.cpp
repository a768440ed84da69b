// The *USER_INTERFACE_FRICTION constants: defaults, ranges, curve references, messages.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "plyform/law/law.hpp"
#include "plyform/law/user_constants.hpp"

namespace plyform::law {
namespace {

using Uc = std::vector<std::optional<double>>;

// MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA
Uc minimal() {
  return {1.0, 30.0, 0.3, 0.1, 300.0, 500.0, 1e-3};
}

TEST(UserConstants, TableIsNumberedInOrder) {
  const auto table = user_constant_table();
  ASSERT_EQ(table.size(), 24u);
  for (std::size_t i = 0; i < table.size(); ++i)
    EXPECT_EQ(table[i].index, int(i) + 1);
  EXPECT_STREQ(table[1].name, "CN");
  EXPECT_STREQ(table[19].name, "CT");
}

TEST(UserConstants, MissingTrailingConstantsTakeDefaults) {
  const auto r = from_user_constants(minimal(), {});
  ASSERT_TRUE(r.ok()) << r.errors.front().message;
  const Parameters& p = r.parameters;
  EXPECT_EQ(p.cn, 30.0);
  EXPECT_EQ(p.sigma_max.lo, 0.3);
  EXPECT_EQ(p.sigma_max.hi, 0.1);
  EXPECT_EQ(p.zeta.lo, 0.0);
  EXPECT_EQ(p.zeta.hi, 0.0);
  EXPECT_EQ(p.beta0, 1.0);
  EXPECT_EQ(p.bond_tol, 0.0);
  EXPECT_EQ(p.friction, FrictionModel::coulomb);
  EXPECT_EQ(p.beta_min, 1e-3);
  EXPECT_EQ(p.ct, 0.0);
  EXPECT_TRUE(std::isinf(p.release_gap));
}

TEST(UserConstants, BlankHiSlotTakesTheLoValue) {
  Uc uc = minimal();
  uc[3] = std::nullopt;  // SMAX_HI blank
  uc.resize(13);
  uc[12] = 0.4;  // MU_LO, MU_HI missing
  const auto r = from_user_constants(uc, {});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.parameters.sigma_max.hi, 0.3);
  EXPECT_EQ(r.parameters.mu.hi, 0.4);
}

struct BadCase {
  int index;  // 1-based
  double value;
  std::string expected;
};

class InvalidConstant : public ::testing::TestWithParam<BadCase> {};

TEST_P(InvalidConstant, IsRejectedWithItsNameValueAndRange) {
  const BadCase& c = GetParam();
  Uc uc = minimal();
  if (uc.size() < std::size_t(c.index))
    uc.resize(std::size_t(c.index));
  uc[std::size_t(c.index - 1)] = c.value;
  const auto r = from_user_constants(uc, {});
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].index, c.index);
  EXPECT_EQ(r.errors[0].message, c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    EveryRange, InvalidConstant,
    ::testing::Values(
        BadCase{1, 2.0, "constant UC1 MODEL = 2: expected the value 1"},
        BadCase{2, 0.0, "constant UC2 CN = 0: expected greater than 0"},
        BadCase{2, -5.0, "constant UC2 CN = -5: expected greater than 0"},
        BadCase{3, 0.0, "constant UC3 SMAX_LO = 0: expected greater than 0"},
        BadCase{4, 0.0, "constant UC4 SMAX_HI = 0: expected greater than 0"},
        BadCase{7, 0.0, "constant UC7 ETA = 0: expected greater than 0"},
        BadCase{8, -0.5,
                "constant UC8 ZETA_LO = -0.5: a negative value selects a load curve and "
                "must be -N, N a curve id"},
        BadCase{10, 1.5, "constant UC10 BETA0 = 1.5: expected from 0 to 1"},
        BadCase{11, -1.0, "constant UC11 BOND_TOL = -1: expected at least 0"},
        BadCase{12, 3.0, "constant UC12 FRIC = 3: expected a whole number from 0 to 1"},
        BadCase{12, 0.5, "constant UC12 FRIC = 0.5: expected a whole number from 0 to 1"},
        BadCase{17, -0.1, "constant UC17 FILM_H = -0.1: expected at least 0"},
        BadCase{18, 120.0, "constant UC18 VDC = 120: expected from 0 to 100"},
        BadCase{19, 0.0, "constant UC19 BETA_MIN = 0: expected greater than 0 and at most 1"},
        BadCase{20, -1.0, "constant UC20 CT = -1: expected at least 0"},
        BadCase{21, 2.0, "constant UC21 COUPLING = 2: expected a whole number from 0 to 1"},
        BadCase{22, -1.0, "constant UC22 DC = -1: expected at least 0"},
        BadCase{13, -3.0, "constant UC13 MU_LO = -3: refers to load curve 3, which is not defined"},
        BadCase{6, 200.0, "constant UC6 T_HI = 200: must not be below T_LO = 300"}));

TEST(UserConstants, RequiredConstantsAreNamedWhenMissing) {
  const Uc uc = {1.0};
  const auto r = from_user_constants(uc, {});
  ASSERT_EQ(r.errors.size(), 3u);
  EXPECT_EQ(r.errors[0].message,
            "constant UC2 CN is required (cohesive normal stiffness C_N, greater than 0) but was "
            "not given");
  EXPECT_EQ(r.errors[1].name, "SMAX_LO");
  EXPECT_EQ(r.errors[2].name, "ETA");
}

TEST(UserConstants, NonFiniteValuesAreRejected) {
  Uc uc = minimal();
  uc[1] = std::nan("");
  const auto r = from_user_constants(uc, {});
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].name, "CN");
}

TEST(UserConstants, TooManyConstants) {
  Uc uc = minimal();
  uc.resize(30, 0.0);
  const auto r = from_user_constants(uc, {});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors[0].message, "NOC = 30 constants given, the law has 24 (UC1 to UC24)");
}

TEST(UserConstants, EqualTransitionTemperaturesNeedEqualValues) {
  Uc uc = minimal();
  uc[5] = 300.0;  // T_HI = T_LO while SMAX differs
  const auto r = from_user_constants(uc, {});
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].name, "T_HI");
}

TEST(UserConstants, HydrodynamicNeedsAFilmThickness) {
  Uc uc = minimal();
  uc.resize(17);
  uc[11] = 1.0;   // FRIC
  uc[14] = 1e-3;  // VISC_LO
  const auto r = from_user_constants(uc, {});
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].message,
            "constant UC17 FILM_H = 0: must be greater than 0 when FRIC = 1 (hydrodynamic)");
}

TEST(UserConstants, NegativeSlotSelectsALoadCurve) {
  const std::vector<Curve> curves{Curve(5, {300.0, 500.0}, {0.5, 0.1}),
                                  Curve(9, {0.0, 1.0}, {1.0, 1.0})};
  Uc uc = minimal();
  uc[2] = -5.0;
  uc[3] = std::nullopt;
  const auto r = from_user_constants(uc, curves);
  ASSERT_TRUE(r.ok()) << r.errors.front().message;
  ASSERT_EQ(r.parameters.curves.size(), 1u);
  EXPECT_EQ(r.parameters.curves[0].id(), 5);
  EXPECT_EQ(r.parameters.sigma_max.curve, 0);
  EXPECT_DOUBLE_EQ(evaluate(r.parameters.sigma_max, r.parameters, 400.0), 0.3);

  uc[3] = 0.2;  // a plain value beside a curve is ambiguous
  const auto bad = from_user_constants(uc, curves);
  ASSERT_EQ(bad.errors.size(), 1u);
  EXPECT_EQ(bad.errors[0].name, "SMAX_HI");
}

TEST(UserConstants, UnusableCurveIsRejected) {
  const std::vector<Curve> curves{Curve(5, {300.0, 300.0}, {0.5, 0.1})};
  Uc uc = minimal();
  uc[2] = -5.0;
  uc[3] = std::nullopt;
  const auto r = from_user_constants(uc, curves);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(
      r.errors[0].message,
      "constant UC3 SMAX_LO = -5: load curve 5 is unusable: abscissae must increase strictly");
}

TEST(UserConstants, RoundTripThroughParameters) {
  Uc uc = minimal();
  uc.resize(24);
  uc[7] = 0.01;
  uc[12] = 0.3;
  uc[17] = 5.0;
  const auto r = from_user_constants(uc, {});
  ASSERT_TRUE(r.ok());
  const auto back = from_user_constants(to_user_constants(r.parameters), r.parameters.curves);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back.parameters.zeta.lo, 0.01);
  EXPECT_EQ(back.parameters.mu.hi, 0.3);
  EXPECT_EQ(back.parameters.vdc, 5.0);
  EXPECT_TRUE(validate(r.parameters).empty());
}

TEST(UserConstants, LawConstructorRejectsInvalidParameters) {
  Parameters p;  // CN, SMAX, ETA all zero
  try {
    Law law(p);
    FAIL() << "expected InvalidParameters";
  } catch (const InvalidParameters& e) {
    EXPECT_GE(e.errors().size(), 3u);
    EXPECT_NE(std::string(e.what()).find("UC2 CN"), std::string::npos);
  }
}

}  // namespace
}  // namespace plyform::law
