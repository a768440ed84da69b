#pragma once
// History files of a run (glstat.csv, nodout.csv, rcforc.csv, cohesive.csv, see product.md):
// a header line, then one line per row; doubles in the shortest form that reads back to the
// same value, integers as integers; every row (or batch of rows) flushed at once, so nothing
// written is lost when the run stops.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace plyform::output {

/// One cell of a mixed row.
using CsvCell = std::variant<double, std::int64_t, std::string_view>;

/// A CSV file with a fixed set of columns. Move-only; the file is closed on destruction.
class CsvHistory {
 public:
  /// Creates (truncates) `file` and writes the header line; throws std::runtime_error naming
  /// the file on failure, std::invalid_argument when `columns` is empty.
  CsvHistory(std::filesystem::path file, std::vector<std::string> columns);
  /// Goes on with `file` as it was after its first `resume_at` bytes (a restart: what a run
  /// wrote after its checkpoint is cut off). With no value, as the constructor above. Throws
  /// std::runtime_error naming the file when it is missing, shorter than that, or has another
  /// header line.
  CsvHistory(std::filesystem::path file, std::vector<std::string> columns,
             std::optional<std::uint64_t> resume_at);
  CsvHistory(CsvHistory&&) noexcept;
  CsvHistory& operator=(CsvHistory&&) noexcept;
  ~CsvHistory();

  /// One row of doubles (`values.size() == columns().size()`), flushed.
  void row(std::span<const double> values);
  void row(std::initializer_list<double> values) { row(std::span(values.begin(), values.size())); }
  /// Several rows at once, row-major (`values.size()` a multiple of the column count), one flush.
  void rows(std::span<const double> values);
  /// One row of doubles, integers and text (quoted when it holds a comma, quote or newline).
  void row_mixed(std::span<const CsvCell> cells);
  void row_mixed(std::initializer_list<CsvCell> cells) {
    row_mixed(std::span(cells.begin(), cells.size()));
  }

  /// Cell-by-cell form for callers that build rows themselves: real/integer/text append cells,
  /// end_row() checks the count and ends the line, flush() writes everything out.
  void real(double value);
  void integer(std::int64_t value);
  void text(std::string_view value);
  void end_row();
  void flush();

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] const std::vector<std::string>& columns() const { return columns_; }
  /// Bytes in the file after the last flush (header included).
  [[nodiscard]] std::uint64_t bytes_written() const { return written_; }

 private:
  struct Closer {
    void operator()(std::FILE* f) const;
  };
  void separator();
  CsvHistory(std::filesystem::path file, std::vector<std::string> columns, std::uint64_t resume_at,
             int tag);

  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::unique_ptr<std::FILE, Closer> file_;
  std::string line_;          ///< pending text, written at flush()
  std::size_t complete_ = 0;  ///< length of line_ holding complete rows
  std::size_t cells_ = 0;     ///< cells in the current row
  std::uint64_t written_ = 0;
};

// ---- The history files of product.md ------------------------------------------------------

inline constexpr std::string_view glstat_file_name = "glstat.csv";
inline constexpr std::array<std::string_view, 9> glstat_columns = {
    "time",          "dt",    "kinetic",     "internal", "hourglass", "contact",
    "external_work", "total", "energy_ratio"};

/// One line of glstat.csv: global energies (model energy unit), time and step (model time unit).
struct GlstatRow {
  double time = 0.0;
  double dt = 0.0;
  double kinetic = 0.0;
  double internal = 0.0;
  double hourglass = 0.0;
  double contact = 0.0;
  double external_work = 0.0;
  double total = 0.0;
  double energy_ratio = 0.0;  ///< total / (initial total + external work), dimensionless
};

inline constexpr std::string_view nodout_file_name = "nodout.csv";
inline constexpr std::array<std::string_view, 11> nodout_columns = {
    "time", "node", "x", "y", "z", "ux", "uy", "uz", "vx", "vy", "vz"};

/// One line of nodout.csv: a history node (deck id) with its current coordinates,
/// displacement and velocity (model length and time units).
struct NodoutRow {
  double time = 0.0;
  std::int64_t node = 0;
  double x = 0.0, y = 0.0, z = 0.0;
  double ux = 0.0, uy = 0.0, uz = 0.0;
  double vx = 0.0, vy = 0.0, vz = 0.0;
};

inline constexpr std::string_view rcforc_file_name = "rcforc.csv";
inline constexpr std::array<std::string_view, 5> rcforc_columns = {"time", "interface", "fx", "fy",
                                                                   "fz"};

/// One line of rcforc.csv: resultant force (model force unit, global axes) on the slave side
/// of contact interface `interface` (deck id).
struct RcforcRow {
  double time = 0.0;
  std::int64_t interface = 0;
  double fx = 0.0, fy = 0.0, fz = 0.0;
};

inline constexpr std::string_view cohesive_file_name = "cohesive.csv";
inline constexpr std::array<std::string_view, 8> cohesive_columns = {
    "time", "interface", "node", "state", "gap", "pressure", "tau", "beta"};

/// One line of cohesive.csv: a history node that is a slave node of cohesive interface
/// `interface`; `state` as a word; gap (length), pressure and tau (stress, pressure positive in
/// compression), beta (adhesion intensity, dimensionless).
struct CohesiveRow {
  double time = 0.0;
  std::int64_t interface = 0;
  std::int64_t node = 0;
  std::string_view state;
  double gap = 0.0, pressure = 0.0, tau = 0.0, beta = 0.0;
};

/// glstat.csv: one row per output time.
class GlstatFile {
 public:
  explicit GlstatFile(std::filesystem::path file, std::optional<std::uint64_t> resume_at = {});
  void write(const GlstatRow& row);
  [[nodiscard]] const CsvHistory& csv() const { return csv_; }

 private:
  CsvHistory csv_;
};

/// nodout.csv: the rows of all history nodes of one output time, flushed together.
class NodoutFile {
 public:
  explicit NodoutFile(std::filesystem::path file, std::optional<std::uint64_t> resume_at = {});
  void write(std::span<const NodoutRow> rows);
  [[nodiscard]] const CsvHistory& csv() const { return csv_; }

 private:
  CsvHistory csv_;
};

/// rcforc.csv: the rows of all interfaces of one output time, flushed together.
class RcforcFile {
 public:
  explicit RcforcFile(std::filesystem::path file, std::optional<std::uint64_t> resume_at = {});
  void write(std::span<const RcforcRow> rows);
  [[nodiscard]] const CsvHistory& csv() const { return csv_; }

 private:
  CsvHistory csv_;
};

/// cohesive.csv: the rows of all cohesive history nodes of one output time, flushed together.
class CohesiveFile {
 public:
  explicit CohesiveFile(std::filesystem::path file, std::optional<std::uint64_t> resume_at = {});
  void write(std::span<const CohesiveRow> rows);
  [[nodiscard]] const CsvHistory& csv() const { return csv_; }

 private:
  CsvHistory csv_;
};

}  // namespace plyform::output
