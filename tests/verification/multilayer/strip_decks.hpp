#pragma once
// A three-layer strip for the multilayer verification tests: metal / thermoplastic core /
// metal, each layer its own shell mesh (its own *PART, *SECTION_SHELL and material), the skins
// the slave sides of one-way contacts against the core (as examples/square_cup joins its
// layers). The decks run through `plyform run` in-process; the tests read its CSV files.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "plyform/app/commands.hpp"
#include "temp_dir.hpp"

namespace plyform::test::multilayer {

struct Layer {
  const char* title;
  double thickness, z, modulus, density;
};

// Aluminium 0.25 / polymer core 1.00 / aluminium 0.25 mm (the moduli of examples/square_cup),
// mid-surfaces at their real offsets, so the layers' faces touch at gap 0. Units mm, t, s, MPa,
// N. Poisson's ratio 0 in every layer: a strip of one element across its width then is a beam
// (no plate factor 1 - nu^2, no anticlastic curvature), as the closed forms assume.
inline constexpr double kSkin = 0.25, kCore = 1.0, kWidth = 10.0;
inline constexpr double kSkinE = 70000.0, kCoreE = 1500.0;
inline constexpr double kH = 0.5 * (kCore + kSkin);  // distance between skin and core mid-surfaces
inline constexpr std::array<Layer, 3> kLayers = {{
    {"lower skin", kSkin, -kH, kSkinE, 2.7e-9},
    {"core", kCore, 0.0, kCoreE, 1.2e-9},
    {"upper skin", kSkin, kH, kSkinE, 2.7e-9},
}};
inline constexpr double kShearFactor = 0.8333;  // SHRF of every layer

/// The interface between the core and each skin.
enum class Interface {
  bonded,        ///< cohesive law, bonded at t = 0: C_N normal and C_T tangential springs
  frictionless,  ///< plain penalty contact, mu = 0, no adhesion
  sliding,       ///< cohesive law bonded normally only (C_T = 0, mu = 0): free slip, no opening
};
inline constexpr double kCn = 1.0e4, kCt = 1.0e4;  // MPa/mm, of the cohesive interfaces

/// Deck text in LS-DYNA's free format (comma-separated cards).
class Deck {
 public:
  Deck() {
    os_.precision(17);
    os_ << "*KEYWORD\n";
  }
  template <class... T>
  Deck& card(const T&... v) {
    bool first = true;
    ((os_ << (first ? "" : ",") << v, first = false), ...);
    os_ << (sizeof...(T) == 1 ? ",\n" : "\n");  // a lone field needs a comma (free format)
    return *this;
  }
  Deck& kw(const std::string& k) {
    os_ << k << "\n";
    return *this;
  }
  Deck& ids(const std::vector<int>& v) {
    for (std::size_t i = 0; i < v.size(); ++i)
      os_ << v[i] << ((i % 8 == 7 || i + 1 == v.size()) ? "\n" : ",");
    return *this;
  }
  [[nodiscard]] std::string text() const { return os_.str() + "*END\n"; }

 private:
  std::ostringstream os_;
};

/// Node id of layer `p` (1, 2, 3 from the bottom) at column i (x = i L / nx), row j (y = j b).
inline int node_id(int p, int nx, int i, int j) {
  return 1000 * p + j * (nx + 1) + i + 1;
}

/// Elements along the strip of layer p: nx, the core's `core_extra` more (of the same length).
inline int columns(int p, int nx, int core_extra) {
  return p == 2 ? nx + core_extra : nx;
}

/// The three layers of a strip of `length` in nx x 1 shells: parts, sections, materials,
/// nodes and elements, the plane-strip SPCs (every node: y, rotations about x and z) and the
/// clamp of every layer at x = 0; the two interfaces (contacts 1: lower skin, 2: upper skin,
/// each the slave against the core). The core may run `core_extra` elements beyond the skins'
/// ends (node ids: node_id(2, nx + core_extra, ...)).
inline void write_strip(Deck& d, double length, int nx, Interface interface, int core_extra = 0) {
  // PENOPT 3: the slave's (a skin's) penalty; the core's is 1/47 of it (as square_cup sets).
  d.kw("*CONTROL_CONTACT").card(0.1, 0.0, 0, 0, 3);
  d.kw("*HOURGLASS").card(1, 4, 0.1);
  for (int p = 1; p <= 3; ++p) {
    const Layer& l = kLayers[static_cast<std::size_t>(p - 1)];
    d.kw("*PART").kw(l.title).card(p, p, p, 0, 1);
    d.kw("*SECTION_SHELL").card(p, 2, kShearFactor, 3);
    d.card(l.thickness, l.thickness, l.thickness, l.thickness);
    d.kw("*MAT_ELASTIC").card(p, l.density, l.modulus, 0.0);
    const int n = columns(p, nx, core_extra);
    d.kw("*NODE");
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= n; ++i)
        d.card(node_id(p, n, i, j), length * i / nx, kWidth * j, l.z);
    d.kw("*ELEMENT_SHELL");
    for (int i = 0; i < n; ++i)
      d.card(1000 * p + i + 1, p, node_id(p, n, i, 0), node_id(p, n, i + 1, 0),
             node_id(p, n, i + 1, 1), node_id(p, n, i, 1));
  }
  std::vector<int> all, root;
  for (int p = 1; p <= 3; ++p)
    for (int j = 0; j <= 1; ++j) {
      const int n = columns(p, nx, core_extra);
      root.push_back(node_id(p, n, 0, j));
      for (int i = 1; i <= n; ++i)
        all.push_back(node_id(p, n, i, j));
    }
  d.kw("*SET_NODE_LIST").card(1).ids(root);
  d.kw("*SET_NODE_LIST").card(2).ids(all);
  d.kw("*BOUNDARY_SPC_SET").card(1, 0, 1, 1, 1, 1, 1, 1);
  d.kw("*BOUNDARY_SPC_SET").card(2, 0, 0, 1, 0, 1, 0, 1);
  for (int c = 1; c <= 2; ++c) {
    d.kw("*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID").card(c, c == 1 ? "lower skin" : "upper skin");
    d.card(c == 1 ? 1 : 3, 2, 3, 3).card(0.0, 0.0).card(1.0, 1.0);
    if (interface == Interface::frictionless)
      continue;
    // MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO | ZETA_HI BETA0 BOND_TOL FRIC MU_LO MU_HI
    // VISC_LO VISC_HI | FILM_H VDC BETA_MIN CT. sigma_max 100 MPa: the interfaces carry well
    // under 1 MPa here, so beta stays 1.
    const double ct = interface == Interface::bonded ? kCt : 0.0;
    d.kw("*USER_INTERFACE_FRICTION").card(c, 20, 0);
    d.card(1, kCn, 100.0, 100.0, 0.0, 0.0, 1e-9, 0.0);
    d.card(0.0, 1.0, 1e-3, 0, 0.0, 0.0, 0.0, 0.0);
    d.card(0.0, 0.0, 1e-3, ct);
  }
}

/// C2 ramp from 0 to 1 over [0, 1] (zero velocity and acceleration at both ends): a load or
/// motion ramped so over a few periods of the slowest mode leaves little vibration behind.
inline double smooth_ramp(double s) {
  if (s <= 0.0)
    return 0.0;
  if (s >= 1.0)
    return 1.0;
  return s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
}

/// A CSV file as rows of named cells.
struct Csv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  [[nodiscard]] std::size_t column(const std::string& name) const {
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == name)
        return c;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};

inline Csv read_csv(const std::filesystem::path& file) {
  Csv csv;
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  std::string line;
  const auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::stringstream ss(l);
    std::string cell;
    while (std::getline(ss, cell, ','))
      cells.push_back(cell);
    return cells;
  };
  if (std::getline(in, line))
    csv.columns = split(line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (const std::string& cell : split(line))
      row.push_back(cell.empty() ? std::nan("") : std::stod(cell));
    csv.rows.push_back(row);
  }
  return csv;
}

/// Runs `deck` with `plyform run` (one thread) into dir/name_out and returns that folder.
inline std::filesystem::path run(TempDir& dir, const std::string& name, const std::string& deck) {
  app::RunOptions o;
  o.deck = dir.write(name + ".k", deck);
  o.output = dir.path() / (name + "_out");
  o.progress = false;
  std::ostringstream out, err;
  EXPECT_EQ(app::run_deck(o, out, err), 0) << err.str();
  return *o.output;
}

/// What glstat.csv says of a run's energy books.
struct Books {
  double worst_ratio = 0.0;      ///< largest |energy_ratio - 1| once work has been done
  double min_internal = 0.0;     ///< smallest internal energy at those times
  double hourglass_share = 0.0;  ///< largest hourglass / internal energy at those times
  double kinetic_share = 0.0;    ///< kinetic / internal energy at the end
};

/// The books from the first output with 1 % of the final external work done (before that the
/// ratio divides round-off by round-off).
inline Books read_books(const std::filesystem::path& out) {
  const Csv g = read_csv(out / "glstat.csv");
  const std::size_t ratio = g.column("energy_ratio"), internal = g.column("internal");
  const std::size_t hourglass = g.column("hourglass"), kinetic = g.column("kinetic");
  const std::size_t work = g.column("external_work");
  Books b;
  if (g.rows.empty())
    return b;
  const double final_work = g.rows.back()[work];
  b.min_internal = g.rows.back()[internal];
  for (const auto& r : g.rows) {
    if (std::abs(r[work]) < 0.01 * std::abs(final_work))
      continue;
    b.worst_ratio = std::max(b.worst_ratio, std::abs(r[ratio] - 1.0));
    b.min_internal = std::min(b.min_internal, r[internal]);
    b.hourglass_share = std::max(b.hourglass_share, r[hourglass] / r[internal]);
  }
  b.kinetic_share = g.rows.back()[kinetic] / g.rows.back()[internal];
  return b;
}

/// The glstat checks every run of these tests must pass.
inline void expect_books_close(const Books& b, double kinetic_limit) {
  EXPECT_LT(b.worst_ratio, 0.02);
  EXPECT_GT(b.min_internal, 0.0);
  EXPECT_LT(b.hourglass_share, 0.02);
  EXPECT_LT(b.kinetic_share, kinetic_limit);  // quasi-static at the end
}

}  // namespace plyform::test::multilayer
