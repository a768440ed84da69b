#include "plyform/app/probe_csv.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "plyform/app/path_csv.hpp"

namespace plyform::app {
namespace {

enum Column { kTime, kGap, kStress, kPressure, kForce, kTemperature, kSlipX, kSlipY, kColumns };

struct Alias {
  std::string_view name;
  Column column;
};
constexpr std::array<Alias, 14> kAliases{{{"time", kTime},
                                          {"t", kTime},
                                          {"gap", kGap},
                                          {"opening", kGap},
                                          {"separation", kGap},
                                          {"stress", kStress},
                                          {"traction", kStress},
                                          {"tension", kStress},
                                          {"pressure", kPressure},
                                          {"force", kForce},
                                          {"load", kForce},
                                          {"temperature", kTemperature},
                                          {"slip_x", kSlipX},
                                          {"slip_y", kSlipY}}};

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r\"");
  const auto e = s.find_last_not_of(" \t\r\"");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ','))
    cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',')
    cells.emplace_back();
  return cells;
}

/// "Force [N]" -> "force": lower case, a unit in brackets or parentheses dropped.
std::string column_key(const std::string& header) {
  std::string s = header.substr(0, header.find_first_of("[("));
  s = trim(s);
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

ProbeCurve read_probe_csv(const std::filesystem::path& file, const ProbeCsvOptions& options) {
  std::ifstream in(file);
  const std::string name = file.string();
  if (!in)
    throw PathError(name + ": cannot open the curve file");
  ProbeCurve result;
  result.curve.name = file.filename().string();
  const auto fail = [&](int line, const std::string& what) {
    throw PathError(fmt::format("{}:{}: {}", name, line, what));
  };

  std::string line;
  int line_no = 0;
  std::array<int, kColumns> column{};
  column.fill(-1);
  std::array<std::string, kColumns> header_of{};
  std::vector<std::string> ignored;
  std::size_t n_cells = 0;
  while (std::getline(in, line)) {
    ++line_no;
    line = trim(line);
    if (line.empty() || line[0] == '#')
      continue;
    const auto cells = split(line);
    n_cells = cells.size();
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string key = column_key(cells[c]);
      const auto alias = std::find_if(kAliases.begin(), kAliases.end(),
                                      [&](const Alias& a) { return a.name == key; });
      if (alias == kAliases.end()) {
        ignored.push_back(cells[c]);
        continue;
      }
      if (column[alias->column] >= 0) {
        fail(line_no, fmt::format("columns '{}' and '{}' give the same quantity",
                                  header_of[alias->column], cells[c]));
      }
      column[alias->column] = static_cast<int>(c);
      header_of[alias->column] = cells[c];
    }
    break;
  }
  const int tractions = (column[kStress] >= 0) + (column[kPressure] >= 0) + (column[kForce] >= 0);
  if (tractions == 0) {
    fail(line_no,
         "no traction column: name one 'stress' (or 'traction', positive in tension), "
         "'pressure' (positive in compression) or 'force' (positive in tension, with --area)");
  }
  if (tractions > 1)
    fail(line_no, "more than one traction column (stress, pressure, force): keep one");
  const Column traction = column[kStress] >= 0     ? kStress
                          : column[kPressure] >= 0 ? kPressure
                                                   : kForce;
  result.traction_column = header_of[traction];
  if (traction == kForce && !options.area) {
    fail(line_no, fmt::format("column '{}' is a force: give the probe area with --area "
                              "(stress = force / area)",
                              header_of[kForce]));
  }
  const bool has_time = column[kTime] >= 0;
  const bool has_gap = column[kGap] >= 0;
  if (!has_gap && !has_time)
    fail(line_no, "needs a 'gap' (or 'opening') column, or a 'time' column and --rate");
  if (!(has_time && has_gap) && !options.rate) {
    fail(line_no, fmt::format("has a '{}' column but no '{}' column: give the opening rate "
                              "with --rate",
                              has_gap ? "gap" : "time", has_gap ? "time" : "gap"));
  }
  if (has_time && has_gap && options.rate) {
    result.notes.push_back("--rate not used: the file gives the time and the gap of every point");
  }
  if (!ignored.empty()) {
    std::string list;
    for (const std::string& s : ignored)
      list += (list.empty() ? "" : ", ") + s;
    result.notes.push_back("columns not used: " + list);
  }

  struct Row {
    std::array<double, kColumns> v{};
    int line = 0;
  };
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    ++line_no;
    line = trim(line);
    if (line.empty() || line[0] == '#')
      continue;
    const auto cells = split(line);
    if (cells.size() != n_cells) {
      fail(line_no, fmt::format("expected {} values, found {}", n_cells, cells.size()));
    }
    Row row;
    row.line = line_no;
    for (int k = 0; k < kColumns; ++k) {
      if (column[k] < 0)
        continue;
      const std::string& text = cells[static_cast<std::size_t>(column[k])];
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE ||
          !std::isfinite(v)) {
        fail(line_no,
             fmt::format("column {}: expected a finite number, got '{}'", header_of[k], text));
      }
      row.v[static_cast<std::size_t>(k)] = v;
    }
    rows.push_back(row);
  }
  if (rows.size() < 3)
    throw PathError(name + ": a curve needs at least three rows after the header");

  const double t0 = rows.front().v[kTime];
  const double g0 = rows.front().v[kGap];
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    law::PathPoint p;
    if (has_time && has_gap) {
      p.time = r.v[kTime];
      p.gap = r.v[kGap];
    } else if (has_time) {
      p.time = r.v[kTime];
      p.gap = *options.rate * (p.time - t0);
    } else {
      p.gap = r.v[kGap];
      p.time = (p.gap - g0) / *options.rate;
      if (i > 0 && !(p.gap > rows[i - 1].v[kGap])) {
        fail(r.line, fmt::format("column {}: the opening does not increase ({} after {}); "
                                 "without a time column the rate gives the times of a "
                                 "monotone opening only: add the time of every point to fit a "
                                 "path that holds or closes",
                                 header_of[kGap], p.gap, rows[i - 1].v[kGap]));
      }
    }
    if (i > 0 && !(p.time > result.curve.path.back().time)) {
      fail(r.line,
           fmt::format("column {}: the time must increase from row to row", header_of[kTime]));
    }
    p.slip[0] = r.v[kSlipX];
    p.slip[1] = r.v[kSlipY];
    p.temperature =
        column[kTemperature] >= 0 ? r.v[kTemperature] : options.temperature.value_or(0.0);
    result.curve.path.push_back(p);
    const double value = r.v[static_cast<std::size_t>(traction)];
    result.curve.stress.push_back(traction == kPressure ? -value
                                  : traction == kForce  ? value / *options.area
                                                        : value);
  }
  result.curve.area = options.area.value_or(0.0);
  return result;
}

}  // namespace plyform::app
