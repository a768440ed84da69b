// *CONTROL_PARALLEL: every field lands in its member, NCPU gives the thread count (|NCPU|, a
// blank or 0 is LS-DYNA's 1), a negative NCPU (consistency, which plyform always has) is read
// without a warning, and the values that ask for what plyform does not do are warned about by
// the field's name.
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, expect_error, contains

std::string all_warnings(const ReadResult& r) {
  std::string out;
  for (const Diagnostic& d : r.warnings)
    out += d.to_string() + "\n";
  return out;
}

TEST(ControlParallel, EveryFieldFixedFormat) {
  const ReadResult r = read_ok(
      "*CONTROL_PARALLEL\n"
      "$     ncpu    numrhs     const      para\n"
      "         4         1         1         2\n");
  ASSERT_TRUE(r.model.parallel.has_value());
  const model::ControlParallelDesc& p = *r.model.parallel;
  EXPECT_EQ(p.ncpu, 4);
  EXPECT_EQ(p.numrhs, 1);
  EXPECT_EQ(p.consistency, 1);
  EXPECT_EQ(p.para, 2);
  EXPECT_EQ(p.threads(), 4);
  EXPECT_EQ(p.where.line, 3);
  EXPECT_TRUE(r.warnings.empty()) << all_warnings(r);
}

TEST(ControlParallel, BlanksAndZerosTakeLsDynasDefaults) {
  ReadResult r = read_ok("*CONTROL_PARALLEL\n\n");
  ASSERT_TRUE(r.model.parallel.has_value());
  EXPECT_EQ(r.model.parallel->ncpu, 1);
  EXPECT_EQ(r.model.parallel->threads(), 1);
  EXPECT_EQ(r.model.parallel->consistency, 2);
  EXPECT_TRUE(r.warnings.empty()) << all_warnings(r);
  // A generator's "0 0 1 1": NCPU 0 is one thread, consistency on: nothing to warn about.
  r = read_ok("*CONTROL_PARALLEL\n         0         0         1         1\n");
  EXPECT_EQ(r.model.parallel->threads(), 1);
  EXPECT_EQ(r.model.parallel->consistency, 1);
  EXPECT_TRUE(r.warnings.empty()) << all_warnings(r);
  r = read_ok("*CONTROL_PARALLEL\n2,,0\n");
  EXPECT_EQ(r.model.parallel->consistency, 2);  // CONST 0 reads as LS-DYNA's default, off
  EXPECT_TRUE(r.warnings.empty()) << all_warnings(r);
}

TEST(ControlParallel, NegativeNcpuIsThreadsWithConsistencyAndNoWarning) {
  const ReadResult r = read_ok("*CONTROL_PARALLEL\n-3\n");
  EXPECT_EQ(r.model.parallel->ncpu, -3);
  EXPECT_EQ(r.model.parallel->threads(), 3);
  EXPECT_TRUE(r.warnings.empty()) << all_warnings(r);
}

TEST(ControlParallel, IntegralRealNcpuFreeFormat) {
  const ReadResult r = read_ok("*CONTROL_PARALLEL\n2.0,1.,1.0\n");
  EXPECT_EQ(r.model.parallel->threads(), 2);
  EXPECT_EQ(r.model.parallel->consistency, 1);
}

TEST(ControlParallel, WarnsByNameAboutWhatPlyformDoesNotDo) {
  const ReadResult r = read_ok("*CONTROL_PARALLEL\n4,0,2\n");
  ASSERT_EQ(r.warnings.size(), 2u) << all_warnings(r);
  EXPECT_EQ(r.warnings[0].field, "NUMRHS");
  EXPECT_EQ(r.warnings[0].where.line, 2);
  EXPECT_TRUE(contains(r.warnings[0].message, "NUMRHS 0")) << r.warnings[0].message;
  EXPECT_EQ(r.warnings[1].field, "CONST");
  EXPECT_TRUE(contains(r.warnings[1].message, "CONST 2 (consistency off, for speed) is not done"))
      << r.warnings[1].message;
  const ReadResult para = read_ok("*CONTROL_PARALLEL\n4,1,1,0\n");
  ASSERT_EQ(para.warnings.size(), 1u) << all_warnings(para);
  EXPECT_EQ(para.warnings[0].field, "PARA");
  EXPECT_EQ(para.warnings[0].keyword, "*CONTROL_PARALLEL");
  // NUMRHS 0 with one thread asks for nothing plyform does not do.
  EXPECT_TRUE(read_ok("*CONTROL_PARALLEL\n1,0\n").warnings.empty());
}

TEST(ControlParallel, Rejections) {
  constexpr std::string_view kKw = "*CONTROL_PARALLEL";
  expect_error("*CONTROL_PARALLEL\n2000\n", 2, kKw, "NCPU", "out of range");
  expect_error("*CONTROL_PARALLEL\n2.5\n", 2, kKw, "NCPU", "not a whole number");
  expect_error("*CONTROL_PARALLEL\n2,3\n", 2, kKw, "NUMRHS", "NUMRHS takes 0 or 1");
  expect_error("*CONTROL_PARALLEL\n2,0,3\n", 2, kKw, "CONST", "CONST takes 1 (on) or 2 (off)");
  expect_error("*CONTROL_PARALLEL\n2,0,1,3\n", 2, kKw, "PARA", "PARA takes 0, 1 or 2");
  expect_error("*CONTROL_PARALLEL\n", 1, kKw, "", "missing card 1");
  expect_error("*CONTROL_PARALLEL\n2\n3\n", 3, kKw, "", "one card");
}

}  // namespace
}  // namespace plyform::keyword
