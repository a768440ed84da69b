// The heat transfer keywords: *CONTROL_SOLUTION, *CONTROL_THERMAL_SOLVER,
// *CONTROL_THERMAL_TIMESTEP, *MAT_THERMAL_ISOTROPIC/_ORTHOTROPIC, *BOUNDARY_CONVECTION_SET,
// *BOUNDARY_FLUX_SET, *BOUNDARY_RADIATION_SET, *DATABASE_TPRINT and *PART TMID. Each field
// lands in its own struct member (distinct values, so a transposition shows), blanks take
// LS-DYNA's defaults, and each value plyform rejects names its file, line, keyword and field.
#include <array>
#include <initializer_list>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, single_error, expect_error, ...

using model::HeatBoundaryKind;

/// One fixed-format card line: each value right-aligned in its 10 columns ("" leaves a field
/// blank).
std::string fixed(std::initializer_list<std::string_view> fields) {
  std::string line;
  for (std::string_view f : fields) {
    line += std::string(10 - f.size(), ' ');
    line += f;
  }
  return line + "\n";
}

// --- *CONTROL_SOLUTION

TEST(ControlSolution, EveryFieldFixedFormat) {
  const ReadResult r = read_ok(
      "*CONTROL_SOLUTION\n"
      "$#    soln       nlq     isnan     lcint     lcacc     ncdcf    nocopy      crvp\n" +
      fixed({"2", "16", "1", "250", "0", "1", "0", "2"}));
  ASSERT_TRUE(r.model.control_solution);
  const model::ControlSolutionDesc& s = *r.model.control_solution;
  EXPECT_EQ(s.soln, 2);
  EXPECT_EQ(s.nlq, 16);
  EXPECT_EQ(s.isnan, 1);
  EXPECT_EQ(s.lcint, 250);
  EXPECT_EQ(s.where.file, "deck.k");
  EXPECT_EQ(s.where.line, 3);
}

TEST(ControlSolution, BlanksTakeTheDefaultsAndTheLastOneWins) {
  const ReadResult r = read_ok("*CONTROL_SOLUTION\n0,7,1,300\n*CONTROL_SOLUTION\n1\n");
  ASSERT_TRUE(r.model.control_solution);
  const model::ControlSolutionDesc& s = *r.model.control_solution;
  EXPECT_EQ(s.soln, 1);
  EXPECT_EQ(s.nlq, 0);
  EXPECT_EQ(s.isnan, 0);
  EXPECT_EQ(s.lcint, 100);
  EXPECT_EQ(s.where.line, 4);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].keyword, "*CONTROL_SOLUTION");
  EXPECT_EQ(r.warnings[0].where.line, 3);
  EXPECT_TRUE(contains(r.warnings[0].message, "replaces the one at deck.k:2"))
      << r.warnings[0].message;
}

TEST(ControlSolution, Rejections) {
  constexpr std::string_view kKw = "*CONTROL_SOLUTION";
  expect_error("*CONTROL_SOLUTION\n3\n", 2, kKw, "SOLN", "must be one of 0, 1, 2");
  expect_error("*CONTROL_SOLUTION\n1,,2\n", 2, kKw, "ISNAN", "must be one of 0, 1");
  expect_error("*CONTROL_SOLUTION\n1,,,-5\n", 2, kKw, "LCINT", ">= 0");
  expect_error("*CONTROL_SOLUTION\n1,,,,1\n", 2, kKw, "LCACC", "truncating curve values");
  expect_error("*CONTROL_SOLUTION\n1,,,,,2\n", 2, kKw, "NCDCF", "*DEFINE_CURVE_FUNCTION");
  expect_error("*CONTROL_SOLUTION\n1,,,,,,1\n", 2, kKw, "NOCOPY", "memory option");
  expect_error("*CONTROL_SOLUTION\n1,,,,,,,3\n", 2, kKw, "CRVP", "must be one of 0, 1, 2");
  const Diagnostic d = single_error("*CONTROL_SOLUTION\n");
  EXPECT_EQ(d.keyword, kKw);
  EXPECT_TRUE(contains(d.message, "missing card 1")) << d.message;
}

// --- *CONTROL_THERMAL_SOLVER

TEST(ControlThermalSolver, EveryFieldOfTheThreeCards) {
  const ReadResult r = read_ok(
      "*CONTROL_THERMAL_SOLVER\n"
      "$#   atype     ptype    solver     cgtol       gpt    eqheat     fwork       sbc\n" +
      fixed({"1", "0", "12", "1e-5", "1", "4.184", "0.9", "5.67e-8"}) +
      "$#  msglvl    maxitr    abstol    reltol     omega                          tsf\n" +
      fixed({"2", "250", "1e-12", "1e-8", "0", "", "", "1000.0"}) +
      "$#   mxdmp      dtvf    varden                ncycl\n" + fixed({"0", "0.25", "0", "", "5"}));
  ASSERT_TRUE(r.model.thermal_solver);
  const model::ControlThermalSolverDesc& s = *r.model.thermal_solver;
  EXPECT_EQ(s.atype, 1);
  EXPECT_EQ(s.ptype, 0);
  EXPECT_EQ(s.solver, 12);
  EXPECT_EQ(s.gpt, 1);
  EXPECT_DOUBLE_EQ(s.eqheat, 4.184);
  EXPECT_DOUBLE_EQ(s.fwork, 0.9);
  EXPECT_DOUBLE_EQ(s.sbc, 5.67e-8);
  EXPECT_EQ(s.msglvl, 2);
  EXPECT_EQ(s.maxitr, 250);
  EXPECT_DOUBLE_EQ(s.abstol, 1e-12);
  EXPECT_DOUBLE_EQ(s.reltol, 1e-8);
  EXPECT_DOUBLE_EQ(s.omega, 0.0);
  EXPECT_DOUBLE_EQ(s.tsf, 1000.0);
  EXPECT_EQ(s.mxdmp, 0);
  EXPECT_DOUBLE_EQ(s.dtvf, 0.25);
  EXPECT_EQ(s.varden, 0);
  EXPECT_EQ(s.ncycl, 5);
  EXPECT_EQ(s.where.line, 3);
}

TEST(ControlThermalSolver, BlanksAndZerosTakeTheDefaults) {
  for (const char* deck : {"*CONTROL_THERMAL_SOLVER\n1\n", "*CONTROL_THERMAL_SOLVER\n1\n\n\n",
                           "*CONTROL_THERMAL_SOLVER\n1,0,,0\n0,0,0,0,0,,,0\n0,0,0,,0\n",
                           "*CONTROL_THERMAL_SOLVER\n1,0,0,0,0,0.0\n"}) {
    SCOPED_TRACE(deck);
    const ReadResult r = read_ok(deck);
    ASSERT_TRUE(r.model.thermal_solver);
    const model::ControlThermalSolverDesc& s = *r.model.thermal_solver;
    EXPECT_EQ(s.atype, 1);
    EXPECT_EQ(s.solver, 11);
    EXPECT_EQ(s.gpt, 8);
    EXPECT_DOUBLE_EQ(s.eqheat, 1.0);
    EXPECT_DOUBLE_EQ(s.fwork, 1.0);
    EXPECT_DOUBLE_EQ(s.sbc, 0.0);
    EXPECT_EQ(s.msglvl, 0);
    EXPECT_EQ(s.maxitr, 500);
    EXPECT_DOUBLE_EQ(s.abstol, 1e-10);
    EXPECT_DOUBLE_EQ(s.reltol, 1e-6);
    EXPECT_DOUBLE_EQ(s.tsf, 1.0);
    EXPECT_DOUBLE_EQ(s.dtvf, 0.0);
    EXPECT_EQ(s.ncycl, 1);
  }
}

TEST(ControlThermalSolver, NegativeTsfIsACurveKeptAsWrittenAndFworkZeroStays) {
  // Card 2 without card 3; FWORK 0 (no heat from the work) is a value, not the default.
  const ReadResult r = read_ok("*CONTROL_THERMAL_SOLVER\n0,0,11,,8,,0.0\n,,,,,,,-7\n");
  ASSERT_TRUE(r.model.thermal_solver);
  EXPECT_EQ(r.model.thermal_solver->atype, 0);
  EXPECT_DOUBLE_EQ(r.model.thermal_solver->fwork, 0.0);
  EXPECT_DOUBLE_EQ(r.model.thermal_solver->tsf, -7.0);
  EXPECT_EQ(r.model.thermal_solver->ncycl, 1);
}

TEST(ControlThermalSolver, Rejections) {
  constexpr std::string_view kKw = "*CONTROL_THERMAL_SOLVER";
  expect_error("*CONTROL_THERMAL_SOLVER\n2\n", 2, kKw, "ATYPE", "must be one of 0, 1");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,1\n", 2, kKw, "PTYPE", "nonlinear");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,2\n", 2, kKw, "PTYPE", "not supported yet");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,3\n", 2, kKw, "PTYPE", "[0, 2]");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,0,17\n", 2, kKw, "SOLVER", "17 (GMRES)");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,0,14\n", 2, kKw, "SOLVER", "13-16");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,0,19\n", 2, kKw, "SOLVER", "MUMPS");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,0,30\n", 2, kKw, "SOLVER", "nonsymmetric direct");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,0,3\n", 2, kKw, "SOLVER", "must be one of 0, 11, 12");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,0,11,,4\n", 2, kKw, "GPT", "must be one of 0, 8, 1");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,0,11,,8,-1.0\n", 2, kKw, "EQHEAT", ">= 0");
  expect_error("*CONTROL_THERMAL_SOLVER\n1,0,11,,8,1.0,1.5\n", 2, kKw, "FWORK", "[0, 1]");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n,-1\n", 3, kKw, "MAXITR", ">= 0");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n,,-1e-9\n", 3, kKw, "ABSTOL", ">= 0");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n,,,-1e-9\n", 3, kKw, "RELTOL", ">= 0");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n3\n", 3, kKw, "MSGLVL", "must be one of 0, 1, 2");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n0,0,0,0,1.2\n", 3, kKw, "OMEGA",
               "OMEGA = 1.2 (the relaxation of solvers 14 and 16) is not supported yet");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n0,0,0,0,0,5\n", 3, kKw, "UNUSED",
               "field 6 holds 5, but LS-DYNA does not use it");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n\n3\n", 4, kKw, "MXDMP", "dumps of the thermal matrix");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n\n0,0,1\n", 4, kKw, "VARDEN", "stays TRO");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n\n0,0,0,2\n", 4, kKw, "UNUSED", "field 4");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n\n0,0,0,,-2\n", 4, kKw, "NCYCL", ">= 0");
  expect_error("*CONTROL_THERMAL_SOLVER\n1\n\n\n1\n", 5, kKw, "", "no further cards");
}

// --- *CONTROL_THERMAL_TIMESTEP

TEST(ControlThermalTimestep, EveryFieldFixedFormat) {
  const ReadResult r = read_ok(
      "*CONTROL_THERMAL_TIMESTEP\n"
      "$#      ts       tip       its      tmin      tmax     dtemp      tscp      lcts\n" +
      fixed({"1", "0.75", "0.01", "0.002", "0.3", "5.0", "0.25", "0"}));
  ASSERT_TRUE(r.model.thermal_timestep);
  const model::ControlThermalTimestepDesc& t = *r.model.thermal_timestep;
  EXPECT_EQ(t.ts, 1);
  EXPECT_DOUBLE_EQ(t.tip, 0.75);
  EXPECT_DOUBLE_EQ(t.its, 0.01);
  EXPECT_DOUBLE_EQ(t.tmin, 0.002);
  EXPECT_DOUBLE_EQ(t.tmax, 0.3);
  EXPECT_DOUBLE_EQ(t.dtemp, 5.0);
  EXPECT_DOUBLE_EQ(t.tscp, 0.25);
  EXPECT_EQ(t.lcts, 0);
  EXPECT_EQ(t.where.line, 3);
}

TEST(ControlThermalTimestep, BlanksAndZerosTakeTheDefaults) {
  for (const char* deck :
       {"*CONTROL_THERMAL_TIMESTEP\n,,0.1\n", "*CONTROL_THERMAL_TIMESTEP\n0,0,0.1,0,0,0,0,0\n"}) {
    SCOPED_TRACE(deck);
    const ReadResult r = read_ok(deck);
    ASSERT_TRUE(r.model.thermal_timestep);
    const model::ControlThermalTimestepDesc& t = *r.model.thermal_timestep;
    EXPECT_EQ(t.ts, 0);
    EXPECT_DOUBLE_EQ(t.tip, 0.5);
    EXPECT_DOUBLE_EQ(t.its, 0.1);
    EXPECT_DOUBLE_EQ(t.tmin, 0.0);
    EXPECT_DOUBLE_EQ(t.tmax, 0.0);
    EXPECT_DOUBLE_EQ(t.dtemp, 1.0);
    EXPECT_DOUBLE_EQ(t.tscp, 0.5);
  }
  const ReadResult r = read_ok("*CONTROL_THERMAL_TIMESTEP\n0,1.0,0.1\n");
  EXPECT_DOUBLE_EQ(r.model.thermal_timestep->tip, 1.0);  // backward Euler is allowed
}

TEST(ControlThermalTimestep, Rejections) {
  constexpr std::string_view kKw = "*CONTROL_THERMAL_TIMESTEP";
  expect_error("*CONTROL_THERMAL_TIMESTEP\n2\n", 2, kKw, "TS", "must be one of 0, 1");
  expect_error("*CONTROL_THERMAL_TIMESTEP\n0,0.4,0.1\n", 2, kKw, "TIP",
               "TIP = 0.4 is below 0.5: the implicit step is not unconditionally stable");
  expect_error("*CONTROL_THERMAL_TIMESTEP\n0,1.5,0.1\n", 2, kKw, "TIP", "[0, 1]");
  expect_error("*CONTROL_THERMAL_TIMESTEP\n0,0.5,-0.1\n", 2, kKw, "ITS", ">= 0");
  expect_error("*CONTROL_THERMAL_TIMESTEP\n1,0.5,0.1,-3\n", 2, kKw, "TMIN",
               "TMIN = -3 (the smallest step against time, curve 3) is not supported yet");
  expect_error("*CONTROL_THERMAL_TIMESTEP\n1,0.5,0.1,0,-4\n", 2, kKw, "TMAX", "curve 4");
  expect_error("*CONTROL_THERMAL_TIMESTEP\n1,0.5,0.1,0,0,-2\n", 2, kKw, "DTEMP", "curve 2");
  expect_error("*CONTROL_THERMAL_TIMESTEP\n1,0.5,0.1,0,0,1,1.0\n", 2, kKw, "TSCP", "[0, 1)");
  expect_error("*CONTROL_THERMAL_TIMESTEP\n1,0.5,0.1,0,0,1,0.5,6\n", 2, kKw, "LCTS",
               "a curve of the thermal step");
}

// --- *MAT_THERMAL_ISOTROPIC

TEST(MatThermalIsotropic, EveryFieldWithTitle) {
  const ReadResult r = read_ok(
      "*MAT_THERMAL_ISOTROPIC_TITLE\n"
      "tool steel\n"
      "$#    tmid       tro     tgrlc    tgmult      tlat      hlat\n" +
      fixed({"7", "7850.0", "3", "2.5", "1700.0", "0.0"}) + "$#      hc        tc\n" +
      fixed({"460.0", "45.0"}) + "*MAT_THERMAL_ISOTROPIC\n8,,,,\n500,0\n");
  const auto& m = r.model.thermal_materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].id, 7);
  EXPECT_FALSE(m[0].orthotropic);
  EXPECT_DOUBLE_EQ(m[0].density, 7850.0);
  EXPECT_EQ(m[0].tgrlc, 3);
  EXPECT_DOUBLE_EQ(m[0].tgmult, 2.5);
  EXPECT_DOUBLE_EQ(m[0].tlat, 1700.0);
  EXPECT_DOUBLE_EQ(m[0].hlat, 0.0);
  EXPECT_DOUBLE_EQ(m[0].heat_capacity, 460.0);
  EXPECT_EQ(m[0].conductivity, (std::array<double, 3>{45.0, 45.0, 45.0}));
  EXPECT_EQ(m[0].aopt, 0);
  EXPECT_EQ(m[0].where.line, 4);
  // Blanks: TRO 0 (the structural density), no generation.
  EXPECT_EQ(m[1].id, 8);
  EXPECT_DOUBLE_EQ(m[1].density, 0.0);
  EXPECT_EQ(m[1].tgrlc, 0);
  EXPECT_DOUBLE_EQ(m[1].tgmult, 0.0);
  EXPECT_DOUBLE_EQ(m[1].heat_capacity, 500.0);
  EXPECT_EQ(m[1].conductivity, (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_EQ(m[1].where.line, 8);
}

// Decks written by other tools put TGRLC as a real: LS-DYNA reads 0.0 as 0 (no curve).
TEST(MatThermalIsotropic, TgrlcWrittenAsARealIsItsInteger) {
  const ReadResult r =
      read_ok("*MAT_THERMAL_ISOTROPIC\n" + fixed({"1", "7850.0", "0.0", "0.0", "0.0", "0.0"}) +
              fixed({"460.0", "45.0"}) + "*MAT_THERMAL_ISOTROPIC\n2,0.,3.,1.5\n500,50\n");
  const auto& m = r.model.thermal_materials;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].tgrlc, 0);
  EXPECT_EQ(m[1].tgrlc, 3);
  EXPECT_DOUBLE_EQ(m[1].tgmult, 1.5);
  expect_error("*MAT_THERMAL_ISOTROPIC\n1,0,0.5\n500,50\n", 2, "*MAT_THERMAL_ISOTROPIC", "TGRLC",
               "expected an integer, got '0.5', which is not a whole number");
}

TEST(MatThermalIsotropic, Rejections) {
  constexpr std::string_view kKw = "*MAT_THERMAL_ISOTROPIC";
  expect_error("*MAT_THERMAL_ISOTROPIC\n,7800\n500,50\n", 2, kKw, "TMID", "required");
  expect_error("*MAT_THERMAL_ISOTROPIC\n0,7800\n500,50\n", 2, kKw, "TMID", ">= 1");
  expect_error("*MAT_THERMAL_ISOTROPIC\n1,-1\n500,50\n", 2, kKw, "TRO", ">= 0");
  expect_error("*MAT_THERMAL_ISOTROPIC\n1,0,-2\n500,50\n", 2, kKw, "TGRLC",
               "TGRLC = -2 (the heat generation rate against temperature, curve 2) is not "
               "supported yet");
  expect_error("*MAT_THERMAL_ISOTROPIC\n1,0,0,0,1700,2.7e5\n500,50\n", 2, kKw, "HLAT",
               "latent heat");
  expect_error("*MAT_THERMAL_ISOTROPIC\n1\n0,50\n", 3, kKw, "HC", "HC must be > 0");
  expect_error("*MAT_THERMAL_ISOTROPIC\n1\n,50\n", 3, kKw, "HC", "required");
  expect_error("*MAT_THERMAL_ISOTROPIC\n1\n500,-50\n", 3, kKw, "TC", ">= 0");
  expect_error("*MAT_THERMAL_ISOTROPIC\n1\n", 2, kKw, "", "missing card 2 (HC TC)");
}

// --- *MAT_THERMAL_ORTHOTROPIC

TEST(MatThermalOrthotropic, EveryFieldWithTitle) {
  const ReadResult r = read_ok(
      "*MAT_THERMAL_ORTHOTROPIC_TITLE\n"
      "laminate\n"
      "$#    tmid       tro     tgrlc    tgmult      aopt      tlat      hlat\n" +
      fixed({"4", "1600.0", "9", "3.5", "2.0", "450.0", "0.0"}) +
      "$#      hc        k1        k2        k3\n" + fixed({"1200.0", "5.0", "0.6", "0.7"}) +
      "$#      xp        yp        zp        a1        a2        a3\n" +
      fixed({"1.5", "2.5", "3.5", "1.0", "1.0", "0.0"}) + "$#      d1        d2        d3\n" +
      fixed({"-1.0", "1.0", "0.5"}));
  const auto& m = r.model.thermal_materials;
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].id, 4);
  EXPECT_TRUE(m[0].orthotropic);
  EXPECT_DOUBLE_EQ(m[0].density, 1600.0);
  EXPECT_EQ(m[0].tgrlc, 9);
  EXPECT_DOUBLE_EQ(m[0].tgmult, 3.5);
  EXPECT_EQ(m[0].aopt, 2);
  EXPECT_DOUBLE_EQ(m[0].tlat, 450.0);
  EXPECT_DOUBLE_EQ(m[0].hlat, 0.0);
  EXPECT_DOUBLE_EQ(m[0].heat_capacity, 1200.0);
  EXPECT_EQ(m[0].conductivity, (std::array<double, 3>{5.0, 0.6, 0.7}));
  EXPECT_EQ(m[0].p, (std::array<double, 3>{1.5, 2.5, 3.5}));
  EXPECT_EQ(m[0].a, (std::array<double, 3>{1.0, 1.0, 0.0}));
  EXPECT_EQ(m[0].d, (std::array<double, 3>{-1.0, 1.0, 0.5}));
  EXPECT_EQ(m[0].where.line, 4);
}

TEST(MatThermalOrthotropic, AxesFromTheElementNeedNoVectorCards) {
  const ReadResult r = read_ok("*MAT_THERMAL_ORTHOTROPIC\n5\n900,1,2,3\n");
  const auto& m = r.model.thermal_materials;
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].aopt, 0);
  EXPECT_EQ(m[0].conductivity, (std::array<double, 3>{1.0, 2.0, 3.0}));
  EXPECT_EQ(m[0].a, (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_EQ(m[0].d, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

TEST(MatThermalOrthotropic, Rejections) {
  constexpr std::string_view kKw = "*MAT_THERMAL_ORTHOTROPIC";
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1,0,0,0,1\n900,1,2,3\n", 2, kKw, "AOPT",
               "AOPT 1 (axes from a point P)");
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1,0,0,0,3\n900,1,2,3\n", 2, kKw, "AOPT",
               "must be one of 0, 2");
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1,0,0,0,0,0,5e4\n900,1,2,3\n", 2, kKw, "HLAT",
               "latent heat");
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1,0,-4\n900,1,2,3\n", 2, kKw, "TGRLC", "curve 4");
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1\n900,1,-2,3\n", 3, kKw, "K2", ">= 0");
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1\n0,1,2,3\n", 3, kKw, "HC", "must be > 0");
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1\n", 2, kKw, "", "missing card 2 (HC K1 K2 K3)");
  // AOPT 2: A on card 3, D on card 4.
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1,0,0,0,2\n900,1,2,3\n0,0,0,0,0,0\n0,1,0\n", 4, kKw, "A1",
               "non-zero vector A");
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1,0,0,0,2\n900,1,2,3\n0,0,0,1,0,0\n2,0,0\n", 5, kKw, "D1",
               "not parallel to A");
  expect_error("*MAT_THERMAL_ORTHOTROPIC\n1,0,0,0,2\n900,1,2,3\n0,0,0,1,0,0\n", 4, kKw, "D1",
               "non-zero");
}

// --- *BOUNDARY_CONVECTION_SET

TEST(BoundaryConvectionSet, PairsOfCardsWithEveryField) {
  const ReadResult r = read_ok(
      "*BOUNDARY_CONVECTION_SET\n"
      "$#    ssid    pserod\n" +
      fixed({"3", "0"}) + "$#   hlcid     hmult     tlcid     tmult       loc\n" +
      fixed({"11", "25.0", "12", "293.0", "0"}) + "4\n" + "\n");
  const auto& b = r.model.heat_boundaries;
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].kind, HeatBoundaryKind::kConvection);
  EXPECT_EQ(b[0].segment_set_id, 3);
  EXPECT_EQ(b[0].pserod, 0);
  EXPECT_EQ(b[0].curve_id, 11);
  EXPECT_DOUBLE_EQ(b[0].mult, 25.0);
  EXPECT_EQ(b[0].ambient_curve_id, 12);
  EXPECT_DOUBLE_EQ(b[0].ambient_mult, 293.0);
  EXPECT_EQ(b[0].loc, 0);
  EXPECT_EQ(b[0].where.line, 5);
  // A blank card 2: constant h and ambient temperature, both 1.
  EXPECT_EQ(b[1].segment_set_id, 4);
  EXPECT_EQ(b[1].curve_id, 0);
  EXPECT_DOUBLE_EQ(b[1].mult, 1.0);
  EXPECT_EQ(b[1].ambient_curve_id, 0);
  EXPECT_DOUBLE_EQ(b[1].ambient_mult, 1.0);
  EXPECT_EQ(b[1].where.line, 7);
}

TEST(BoundaryConvectionSet, Rejections) {
  constexpr std::string_view kKw = "*BOUNDARY_CONVECTION_SET";
  expect_error("*BOUNDARY_CONVECTION_SET\n,0\n0,10,0,300\n", 2, kKw, "SSID", "required");
  expect_error("*BOUNDARY_CONVECTION_SET\n0\n0,10,0,300\n", 2, kKw, "SSID", ">= 1");
  expect_error("*BOUNDARY_CONVECTION_SET\n1,2\n0,10,0,300\n", 2, kKw, "PSEROD", "erode");
  expect_error("*BOUNDARY_CONVECTION_SET\n1\n-3,10,0,300\n", 3, kKw, "HLCID",
               "HLCID = -3 (h against temperature, curve 3) is not supported yet");
  expect_error("*BOUNDARY_CONVECTION_SET\n1\n0,10,-1,300\n", 3, kKw, "TLCID", ">= 0");
  expect_error("*BOUNDARY_CONVECTION_SET\n1\n0,10,0,300,2\n", 3, kKw, "LOC", "-1, 0, 1");
  expect_error("*BOUNDARY_CONVECTION_SET\n1\n0,10,0,300\n2\n", 4, kKw, "",
               "missing card 2 (HLCID HMULT TLCID TMULT LOC)");
  expect_error("*BOUNDARY_CONVECTION_SET\n", 1, kKw, "", "missing card 1");
}

// --- *BOUNDARY_FLUX_SET

TEST(BoundaryFluxSet, EveryFieldAndBlanks) {
  const ReadResult r = read_ok(
      "*BOUNDARY_FLUX_SET\n"
      "$#    ssid    pserod\n" +
      fixed({"6", "0"}) +
      "$#    lcid      mlc1      mlc2      mlc3      mlc4       loc     nhisv\n" +
      fixed({"21", "1.5", "2.5", "3.5", "4.5", "0", "0"}) + "7\n\n");
  const auto& b = r.model.heat_boundaries;
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].kind, HeatBoundaryKind::kFlux);
  EXPECT_EQ(b[0].segment_set_id, 6);
  EXPECT_EQ(b[0].curve_id, 21);
  EXPECT_EQ(b[0].node_mult, (std::array<double, 4>{1.5, 2.5, 3.5, 4.5}));
  EXPECT_EQ(b[0].loc, 0);
  EXPECT_EQ(b[0].nhisv, 0);
  EXPECT_EQ(b[0].where.line, 5);
  EXPECT_EQ(b[1].segment_set_id, 7);
  EXPECT_EQ(b[1].curve_id, 0);
  EXPECT_EQ(b[1].node_mult, (std::array<double, 4>{1.0, 1.0, 1.0, 1.0}));
}

TEST(BoundaryFluxSet, Rejections) {
  constexpr std::string_view kKw = "*BOUNDARY_FLUX_SET";
  expect_error("*BOUNDARY_FLUX_SET\n1\n-2,1,1,1,1\n", 3, kKw, "LCID",
               "LCID = -2 (the flux against temperature, curve 2) is not supported yet");
  expect_error("*BOUNDARY_FLUX_SET\n1\n0,1,1,1,1,0,2\n", 3, kKw, "NHISV", "user flux subroutine");
  expect_error("*BOUNDARY_FLUX_SET\n1\n0,1,1,1,1,-2\n", 3, kKw, "LOC", "-1, 0, 1");
  expect_error("*BOUNDARY_FLUX_SET\n1\n0,1,1,1,1,0,0,9\n", 3, kKw, "UNUSED", "field 8");
  expect_error("*BOUNDARY_FLUX_SET\n1,3\n0\n", 2, kKw, "PSEROD", "erode");
}

// --- *BOUNDARY_RADIATION_SET

TEST(BoundaryRadiationSet, EveryFieldAndBlanks) {
  const ReadResult r = read_ok(
      "*BOUNDARY_RADIATION_SET\n"
      "$#    ssid      type                                               pserod\n" +
      fixed({"9", "1", "", "", "", "", "0"}) +
      "$#  rflcid    rfmult    tilcid    timult       loc\n" +
      fixed({"31", "4.5e-8", "32", "300.0", "0"}) + "10\n\n");
  const auto& b = r.model.heat_boundaries;
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].kind, HeatBoundaryKind::kRadiation);
  EXPECT_EQ(b[0].segment_set_id, 9);
  EXPECT_EQ(b[0].type, 1);
  EXPECT_EQ(b[0].pserod, 0);
  EXPECT_EQ(b[0].curve_id, 31);
  EXPECT_DOUBLE_EQ(b[0].mult, 4.5e-8);
  EXPECT_EQ(b[0].ambient_curve_id, 32);
  EXPECT_DOUBLE_EQ(b[0].ambient_mult, 300.0);
  EXPECT_EQ(b[0].where.line, 5);
  EXPECT_EQ(b[1].segment_set_id, 10);
  EXPECT_EQ(b[1].type, 1);
  EXPECT_EQ(b[1].curve_id, 0);
  EXPECT_DOUBLE_EQ(b[1].mult, 1.0);
  EXPECT_EQ(b[1].ambient_curve_id, 0);
  EXPECT_DOUBLE_EQ(b[1].ambient_mult, 1.0);
}

TEST(BoundaryRadiationSet, Rejections) {
  constexpr std::string_view kKw = "*BOUNDARY_RADIATION_SET";
  expect_error("*BOUNDARY_RADIATION_SET\n1,2\n0,1e-8,0,300\n", 2, kKw, "TYPE",
               "radiation in an enclosure");
  expect_error("*BOUNDARY_RADIATION_SET\n1,1,5\n0,1e-8,0,300\n", 2, kKw, "UNUSED", "field 3");
  expect_error("*BOUNDARY_RADIATION_SET\n1,1,,,,,4\n0,1e-8,0,300\n", 2, kKw, "PSEROD", "erode");
  expect_error("*BOUNDARY_RADIATION_SET\n1\n-4,1e-8,0,300\n", 3, kKw, "RFLCID",
               "RFLCID = -4 (f against temperature, curve 4) is not supported yet");
  expect_error("*BOUNDARY_RADIATION_SET\n1\n0,1e-8,-2,300\n", 3, kKw, "TILCID", ">= 0");
  expect_error("*BOUNDARY_RADIATION_SET\n1\n0,1e-8,0,300,2\n", 3, kKw, "LOC", "-1, 0, 1");
}

// --- *DATABASE_TPRINT

TEST(DatabaseTprint, EveryFieldDefaultsAndTheLastOneWins) {
  ReadResult r = read_ok("*DATABASE_TPRINT\n" + fixed({"2.5e-3", "1", "0", "2"}));
  ASSERT_TRUE(r.model.tprint);
  EXPECT_DOUBLE_EQ(r.model.tprint->dt, 2.5e-3);
  EXPECT_EQ(r.model.tprint->binary, 1);
  EXPECT_EQ(r.model.tprint->lcur, 0);
  EXPECT_EQ(r.model.tprint->ioopt, 2);
  EXPECT_EQ(r.model.tprint->where.line, 2);
  EXPECT_TRUE(r.model.ascii_outputs.empty());  // not one of the ASCII outputs

  r = read_ok("*DATABASE_TPRINT\n1e-3\n*DATABASE_TPRINT\n2e-3\n");
  ASSERT_TRUE(r.model.tprint);
  EXPECT_DOUBLE_EQ(r.model.tprint->dt, 2e-3);
  EXPECT_EQ(r.model.tprint->binary, 0);
  EXPECT_EQ(r.model.tprint->ioopt, 1);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0].message, "replaces the one at deck.k:2"))
      << r.warnings[0].message;
}

TEST(DatabaseTprint, Rejections) {
  expect_error("*DATABASE_TPRINT\n1e-3,0,4\n", 2, "*DATABASE_TPRINT", "LCUR",
               "a curve of the output interval");
  expect_error("*DATABASE_TPRINT\n-1e-3\n", 2, "*DATABASE_TPRINT", "DT", ">= 0");
}

// --- *PART TMID

TEST(PartThermalMaterial, TmidIsKept) {
  const ReadResult r = read_ok("*PART\nblank\n1,2,3,0,0,0,0,4\n*PART\ndie\n2,2,3\n");
  ASSERT_EQ(r.model.parts.size(), 2u);
  EXPECT_EQ(r.model.parts[0].thermal_material_id, 4);
  EXPECT_EQ(r.model.parts[1].thermal_material_id, 0);  // no heat conduction in the die
  expect_error("*PART\np\n1,1,1,0,0,0,0,-1\n", 3, "*PART", "TMID", ">= 0");
}

// --- *CONTACT_..._THERMAL: the thermal card after card 3
TEST(ContactThermal, TheThermalCardLandsInItsFields) {
  const ReadResult r = read_ok(
      "*CONTACT_SURFACE_TO_SURFACE_THERMAL_ID\n5,lap\n2,1,3,3\n0.2,0.1\n1,1\n"
      "40.0,1e-8,5000.0,0.01,0.5,0.7,0,1\n*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_THERMAL\n"
      "3,4,3,3\n\n\n0,0,-9,0,0.1\n");
  ASSERT_EQ(r.model.contacts.size(), 2u);
  const model::ContactDesc& c = r.model.contacts[0];
  EXPECT_TRUE(c.thermal);
  EXPECT_EQ(c.id, 5);
  EXPECT_DOUBLE_EQ(c.fs, 0.2);
  EXPECT_DOUBLE_EQ(c.k, 40.0);
  EXPECT_DOUBLE_EQ(c.frad, 1e-8);
  EXPECT_DOUBLE_EQ(c.h0, 5000.0);
  EXPECT_DOUBLE_EQ(c.lmin, 0.01);
  EXPECT_DOUBLE_EQ(c.lmax, 0.5);
  EXPECT_DOUBLE_EQ(c.ftosa, 0.7);
  EXPECT_EQ(c.algo, 1);
  const model::ContactDesc& d = r.model.contacts[1];
  EXPECT_TRUE(d.thermal);
  EXPECT_DOUBLE_EQ(d.h0, -9.0);  // a curve of the conductance against pressure
  EXPECT_DOUBLE_EQ(d.ftosa, 0.5);
  EXPECT_EQ(d.algo, 0);
}

TEST(ContactThermal, Rejections) {
  constexpr std::string_view kKw = "*CONTACT_SURFACE_TO_SURFACE_THERMAL";
  expect_error("*CONTACT_SURFACE_TO_SURFACE_THERMAL\n2,1,3,3\n\n\n0,0,1,0.5,0.1\n", 5, kKw, "LMAX",
               "below LMIN");
  expect_error("*CONTACT_SURFACE_TO_SURFACE_THERMAL\n2,1,3,3\n\n\n0,0,1,0,0.1,0.5,2\n", 5, kKw,
               "BC_FLG", "one of 0, 1");
  expect_error("*CONTACT_SURFACE_TO_SURFACE_THERMAL\n2,1,3,3\n\n\n0,0,1,0,0.1,0.5,0,2\n", 5, kKw,
               "ALGO", "0 or 1");
  expect_error("*CONTACT_SURFACE_TO_SURFACE_THERMAL\n2,1,3,3\n\n\n-3\n", 5, kKw, "K", ">= 0");
}

}  // namespace
}  // namespace plyform::keyword
