#include "plyform/app/path_csv.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace plyform::app {
namespace {

constexpr std::array<const char*, 5> kColumns{"time", "gap", "slip_x", "slip_y", "temperature"};

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
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

}  // namespace

std::vector<law::PathPoint> read_path_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  const std::string name = file.string();
  if (!in)
    throw PathError(name + ": cannot open the path file");
  std::string line;
  int line_no = 0;
  std::array<int, kColumns.size()> column{};
  column.fill(-1);
  std::size_t n_cells = 0;
  // Header: the first line that is not blank and not a '#' comment.
  while (std::getline(in, line)) {
    ++line_no;
    line = trim(line);
    if (line.empty() || line[0] == '#')
      continue;
    const auto cells = split(line);
    n_cells = cells.size();
    for (std::size_t c = 0; c < cells.size(); ++c) {
      bool known = false;
      for (std::size_t k = 0; k < kColumns.size(); ++k) {
        if (cells[c] == kColumns[k]) {
          if (column[k] >= 0) {
            throw PathError(name + ":" + std::to_string(line_no) + ": column '" + cells[c] +
                            "' appears twice");
          }
          column[k] = static_cast<int>(c);
          known = true;
        }
      }
      if (!known) {
        throw PathError(name + ":" + std::to_string(line_no) + ": unknown column '" + cells[c] +
                        "' (expected time,gap,slip_x,slip_y,temperature)");
      }
    }
    break;
  }
  for (std::size_t k = 0; k < kColumns.size(); ++k) {
    if (column[k] < 0) {
      throw PathError(name + ":" + std::to_string(line_no) + ": missing column '" + kColumns[k] +
                      "' (the header must name time,gap,slip_x,slip_y,temperature)");
    }
  }

  std::vector<law::PathPoint> path;
  while (std::getline(in, line)) {
    ++line_no;
    line = trim(line);
    if (line.empty() || line[0] == '#')
      continue;
    const auto cells = split(line);
    if (cells.size() != n_cells) {
      throw PathError(name + ":" + std::to_string(line_no) + ": expected " +
                      std::to_string(n_cells) + " values, found " + std::to_string(cells.size()));
    }
    std::array<double, kColumns.size()> v{};
    for (std::size_t k = 0; k < kColumns.size(); ++k) {
      const std::string& text = cells[static_cast<std::size_t>(column[k])];
      char* end = nullptr;
      errno = 0;
      v[k] = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE ||
          !std::isfinite(v[k])) {
        throw PathError(name + ":" + std::to_string(line_no) + ": column " + kColumns[k] +
                        ": expected a finite number, got '" + text + "'");
      }
    }
    if (!path.empty() && !(v[0] > path.back().time)) {
      throw PathError(name + ":" + std::to_string(line_no) +
                      ": column time: must increase from row to row");
    }
    law::PathPoint pt;
    pt.time = v[0];
    pt.gap = v[1];
    pt.slip[0] = v[2];
    pt.slip[1] = v[3];
    pt.temperature = v[4];
    path.push_back(pt);
  }
  if (path.size() < 2) {
    throw PathError(name + ": the path needs at least two rows after the header");
  }
  return path;
}

}  // namespace plyform::app
