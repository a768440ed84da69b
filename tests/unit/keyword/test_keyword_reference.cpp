#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "plyform/keyword/keyword_reference.hpp"

namespace plyform::keyword {
namespace {

TEST(KeywordReference, DocsFileIsUpToDate) {
  const std::filesystem::path file = std::filesystem::path(PLYFORM_SOURCE_DIR) / "docs/keywords.md";
  const std::string generated = keyword_reference_markdown();
  if (const char* update = std::getenv("PLYFORM_UPDATE_DOCS"); update && *update == '1') {
    std::ofstream(file, std::ios::binary) << generated;
  }
  std::ifstream in(file, std::ios::binary);
  ASSERT_TRUE(in) << file << " is missing; run test_keyword with PLYFORM_UPDATE_DOCS=1";
  std::ostringstream committed;
  committed << in.rdbuf();
  EXPECT_EQ(committed.str(), generated)
      << file << " differs from the card tables; run test_keyword with PLYFORM_UPDATE_DOCS=1";
}

TEST(KeywordReference, ListsEveryKeywordAndField) {
  const std::string text = keyword_reference_markdown();
  for (const char* part : {"## *DEFINE_CURVE", "`*DEFINE_CURVE_TITLE`", "| SFA | 21-30 | R | 1 |",
                           "## *USER_INTERFACE_FRICTION", "| UC1 |", "## *PARAMETER",
                           "`*PARAMETER_EXPRESSION_LOCAL`", "## *INCLUDE_PATH", "## *END"}) {
    EXPECT_NE(text.find(part), std::string::npos) << part;
  }
}

}  // namespace
}  // namespace plyform::keyword
