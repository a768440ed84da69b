// *DATABASE_ELOUT with *DATABASE_HISTORY_SHELL / _SOLID: elout.csv as `plyform run` writes it,
// against closed forms of slow uniaxial tension (the ends ramped to a constant speed over a
// quarter of the run, some 60 wave transits, so the bar is near equilibrium):
// - an elastic strip with Poisson's ratio 0, lying at 30 degrees to the x axis: the global
//   stress of a middle element is sigma d (x) d with sigma = F / A (the held end's reaction from
//   spcforc.csv over the unchanged section) = E ln(L / L0) (nodout.csv's end displacement);
// - a strip and a bar of hexahedra of bilinear J2 (*MAT_PLASTIC_KINEMATIC, isotropic): past
//   yield sigma = (sigma_y + H ln(L / L0)) / (1 + H / E) and the effective plastic strain
//   ln(L / L0) - sigma / E, H = E E_t / (E - E_t), at every thickness point.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace {

constexpr double kE = 210000.0, kRho = 7.85e-9, kSigmaY = 200.0, kEt = 2000.0;
constexpr double kEnd = 5.0e-4;  // run time; the ends reach their speed at kEnd / 4
constexpr double kL = 10.0, kW = 1.0, kT = 0.5;
constexpr double kH = kE * kEt / (kE - kEt);  // plastic modulus of the bilinear law

/// A CSV file as rows of named cells.
struct Csv {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  double at(std::size_t row, const std::string& column) const {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (columns[c] == column)
        return rows[row][c].empty() ? std::nan("") : std::stod(rows[row][c]);
    }
    ADD_FAILURE() << "no column " << column;
    return 0.0;
  }
  const std::string& text(std::size_t row, const std::string& column) const {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (columns[c] == column)
        return rows[row][c];
    }
    static const std::string none;
    ADD_FAILURE() << "no column " << column;
    return none;
  }
};

Csv read_csv(const std::filesystem::path& file) {
  Csv csv;
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  std::string line;
  const auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::stringstream ss(l);
    std::string cell;
    while (std::getline(ss, cell, ','))
      cells.push_back(cell);
    if (!l.empty() && l.back() == ',')
      cells.emplace_back();
    return cells;
  };
  if (std::getline(in, line))
    csv.columns = split(line);
  while (std::getline(in, line))
    csv.rows.push_back(split(line));
  return csv;
}

/// Runs `deck` with `plyform run` into dir/out.
std::filesystem::path run(test::TempDir& dir, const std::string& name, const std::string& deck) {
  app::RunOptions o;
  o.deck = dir.write(name, deck);
  o.output = dir.path() / (name + "_out");
  o.progress = false;
  std::ostringstream out, err;
  EXPECT_EQ(app::run_deck(o, out, err), 0) << err.str();
  return *o.output;
}

// Every card with a comma (free format): the numbers are longer than a 10-character field.
std::string outputs(int history_node) {
  std::ostringstream os;
  os.precision(17);
  os << "*DATABASE_ELOUT\n"
     << kEnd / 20 << ",1,0,1,0,0,0,0\n"
     << "*DATABASE_NODOUT\n"
     << kEnd / 20 << ",1\n*DATABASE_SPCFORC\n"
     << kEnd / 20 << ",1\n"
     << "*DATABASE_HISTORY_NODE\n"
     << history_node << "\n"
     << "*DEFINE_CURVE\n1\n0,0\n"
     << kEnd / 4 << ",1\n"
     << kEnd << ",1\n";
  return os.str();
}

// A strip of 10 x 1 shells of 1 mm (NIP 3) along d = (cos a, sin a, 0), its end i = 10 pulled
// along d at `speed`. `plastic`: *MAT_PLASTIC_KINEMATIC, the held end free across the strip (a
// = 0 only); else *MAT_ELASTIC with PR 0, both ends held across (no contraction to block).
std::string strip_deck(double angle, bool plastic, double speed, int elform = 2) {
  const double c = std::cos(angle), s = std::sin(angle);
  const auto nid = [](int i, int j) { return 1 + i + 11 * j; };
  std::ostringstream os;
  os.precision(17);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n" << kEnd << ",0\n" << outputs(nid(10, 0));
  os << "*DATABASE_HISTORY_SHELL\n5,0,0,0,0,0,0,0\n";
  os << "*PART\nstrip\n1,1,1\n*SECTION_SHELL\n1," << elform << ",0.8333,3\n"
     << kT << "," << kT << "," << kT << "," << kT << "\n";
  if (plastic) {
    os << "*MAT_PLASTIC_KINEMATIC\n1," << kRho << "," << kE << ",0.3," << kSigmaY << "," << kEt
       << ",1.0\n0,0,0\n";
  } else {
    os << "*MAT_ELASTIC\n1," << kRho << "," << kE << ",0.0\n";
  }
  os << "*NODE\n";
  for (int j = 0; j <= 1; ++j) {
    for (int i = 0; i <= 10; ++i)
      os << nid(i, j) << "," << i * c - j * kW * s << "," << i * s + j * kW * c << ",0\n";
  }
  // Element 5 has its first edge across the strip, so its frame is not the strip's axes.
  os << "*ELEMENT_SHELL\n";
  for (int i = 0; i < 10; ++i) {
    if (i + 1 == 5)
      os << i + 1 << ",1," << nid(i + 1, 0) << "," << nid(i + 1, 1) << "," << nid(i, 1) << ","
         << nid(i, 0) << "\n";
    else
      os << i + 1 << ",1," << nid(i, 0) << "," << nid(i + 1, 0) << "," << nid(i + 1, 1) << ","
         << nid(i, 1) << "\n";
  }
  // Every node in the plane z = 0, no rotations; the held end along d, the pulled end driven.
  os << "*BOUNDARY_SPC_NODE\n";
  for (int j = 0; j <= 1; ++j) {
    for (int i = 0; i <= 10; ++i) {
      const bool held = i == 0 && (!plastic || j == 0);
      const bool x = i == 0, y = held;
      os << nid(i, j) << ",0," << (x ? 1 : 0) << "," << (y ? 1 : 0) << ",1,1,1,1\n";
    }
  }
  os << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int j = 0; j <= 1; ++j) {
    os << nid(10, j) << ",1,0,1," << speed * c << "\n";
    if (!plastic)
      os << nid(10, j) << ",2,0,1," << speed * s << "\n";
  }
  os << "*END\n";
  return os.str();
}

// The end displacement along d at each nodout time (the history node's).
std::map<std::string, double> stretch_of(const Csv& nodout, double angle) {
  std::map<std::string, double> u;
  for (std::size_t r = 0; r < nodout.rows.size(); ++r) {
    u[nodout.text(r, "time")] =
        nodout.at(r, "ux") * std::cos(angle) + nodout.at(r, "uy") * std::sin(angle);
  }
  return u;
}

// ELFORM 2 and 16 (ELFORM 16: each thickness point's mean over the four in-plane points).
class DeckEloutStrip : public ::testing::TestWithParam<int> {};

TEST_P(DeckEloutStrip, ElasticStripAtAnAngleWritesGlobalStressEqualToForceOverArea) {
  test::TempDir dir;
  const double angle = std::numbers::pi / 6.0, c = std::cos(angle), s = std::sin(angle);
  const auto out =
      run(dir, "strip_elastic.k", strip_deck(angle, false, 0.02 / (0.875 * kEnd), GetParam()));
  const Csv elout = read_csv(out / "elout.csv");
  const Csv spcforc = read_csv(out / "spcforc.csv");
  const auto u = stretch_of(read_csv(out / "nodout.csv"), angle);
  ASSERT_EQ(elout.rows.size(), 21u * 3u);
  // The held end's reaction along d, per time (the force the constraints apply, so -F); the
  // other nodes are listed too (their z is held) and the pulled ones carry the opposite force.
  std::map<std::string, double> force;
  for (std::size_t r = 0; r < spcforc.rows.size(); ++r) {
    const double node = spcforc.at(r, "node");
    if (node == 1.0 || node == 12.0)
      force[spcforc.text(r, "time")] -= spcforc.at(r, "fx") * c + spcforc.at(r, "fy") * s;
  }
  double worst_force = 0.0, worst_strain = 0.0, worst_off = 0.0;
  for (std::size_t r = 0; r < elout.rows.size(); ++r) {
    EXPECT_EQ(elout.at(r, "element"), 5.0);
    EXPECT_EQ(elout.at(r, "part"), 1.0);
    EXPECT_EQ(elout.text(r, "type"), "shell");
    EXPECT_EQ(elout.at(r, "points"), 3.0);
    EXPECT_EQ(elout.at(r, "point"), static_cast<double>(r % 3 + 1));
    const double zeta[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};  // 3-point Gauss
    EXPECT_NEAR(elout.at(r, "zeta"), zeta[r % 3], 1e-12);
    const std::string& t = elout.text(r, "time");
    if (std::stod(t) < 0.5 * kEnd)
      continue;
    const double sxx = elout.at(r, "sxx"), syy = elout.at(r, "syy"), sxy = elout.at(r, "sxy");
    const double sigma = c * c * sxx + s * s * syy + 2.0 * c * s * sxy;  // d . sigma . d
    const double f_over_a = force.at(t) / (kW * kT);
    const double closed = kE * std::log1p(u.at(t) / kL);
    worst_force = std::max(worst_force, std::abs(sigma / f_over_a - 1.0));
    worst_strain = std::max(worst_strain, std::abs(sigma / closed - 1.0));
    // sigma d (x) d: sxx = sigma c^2, syy = sigma s^2, sxy = sigma c s; nothing out of plane.
    for (double off : {sxx - sigma * c * c, syy - sigma * s * s, sxy - sigma * c * s,
                       elout.at(r, "szz"), elout.at(r, "syz"), elout.at(r, "szx")})
      worst_off = std::max(worst_off, std::abs(off) / sigma);
    EXPECT_EQ(elout.at(r, "plastic_strain"), 0.0);
  }
  std::printf(
      "elastic strip at 30 deg: sigma against F/A %.3g, against E ln(L/L0) %.3g, "
      "components against sigma d(x)d %.3g (relative)\n",
      worst_force, worst_strain, worst_off);
  EXPECT_LT(worst_force, 1e-3);
  EXPECT_LT(worst_strain, 1e-3);
  EXPECT_LT(worst_off, 1e-9);
}

TEST_P(DeckEloutStrip, PlasticStripFollowsTheBilinearLawAtEveryThicknessPoint) {
  test::TempDir dir;
  const auto out =
      run(dir, "strip_plastic.k", strip_deck(0.0, true, 0.2 / (0.875 * kEnd), GetParam()));
  const Csv elout = read_csv(out / "elout.csv");
  const auto u = stretch_of(read_csv(out / "nodout.csv"), 0.0);
  ASSERT_EQ(elout.rows.size(), 21u * 3u);
  double worst_stress = 0.0, worst_plastic = 0.0, last_plastic = 0.0;
  for (std::size_t r = 0; r < elout.rows.size(); ++r) {
    const std::string& t = elout.text(r, "time");
    if (std::stod(t) < 0.5 * kEnd)
      continue;
    const double eps = std::log1p(u.at(t) / kL);
    const double sigma = (kSigmaY + kH * eps) / (1.0 + kH / kE), plastic = eps - sigma / kE;
    worst_stress = std::max(worst_stress, std::abs(elout.at(r, "sxx") / sigma - 1.0));
    worst_plastic =
        std::max(worst_plastic, std::abs(elout.at(r, "plastic_strain") / plastic - 1.0));
    last_plastic = plastic;
    EXPECT_LT(std::abs(elout.at(r, "syy")), 5e-3 * sigma);
    EXPECT_LT(std::abs(elout.at(r, "sxy")), 5e-3 * sigma);
  }
  std::printf(
      "plastic strip: sxx against (sigma_y + H eps)/(1 + H/E) %.3g, plastic strain "
      "against eps - sigma/E %.3g (relative; plastic strain reached %.4f)\n",
      worst_stress, worst_plastic, last_plastic);
  EXPECT_GT(last_plastic, 0.015);
  EXPECT_LT(worst_stress, 1e-3);
  EXPECT_LT(worst_plastic, 5e-3);
}

INSTANTIATE_TEST_SUITE_P(Elform, DeckEloutStrip, ::testing::Values(2, 16),
                         [](const ::testing::TestParamInfo<int>& i) {
                           return "ELFORM_" + std::to_string(i.param);
                         });

// A bar of 4 x 1 x 1 hexahedra of 1 mm (ELFORM 1, or 2: the mean of its points), symmetry
// planes x = 0, y = 0, z = 0, the face x = 4 pulled: uniaxial stress in every element.
std::string bar_deck(int elform, double speed) {
  const auto nid = [](int i, int j, int k) { return 1 + i + 5 * (j + 2 * k); };
  std::ostringstream os;
  os.precision(17);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n" << kEnd << ",0\n" << outputs(nid(4, 1, 1));
  os << "*DATABASE_HISTORY_SOLID_ID\n3,middle\n";
  os << "*PART\nbar\n1,1,1\n*SECTION_SOLID\n1," << elform << "\n"
     << "*MAT_PLASTIC_KINEMATIC\n1," << kRho << "," << kE << ",0.3," << kSigmaY << "," << kEt
     << ",1.0\n0,0,0\n*NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 4; ++i)
        os << nid(i, j, k) << "," << i << "," << j << "," << k << "\n";
  os << "*ELEMENT_SOLID\n";
  for (int i = 0; i < 4; ++i) {
    os << i + 1 << ",1," << nid(i, 0, 0) << "," << nid(i + 1, 0, 0) << "," << nid(i + 1, 1, 0)
       << "," << nid(i, 1, 0) << "," << nid(i, 0, 1) << "," << nid(i + 1, 0, 1) << ","
       << nid(i + 1, 1, 1) << "," << nid(i, 1, 1) << "\n";
  }
  os << "*BOUNDARY_SPC_NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 4; ++i) {
        const int x = i == 0, y = j == 0, z = k == 0;
        if (x + y + z > 0)
          os << nid(i, j, k) << ",0," << x << "," << y << "," << z << "\n";
      }
  os << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      os << nid(4, j, k) << ",1,0,1," << speed << "\n";
  os << "*END\n";
  return os.str();
}

TEST(DeckElout, PlasticHexahedraFollowTheBilinearLaw) {
  for (int elform : {1, 2}) {
    test::TempDir dir;
    const auto out = run(dir, "bar.k", bar_deck(elform, 0.08 / (0.875 * kEnd)));
    const Csv elout = read_csv(out / "elout.csv");
    const auto u = stretch_of(read_csv(out / "nodout.csv"), 0.0);
    ASSERT_EQ(elout.rows.size(), 21u);
    double worst_stress = 0.0, worst_plastic = 0.0, worst_off = 0.0, last_plastic = 0.0;
    for (std::size_t r = 0; r < elout.rows.size(); ++r) {
      EXPECT_EQ(elout.at(r, "element"), 3.0);
      EXPECT_EQ(elout.text(r, "type"), "solid");
      EXPECT_EQ(elout.at(r, "point"), 1.0);
      EXPECT_EQ(elout.at(r, "points"), 1.0);
      EXPECT_TRUE(elout.text(r, "zeta").empty());
      const std::string& t = elout.text(r, "time");
      if (std::stod(t) < 0.5 * kEnd)
        continue;
      const double eps = std::log1p(u.at(t) / 4.0);
      const double sigma = (kSigmaY + kH * eps) / (1.0 + kH / kE), plastic = eps - sigma / kE;
      worst_stress = std::max(worst_stress, std::abs(elout.at(r, "sxx") / sigma - 1.0));
      worst_plastic =
          std::max(worst_plastic, std::abs(elout.at(r, "plastic_strain") / plastic - 1.0));
      for (const char* c : {"syy", "szz", "sxy", "syz", "szx"})
        worst_off = std::max(worst_off, std::abs(elout.at(r, c)) / sigma);
      last_plastic = plastic;
    }
    std::printf(
        "hexahedra ELFORM %d: sxx against the bilinear law %.3g, plastic strain %.3g, "
        "other components %.3g (relative; plastic strain reached %.4f)\n",
        elform, worst_stress, worst_plastic, worst_off, last_plastic);
    EXPECT_GT(last_plastic, 0.015);
    EXPECT_LT(worst_stress, 1e-3) << "ELFORM " << elform;
    EXPECT_LT(worst_plastic, 1e-3) << "ELFORM " << elform;
    EXPECT_LT(worst_off, 1e-3) << "ELFORM " << elform;
  }
}

}  // namespace
}  // namespace plyform
