#include "plyform/output/vtu_series.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "scratch_dir.hpp"
#include "vtu_arrays.hpp"

namespace plyform::output {
namespace {

using test::appended_arrays;
using testing::read_text;
using testing::ScratchDir;

/// Two hexahedra sharing a face and a quad on top: 12 + 2 points.
struct Mesh {
  std::vector<double> x, y, z;
  std::vector<std::int64_t> connectivity{0, 1, 4,  3, 6, 7, 10, 9,   //
                                         1, 2, 5,  4, 7, 8, 11, 10,  //
                                         6, 7, 12, 13};
  std::vector<std::int64_t> offsets{8, 16, 20};
  std::vector<std::uint8_t> types{vtk_cell::hexahedron, vtk_cell::hexahedron, vtk_cell::quad};
  std::vector<double> displacement, temperature, stress;
  std::vector<std::int64_t> node_id, element_id, part{1, 1, 2};

  Mesh() {
    for (int k = 0; k < 2; ++k) {
      for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 3; ++i) {
          x.push_back(0.1 * i);
          y.push_back(0.1 * j);
          z.push_back(0.05 * k);
        }
      }
    }
    x.insert(x.end(), {0.1, 0.0});
    y.insert(y.end(), {0.2, 0.2});
    z.insert(z.end(), {0.05, 0.05});
    for (std::size_t p = 0; p < x.size(); ++p) {
      node_id.push_back(static_cast<std::int64_t>(1000 + p));
      temperature.push_back(p == 3 ? std::numeric_limits<double>::quiet_NaN() : 20.0 + 1.0 / 3.0);
      for (int c = 0; c < 3; ++c) {
        displacement.push_back(1e-3 * static_cast<double>(p) + 1e-7 * c);
      }
    }
    for (int e = 0; e < 3; ++e) {
      element_id.push_back(50 + e);
      for (int c = 0; c < 6; ++c) {
        stress.push_back(1e6 * e - 1.25e5 * c);
      }
    }
  }

  GridPiece piece() const {
    GridPiece p;
    p.x = x;
    p.y = y;
    p.z = z;
    p.connectivity = connectivity;
    p.offsets = offsets;
    p.cell_types = types;
    p.point_data = {{"displacement", 3, displacement}, {"temperature", 1, temperature}};
    p.cell_data = {{"stress", 6, stress}};
    p.point_ids = {{"node_id", node_id}};
    p.cell_ids = {{"element_id", element_id}, {"part", part}};
    return p;
  }
};

template <class T>
std::string bytes_of(const std::vector<T>& values) {
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos;
       pos = text.find(what, pos + 1)) {
    ++n;
  }
  return n;
}

TEST(VtuSeries, PvdRewrittenAfterEveryState) {
  ScratchDir dir;
  const Mesh mesh;
  VtuSeries series(dir / "out");
  EXPECT_EQ(series.states_written(), 0u);
  const double times[] = {0.0, 1e-4, 2.5e-4};
  for (std::size_t s = 0; s < 3; ++s) {
    series.write_state(times[s], mesh.piece());
    EXPECT_EQ(series.states_written(), s + 1);
    const std::string pvd = read_text(dir / "out" / "results.pvd");
    EXPECT_EQ(pvd.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\"", 0), 0u);
    EXPECT_NE(pvd.find("</Collection>\n</VTKFile>\n"), std::string::npos);
    EXPECT_EQ(count(pvd, "<DataSet "), s + 1);
    EXPECT_NE(pvd.find("<DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"results_0000.vtu\"/>"),
              std::string::npos);
    if (s >= 1) {
      EXPECT_NE(pvd.find("timestep=\"0.0001\" group=\"\" part=\"0\" file=\"results_0001.vtu\""),
                std::string::npos);
    }
    if (s >= 2) {
      EXPECT_NE(pvd.find("timestep=\"0.00025\" group=\"\" part=\"0\" file=\"results_0002.vtu\""),
                std::string::npos);
    }
  }
  const ScratchDir& d = dir;
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(d.path() / "out")) {
    files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"results.pvd", "results_0000.vtu", "results_0001.vtu",
                                             "results_0002.vtu"}));
}

TEST(VtuSeries, AppendedArraysHoldTheExactBytes) {
  ScratchDir dir;
  const Mesh mesh;
  VtuSeries series(dir.path());
  series.write_state(0.5, mesh.piece());
  const std::string vtu = read_text(dir / "results_0000.vtu");
  EXPECT_NE(vtu.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(vtu.find("<Piece NumberOfPoints=\"14\" NumberOfCells=\"3\">"), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"stress\" NumberOfComponents=\"6\""), std::string::npos);
  EXPECT_NE(vtu.find("<DataArray type=\"Int64\" Name=\"node_id\""), std::string::npos);
  EXPECT_NE(vtu.find("<DataArray type=\"UInt8\" Name=\"types\""), std::string::npos);
  const auto arrays = appended_arrays(vtu);
  std::vector<double> points;
  for (std::size_t p = 0; p < mesh.x.size(); ++p) {
    points.insert(points.end(), {mesh.x[p], mesh.y[p], mesh.z[p]});
  }
  EXPECT_EQ(arrays.at("TimeValue"), bytes_of(std::vector<double>{0.5}));
  EXPECT_EQ(arrays.at("Points"), bytes_of(points));
  EXPECT_EQ(arrays.at("displacement"), bytes_of(mesh.displacement));
  EXPECT_EQ(arrays.at("temperature"), bytes_of(mesh.temperature));  // the NaN bit for bit
  EXPECT_EQ(arrays.at("stress"), bytes_of(mesh.stress));
  EXPECT_EQ(arrays.at("node_id"), bytes_of(mesh.node_id));
  EXPECT_EQ(arrays.at("element_id"), bytes_of(mesh.element_id));
  EXPECT_EQ(arrays.at("part"), bytes_of(mesh.part));
  EXPECT_EQ(arrays.at("connectivity"), bytes_of(mesh.connectivity));
  EXPECT_EQ(arrays.at("offsets"), bytes_of(mesh.offsets));
  EXPECT_EQ(arrays.at("types"), bytes_of(mesh.types));
  EXPECT_EQ(vtu.substr(vtu.size() - 30), "\n  </AppendedData>\n</VTKFile>\n");
}

TEST(VtuSeries, NamesAreXmlEscaped) {
  ScratchDir dir;
  const Mesh mesh;
  GridPiece piece = mesh.piece();
  piece.point_data[1].name = "T<\"&'>";
  VtuSeries series(dir.path());
  series.write_state(0.0, piece);
  EXPECT_NE(read_text(dir / "results_0000.vtu").find("Name=\"T&lt;&quot;&amp;&apos;&gt;\""),
            std::string::npos);
}

TEST(VtuSeries, InconsistentPiecesAreRejectedAndNothingIsWritten) {
  ScratchDir dir;
  const Mesh mesh;
  VtuSeries series(dir.path());
  const auto rejected = [&](GridPiece piece) {
    EXPECT_THROW(series.write_state(0.0, piece), std::invalid_argument);
  };
  {
    GridPiece p = mesh.piece();
    p.y = p.y.first(3);
    rejected(p);
  }
  {
    GridPiece p = mesh.piece();
    p.offsets = p.offsets.first(2);
    rejected(p);
  }
  {
    std::vector<std::int64_t> conn = mesh.connectivity;
    conn[5] = 14;  // one past the last point
    GridPiece p = mesh.piece();
    p.connectivity = conn;
    rejected(p);
  }
  {
    std::vector<std::int64_t> offsets{8, 7, 20};
    GridPiece p = mesh.piece();
    p.offsets = offsets;
    rejected(p);
  }
  {
    GridPiece p = mesh.piece();
    p.connectivity = p.connectivity.first(19);
    rejected(p);
  }
  {
    GridPiece p = mesh.piece();
    p.cell_data[0].components = 5;
    rejected(p);
  }
  {
    GridPiece p = mesh.piece();
    p.point_ids[0].values = p.point_ids[0].values.first(13);
    rejected(p);
  }
  EXPECT_THROW(series.write_state(std::numeric_limits<double>::quiet_NaN(), mesh.piece()),
               std::invalid_argument);
  EXPECT_EQ(series.states_written(), 0u);
  EXPECT_TRUE(dir.listing().empty());
}

TEST(VtuSeries, EmptyPieceIsValid) {
  ScratchDir dir;
  VtuSeries series(dir.path());
  series.write_state(0.0, GridPiece{});
  EXPECT_EQ(series.states_written(), 1u);
  EXPECT_NE(read_text(dir / "results_0000.vtu").find("NumberOfPoints=\"0\" NumberOfCells=\"0\""),
            std::string::npos);
}

TEST(VtuSeries, IoFailureNamesTheFileAndLeavesNoTempFile) {
  ScratchDir dir;
  const Mesh mesh;
  VtuSeries series(dir.path());
  series.write_state(0.0, mesh.piece());
  // A folder where the next state file should go: the rename fails.
  std::filesystem::create_directory(dir / "results_0001.vtu");
  try {
    series.write_state(1.0, mesh.piece());
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("results_0001.vtu"), std::string::npos) << e.what();
  }
  EXPECT_EQ(series.states_written(), 1u);
  EXPECT_EQ(dir.listing(),
            (std::vector<std::string>{"results.pvd", "results_0000.vtu", "results_0001.vtu"}));
  EXPECT_EQ(count(read_text(dir / "results.pvd"), "<DataSet "), 1u);  // still the valid series
}

TEST(VtuSeries, FolderThatCannotBeCreatedIsNamed) {
  ScratchDir dir;
  { std::ofstream(dir / "file") << "x"; }
  try {
    VtuSeries series(dir / "file" / "out");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("out"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plyform::output
