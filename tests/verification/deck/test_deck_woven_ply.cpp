// The shipped woven carbon/PA6 parameter set (examples/materials/cf_pa6_woven_ply.k) end to end:
// read through *INCLUDE, validated, built, and sheared in a picture frame at 260 C. The frame's
// work per area equals the integral of the table's 260 C shear curve plus the matrix's
// closed-form work at EM(260 C) within 2 %; the families keep the frame's angle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "homogeneous_motion.hpp"
#include "plyform/keyword/read_deck.hpp"
#include "plyform/material/woven_ply.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace {

std::string frame_deck(double temperature, const char* part = "1,1,249\n", int elform = 2) {
  std::ostringstream os;
  os << "*KEYWORD\n*INCLUDE\n"
     << PLYFORM_SOURCE_DIR << "/examples/materials/cf_pa6_woven_ply.k\n"
     << "*CONTROL_TERMINATION\n0.001\n*DATABASE_GLSTAT\n0.0001\n"
     << "*PART\nply\n"
     << part << "*SECTION_SHELL\n1," << elform << ",0.8333,3\n0.5,0.5,0.5,0.5\n"
     << "*INITIAL_TEMPERATURE_SET\n0," << temperature << "\n*NODE\n";
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i)
      os << j * 3 + i + 1 << "," << 5.0 * i << "," << 5.0 * j << ",0\n";
  os << "*ELEMENT_SHELL\n";
  int e = 1;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int n = j * 3 + i + 1;
      os << e++ << ",1," << n << "," << n + 1 << "," << n + 4 << "," << n + 3 << "\n";
    }
  os << "*END\n";
  return os.str();
}

class DeckWovenPlyFrame : public ::testing::TestWithParam<int> {};

TEST_P(DeckWovenPlyFrame, ShippedCarbonPa6SetShearsByItsTableInAPictureFrame) {
  test::TempDir dir;
  const int elform = GetParam();
  const auto read =
      keyword::read_deck(dir.write("frame.k", frame_deck(260.0, "1,1,249\n", elform)));
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  const auto errors = setup::validate(read.model);
  ASSERT_TRUE(errors.empty()) << errors.front().to_string();
  auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  core::Model m = std::move(*built.model);
  EXPECT_EQ(m.shell_blocks.at(0).formulation, elform == 16
                                                  ? core::ShellFormulation::fully_integrated
                                                  : core::ShellFormulation::belytschko_tsay);
  const auto& ply = std::get<core::ReinforcedThermoplastic>(m.materials.at(0));
  ASSERT_EQ(ply.shear[0].stress.value, (std::vector<double>{230.0, 260.0, 280.0}));
  EXPECT_DOUBLE_EQ(ply.fibre[1].modulus, 52000.0);
  EXPECT_DOUBLE_EQ(ply.fibre[1].alpha, 0.5 * std::numbers::pi);

  const double gmax = 40.0 * std::numbers::pi / 180.0, t = 0.5, side = 10.0, end = 1e-3;
  test::prescribe_homogeneous(m, end, 400,
                              [&](double s, double f[2][2]) { test::picture_frame(gmax * s, f); });
  m.controls.end_time = end;
  m.output.d3plot_dt = end;
  test::RecordingSink sink;
  double angle = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    const auto& st = (*s.shells)[0];
    const material::WovenPlyState w = material::woven_ply_state(ply, st.history.data());
    angle = w.shear_angle[0];
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NEAR(angle, gmax, 0.5 * std::numbers::pi / 180.0);
  // The 260 C curve's integral to gmax (piecewise linear: trapezoids), and the matrix.
  const std::vector<double> gx{0.0, 0.35, 0.70}, gy{0.0, 0.020, 0.060};
  const double y_end = gy[1] + (gy[2] - gy[1]) * (gmax - gx[1]) / (gx[2] - gx[1]);
  const double shear = t * (0.5 * gx[1] * gy[1] + 0.5 * (gy[1] + y_end) * (gmax - gx[1]));
  const double em = 1.0 + (0.5 - 1.0) * (260.0 - 225.0) / (280.0 - 225.0);
  const double matrix = test::picture_frame_matrix_work(em, 0.35, gmax, t);
  const double expected = shear + matrix;
  const engine::Energies& e = sink.energies.back();
  EXPECT_NEAR(e.internal / (side * side), expected, 0.02 * expected)
      << "shear " << shear << ", matrix " << matrix;
  if (elform == 16) {
    EXPECT_EQ(e.hourglass, 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Elform, DeckWovenPlyFrame, ::testing::Values(2, 16),
                         [](const ::testing::TestParamInfo<int>& i) {
                           return "ELFORM_" + std::to_string(i.param);
                         });

// The one-point shell holds the fibres inextensible at its centre only: a woven ply with viscous
// hourglass control is warned about (by part, naming HGID and IHQ 4), one with IHQ 4 is not.
TEST(DeckWovenPly, ViscousHourglassControlIsWarnedAbout) {
  test::TempDir dir;
  const auto warnings_of = [&](const std::string& deck) {
    const auto read = keyword::read_deck(dir.write("hg.k", deck));
    EXPECT_TRUE(read.ok()) << read.errors.front().to_string();
    std::string text;
    for (const auto& w : setup::build(read.model).warnings)
      text += w.to_string() + "\n";
    return text;
  };
  const std::string viscous = warnings_of(frame_deck(260.0));
  EXPECT_NE(viscous.find("HGID"), std::string::npos) << viscous;
  EXPECT_NE(viscous.find("IHQ 4"), std::string::npos) << viscous;
  const std::string stiff = warnings_of(frame_deck(260.0, "1,1,249,0,7\n*HOURGLASS\n7,4,0.03\n"));
  EXPECT_EQ(stiff.find("HGID"), std::string::npos) << stiff;
  // The fully integrated shell has no hourglass modes: no advice to use IHQ 4, and a given
  // *HOURGLASS is said to be ignored (as LS-DYNA ignores it for ELFORM 16).
  const std::string full = warnings_of(frame_deck(260.0, "1,1,249\n", 16));
  EXPECT_EQ(full.find("HGID"), std::string::npos) << full;
  const std::string full_hg =
      warnings_of(frame_deck(260.0, "1,1,249,0,7\n*HOURGLASS\n7,4,0.03\n", 16));
  EXPECT_NE(full_hg.find("ignored for the fully integrated shell"), std::string::npos) << full_hg;
  // The shells' bulk viscosity is in it as in the BT shell: nothing to warn about.
  const std::string full_bv =
      warnings_of(frame_deck(260.0, "1,1,249\n*CONTROL_BULK_VISCOSITY\n1.5,0.06,-2\n", 16));
  EXPECT_EQ(full_bv.find("bulk viscosity"), std::string::npos) << full_bv;
}

}  // namespace
}  // namespace plyform
