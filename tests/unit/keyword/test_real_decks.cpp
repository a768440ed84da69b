// The third-party decks of ../shared/decks/real (when present): the reader must return on each,
// quickly, with every error located. Most report unsupported keywords for now.
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

namespace fs = std::filesystem;

fs::path real_decks_folder() {
  return fs::path(PLYFORM_SOURCE_DIR) / ".." / "shared/decks/real";
}

/// The `path` of each `role=deck` row of MANIFEST.tsv.
std::vector<std::string> manifest_decks(const fs::path& manifest) {
  std::ifstream in(manifest);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::string> decks;
  while (std::getline(in, line)) {
    std::vector<std::string> columns;
    std::istringstream row(line);
    for (std::string column; std::getline(row, column, '\t');) {
      columns.push_back(column);
    }
    if (columns.size() > 6 && columns[6] == "deck") {
      decks.push_back(columns[0]);
    }
  }
  return decks;
}

const model::CurveDesc* find_curve(const ReadResult& result, int id) {
  for (const model::CurveDesc& curve : result.model.curves) {
    if (curve.id == id) {
      return &curve;
    }
  }
  return nullptr;
}

/// Decks of MANIFEST.tsv that read with no error (the solver-core keyword subset).
constexpr int kAcceptedRealDecks = 9;

class RealDecks : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(real_decks_folder() / "MANIFEST.tsv")) {
      GTEST_SKIP() << "no real decks at " << real_decks_folder();
    }
  }
};

TEST_F(RealDecks, EveryDeckReadsWithLocatedErrorsOnly) {
  const std::vector<std::string> decks = manifest_decks(real_decks_folder() / "MANIFEST.tsv");
  ASSERT_GT(decks.size(), 20u);
  const auto start = std::chrono::steady_clock::now();
  for (const std::string& deck : decks) {
    SCOPED_TRACE(deck);
    const ReadResult result = read_deck(real_decks_folder() / deck);
    EXPECT_FALSE(result.model.files_read.empty());
    for (const Diagnostic& error : result.errors) {
      EXPECT_FALSE(error.where.file.empty()) << error.to_string();
      EXPECT_GT(error.where.line, 0) << error.to_string();
      EXPECT_FALSE(error.keyword.empty()) << error.to_string();
      EXPECT_FALSE(error.message.empty()) << error.to_string();
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // About 6 MB of text in all: linear reading takes well under a second even in a debug build
  // with sanitizers; anything quadratic takes far longer.
  EXPECT_LT(seconds, 10.0);
}

TEST_F(RealDecks, CountsTheFullyAcceptedDecks) {
  // With the solver-core keywords more decks read without error; the count may only grow.
  const std::vector<std::string> decks = manifest_decks(real_decks_folder() / "MANIFEST.tsv");
  int accepted = 0;
  for (const std::string& deck : decks) {
    const ReadResult result = read_deck(real_decks_folder() / deck);
    if (result.ok()) {
      ++accepted;
    } else {
      std::printf("  %-70s first error: %s\n", deck.c_str(),
                  result.errors.front().to_string().c_str());
    }
  }
  std::printf("real decks fully accepted by the reader: %d of %zu\n", accepted, decks.size());
  EXPECT_GE(accepted, kAcceptedRealDecks);
}

TEST_F(RealDecks, OneElementLoadControlReadsItsSegmentPressure) {
  // k1zr's one-element deck loads its top face by *LOAD_SEGMENT (fixed format, trailing
  // blanks on the keyword line): the curve, its scale and the four nodes as written.
  const ReadResult result = read_deck(real_decks_folder() / "k1zr/one-element-loadcontrol.k");
  ASSERT_TRUE(result.ok()) << result.errors.front().to_string();
  ASSERT_EQ(result.model.pressure_loads.size(), 1u);
  const model::LoadPressureDesc& p = result.model.pressure_loads[0];
  EXPECT_EQ(p.target, model::PressureTarget::kSegment);
  EXPECT_EQ(p.curve_id, 1);
  EXPECT_DOUBLE_EQ(p.scale, 1.0);
  EXPECT_DOUBLE_EQ(p.arrival, 0.0);
  EXPECT_EQ(p.nodes, (std::array<int, 4>{5, 6, 7, 8}));
}

TEST_F(RealDecks, ParametersExpressionsAndLongCurveThroughIncludes) {
  const ReadResult result =
      read_deck(real_decks_folder() /
                "muscle/impedance/impedance_0p027stim_0p4mm_15Hz/impedance_0p027stim_0p4mm_15Hz.k");
  const model::CurveDesc* perturbation = find_curve(result, 4);
  ASSERT_NE(perturbation, nullptr);
  EXPECT_GT(perturbation->abscissa.size(), 2000u);
  // Curve 5 ends at &timeE = points / freq = 2048 * dtsignal (PARAMETER_EXPRESSION chain).
  const model::CurveDesc* curve5 = find_curve(result, 5);
  ASSERT_NE(curve5, nullptr);
  ASSERT_EQ(curve5->abscissa.size(), 2u);
  EXPECT_NEAR(curve5->abscissa[1], 2048 * 0.003, 1e-9);
}

TEST_F(RealDecks, LowerCaseCommaCurvesWithUndefinedParameters) {
  const ReadResult result =
      read_deck(real_decks_folder() / "umat2scale/thermal_cycles_v03/curves.k");
  EXPECT_EQ(result.model.curves.size(), 5u);  // curve 11 uses &temp_0, defined elsewhere
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].where.line, 9);
  EXPECT_EQ(result.errors[0].message, "undefined parameter &temp_0");
}

TEST_F(RealDecks, MetalformingDeckReadsShellsMaterialsAndRigidTools) {
  // Shells, shell sections, *MAT_RIGID tools and their prescribed motion all read; so do the
  // controls, the contacts, *MAT_037 and the springback output. (The file has no *PART: the
  // parts its sets and contacts name are not in it, so it does not run on its own.)
  const ReadResult result = read_deck(real_decks_folder() / "pydyna/metalforming/model.k");
  EXPECT_EQ(result.model.shells.size(), 3562u);
  ASSERT_EQ(result.model.shell_sections.size(), 5u);
  EXPECT_EQ(result.model.shell_sections[0].elform, 16);
  EXPECT_EQ(result.model.shell_sections[0].nip, 5);
  EXPECT_DOUBLE_EQ(result.model.shell_sections[0].shear_factor, 0.833);
  EXPECT_DOUBLE_EQ(result.model.shell_sections[0].thickness[3], 1.5);
  ASSERT_EQ(result.model.rigid_materials.size(), 4u);
  EXPECT_EQ(result.model.rigid_materials[0].cmo, 1);
  EXPECT_EQ(result.model.rigid_materials[0].con1, 7);
  EXPECT_EQ(result.model.rigid_materials[0].con2, 6);
  ASSERT_EQ(result.model.rigid_motions.size(), 2u);
  EXPECT_EQ(result.model.rigid_motions[0].part_id, 2);
  EXPECT_EQ(result.model.rigid_motions[0].dof, 6);
  EXPECT_DOUBLE_EQ(result.model.rigid_motions[0].scale, -1.0);
  // Every keyword reads (*MAT_037's R = -1.593 is LS-DYNA's stabilised return with the ratio
  // 1.593). (*CONTROL_ADAPSTEP and *INTERFACE_SPRINGBACK_LSDYNA are now read with warnings,
  // *CONTROL_SHELL's ESORT 1 read (the sheet has no triangle) with its card 3, *CONTROL_CONTACT's
  // PENOPT 4 read as the slave stiffness plyform makes, *CONTROL_BULK_VISCOSITY TYPE -1 puts the
  // bulk viscosity in the shells.) The four forming contacts read, with their optional cards B
  // and C as LS-PrePost writes them (defaults, SNLOG 1, IGAP 1).
  EXPECT_TRUE(result.errors.empty()) << result.errors.front().to_string();
  ASSERT_EQ(result.model.transversely_anisotropic_materials.size(), 1u);
  EXPECT_DOUBLE_EQ(result.model.transversely_anisotropic_materials[0].r, -1.593);
  EXPECT_EQ(result.model.transversely_anisotropic_materials[0].hlcid, 1);
  ASSERT_EQ(result.model.contacts.size(), 4u);
  for (const model::ContactDesc& c : result.model.contacts) {
    EXPECT_EQ(c.kind, model::ContactKind::forming_one_way_surface_to_surface);
    EXPECT_EQ(c.sstyp, model::ContactSideType::part);
    EXPECT_DOUBLE_EQ(c.fs, 0.125);
    EXPECT_DOUBLE_EQ(c.vdc, 20.0);
    EXPECT_EQ(c.bsort, 100);
  }
  // *DATABASE_GLSTAT, _MATSUM and _RCFORC are read.
  ASSERT_EQ(result.model.ascii_outputs.size(), 3u);
  EXPECT_EQ(result.model.ascii_outputs[1].name, "MATSUM");
  EXPECT_EQ(result.model.ascii_outputs[2].name, "RCFORC");
}

TEST_F(RealDecks, MissingWindowsIncludeIsLocated) {
  const ReadResult result = read_deck(real_decks_folder() / "jfriedlein/main.k");
  bool found = false;
  for (const Diagnostic& error : result.errors) {
    if (error.keyword == "*INCLUDE" && error.where.file.ends_with("main_-_chooseNumEx.k")) {
      found = error.where.line == 54;
    }
  }
  EXPECT_TRUE(found);
}

TEST(ReaderSpeed, LargeDeckIsReadInLinearTime) {
  std::string deck = "*KEYWORD\n*NODE\n";
  for (int i = 1; i <= 200000; ++i) {
    deck += std::to_string(i) + ",0.0,1.0,2.0\n";
  }
  deck += "*DEFINE_CURVE\n1\n";
  for (int i = 0; i < 100000; ++i) {
    deck += std::to_string(i) + ".0," + std::to_string(i % 7) + ".5\n";
  }
  const auto start = std::chrono::steady_clock::now();
  const ReadResult result = read_deck_text(deck, "big.k");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(result.errors.empty());
  ASSERT_EQ(result.model.nodes.size(), 200000u);
  ASSERT_EQ(result.model.curves.size(), 1u);
  EXPECT_EQ(result.model.curves[0].abscissa.size(), 100000u);
  EXPECT_LT(seconds, 5.0);
}

}  // namespace
}  // namespace plyform::keyword
