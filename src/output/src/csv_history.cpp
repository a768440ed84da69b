#include "plyform/output/csv_history.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <iterator>
#include <stdexcept>

namespace plyform::output {
namespace {

std::vector<std::string> to_strings(std::span<const std::string_view> names) {
  return {names.begin(), names.end()};
}

[[noreturn]] void io_error(std::string_view what, const std::filesystem::path& file) {
  const int error = errno;
  throw std::runtime_error(fmt::format("{} {}: {}", what, file.string(),
                                       error != 0 ? std::strerror(error) : "I/O error"));
}

}  // namespace

void CsvHistory::Closer::operator()(std::FILE* f) const {
  std::fclose(f);
}

CsvHistory::CsvHistory(std::filesystem::path file, std::vector<std::string> columns)
    : path_(std::move(file)), columns_(std::move(columns)) {
  if (columns_.empty()) {
    throw std::invalid_argument("CSV file " + path_.string() + " needs at least one column");
  }
  file_.reset(std::fopen(path_.c_str(), "wb"));
  if (!file_) {
    io_error("cannot open", path_);
  }
  for (const std::string& column : columns_) {
    text(column);
  }
  end_row();
  flush();
}

CsvHistory::CsvHistory(std::filesystem::path file, std::vector<std::string> columns,
                       std::optional<std::uint64_t> resume_at)
    : CsvHistory(resume_at ? CsvHistory(std::move(file), std::move(columns), *resume_at, 0)
                           : CsvHistory(std::move(file), std::move(columns))) {}

CsvHistory::CsvHistory(std::filesystem::path file, std::vector<std::string> columns,
                       std::uint64_t resume_at, int /*tag*/)
    : path_(std::move(file)), columns_(std::move(columns)) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path_, ec);
  if (ec || size < resume_at) {
    throw std::runtime_error(fmt::format(
        "cannot go on with {}: it has {} bytes, the checkpoint counts {} (was it removed or "
        "cut since?)",
        path_.string(), ec ? 0 : size, resume_at));
  }
  {
    // The header must be this file's (the same columns).
    std::FILE* f = std::fopen(path_.c_str(), "rb");
    if (f == nullptr)
      io_error("cannot open", path_);
    std::string head;
    for (int c = std::fgetc(f); c != EOF && c != '\n'; c = std::fgetc(f))
      head += static_cast<char>(c);
    std::fclose(f);
    std::string expected;
    for (const std::string& column : columns_)
      expected += (expected.empty() ? "" : ",") + column;
    if (head != expected) {
      throw std::runtime_error(fmt::format("cannot go on with {}: its header is '{}', not '{}'",
                                           path_.string(), head, expected));
    }
  }
  std::filesystem::resize_file(path_, resume_at, ec);
  if (ec)
    throw std::runtime_error("cannot cut " + path_.string() + ": " + ec.message());
  file_.reset(std::fopen(path_.c_str(), "ab"));
  if (!file_)
    io_error("cannot open", path_);
  written_ = resume_at;
}

CsvHistory::CsvHistory(CsvHistory&&) noexcept = default;
CsvHistory& CsvHistory::operator=(CsvHistory&&) noexcept = default;

CsvHistory::~CsvHistory() {
  if (file_) {
    // Complete rows only; errors cannot be reported from here.
    std::fwrite(line_.data(), 1, complete_, file_.get());
  }
}

void CsvHistory::separator() {
  if (cells_ >= columns_.size()) {
    throw std::logic_error(
        fmt::format("CSV file {}: more than {} cells in a row", path_.string(), columns_.size()));
  }
  if (cells_ > 0) {
    line_ += ',';
  }
  ++cells_;
}

void CsvHistory::real(double value) {
  separator();
  fmt::format_to(std::back_inserter(line_), "{}", value);
}

void CsvHistory::integer(std::int64_t value) {
  separator();
  fmt::format_to(std::back_inserter(line_), "{}", value);
}

void CsvHistory::text(std::string_view value) {
  separator();
  if (value.find_first_of(",\"\n\r") == std::string_view::npos) {
    line_ += value;
    return;
  }
  line_ += '"';
  for (const char c : value) {
    if (c == '"') {
      line_ += '"';
    }
    line_ += c;
  }
  line_ += '"';
}

void CsvHistory::end_row() {
  if (cells_ != columns_.size()) {
    throw std::logic_error(fmt::format("CSV file {}: row with {} cells, expected {}",
                                       path_.string(), cells_, columns_.size()));
  }
  line_ += '\n';
  cells_ = 0;
  complete_ = line_.size();
}

void CsvHistory::flush() {
  if (!file_) {
    throw std::logic_error("CSV file used after move");
  }
  if (complete_ > 0) {
    if (std::fwrite(line_.data(), 1, complete_, file_.get()) != complete_) {
      io_error("cannot write", path_);
    }
    written_ += complete_;
    line_.erase(0, complete_);
    complete_ = 0;
  }
  if (std::fflush(file_.get()) != 0) {
    io_error("cannot write", path_);
  }
}

void CsvHistory::row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(fmt::format("CSV file {}: row of {} values, expected {}",
                                            path_.string(), values.size(), columns_.size()));
  }
  rows(values);
}

void CsvHistory::rows(std::span<const double> values) {
  if (values.size() % columns_.size() != 0) {
    throw std::invalid_argument(
        fmt::format("CSV file {}: {} values is not a multiple of {} columns", path_.string(),
                    values.size(), columns_.size()));
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    real(values[i]);
    if (cells_ == columns_.size()) {
      end_row();
    }
  }
  flush();
}

void CsvHistory::row_mixed(std::span<const CsvCell> cells) {
  if (cells.size() != columns_.size()) {
    throw std::invalid_argument(fmt::format("CSV file {}: row of {} cells, expected {}",
                                            path_.string(), cells.size(), columns_.size()));
  }
  for (const CsvCell& cell : cells) {
    if (const auto* d = std::get_if<double>(&cell)) {
      real(*d);
    } else if (const auto* i = std::get_if<std::int64_t>(&cell)) {
      integer(*i);
    } else {
      text(std::get<std::string_view>(cell));
    }
  }
  end_row();
  flush();
}

// ---- Typed history files -------------------------------------------------------------------

GlstatFile::GlstatFile(std::filesystem::path file, std::optional<std::uint64_t> resume_at)
    : csv_(std::move(file), to_strings(glstat_columns), resume_at) {}

void GlstatFile::write(const GlstatRow& r) {
  const double values[] = {r.time,          r.dt,        r.kinetic,
                           r.internal,      r.hourglass, r.contact,
                           r.external_work, r.total,     r.energy_ratio};
  csv_.row(values);
}

NodoutFile::NodoutFile(std::filesystem::path file, std::optional<std::uint64_t> resume_at)
    : csv_(std::move(file), to_strings(nodout_columns), resume_at) {}

void NodoutFile::write(std::span<const NodoutRow> rows) {
  for (const NodoutRow& r : rows) {
    csv_.real(r.time);
    csv_.integer(r.node);
    for (const double v : {r.x, r.y, r.z, r.ux, r.uy, r.uz, r.vx, r.vy, r.vz}) {
      csv_.real(v);
    }
    csv_.end_row();
  }
  csv_.flush();
}

RcforcFile::RcforcFile(std::filesystem::path file, std::optional<std::uint64_t> resume_at)
    : csv_(std::move(file), to_strings(rcforc_columns), resume_at) {}

void RcforcFile::write(std::span<const RcforcRow> rows) {
  for (const RcforcRow& r : rows) {
    csv_.real(r.time);
    csv_.integer(r.interface);
    csv_.real(r.fx);
    csv_.real(r.fy);
    csv_.real(r.fz);
    csv_.end_row();
  }
  csv_.flush();
}

CohesiveFile::CohesiveFile(std::filesystem::path file, std::optional<std::uint64_t> resume_at)
    : csv_(std::move(file), to_strings(cohesive_columns), resume_at) {}

void CohesiveFile::write(std::span<const CohesiveRow> rows) {
  for (const CohesiveRow& r : rows) {
    csv_.real(r.time);
    csv_.integer(r.interface);
    csv_.integer(r.node);
    csv_.text(r.state);
    csv_.real(r.gap);
    csv_.real(r.pressure);
    csv_.real(r.tau);
    csv_.real(r.beta);
    csv_.end_row();
  }
  csv_.flush();
}

}  // namespace plyform::output
