#include "plyform/output/csv_history.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "scratch_dir.hpp"

namespace plyform::output {
namespace {

using testing::read_lines;
using testing::read_text;
using testing::ScratchDir;
using testing::split;

double parse_double(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  EXPECT_EQ(ec, std::errc{}) << text;
  EXPECT_EQ(end, text.data() + text.size()) << text;
  return value;
}

TEST(CsvHistory, HeaderThenRowsFlushedAtOnce) {
  ScratchDir dir;
  CsvHistory csv(dir / "h.csv", {"time", "a", "b"});
  EXPECT_EQ(read_text(dir / "h.csv"), "time,a,b\n");  // flushed before any row
  csv.row({0.0, 1.5, -2.0});
  EXPECT_EQ(read_text(dir / "h.csv"), "time,a,b\n0,1.5,-2\n");  // visible while still open
  csv.row({1e-05, 0.1, 1e+300});
  EXPECT_EQ(read_text(dir / "h.csv"), "time,a,b\n0,1.5,-2\n1e-05,0.1,1e+300\n");
}

TEST(CsvHistory, DoublesRoundTripExactly) {
  ScratchDir dir;
  std::mt19937_64 rng(42);
  std::vector<double> values;
  for (int i = 0; i < 3000; ++i) {
    const auto bits = rng();
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) {
      values.push_back(v);
    }
  }
  for (const double v : {0.1, 1.0 / 3.0, -0.0, 5e-324, std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::min(), 123456789012345678.0, 2.5e-7}) {
    values.push_back(v);
  }
  while (values.size() % 4 != 0) {
    values.push_back(1.0);
  }
  {
    CsvHistory csv(dir / "r.csv", {"a", "b", "c", "d"});
    csv.rows(values);
  }
  const auto lines = read_lines(dir / "r.csv");
  ASSERT_EQ(lines.size(), 1 + values.size() / 4);
  std::size_t k = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    for (const std::string& cell : split(lines[i])) {
      const double back = parse_double(cell);
      EXPECT_EQ(std::memcmp(&back, &values[k], sizeof back), 0) << cell;
      ++k;
    }
  }
  EXPECT_EQ(k, values.size());
}

TEST(CsvHistory, NonFiniteValuesAreWords) {
  ScratchDir dir;
  {
    CsvHistory csv(dir / "n.csv", {"a", "b", "c"});
    csv.row({std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
             -std::numeric_limits<double>::infinity()});
  }
  EXPECT_EQ(read_lines(dir / "n.csv").at(1), "nan,inf,-inf");
}

TEST(CsvHistory, MixedRowsQuoteText) {
  ScratchDir dir;
  CsvHistory csv(dir / "m.csv", {"time", "node", "state", "note"});
  const CsvCell cells[] = {0.25, std::int64_t{9007199254740993}, std::string_view("open"),
                           std::string_view("a,\"b\"")};
  csv.row_mixed(cells);
  EXPECT_EQ(read_text(dir / "m.csv"),
            "time,node,state,note\n0.25,9007199254740993,open,\"a,\"\"b\"\"\"\n");
}

TEST(CsvHistory, WrongCountsThrow) {
  ScratchDir dir;
  CsvHistory csv(dir / "w.csv", {"a", "b"});
  EXPECT_THROW(csv.row({1.0}), std::invalid_argument);
  EXPECT_THROW(csv.rows(std::vector<double>{1.0, 2.0, 3.0}), std::invalid_argument);
  csv.real(1.0);
  EXPECT_THROW(csv.end_row(), std::logic_error);
  csv.real(2.0);
  EXPECT_THROW(csv.real(3.0), std::logic_error);
  csv.end_row();
  csv.flush();
  EXPECT_EQ(read_text(dir / "w.csv"), "a,b\n1,2\n");
  EXPECT_THROW(CsvHistory(dir / "e.csv", {}), std::invalid_argument);
}

TEST(CsvHistory, OpenFailureNamesTheFile) {
  ScratchDir dir;
  const auto bad = dir / "missing_folder" / "x.csv";
  try {
    CsvHistory csv(bad, {"a"});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
  }
}

TEST(CsvHistory, PartialRowIsNotWrittenAtClose) {
  ScratchDir dir;
  {
    CsvHistory csv(dir / "p.csv", {"a", "b"});
    csv.real(1.0);
    csv.real(2.0);
    csv.end_row();  // complete, not flushed
    csv.real(3.0);  // incomplete
  }
  EXPECT_EQ(read_text(dir / "p.csv"), "a,b\n1,2\n");
}

TEST(HistoryFiles, GlstatHeaderAndRow) {
  ScratchDir dir;
  GlstatFile glstat(dir / std::string(glstat_file_name));
  glstat.write({.time = 1e-3,
                .dt = 2e-7,
                .kinetic = 1.5,
                .internal = 2.5,
                .hourglass = 0.0,
                .contact = 0.125,
                .external_work = 4.0,
                .total = 4.125,
                .energy_ratio = 1.03125});
  const auto lines = read_lines(dir / "glstat.csv");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0],
            "time,dt,kinetic,internal,hourglass,contact,external_work,total,energy_ratio");
  EXPECT_EQ(lines[1], "0.001,2e-07,1.5,2.5,0,0.125,4,4.125,1.03125");
}

TEST(HistoryFiles, NodoutNodeIsAnInteger) {
  ScratchDir dir;
  NodoutFile nodout(dir / std::string(nodout_file_name));
  const NodoutRow rows[] = {{.time = 0.5,
                             .node = 100000001,
                             .x = 1,
                             .y = 2,
                             .z = 3,
                             .ux = 0.1,
                             .uy = 0.2,
                             .uz = 0.3,
                             .vx = -1,
                             .vy = -2,
                             .vz = -3},
                            {.time = 0.5,
                             .node = 7,
                             .x = 0,
                             .y = 0,
                             .z = 0,
                             .ux = 0,
                             .uy = 0,
                             .uz = 0,
                             .vx = 0,
                             .vy = 0,
                             .vz = 1e20}};
  nodout.write(rows);
  const auto lines = read_lines(dir / "nodout.csv");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "time,node,x,y,z,ux,uy,uz,vx,vy,vz");
  EXPECT_EQ(lines[1], "0.5,100000001,1,2,3,0.1,0.2,0.3,-1,-2,-3");
  EXPECT_EQ(lines[2], "0.5,7,0,0,0,0,0,0,0,0,1e+20");
}

TEST(HistoryFiles, RcforcAndCohesive) {
  ScratchDir dir;
  RcforcFile rcforc(dir / std::string(rcforc_file_name));
  const RcforcRow forces[] = {{.time = 1, .interface = 3, .fx = 1, .fy = -2, .fz = 0.5}};
  rcforc.write(forces);
  CohesiveFile cohesive(dir / std::string(cohesive_file_name));
  const CohesiveRow rows[] = {{.time = 1,
                               .interface = 3,
                               .node = 12,
                               .state = "bonded",
                               .gap = -1e-6,
                               .pressure = 2e6,
                               .tau = 0,
                               .beta = 1}};
  cohesive.write(rows);
  EXPECT_EQ(read_text(dir / "rcforc.csv"), "time,interface,fx,fy,fz\n1,3,1,-2,0.5\n");
  EXPECT_EQ(read_text(dir / "cohesive.csv"),
            "time,interface,node,state,gap,pressure,tau,beta\n1,3,12,bonded,-1e-06,2000000,0,1\n");
}

}  // namespace
}  // namespace plyform::output
