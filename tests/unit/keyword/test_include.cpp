#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "plyform/keyword/read_deck.hpp"
#include "temp_dir.hpp"

namespace plyform::keyword {
namespace {

using plyform::test::TempDir;

std::string all_errors(const ReadResult& result) {
  std::string out;
  for (const Diagnostic& d : result.errors) {
    out += d.to_string() + "\n";
  }
  return out;
}

TEST(Include, ChainWithRelativePathsAndParameters) {
  const TempDir dir;
  dir.write("main/deck.k",
            "*KEYWORD\n*PARAMETER\nR     tend       2.0\n"
            "*INCLUDE\n$# several files on one card\nsub/a.k\n$#\ncurve3.k\n"
            "*DEFINE_CURVE\n1\n0,0\n&tend,1\n*END\n");
  dir.write("main/sub/a.k",
            "*DEFINE_CURVE\n2\n0,0\n&tend,2\n*INCLUDE\n../other/b.k\n*END\n\nignored junk\n");
  dir.write("main/other/b.k", "*PARAMETER_EXPRESSION\nR     tenx &tend*10\n*INCLUDE\nc.k\n");
  dir.write("main/other/c.k", "*DEFINE_CURVE\n4\n0,0\n&tenx,1\n");
  dir.write("main/curve3.k", "*DEFINE_CURVE\n3\n0,0\n&tenx,1");
  const ReadResult result = read_deck(dir.path() / "main/deck.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  std::vector<int> ids;
  for (const model::CurveDesc& curve : result.model.curves) {
    ids.push_back(curve.id);
  }
  EXPECT_EQ(ids, (std::vector<int>{2, 4, 3, 1}));
  EXPECT_DOUBLE_EQ(result.model.curves[1].abscissa[1], 20.0);
  EXPECT_DOUBLE_EQ(result.model.curves[2].abscissa[1], 20.0);
  ASSERT_EQ(result.model.files_read.size(), 5u);
  EXPECT_TRUE(result.model.curves[1].where.file.ends_with("main/other/c.k"))
      << result.model.curves[1].where.file;
}

TEST(Include, ErrorsInIncludedFilesNameThatFile) {
  const TempDir dir;
  dir.write("deck.k", "*KEYWORD\n*INCLUDE\ninc.k\n*ELEMENT_BEAM\n");
  dir.write("inc.k", "$ header\n*DEFINE_CURVE\n1,0,bad\n0,0\n1,1\n");
  const ReadResult result = read_deck(dir.path() / "deck.k");
  ASSERT_EQ(result.errors.size(), 2u) << all_errors(result);
  EXPECT_TRUE(result.errors[0].where.file.ends_with("inc.k"));
  EXPECT_EQ(result.errors[0].where.line, 3);
  EXPECT_EQ(result.errors[0].field, "SFA");
  EXPECT_TRUE(result.errors[1].where.file.ends_with("deck.k"));
  EXPECT_EQ(result.errors[1].where.line, 4);
}

TEST(Include, MissingFileIsReportedAndReadingGoesOn) {
  const TempDir dir;
  dir.write("deck.k", "*INCLUDE\nmissing.k\nthere.k\n*INCLUDE\nD:\\models\\mat.k\n");
  dir.write("there.k", "*DEFINE_CURVE\n1\n0,0\n1,1\n");
  const ReadResult result = read_deck(dir.path() / "deck.k");
  ASSERT_EQ(result.errors.size(), 2u) << all_errors(result);
  EXPECT_EQ(result.errors[0].where.line, 2);
  EXPECT_EQ(result.errors[1].where.line, 5);
  EXPECT_EQ(result.errors[1].keyword, "*INCLUDE");
  EXPECT_EQ(result.model.curves.size(), 1u);
}

TEST(Include, CycleIsDetected) {
  const TempDir dir;
  dir.write("a.k", "*INCLUDE\nb.k\n*DEFINE_CURVE\n1\n0,0\n1,1\n");
  dir.write("b.k", "*INCLUDE\nsub/../a.k\n");
  const ReadResult result = read_deck(dir.path() / "a.k");
  ASSERT_EQ(result.errors.size(), 1u) << all_errors(result);
  const Diagnostic& d = result.errors[0];
  EXPECT_TRUE(d.where.file.ends_with("b.k"));
  EXPECT_EQ(d.where.line, 2);
  EXPECT_NE(d.message.find("include cycle"), std::string::npos) << d.message;
  EXPECT_EQ(result.model.curves.size(), 1u);
}

TEST(Include, SelfIncludeIsACycle) {
  const TempDir dir;
  dir.write("a.k", "*INCLUDE\na.k\n");
  const ReadResult result = read_deck(dir.path() / "a.k");
  ASSERT_EQ(result.errors.size(), 1u) << all_errors(result);
  EXPECT_NE(result.errors[0].message.find("include cycle"), std::string::npos);
}

TEST(Include, SameFileTwiceIsNotACycle) {
  const TempDir dir;
  dir.write("a.k", "*INCLUDE\nb.k\nb.k\n");
  dir.write("b.k", "*TITLE\nfrom b\n");
  const ReadResult result = read_deck(dir.path() / "a.k");
  EXPECT_TRUE(result.ok()) << all_errors(result);
  EXPECT_EQ(result.model.files_read.size(), 3u);
}

TEST(Include, IncludePathRelative) {
  const TempDir dir;
  dir.write("case/run.k", "*INCLUDE_PATH_RELATIVE\n../lib\n*INCLUDE\ncurve.k\n");
  dir.write("lib/curve.k", "*DEFINE_CURVE\n5\n0,0\n1,1\n");
  const ReadResult result = read_deck(dir.path() / "case/run.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  ASSERT_EQ(result.model.curves.size(), 1u);
  EXPECT_EQ(result.model.curves[0].id, 5);
}

TEST(Include, IncludePathFromMainFolder) {
  const TempDir dir;
  dir.write("run.k", "*INCLUDE_PATH\nlib\n*INCLUDE\nsub/x.k\n");
  dir.write("sub/x.k", "*INCLUDE\ncurve.k\n");  // found through the include path
  dir.write("lib/curve.k", "*DEFINE_CURVE\n5\n0,0\n1,1\n");
  const ReadResult result = read_deck(dir.path() / "run.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  EXPECT_EQ(result.model.curves.size(), 1u);
}

TEST(Include, LongFileNameContinues) {
  const TempDir dir;
  dir.write("deck.k", "*INCLUDE\nsome_long_folder/ +\nname.k\n");
  dir.write("some_long_folder/name.k", "*TITLE\nlong\n");
  const ReadResult result = read_deck(dir.path() / "deck.k");
  ASSERT_TRUE(result.ok()) << all_errors(result);
  EXPECT_EQ(result.model.title, "long");
}

TEST(Include, LocalParametersStayInTheirFile) {
  const TempDir dir;
  dir.write("top.k",
            "*KEYWORD\n*PARAMETER\nRgbl          200.0\n*INCLUDE\ninc.k\n"
            "*DEFINE_CURVE\n40\n0,0\n&loc,1\n");
  dir.write("inc.k",
            "*PARAMETER_LOCAL\nRloc          999.0\n*INCLUDE\ninner.k\n"
            "*DEFINE_CURVE\n20\n0,0\n&loc,1\n*DEFINE_CURVE\n30\n0,0\n&gbl,1\n*END\n");
  dir.write("inner.k", "*DEFINE_CURVE\n21\n0,0\n&loc,1\n");
  const ReadResult result = read_deck(dir.path() / "top.k");
  ASSERT_EQ(result.errors.size(), 1u) << all_errors(result);
  EXPECT_TRUE(result.errors[0].where.file.ends_with("top.k"));
  EXPECT_EQ(result.errors[0].where.line, 9);
  EXPECT_EQ(result.errors[0].message, "undefined parameter &loc");
  ASSERT_EQ(result.model.curves.size(), 3u);
  EXPECT_DOUBLE_EQ(result.model.curves[0].abscissa[1], 999.0);  // 21, from inner.k
  EXPECT_DOUBLE_EQ(result.model.curves[2].abscissa[1], 200.0);  // 30
}

}  // namespace
}  // namespace plyform::keyword
