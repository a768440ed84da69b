// *INITIAL_STRESS_SHELL, *INITIAL_STRAIN_SHELL and *INTERFACE_SPRINGBACK_LSDYNA as built: the
// stresses resolved to block elements with their thickness points sorted by T, the dynain's
// part set resolved to the deformable shell blocks; every bad reference a located error naming
// the keyword and field, the strains' not being applied a warning.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"

namespace plyform::setup {
namespace {

using keyword::Diagnostic;

std::string all(const std::vector<Diagnostic>& d) {
  std::string s;
  for (const Diagnostic& x : d)
    s += x.to_string() + "\n";
  return s;
}

// Lines 1-29: shells 1 (part 1, J2) and 2 (part 2, rigid) on nodes 1-6, part set 5 = {1, 2}.
const std::string kSheet =
    "*CONTROL_TERMINATION\n1e-3,\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,2,0,0\n6,2,1,0\n"
    "*PART\nsheet\n1,1,1\n*PART\ntool\n2,1,2\n*SECTION_SHELL\n1,2,0.8333,3\n1,1,1,1\n"
    "*MAT_PIECEWISE_LINEAR_PLASTICITY\n1,7.85e-9,210000,0.3,200,2000\n0,0\n"
    "*MAT_RIGID\n2,7.85e-9,210000,0.3\n"
    "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,2,2,5,6,3\n*SET_PART_LIST\n5\n1,2\n";

BuildResult build_text(const std::string& text) {
  const auto read = keyword::read_deck_text(text, "deck.k");
  EXPECT_TRUE(read.ok()) << all(read.errors);
  EXPECT_TRUE(validate(read.model).empty()) << all(validate(read.model));
  return build(read.model);
}

TEST(BuildInitialState, StressesToBlockElementsSortedByT) {
  const BuildResult r = build_text(kSheet +
                                   "*INITIAL_STRESS_SHELL\n"
                                   "1,1,2\n"
                                   "1.0,10,0,0,0,0,0,0.2\n"
                                   "-1.0,-10,0,0,0,0,0,0.1\n"
                                   "*INTERFACE_SPRINGBACK_LSDYNA\n5\n");
  ASSERT_TRUE(r.errors.empty()) << all(r.errors);
  const core::Model& m = *r.model;
  ASSERT_EQ(m.initial_shell_stresses.size(), 1u);
  const core::InitialShellStress& s = m.initial_shell_stresses[0];
  EXPECT_EQ(s.in_plane, 1);
  ASSERT_EQ(s.t.size(), 2u);
  EXPECT_EQ(s.t[0], -1.0);  // sorted: the bottom first
  EXPECT_EQ(s.stress[0], -10.0);
  EXPECT_EQ(s.plastic_strain[0], 0.1);
  EXPECT_EQ(s.stress[6], 10.0);
  EXPECT_EQ(m.shell_blocks[static_cast<std::size_t>(s.shell.block)]
                .element_id[static_cast<std::size_t>(s.shell.element)],
            1);
  // Part set 5 names the rigid tool too: left out, with a warning.
  EXPECT_TRUE(m.output.dynain.write);
  ASSERT_EQ(m.output.dynain.shell_blocks.size(), 1u);
  EXPECT_EQ(m.output.dynain.shell_blocks[0], s.shell.block);  // the sheet's block
  ASSERT_EQ(r.warnings.size(), 1u) << all(r.warnings);
  EXPECT_EQ(r.warnings[0].field, "PSID");
}

TEST(BuildInitialState, BadReferencesAreLocatedErrors) {
  const auto one_error = [](const std::string& text, int line, const char* keyword,
                            const char* field, const char* part) {
    SCOPED_TRACE(text);
    const BuildResult r = build_text(kSheet + text);
    ASSERT_EQ(r.errors.size(), 1u) << all(r.errors);
    EXPECT_EQ(r.errors[0].where.line, line);
    EXPECT_EQ(r.errors[0].keyword, keyword);
    EXPECT_EQ(r.errors[0].field, field);
    EXPECT_NE(r.errors[0].message.find(part), std::string::npos) << r.errors[0].message;
  };
  one_error("*INITIAL_STRESS_SHELL\n9,1,1\n0,1,0,0,0,0,0,0\n", 31, "*INITIAL_STRESS_SHELL", "EID",
            "not a shell");
  one_error("*INITIAL_STRESS_SHELL\n2,1,1\n0,1,0,0,0,0,0,0\n", 31, "*INITIAL_STRESS_SHELL", "EID",
            "rigid part");
  one_error("*INITIAL_STRESS_SHELL\n1,1,1\n0,1,0,0,0,0,0,0\n1,1,1\n0,1,0,0,0,0,0,0\n", 33,
            "*INITIAL_STRESS_SHELL", "EID", "second time");
  one_error(
      "*INITIAL_STRESS_SHELL\n1,4,1\n0,1,0,0,0,0,0,0\n0,1,0,0,0,0,0,0\n0.5,1,0,0,0,0,0,0\n"
      "0,1,0,0,0,0,0,0\n",
      34, "*INITIAL_STRESS_SHELL", "T", "share");
  one_error("*INITIAL_STRESS_SHELL\n1,1,2\n0.5,1,0,0,0,0,0,0\n0.5,1,0,0,0,0,0,0\n", 33,
            "*INITIAL_STRESS_SHELL", "T", "same T");
  one_error("*INITIAL_STRAIN_SHELL\n9,1,2\n0,0,0,0,0,0,-1\n0,0,0,0,0,0,1\n", 31,
            "*INITIAL_STRAIN_SHELL", "EID", "not a shell");
  one_error("*INTERFACE_SPRINGBACK_LSDYNA\n7\n", 31, "*INTERFACE_SPRINGBACK_LSDYNA", "PSID",
            "not defined");
}

TEST(BuildInitialState, StrainsAreCheckedAndWarnedAbout) {
  const BuildResult r =
      build_text(kSheet + "*INITIAL_STRAIN_SHELL\n1,1,2\n0,0,0,0,0,0,-1\n0,0,0,0,0,0,1\n");
  ASSERT_TRUE(r.errors.empty()) << all(r.errors);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].keyword, "*INITIAL_STRAIN_SHELL");
  EXPECT_NE(r.warnings[0].message.find("not applied"), std::string::npos);
  EXPECT_FALSE(r.model->output.dynain.write);
}

}  // namespace
}  // namespace plyform::setup
