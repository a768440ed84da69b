// A sheet-forming deck end to end (reader, validation, build, engine): a clamped
// elasto-plastic Belytschko-Tsay plate pushed by a *MAT_RIGID punch under
// *BOUNDARY_PRESCRIBED_MOTION_RIGID. Checked against independent references: the punch
// travels the integral of its velocity curve (1 mm), the energy balance closes (kinetic +
// internal + hourglass = external work, the punch's reaction work), and the plate yields.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace {

std::string sheet_deck() {
  std::ostringstream os;
  os << "*KEYWORD\n*CONTROL_TERMINATION\n     0.002\n*DATABASE_BINARY_D3PLOT\n    0.0005\n"
        "*DATABASE_GLSTAT\n   0.00002\n"
        "*PART\nplate\n         1         1         1\n"
        "*SECTION_SHELL\n         1         2    0.8333         5\n"
        "       1.0       1.0       1.0       1.0\n"
        "*MAT_PIECEWISE_LINEAR_PLASTICITY\n"
        "         1   7.85E-9  210000.0       0.3     200.0    1000.0\n"
        "*PART\npunch\n         2         2         2\n"
        "*SECTION_SHELL\n         2         2       1.0         1\n"
        "       1.0       1.0       1.0       1.0\n"
        "*MAT_RIGID\n         2   7.85E-9  210000.0       0.3\n       1.0         4         7\n"
        "*BOUNDARY_PRESCRIBED_MOTION_RIGID\n         2         3         0         1      -1.0\n"
        "*DEFINE_CURVE\n         1\n               0.0               0.0\n"
        "             0.001            1000.0\n             0.002               0.0\n*NODE\n";
  const int n = 10;
  const double a = 40.0;
  const auto nid = [&](int i, int j) { return j * (n + 1) + i + 1; };
  char line[128];
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int fix = (i == 0 || j == 0 || i == n || j == n) ? 7 : 0;
      std::snprintf(line, sizeof line, "%8d%16.6f%16.6f%16.6f%8d%8d\n", nid(i, j), a * i / n,
                    a * j / n, 0.0, fix, fix);
      os << line;
    }
  os << "*ELEMENT_SHELL\n";
  int e = 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      std::snprintf(line, sizeof line, "%8d%8d%8d%8d%8d%8d\n", e++, 1, nid(i, j), nid(i + 1, j),
                    nid(i + 1, j + 1), nid(i, j + 1));
      os << line;
    }
  std::snprintf(line, sizeof line, "%8d%8d%8d%8d%8d%8d\n", 1000, 2, nid(4, 4), nid(6, 4), nid(6, 6),
                nid(4, 6));
  os << line << "*END\n";
  return os.str();
}

TEST(DeckSheet, RigidPunchOnAPlasticPlate) {
  test::TempDir dir;
  const auto read = keyword::read_deck(dir.write("sheet.k", sheet_deck()));
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  ASSERT_TRUE(setup::validate(read.model).empty());
  auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  const core::Model& m = *built.model;
  ASSERT_EQ(m.shell_blocks.size(), 2u);
  test::RecordingSink sink;
  double punch_z = 0.0, max_eps = 0.0;
  sink.on_state = [&](const engine::Snapshot& s) {
    punch_z = s.rigid->report().at(0).centre[2];
    for (double v : (*s.shells)[0].eps_p)
      max_eps = std::max(max_eps, v);
  };
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NEAR(punch_z, -1.0, 1e-9);  // the integral of the velocity triangle
  EXPECT_GT(max_eps, 1e-3);
  ASSERT_GT(sink.energies.size(), 10u);
  const engine::Energies& last = sink.energies.back();
  EXPECT_GT(last.external_work, 100.0);
  EXPECT_NEAR(last.total, last.external_work, 0.01 * last.external_work);
  EXPECT_LT(last.hourglass, 0.05 * last.internal);
}

TEST(DeckSheet, FullyIntegratedShellsBuildOnToolsAndSheets) {
  // ELFORM 16 on the rigid punch (its shells carry only mass and surface) and on the plate (the
  // fully integrated shell, 4 x NIP points per element, no hourglass control).
  std::string deck = sheet_deck();
  for (const auto& [from, to] : {std::pair<std::string, std::string>{
                                     "*SECTION_SHELL\n         2         2       1.0         1\n",
                                     "*SECTION_SHELL\n         2        16       1.0         1\n"},
                                 std::pair<std::string, std::string>{
                                     "*SECTION_SHELL\n         1         2    0.8333         5\n",
                                     "*SECTION_SHELL\n         1        16    0.8333         5\n"}})
    deck.replace(deck.find(from), from.size(), to);
  const auto read = keyword::read_deck_text(deck, "sheet.k");
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  const auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  ASSERT_EQ(built.model->shell_blocks.size(), 2u);
  EXPECT_EQ(built.model->shell_blocks[0].formulation, core::ShellFormulation::fully_integrated);
}

}  // namespace
}  // namespace plyform
