// `plyform check` advises when a woven ply is meshed across its fibres (a family at more than
// 10 degrees to every edge of most of its elements: intra-ply shear locking, docs/materials.md)
// and stays silent when the families lie along the element edges, whichever way the deck
// states their angles (ALPHi, MANGL, AOPT 2's vector).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace {

// A 40 x 20 mm plate of 4 x 2 square shells, a woven ply with the given AOPT line (card 2's
// NFIB, AOPT, ..., A1-A3; AOPT 2 with d = z), MANGL and the two families' angles.
std::string deck(const std::string& aopt_card, double mangl, double alph1, double alph2) {
  std::ostringstream d;
  d << "*KEYWORD\n*CONTROL_TERMINATION\n1.0e-3\n*NODE\n";
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 4; ++i)
      d << 1 + j * 5 + i << "," << 10.0 * i << "," << 10.0 * j << ",0\n";
  d << "*ELEMENT_SHELL\n";
  int e = 1;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      const int a = 1 + j * 5 + i;
      d << e++ << ",1," << a << "," << a + 1 << "," << a + 6 << "," << a + 5 << "\n";
    }
  d << "*PART\nply\n1,1,1\n*SECTION_SHELL\n1,16,0.8333,2\n1.0,1.0,1.0,1.0\n"
    << "*MAT_REINFORCED_THERMOPLASTIC\n1,1.5e-9,1.0,0,0.3\n"
    << aopt_card << (aopt_card.starts_with("2,2") ? "\n,,,0,0,1," : "\n,,,,,,") << mangl << ",0\n"
    << "1," << alph1 << ",500.0\n0.01,0,0,0,2\n2," << alph2 << ",500.0\n*END\n";
  return d.str();
}

std::string check_out(const std::string& text) {
  test::TempDir dir;
  std::ostringstream out, err;
  const int status = run_check(dir.write("ply.k", text), out, err);
  EXPECT_EQ(status, 0) << err.str();
  return out.str();
}

TEST(CheckFibres, APlyAtFortyFiveDegreesToItsElementsIsAdvised) {
  for (const std::string& text : {deck("2,0", 0.0, 45.0, -45.0), deck("2,0", 30.0, 0.0, 90.0),
                                  deck("2,2,0,0,0,1,1,0", 0.0, 0.0, 90.0)}) {
    const std::string out = check_out(text);
    const auto at = out.find("advice: part 1 (*MAT_REINFORCED_THERMOPLASTIC)");
    ASSERT_NE(at, std::string::npos) << out;
    const std::string line = out.substr(at, out.find('\n', at) - at);
    EXPECT_NE(line.find("8 of its 8 elements"), std::string::npos) << line;
    EXPECT_NE(line.find("mesh the ply along its fibres"), std::string::npos) << line;
  }
  EXPECT_NE(check_out(deck("2,0", 0.0, 45.0, -45.0)).find("(up to 45)"), std::string::npos);
  EXPECT_NE(check_out(deck("2,0", 30.0, 0.0, 90.0)).find("(up to 30)"), std::string::npos);
}

TEST(CheckFibres, SilentWhereTheFamiliesFollowTheEdges) {
  // 0 / 90 from the edge 1-2; +-45 turned by MANGL 45; a global axis at 45 degrees with the
  // families at -45 and 45 from it; a family 8 degrees off its edge (within the tolerance).
  for (const std::string& text :
       {deck("2,0", 0.0, 0.0, 90.0), deck("2,0", 45.0, 45.0, -45.0),
        deck("2,2,0,0,0,1,1,0", 0.0, -45.0, 45.0), deck("2,0", 0.0, 8.0, 90.0)})
    EXPECT_EQ(check_out(text).find("advice:"), std::string::npos) << text;
}

}  // namespace
}  // namespace plyform::app
