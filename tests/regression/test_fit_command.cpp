// `plyform fit` end to end (in-process): probe force curves made by `plyform law`'s own driver
// with noise, fitted back from a deck's constants; FIT.k read back through the keyword reader
// and `plyform check`; the file layouts the command accepts; its refusals and exit codes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "plyform/app/commands.hpp"
#include "plyform/keyword/read_deck.hpp"
#include "plyform/law/point_driver.hpp"
#include "plyform/law/user_constants.hpp"
#include "plyform/setup/cohesive_law.hpp"
#include "temp_dir.hpp"

namespace plyform::app {
namespace {

// The probe example's law: C_N 30 MPa/mm, sigma_max 0.3 MPa, eta 3e-3 MPa mm s, bonded at 0.
constexpr double kCn = 30.0, kSmax = 0.3, kEta = 3e-3, kArea = 78.54;

std::string deck(double cn, double smax, double eta) {
  std::ostringstream os;
  os << "*KEYWORD\n*USER_INTERFACE_FRICTION\n         7        11         0\n"
     << "1," << cn << "," << smax << "," << smax << ",20.0,20.0," << eta << ",0.0\n"
     << "0.0,1.0,1.0E-6\n*END\n";
  return os.str();
}

law::Parameters truth() {
  const std::vector<std::optional<double>> uc{1.0,  kCn, kSmax, kSmax, 20.0, 20.0,
                                              kEta, 0.0, 0.0,   1.0,   1e-6};
  return law::from_user_constants(uc, {}).parameters;
}

/// time,gap,force [N] of an opening at rate v to 8 g_c (300 points), Gaussian noise in N.
std::string force_curve(double v, double noise, unsigned seed) {
  std::vector<law::PathPoint> path(301);
  const double g_end = 8.0 * kSmax / kCn;
  for (std::size_t i = 0; i < path.size(); ++i) {
    path[i].gap = g_end * static_cast<double>(i) / 300.0;
    path[i].time = path[i].gap / v;
    path[i].temperature = 20.0;
  }
  const law::Law law(truth());
  const auto samples = law::drive(law, path, {kCn});
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  std::ostringstream os;
  os.precision(12);
  os << "# probe tack test, synthetic\ntime [s],gap [mm],force [N]\n";
  for (const auto& s : samples)
    os << s.at.time << "," << s.at.gap << "," << -s.response.pressure * kArea + gauss(rng) << "\n";
  return os.str();
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// The fitted value of a constant in the report ("CN  start  fitted  std ...").
std::pair<double, double> reported(const std::string& report, const std::string& name) {
  std::istringstream in(report);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first;
    double start = 0, value = 0, se = 0;
    if (words >> first && first == name && words >> start >> value >> se)
      return {value, se};
  }
  ADD_FAILURE() << "no line for " << name << " in\n" << report;
  return {NAN, NAN};
}

TEST(FitCommand, NoisyForceCurvesAtTwoRatesFitBackAndFitKReadsBack) {
  test::TempDir dir;
  FitOptions o;
  o.curves = {dir.write("v003.csv", force_curve(0.003, 0.2, 1)),
              dir.write("v03.csv", force_curve(0.03, 0.2, 2))};
  o.deck = dir.write("base.k", deck(0.6 * kCn, 1.4 * kSmax, 0.5 * kEta));
  o.areas = {kArea};
  o.output = dir.path() / "out" / "probe_fit.k";
  o.plot = false;
  std::ostringstream out, err;
  ASSERT_EQ(run_fit(o, out, err), 0) << out.str() << err.str();
  const auto [cn, cn_se] = reported(out.str(), "CN");
  const auto [smax, smax_se] = reported(out.str(), "SMAX");
  const auto [eta, eta_se] = reported(out.str(), "ETA");
  EXPECT_LT(std::abs(cn - kCn), 3.0 * cn_se) << out.str();
  EXPECT_LT(std::abs(smax - kSmax), 3.0 * smax_se) << out.str();
  EXPECT_LT(std::abs(eta - kEta), 3.0 * eta_se) << out.str();
  EXPECT_NE(out.str().find("(force: RMS"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / "probe_fit_curves.csv"));

  // FIT.k through the keyword reader: the card of NOSID 7 with the fitted constants, valid.
  const keyword::ReadResult back = keyword::read_deck(*o.output);
  ASSERT_TRUE(back.ok()) << read(*o.output);
  ASSERT_EQ(back.model.user_interface_frictions.size(), 1u);
  const auto& uif = back.model.user_interface_frictions.front();
  EXPECT_EQ(uif.contact_id, 7);
  const setup::CohesiveLawBuild built = setup::build_cohesive_law(back.model, uif);
  ASSERT_TRUE(built.parameters) << read(*o.output);
  EXPECT_NEAR(built.parameters->cn, cn, 1e-5 * cn);
  EXPECT_NEAR(built.parameters->sigma_max.lo, smax, 1e-5 * smax);
  EXPECT_EQ(built.parameters->sigma_max.hi, built.parameters->sigma_max.lo);
  EXPECT_NEAR(built.parameters->eta, eta, 1e-5 * eta);
  EXPECT_EQ(built.parameters->t_lo, 20.0);  // fixed constants carried over from the deck
  EXPECT_EQ(built.parameters->bond_tol, 1e-6);
  std::ostringstream check_out, check_err;
  EXPECT_EQ(run_check(*o.output, check_out, check_err), 0) << check_err.str();
  std::printf("%s", out.str().c_str());
}

TEST(FitCommand, AGapOrATimeColumnWithTheRateAreCurves) {
  test::TempDir dir;
  const double v = 0.01;
  std::istringstream in(force_curve(v, 0.0, 1));
  std::string line, gap_only = "opening,stress\n", time_only = "t,traction\n";
  std::getline(in, line);
  std::getline(in, line);
  while (std::getline(in, line)) {
    double t, g, f;
    char c;
    std::istringstream(line) >> t >> c >> g >> c >> f;
    gap_only += std::to_string(g) + "," + std::to_string(f / kArea) + "\n";
    time_only += std::to_string(t) + "," + std::to_string(f / kArea) + "\n";
  }
  for (const auto& [file, text] : {std::pair{"gap.csv", gap_only}, {"time.csv", time_only}}) {
    FitOptions o;
    o.curves = {dir.write(file, text)};
    o.deck = dir.write("base.k", deck(0.7 * kCn, 1.3 * kSmax, kEta));
    o.free = "CN,SMAX";
    o.rates = {v};
    o.output = dir.path() / (std::string(file) + ".k");
    o.plot = false;
    std::ostringstream out, err;
    ASSERT_EQ(run_fit(o, out, err), 0) << file << "\n" << out.str() << err.str();
    EXPECT_NEAR(reported(out.str(), "CN").first, kCn, 0.01 * kCn) << out.str();
    EXPECT_NEAR(reported(out.str(), "SMAX").first, kSmax, 0.01 * kSmax) << out.str();
  }
}

TEST(FitCommand, InputErrorsNameTheFileAndTheReason) {
  test::TempDir dir;
  const auto base = dir.write("base.k", deck(kCn, kSmax, kEta));
  const auto run = [&](FitOptions o) {
    o.deck = base;
    o.plot = false;
    o.output = dir.path() / "x.k";
    std::ostringstream out, err;
    const int rc = run_fit(o, out, err);
    return std::pair{rc, err.str()};
  };
  FitOptions o;
  o.curves = {dir.write("force.csv", force_curve(0.01, 0.0, 1))};
  auto [rc, msg] = run(o);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(msg.find("force.csv:2: column 'force [N]' is a force: give the probe area with --area"),
            std::string::npos)
      << msg;

  o.curves = {dir.write("none.csv", "time,gap\n0,0\n1,1\n2,2\n")};
  std::tie(rc, msg) = run(o);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(msg.find("none.csv:1: no traction column"), std::string::npos) << msg;

  o.curves = {dir.write("back.csv", "gap,stress\n0,0\n0.01,0.3\n0.005,0.1\n0.02,0.01\n")};
  o.rates = {0.01};
  std::tie(rc, msg) = run(o);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(msg.find("back.csv:4: column gap: the opening does not increase"), std::string::npos)
      << msg;

  o.rates = {0.01, 0.02};
  std::tie(rc, msg) = run(o);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(msg.find("--rate takes one value for all curves or one per curve (1), got 2"),
            std::string::npos)
      << msg;

  // A curve cut before its peak: the law cannot be fitted to it, and the message says why.
  std::string text = "time,gap,force\n";
  std::istringstream all(force_curve(0.01, 0.0, 1));
  std::string row;
  std::getline(all, row);
  std::getline(all, row);
  for (int i = 0; i < 30 && std::getline(all, row); ++i)
    text += row + "\n";
  o.curves = {dir.write("cut.csv", text)};
  o.rates.clear();
  o.areas = {kArea};
  std::tie(rc, msg) = run(o);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(msg.find("curve cut.csv: no peak"), std::string::npos) << msg;

  o.curves = {dir.write("ok.csv", force_curve(0.01, 0.0, 1))};
  o.free = "CN,MU_LO";
  std::tie(rc, msg) = run(o);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(msg.find("--free: constant MU_LO (UC13"), std::string::npos) << msg;
}

TEST(FitCommand, AFitThatIsNotMeaningfulExitsThreeWithoutFitK) {
  // Quasi-static curves with noise: eta leaves no trace, so fitting it means nothing.
  test::TempDir dir;
  FitOptions o;
  o.curves = {dir.write("slow.csv", force_curve(1e-5, 0.3, 4))};
  o.areas = {kArea};
  o.deck = dir.write("base.k", deck(kCn, kSmax, kEta));
  o.output = dir.path() / "slow_fit.k";
  o.plot = false;
  std::ostringstream out, err;
  EXPECT_EQ(run_fit(o, out, err), 3) << out.str() << err.str();
  EXPECT_NE(err.str().find("the fit is not meaningful"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("ETA"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(*o.output));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "slow_fit_curves.csv"));
}

TEST(FitCommand, AMissingPythonOnlySkipsThePlot) {
  test::TempDir dir;
  FitOptions o;
  o.curves = {dir.write("v.csv", force_curve(0.01, 0.0, 1))};
  o.areas = {kArea};
  o.free = "CN,SMAX";
  o.output = dir.path() / "fit.k";
  ::setenv("PLYFORM_PYTHON", (dir.path() / "no_python").c_str(), 1);
  std::ostringstream out, err;
  const int rc = run_fit(o, out, err);
  ::unsetenv("PLYFORM_PYTHON");
  EXPECT_EQ(rc, 0) << out.str() << err.str();
  EXPECT_NE(err.str().find("note: no plot: Python interpreter"), std::string::npos) << err.str();
  EXPECT_TRUE(std::filesystem::exists(*o.output));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "fit_curves.png"));
  // Without --deck the start comes from the curves and says so.
  EXPECT_NE(out.str().find("start: the curves (no --deck)"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace plyform::app
