#pragma once
// States of a run for ParaView: OUTDIR/results_NNNN.vtu (VTK XML unstructured grid, raw
// binary appended data with UInt64 block headers) and OUTDIR/results.pvd (the time series),
// both written under a temporary name and renamed, so a run that stops at any point leaves a
// valid series of every state written so far.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace plyform::output {

/// VTK cell type codes (vtkCellType.h) of the cells plyform writes.
namespace vtk_cell {
inline constexpr std::uint8_t triangle = 5;
inline constexpr std::uint8_t quad = 9;
inline constexpr std::uint8_t tetra = 10;
inline constexpr std::uint8_t hexahedron = 12;
inline constexpr std::uint8_t wedge = 13;
}  // namespace vtk_cell

/// A Float64 point or cell array: `values.size() == count * components`, tuples interleaved
/// (a 3-vector as x0 y0 z0 x1 y1 z1 ...). Values are written bit for bit (NaN included).
struct DataArray {
  std::string name;
  int components = 1;
  std::span<const double> values;
};

/// An Int64 point or cell array of one component: deck ids (`node_id`, `element_id`, `part`).
struct IdArray {
  std::string name;
  std::span<const std::int64_t> values;
};

/// One state of an unstructured grid; every span is borrowed for the duration of
/// VtuSeries::write_state only.
struct GridPiece {
  std::span<const double> x, y, z;               ///< point coordinates, current configuration
  std::span<const std::int64_t> connectivity;    ///< point indices (0-based), VTK node order
  std::span<const std::int64_t> offsets;         ///< end offset in connectivity of each cell
  std::span<const std::uint8_t> cell_types;      ///< one vtk_cell code per cell
  std::vector<DataArray> point_data, cell_data;  ///< Float64 arrays
  std::vector<IdArray> point_ids, cell_ids;      ///< Int64 arrays
};

/// Writes OUTDIR/results_NNNN.vtu (NNNN = 0000, 0001, ...; more digits past 9999) per state and
/// rewrites OUTDIR/results.pvd after every state. Files of an earlier run with higher numbers
/// are left alone (results.pvd does not list them).
class VtuSeries {
 public:
  /// Creates `outdir` (and parents) when missing; throws std::runtime_error naming it on failure.
  explicit VtuSeries(std::filesystem::path outdir);

  /// Writes one state at simulated time `time` (must be finite). Throws std::invalid_argument
  /// when the piece is inconsistent (sizes, offsets, connectivity out of range) and
  /// std::runtime_error naming the file on I/O failure; then nothing is added to the series.
  void write_state(double time, const GridPiece& piece);

  /// A restart: the series is the first `times.size()` states of the run it continues
  /// (results_0000.vtu ... as written then); rewrites results.pvd with them, and the next state
  /// takes the next number (a later state of the interrupted run is overwritten).
  void resume(std::span<const double> times);
  /// The times of the states in the series, in order.
  [[nodiscard]] std::vector<double> times() const;

  [[nodiscard]] std::size_t states_written() const { return states_.size(); }
  [[nodiscard]] const std::filesystem::path& outdir() const { return outdir_; }
  [[nodiscard]] std::filesystem::path pvd_path() const { return outdir_ / "results.pvd"; }

 private:
  static std::string file_name_of(std::size_t k);
  void write_pvd() const;

  std::filesystem::path outdir_;
  std::vector<std::pair<double, std::string>> states_;  ///< time, file name
  std::vector<double> points_;                          ///< interleaved coordinates (reused)
  std::string header_;                                  ///< XML head of a .vtu (reused)
};

/// Checks a piece and throws std::invalid_argument describing the first inconsistency.
void validate_piece(const GridPiece& piece);

}  // namespace plyform::output
