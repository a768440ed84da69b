#pragma once
// PATH.csv of `plyform law`: columns time,gap,slip_x,slip_y,temperature (by header name, in
// any order; every column required).

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "plyform/law/point_driver.hpp"

namespace plyform::app {

/// A malformed path file: the message names the file, line and column.
class PathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads the path; throws PathError.
[[nodiscard]] std::vector<law::PathPoint> read_path_csv(const std::filesystem::path& file);

}  // namespace plyform::app
