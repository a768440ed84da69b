// Writes OUTDIR/results.pvd with three states of a small mesh (two hexahedra sharing a face
// and a quad on top) through plyform::output::VtuSeries, a summary.json, and OUTDIR/expected.json
// with every value written, for check_vtk_reader.py to compare against VTK's reader.
// Usage: output_vtk_fixture OUTDIR

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "plyform/output/summary_json.hpp"
#include "plyform/output/vtu_series.hpp"

namespace {

using plyform::output::DataArray;
using plyform::output::GridPiece;
using plyform::output::IdArray;
namespace vtk_cell = plyform::output::vtk_cell;

/// A JSON number (always with a fraction or exponent), or null for NaN; 17 significant digits
/// read back exactly.
std::string number(double v) {
  if (std::isnan(v)) {
    return "null";
  }
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  std::string text = buffer;
  if (text.find_first_of(".e") == std::string::npos) {
    text += ".0";  // so that -0 reads back as a float with its sign
  }
  return text;
}

template <class T>
std::string json_list(std::span<const T> values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) {
      out += ",";
    }
    if constexpr (std::is_floating_point_v<T>) {
      out += number(values[i]);
    } else {
      out += std::to_string(static_cast<long long>(values[i]));
    }
  }
  return out + "]";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: output_vtk_fixture OUTDIR\n");
    return 2;
  }
  try {
    const std::filesystem::path outdir = argv[1];
    std::filesystem::remove_all(outdir);
    plyform::output::VtuSeries series(outdir);

    // Points: a 3 x 2 x 2 grid (12 points) and two more for the quad.
    std::vector<double> x0, y0, z0;
    for (int k = 0; k < 2; ++k) {
      for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 3; ++i) {
          x0.push_back(0.1 * i);
          y0.push_back(0.1 * j + 1.0 / 3.0);
          z0.push_back(0.05 * k - 1e-300);
        }
      }
    }
    x0.insert(x0.end(), {0.1, 0.0});
    y0.insert(y0.end(), {0.2 + 1.0 / 3.0, 0.2 + 1.0 / 3.0});
    z0.insert(z0.end(), {0.05, 0.05});
    const std::size_t n = x0.size();
    const std::vector<std::int64_t> connectivity{0, 1, 4, 3, 6,  7,  10, 9, 1,  2,
                                                 5, 4, 7, 8, 11, 10, 6,  7, 12, 13};
    const std::vector<std::int64_t> offsets{8, 16, 20};
    const std::vector<std::uint8_t> types{vtk_cell::hexahedron, vtk_cell::hexahedron,
                                          vtk_cell::quad};
    std::vector<std::int64_t> node_id(n);
    for (std::size_t p = 0; p < n; ++p) {
      node_id[p] = 9000000000LL + static_cast<std::int64_t>(7 * p);  // beyond 32 bits
    }
    const std::vector<std::int64_t> element_id{101, 102, 2001};
    const std::vector<std::int64_t> part{1, 1, 2};

    const double times[] = {0.0, 1.25e-4, 2.5e-4};
    std::string expected = "{\n  \"states\": [\n";
    for (int s = 0; s < 3; ++s) {
      const double t = times[s];
      std::vector<double> x(n), y(n), z(n), displacement(3 * n), velocity(3 * n), temperature(n),
          beta(n);
      for (std::size_t p = 0; p < n; ++p) {
        const double ux = 1e-3 * s * std::sin(static_cast<double>(p));
        const double uz = -2e-4 * s * static_cast<double>(p) / 7.0;
        x[p] = x0[p] + ux;
        y[p] = y0[p];
        z[p] = z0[p] + uz;
        displacement[3 * p] = ux;
        displacement[3 * p + 1] = 0.0;
        displacement[3 * p + 2] = uz;
        velocity[3 * p] = ux / (t + 1e-9);
        velocity[3 * p + 1] = -0.0;
        velocity[3 * p + 2] = 1e-17 * static_cast<double>(p);
        temperature[p] = 180.0 + 0.1 * s + 1e-12 * static_cast<double>(p);
        beta[p] = p >= 12 ? 1.0 - 0.3 * s : std::numeric_limits<double>::quiet_NaN();
      }
      std::vector<double> stress(6 * 3), plastic_strain(3), thickness(3);
      for (std::size_t e = 0; e < 3; ++e) {
        for (std::size_t c = 0; c < 6; ++c) {
          stress[6 * e + c] =
              1.5e6 * s - 2.5e5 * static_cast<double>(c) + 1.0 / 7.0 * static_cast<double>(e);
        }
        plastic_strain[e] = 0.01 * s * static_cast<double>(e);
        thickness[e] = e == 2 ? 1e-3 : std::numeric_limits<double>::quiet_NaN();
      }
      GridPiece piece;
      piece.x = x;
      piece.y = y;
      piece.z = z;
      piece.connectivity = connectivity;
      piece.offsets = offsets;
      piece.cell_types = types;
      piece.point_data = {DataArray{"displacement", 3, displacement},
                          DataArray{"velocity", 3, velocity},
                          DataArray{"temperature", 1, temperature}, DataArray{"beta", 1, beta}};
      piece.cell_data = {DataArray{"stress", 6, stress},
                         DataArray{"plastic_strain", 1, plastic_strain},
                         DataArray{"thickness", 1, thickness}};
      piece.point_ids = {IdArray{"node_id", node_id}};
      piece.cell_ids = {IdArray{"element_id", element_id}, IdArray{"part", part}};
      series.write_state(t, piece);

      using std::span;
      expected += "    {\"time\": " + number(t) + ", \"file\": \"results_000" + std::to_string(s) +
                  ".vtu\",\n";
      expected += "     \"x\": " + json_list(span<const double>(x)) + ",\n";
      expected += "     \"y\": " + json_list(span<const double>(y)) + ",\n";
      expected += "     \"z\": " + json_list(span<const double>(z)) + ",\n";
      expected +=
          "     \"connectivity\": " + json_list(span<const std::int64_t>(connectivity)) + ",\n";
      expected += "     \"offsets\": " + json_list(span<const std::int64_t>(offsets)) + ",\n";
      expected += "     \"types\": " + json_list(span<const std::uint8_t>(types)) + ",\n";
      expected += "     \"point_data\": {";
      expected += "\"displacement\": [3, " + json_list(span<const double>(displacement)) + "], ";
      expected += "\"velocity\": [3, " + json_list(span<const double>(velocity)) + "], ";
      expected += "\"temperature\": [1, " + json_list(span<const double>(temperature)) + "], ";
      expected += "\"beta\": [1, " + json_list(span<const double>(beta)) + "]},\n";
      expected += "     \"cell_data\": {";
      expected += "\"stress\": [6, " + json_list(span<const double>(stress)) + "], ";
      expected +=
          "\"plastic_strain\": [1, " + json_list(span<const double>(plastic_strain)) + "], ";
      expected += "\"thickness\": [1, " + json_list(span<const double>(thickness)) + "]},\n";
      expected +=
          "     \"point_ids\": {\"node_id\": " + json_list(span<const std::int64_t>(node_id)) +
          "},\n";
      expected +=
          "     \"cell_ids\": {\"element_id\": " + json_list(span<const std::int64_t>(element_id)) +
          ", \"part\": " + json_list(span<const std::int64_t>(part)) + "}}";
      expected += s < 2 ? ",\n" : "\n";
    }
    expected += "  ]\n}\n";
    std::ofstream(outdir / "expected.json") << expected;

    plyform::output::RunSummary summary;
    summary.cycles = 3;
    summary.final_time = times[2];
    summary.warnings = {"quote \" backslash \\ newline \n tab \t",
                        "\xC2\xB0"
                        "C and a bad byte \xFF"};
    plyform::output::write_summary_json(outdir / "summary.json", summary);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "output_vtk_fixture: %s\n", e.what());
    return 1;
  }
}
