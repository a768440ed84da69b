#include "plyform/output/vtu_series.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "atomic_file.hpp"

namespace plyform::output {
namespace {

static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big,
              "mixed-endian hosts are not supported");
constexpr std::string_view byte_order =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

/// One block of the appended section: a UInt64 byte count, then the bytes.
struct Block {
  const void* data;
  std::uint64_t bytes;
};

void append_xml_escaped(std::string& out, std::string_view text) {
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
}

[[noreturn]] void invalid(const std::string& message) {
  throw std::invalid_argument("VTU piece: " + message);
}

class HeaderBuilder {
 public:
  HeaderBuilder(std::string& out, std::vector<Block>& blocks) : out_(out), blocks_(blocks) {}

  /// Adds a DataArray element referring to the next appended block.
  void array(std::string_view indent, std::string_view type, std::string_view name, int components,
             const void* data, std::uint64_t bytes, std::string_view extra_attributes = {}) {
    fmt::format_to(std::back_inserter(out_), "{}<DataArray type=\"{}\"", indent, type);
    if (!name.empty()) {
      out_ += " Name=\"";
      append_xml_escaped(out_, name);
      out_ += '"';
    }
    if (components != 1) {
      fmt::format_to(std::back_inserter(out_), " NumberOfComponents=\"{}\"", components);
    }
    out_ += extra_attributes;
    fmt::format_to(std::back_inserter(out_), " format=\"appended\" offset=\"{}\"/>\n", offset_);
    blocks_.push_back({data, bytes});
    offset_ += sizeof(std::uint64_t) + bytes;
  }

 private:
  std::string& out_;
  std::vector<Block>& blocks_;
  std::uint64_t offset_ = 0;
};

template <class T>
std::uint64_t bytes_of(std::span<const T> values) {
  return static_cast<std::uint64_t>(values.size_bytes());
}

}  // namespace

void validate_piece(const GridPiece& piece) {
  const std::size_t n_points = piece.x.size();
  const std::size_t n_cells = piece.cell_types.size();
  if (piece.y.size() != n_points || piece.z.size() != n_points) {
    invalid(fmt::format("coordinate arrays differ in length (x {}, y {}, z {})", piece.x.size(),
                        piece.y.size(), piece.z.size()));
  }
  if (piece.offsets.size() != n_cells) {
    invalid(fmt::format("{} offsets for {} cell types", piece.offsets.size(), n_cells));
  }
  std::int64_t previous = 0;
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (piece.offsets[c] < previous) {
      invalid(fmt::format("offset of cell {} ({}) is below the previous one ({})", c,
                          piece.offsets[c], previous));
    }
    previous = piece.offsets[c];
  }
  if (static_cast<std::uint64_t>(previous) != piece.connectivity.size()) {
    invalid(fmt::format("last offset {} differs from the connectivity length {}", previous,
                        piece.connectivity.size()));
  }
  const auto limit = static_cast<std::int64_t>(n_points);
  for (std::size_t i = 0; i < piece.connectivity.size(); ++i) {
    const std::int64_t p = piece.connectivity[i];
    if (p < 0 || p >= limit) {
      invalid(fmt::format("connectivity entry {} is {}, outside 0..{}", i, p, limit - 1));
    }
  }
  const auto check_data = [](const std::vector<DataArray>& arrays, std::size_t count,
                             std::string_view where) {
    for (const DataArray& a : arrays) {
      if (a.name.empty()) {
        invalid(fmt::format("a {} array has no name", where));
      }
      if (a.components < 1) {
        invalid(fmt::format("{} array '{}' has {} components", where, a.name, a.components));
      }
      if (a.values.size() != count * static_cast<std::size_t>(a.components)) {
        invalid(fmt::format("{} array '{}' has {} values, expected {} x {}", where, a.name,
                            a.values.size(), count, a.components));
      }
    }
  };
  const auto check_ids = [](const std::vector<IdArray>& arrays, std::size_t count,
                            std::string_view where) {
    for (const IdArray& a : arrays) {
      if (a.name.empty()) {
        invalid(fmt::format("a {} id array has no name", where));
      }
      if (a.values.size() != count) {
        invalid(fmt::format("{} id array '{}' has {} values, expected {}", where, a.name,
                            a.values.size(), count));
      }
    }
  };
  check_data(piece.point_data, n_points, "point");
  check_data(piece.cell_data, n_cells, "cell");
  check_ids(piece.point_ids, n_points, "point");
  check_ids(piece.cell_ids, n_cells, "cell");
}

std::string VtuSeries::file_name_of(std::size_t k) {
  return fmt::format("results_{:04d}.vtu", k);
}

VtuSeries::VtuSeries(std::filesystem::path outdir) : outdir_(std::move(outdir)) {
  std::error_code ec;
  std::filesystem::create_directories(outdir_, ec);
  if (ec || !std::filesystem::is_directory(outdir_)) {
    throw std::runtime_error("cannot create output folder " + outdir_.string() + ": " +
                             (ec ? ec.message() : std::string("not a folder")));
  }
}

void VtuSeries::write_state(double time, const GridPiece& piece) {
  if (!std::isfinite(time)) {
    throw std::invalid_argument(fmt::format("VTU state time is not finite ({})", time));
  }
  validate_piece(piece);
  const std::size_t n_points = piece.x.size();
  const std::size_t n_cells = piece.cell_types.size();

  points_.resize(3 * n_points);
  for (std::size_t i = 0; i < n_points; ++i) {
    points_[3 * i] = piece.x[i];
    points_[3 * i + 1] = piece.y[i];
    points_[3 * i + 2] = piece.z[i];
  }

  std::vector<Block> blocks;
  blocks.reserve(8 + piece.point_data.size() + piece.cell_data.size() + piece.point_ids.size() +
                 piece.cell_ids.size());
  header_.clear();
  HeaderBuilder xml(header_, blocks);
  fmt::format_to(std::back_inserter(header_),
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" "
                 "header_type=\"UInt64\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <FieldData>\n",
                 byte_order);
  header_ += "      <!-- simulated time of this state -->\n";
  xml.array("      ", "Float64", "TimeValue", 1, &time, sizeof(double), " NumberOfTuples=\"1\"");
  fmt::format_to(std::back_inserter(header_),
                 "    </FieldData>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n"
                 "      <PointData>\n",
                 n_points, n_cells);
  for (const DataArray& a : piece.point_data) {
    xml.array("        ", "Float64", a.name, a.components, a.values.data(), bytes_of(a.values));
  }
  for (const IdArray& a : piece.point_ids) {
    xml.array("        ", "Int64", a.name, 1, a.values.data(), bytes_of(a.values));
  }
  header_ += "      </PointData>\n      <CellData>\n";
  for (const DataArray& a : piece.cell_data) {
    xml.array("        ", "Float64", a.name, a.components, a.values.data(), bytes_of(a.values));
  }
  for (const IdArray& a : piece.cell_ids) {
    xml.array("        ", "Int64", a.name, 1, a.values.data(), bytes_of(a.values));
  }
  header_ += "      </CellData>\n      <Points>\n";
  xml.array("        ", "Float64", "Points", 3, points_.data(),
            bytes_of(std::span<const double>(points_)));
  header_ += "      </Points>\n      <Cells>\n";
  xml.array("        ", "Int64", "connectivity", 1, piece.connectivity.data(),
            bytes_of(piece.connectivity));
  xml.array("        ", "Int64", "offsets", 1, piece.offsets.data(), bytes_of(piece.offsets));
  xml.array("        ", "UInt8", "types", 1, piece.cell_types.data(), bytes_of(piece.cell_types));
  header_ +=
      "      </Cells>\n"
      "    </Piece>\n"
      "  </UnstructuredGrid>\n"
      "  <AppendedData encoding=\"raw\">\n"
      "   _";

  const std::string file_name = file_name_of(states_.size());
  {
    detail::AtomicFile vtu(outdir_ / file_name);
    vtu.write(header_);
    for (const Block& b : blocks) {
      vtu.write(&b.bytes, sizeof b.bytes);
      vtu.write(b.data, static_cast<std::size_t>(b.bytes));
    }
    vtu.write("\n  </AppendedData>\n</VTKFile>\n");
    vtu.commit();
  }

  states_.emplace_back(time, file_name);
  try {
    write_pvd();
  } catch (...) {
    states_.pop_back();
    throw;
  }
}

void VtuSeries::write_pvd() const {
  std::string pvd;
  fmt::format_to(std::back_inserter(pvd),
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"{}\">\n"
                 "  <Collection>\n",
                 byte_order);
  for (const auto& [t, file] : states_) {
    fmt::format_to(std::back_inserter(pvd),
                   "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"", t);
    append_xml_escaped(pvd, file);
    pvd += "\"/>\n";
  }
  pvd += "  </Collection>\n</VTKFile>\n";
  detail::AtomicFile pvd_file(pvd_path());
  pvd_file.write(pvd);
  pvd_file.commit();
}

void VtuSeries::resume(std::span<const double> times) {
  states_.clear();
  for (std::size_t k = 0; k < times.size(); ++k)
    states_.emplace_back(times[k], file_name_of(k));
  write_pvd();
}

std::vector<double> VtuSeries::times() const {
  std::vector<double> t;
  for (const auto& st : states_)
    t.push_back(st.first);
  return t;
}

}  // namespace plyform::output
