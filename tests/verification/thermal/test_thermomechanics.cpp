// Temperature-dependent mechanics against closed forms: free thermal expansion with a
// coefficient that varies with temperature (the length grows by exp(integral of alpha dT)),
// fully restrained expansion (sigma = -3 K integral alpha dT in a solid, -E/(1 - nu) of it in a
// shell plane), *MAT_ELASTIC_PLASTIC_THERMAL in uniaxial tension at two temperatures (the
// bilinear curve of the constants interpolated in its table), the heat of plastic work
// (adiabatic: the temperature rise FWORK sigma_y eps_p / (rho c)), and the stop when a
// temperature leaves the *MAT_004 table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"
#include "thermal_decks.hpp"

namespace plyform {
namespace test_thermomechanics {

constexpr double kYoung = 2.0e11, kPoisson = 0.3;
constexpr double kSide = 0.01, kShellThickness = 0.001;

core::Model build(const std::string& text) {
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("thermomechanics.k", text));
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().to_string());
  const auto problems = setup::validate(read.model);
  EXPECT_TRUE(problems.empty()) << problems.front().to_string();
  auto built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  return *built.model;
}

enum class Body { hex_one_point, hex_selective, shell };

const char* body_name(Body b) {
  return b == Body::hex_one_point   ? "hex_elform1"
         : b == Body::hex_selective ? "hex_elform2"
                                    : "shell";
}

// One element: a cube of side kSide (nodes 4 i + 2 j + k + 1 at (i, j, k) kSide), ELFORM 1 or 2,
// or a square shell of thickness kShellThickness (nodes 2 i + j + 1 at (i, j) kSide). Set 3:
// every node.
std::string element(Body b) {
  std::string deck;
  if (b == Body::shell) {
    deck = test::shell_strip(1, kSide, kSide, kShellThickness);
    deck += "*SET_NODE_LIST\n3\n1,2,3,4\n";
  } else {
    deck = test::hex_strip(1, kSide, kSide);
    if (b == Body::hex_selective) {
      const std::string one = "*SECTION_SOLID\n1,1\n";
      deck.replace(deck.find(one), one.size(), "*SECTION_SOLID\n1,2\n");
    }
    deck += "*SET_NODE_LIST\n3\n1,2,3,4,5,6,7,8\n";
  }
  return deck;
}

std::string header(double end_time, double state_dt) {
  std::ostringstream os;
  os.precision(12);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << "\n";
  os << "*DATABASE_BINARY_D3PLOT\n" << state_dt << "\n*DATABASE_GLSTAT\n" << state_dt << "\n";
  os << "*MAT_THERMAL_ISOTROPIC\n1,0.0\n"
     << test::kHeatCapacity << "," << test::kConductivity << "\n";
  return os.str();
}

// --- Thermal expansion --------------------------------------------------------------------

// alpha(T) = 1e-5 + 2e-8 T (1/K), heated from 20 to 520 K over the run: the thermal strain
// integral alpha dT = 1e-5 * 500 + 1e-8 (520^2 - 20^2).
constexpr double kT0 = 20.0, kT1 = 520.0;
const double kThermalStrain = 1e-5 * (kT1 - kT0) + 1e-8 * (kT1 * kT1 - kT0 * kT0);

std::string expansion_deck(Body b, bool restrained, double end_time) {
  std::ostringstream os;
  os.precision(12);
  os << header(end_time, end_time / 4);
  os << "*MAT_ELASTIC\n1," << test::kRho << "," << kYoung << "," << kPoisson << "\n";
  os << "*MAT_ADD_THERMAL_EXPANSION\n1,9\n*DEFINE_CURVE\n9\n0,1e-5\n1000,3e-5\n";
  os << element(b);
  os << "*DEFINE_CURVE\n8\n0," << kT0 << "\n" << end_time << "," << kT1 << "\n";
  os << "*BOUNDARY_TEMPERATURE_SET\n3,8,1.0\n*INITIAL_TEMPERATURE_SET\n0," << kT0 << "\n";
  if (restrained) {
    os << "*BOUNDARY_SPC_SET\n3,0,1,1,1,0,0,0\n";
  } else if (b == Body::shell) {
    // Statically determinate: node 1 held, node 3 (x = a) on the x axis, every node in the plane.
    os << "*BOUNDARY_SPC_NODE\n1,0,1,1,1\n3,0,0,1,1\n2,0,1,0,1\n4,0,0,0,1\n";
  } else {
    os << "*BOUNDARY_SPC_NODE\n1,0,1,1,1\n2,0,1,1,0\n3,0,1,0,1\n5,0,0,1,1\n";
  }
  return os.str() + "*END\n";
}

class ThermalExpansion : public ::testing::TestWithParam<Body> {};

TEST_P(ThermalExpansion, AFreeBodyGrowsByTheIntegralOfAlphaWithoutStress) {
  const Body b = GetParam();
  const double end_time = 0.01;  // 2500 wave transits: quasi-static
  const core::Model m = build(expansion_deck(b, false, end_time));
  test::RecordingSink sink;
  double ux = 0.0, uz = 0.0, stress = 0.0, thickness = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    // The far corner: node 4 i + 2 j + k + 1 = 8 (hexahedron), 2 i + j + 1 = 4 (shell).
    const std::size_t far = b == Body::shell ? 3 : 7;
    ux = s.nodes->ux[far];
    uz = s.nodes->uz[far];
    stress = 0.0;
    if (b == Body::shell) {
      const element::ShellBlockState& st = s.shells->front();
      for (const auto& c : st.s)
        for (double v : c)
          stress = std::max(stress, std::abs(v));
      thickness = st.thickness.front();
    } else {
      for (const auto& c : s.solids->front().s)
        for (double v : c)
          stress = std::max(stress, std::abs(v));
    }
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  // The tangent coefficient: d ln L = alpha dT, so L = L0 exp(integral).
  const double growth = std::exp(kThermalStrain) - 1.0;
  EXPECT_NEAR(ux, kSide * growth, 2e-3 * kSide * growth) << body_name(b);
  if (b == Body::shell) {
    EXPECT_NEAR(thickness, kShellThickness * (1.0 + growth), 2e-3 * kShellThickness * growth);
  } else {
    EXPECT_NEAR(uz, kSide * growth, 2e-3 * kSide * growth);
  }
  // Against the restrained stress scale E alpha dT, what is left is the dynamics' noise.
  EXPECT_LT(stress, 2e-3 * kYoung * kThermalStrain) << body_name(b);
}

TEST_P(ThermalExpansion, ARestrainedBodyCarriesTheClosedFormThermalStress) {
  const Body b = GetParam();
  const double end_time = 0.002;
  const core::Model m = build(expansion_deck(b, true, end_time));
  test::RecordingSink sink;
  double sxx = 0.0, syy = 0.0, szz = 0.0, thickness = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    if (b == Body::shell) {
      const element::ShellBlockState& st = s.shells->front();
      sxx = st.s[0].front(), syy = st.s[1].front(), szz = 0.0;
      thickness = st.thickness.front();
    } else {
      const element::SolidBlockState& st = s.solids->front();
      sxx = st.s[0].front(), syy = st.s[1].front(), szz = st.s[2].front();
    }
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  if (b == Body::shell) {
    // Plane stress: sigma = -E/(1 - nu) eps_th in the plane; the free thickness strain
    // (1 + nu)/(1 - nu) eps_th (thermal plus the Poisson part of the in-plane stress).
    const double expected = -kYoung / (1.0 - kPoisson) * kThermalStrain;
    EXPECT_NEAR(sxx, expected, 1e-4 * std::abs(expected));
    EXPECT_NEAR(syy, expected, 1e-4 * std::abs(expected));
    // (a true strain: the thickness grows by its exponential).
    const double tz = std::exp((1.0 + kPoisson) / (1.0 - kPoisson) * kThermalStrain) - 1.0;
    EXPECT_NEAR(thickness / kShellThickness - 1.0, tz, 1e-4 * tz);
  } else {
    const double expected = -kYoung / (1.0 - 2.0 * kPoisson) * kThermalStrain;  // -3 K eps_th
    for (double s : {sxx, syy, szz})
      EXPECT_NEAR(s, expected, 1e-6 * std::abs(expected)) << body_name(b);
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, ThermalExpansion,
                         ::testing::Values(Body::hex_one_point, Body::hex_selective, Body::shell),
                         [](const auto& p) { return std::string(body_name(p.param)); });

// --- Uniaxial tension: *MAT_ELASTIC_PLASTIC_THERMAL and the heat of plastic work ----------

// The *MAT_004 table: E, SIGY and ETAN fall with temperature; no expansion.
constexpr double kTableT[3] = {20.0, 300.0, 600.0};
constexpr double kTableE[3] = {2.0e11, 1.8e11, 1.2e11};
constexpr double kTableSigy[3] = {3.0e8, 2.0e8, 0.8e8};
constexpr double kTableEtan[3] = {2.0e9, 1.0e9, 0.5e9};

std::string mat004() {
  std::ostringstream os;
  os.precision(12);
  os << "*MAT_ELASTIC_PLASTIC_THERMAL\n1," << test::kRho << "\n";
  const auto row = [&](const double* v) { os << v[0] << "," << v[1] << "," << v[2] << "\n"; };
  row(kTableT);
  row(kTableE);
  os << "0.3,0.3,0.3\n0,0,0\n";
  row(kTableSigy);
  row(kTableEtan);
  return os.str();
}

// Uniaxial stress: the x = 0 face held in x, the y = 0 and z = 0 faces in y and z (symmetry),
// the x = a face pulled at a velocity that ramps up over the first tenth of the run to a
// true strain of about 3 %.
std::string tension_deck(Body b, const std::string& material, double end_time,
                         const std::string& extra) {
  std::ostringstream os;
  os.precision(12);
  os << header(end_time, end_time / 40) << material << element(b);
  const double v = 0.03 * kSide / (0.95 * end_time);
  os << "*DEFINE_CURVE\n7\n0,0\n"
     << 0.1 * end_time << "," << v << "\n"
     << end_time << "," << v << "\n";
  os << "*BOUNDARY_PRESCRIBED_MOTION_SET\n2,1,0,7,1.0\n";
  if (b == Body::shell) {
    os << "*BOUNDARY_SPC_SET\n1,0,1,0,1,0,0,0\n*BOUNDARY_SPC_NODE\n1,0,0,1,0\n3,0,0,1,0\n";
    os << "*BOUNDARY_SPC_SET\n3,0,0,0,1,0,0,0\n";
  } else {
    os << "*BOUNDARY_SPC_SET\n1,0,1,0,0\n*SET_NODE_LIST\n4\n1,2,5,6\n*SET_NODE_LIST\n5\n1,3,5,7\n";
    os << "*BOUNDARY_SPC_SET\n4,0,0,1,0\n*BOUNDARY_SPC_SET\n5,0,0,0,1\n";
  }
  return os.str() + extra + "*END\n";
}

// Axial true strain and axial stress at each state.
struct TensionProbe {
  std::vector<std::pair<double, double>> curve;
  test::RecordingSink sink;
  explicit TensionProbe(Body b) {
    sink.on_state = [this, b](const engine::Snapshot& s) {
      const std::size_t far = b == Body::shell ? 3 : 7;
      const double strain = std::log(1.0 + s.nodes->ux[far] / kSide);
      const double stress =
          b == Body::shell ? s.shells->front().s[0].front() : s.solids->front().s[0].front();
      curve.emplace_back(strain, stress);
    };
  }
};

struct TensionCase {
  Body body;
  double temperature;
};

class ThermalPlasticTension : public ::testing::TestWithParam<TensionCase> {};

TEST_P(ThermalPlasticTension, FollowsTheBilinearCurveOfItsTemperature) {
  const auto [b, temp] = GetParam();
  const double end_time = 0.01;
  const core::Model m = build(tension_deck(
      b, mat004(), end_time, "*INITIAL_TEMPERATURE_SET\n0," + std::to_string(temp) + "\n"));
  TensionProbe probe(b);
  const engine::RunResult r = engine::run(m, probe.sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  // The constants at the temperature, linear in the table.
  const int i = temp < kTableT[1] ? 0 : 1;
  const double w = (temp - kTableT[i]) / (kTableT[i + 1] - kTableT[i]);
  const auto at = [&](const double* v) { return v[i] + w * (v[i + 1] - v[i]); };
  const double e = at(kTableE), sigy = at(kTableSigy), etan = at(kTableEtan);
  // Uniaxial stress: the shell's plane stress and the solid's both give E and ETAN in the
  // axial direction (rate form, true strain).
  const double yield_strain = sigy / e;
  int elastic = 0, plastic = 0;
  for (const auto& [strain, stress] : probe.curve) {
    if (strain < 0.5 * yield_strain && strain > 0.1 * yield_strain) {
      EXPECT_NEAR(stress, e * strain, 0.01 * e * strain) << "elastic, strain " << strain;
      ++elastic;
    } else if (strain > 3.0 * yield_strain) {
      const double expected = sigy + etan * (strain - yield_strain);
      EXPECT_NEAR(stress, expected, 0.01 * expected) << "plastic, strain " << strain;
      ++plastic;
    }
  }
  EXPECT_GE(elastic, 1);
  EXPECT_GE(plastic, 10);
}

INSTANTIATE_TEST_SUITE_P(Temperatures, ThermalPlasticTension,
                         ::testing::Values(TensionCase{Body::hex_one_point, 160.0},
                                           TensionCase{Body::hex_one_point, 450.0},
                                           TensionCase{Body::shell, 160.0},
                                           TensionCase{Body::shell, 450.0}),
                         [](const auto& p) {
                           return std::string(body_name(p.param.body)) + "_at_" +
                                  std::to_string(static_cast<int>(p.param.temperature));
                         });

TEST(ThermalPlasticTension, StopsWhenATemperatureLeavesTheTable) {
  const core::Model m = build(
      tension_deck(Body::hex_one_point, mat004(), 0.001, "*INITIAL_TEMPERATURE_SET\n0,700\n"));
  test::RecordingSink sink;
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.error.find("node 1 of part 1 is at temperature 700"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("*MAT_ELASTIC_PLASTIC_THERMAL table of its material [20, 600]"),
            std::string::npos)
      << r.error;
}

// Adiabatic heating: perfectly plastic *MAT_024 (SIGY 2e8, ETAN 0) pulled with the
// temperatures computed (SOLN 2) and FWORK 0.9: every node stores FWORK sigma_y eps_p V of the
// plastic work (uniform, so nothing conducts), a rise of FWORK sigma_y eps_p / (rho c).
class PlasticWorkHeat : public ::testing::TestWithParam<Body> {};

TEST_P(PlasticWorkHeat, RaisesTheTemperatureByTheAdiabaticClosedForm) {
  const Body b = GetParam();
  const double end_time = 0.01, sigy = 2.0e8, fwork = 0.9;
  std::ostringstream mat;
  mat.precision(12);
  mat << "*MAT_PIECEWISE_LINEAR_PLASTICITY\n1," << test::kRho << "," << kYoung << "," << kPoisson
      << "," << sigy << ",0.0\n";
  std::ostringstream thermal;
  thermal << "*CONTROL_SOLUTION\n2\n*CONTROL_THERMAL_SOLVER\n1,0,11,0,0,1.0," << fwork
          << "\n*CONTROL_THERMAL_TIMESTEP\n0,0.5,1.0e-4\n*INITIAL_TEMPERATURE_SET\n0,300\n";
  const core::Model m = build(tension_deck(b, mat.str(), end_time, thermal.str()));
  TensionProbe probe(b);
  double temperature_min = 1e300, temperature_max = -1e300, final_strain = 0.0;
  const auto tension_state = probe.sink.on_state;
  probe.sink.on_state = [&](const engine::Snapshot& s) {
    tension_state(s);
    temperature_min = *std::min_element(s.nodes->temperature.begin(), s.nodes->temperature.end());
    temperature_max = *std::max_element(s.nodes->temperature.begin(), s.nodes->temperature.end());
    final_strain = probe.curve.back().first;
  };
  const engine::RunResult r = engine::run(m, probe.sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  const double eps_p = final_strain - sigy / kYoung;
  ASSERT_GT(eps_p, 0.02);
  const double rise = fwork * sigy * eps_p / (test::kRho * test::kHeatCapacity);
  EXPECT_NEAR(temperature_min - 300.0, rise, 0.01 * rise) << body_name(b);
  EXPECT_NEAR(temperature_max - 300.0, rise, 0.01 * rise) << body_name(b);
  const double volume = kSide * kSide * (b == Body::shell ? kShellThickness : kSide);
  EXPECT_NEAR(r.heat.plastic, fwork * sigy * eps_p * volume, 0.01 * fwork * sigy * eps_p * volume);
  EXPECT_NEAR(r.heat.stored, r.heat.entered(), 1e-6 * r.heat.moved);
}

INSTANTIATE_TEST_SUITE_P(Elements, PlasticWorkHeat,
                         ::testing::Values(Body::hex_one_point, Body::hex_selective, Body::shell),
                         [](const auto& p) { return std::string(body_name(p.param)); });

}  // namespace test_thermomechanics
}  // namespace plyform
