#pragma once
// Small deck writer for the contact verification tests: comma-separated cards (LS-DYNA's free
// format), flat shell plates and hexahedral blocks with deck ids, and a runner that reads,
// validates, builds and runs a deck and keeps what the engine reports.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"

namespace plyform::test {

class DeckWriter {
 public:
  DeckWriter() {
    os_.precision(15);
    os_ << "*KEYWORD\n";
  }

  /// One card in free format; a card of one field gets a trailing comma (without a comma
  /// LS-DYNA reads fixed 10-character fields).
  template <class... T>
  DeckWriter& card(const T&... v) {
    bool first = true;
    ((os_ << (first ? "" : ",") << v, first = false), ...);
    os_ << (sizeof...(T) == 1 ? ",\n" : "\n");
    return *this;
  }
  DeckWriter& kw(const std::string& k) {
    os_ << k << "\n";
    return *this;
  }
  /// Text as it is (whole lines, each ending with a newline).
  DeckWriter& raw(const std::string& text) {
    os_ << text;
    return *this;
  }
  /// A list of ids, eight per card.
  DeckWriter& ids(const std::vector<int>& v) {
    for (std::size_t i = 0; i < v.size(); ++i)
      os_ << v[i] << ((i % 8 == 7 || i + 1 == v.size()) ? "\n" : ",");
    return *this;
  }

  /// A flat plate of nx x ny shells of `part` in [x0, x1] x [y0, y1] at height z (node order
  /// counter-clockwise seen from +z, or clockwise when `flip`). Returns its node ids.
  std::vector<int> plate(int part, int first_node, int first_element, double x0, double x1,
                         double y0, double y1, int nx, int ny, double z, bool flip = false) {
    std::vector<int> nodes;
    kw("*NODE");
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const int id = first_node + j * (nx + 1) + i;
        card(id, x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny, z);
        nodes.push_back(id);
      }
    kw("*ELEMENT_SHELL");
    int e = first_element;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int a = first_node + j * (nx + 1) + i;
        if (flip)
          card(e++, part, a, a + nx + 1, a + nx + 2, a + 1);
        else
          card(e++, part, a, a + 1, a + nx + 2, a + nx + 1);
      }
    return nodes;
  }

  /// A block of nx x ny x nz hexahedra of `part`; returns the node ids of its top face.
  std::vector<int> block(int part, int first_node, int first_element, double x0, double x1,
                         double y0, double y1, double z0, double z1, int nx, int ny, int nz) {
    std::vector<int> top;
    kw("*NODE");
    const auto id = [&](int i, int j, int k) {
      return first_node + (k * (ny + 1) + j) * (nx + 1) + i;
    };
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
          card(id(i, j, k), x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny,
               z0 + (z1 - z0) * k / nz);
          if (k == nz)
            top.push_back(id(i, j, k));
        }
    kw("*ELEMENT_SOLID");
    int e = first_element;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          card(e++, part, id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
               id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1));
    return top;
  }

  [[nodiscard]] std::string text() const { return os_.str() + "*END\n"; }

 private:
  std::ostringstream os_;
};

/// A `*USER_INTERFACE_FRICTION` for contact `id`: the cohesive law bonded at t = 0 (BOND_TOL
/// 1e-3), C_N `cn`, sigma_max `smax` at every temperature, rate free, with no tangential
/// adhesion, no friction, no healing and no damping: its books are the normal adhesion's alone.
inline void bonded_without_shear(DeckWriter& d, int id, double cn, double smax) {
  // UC1..UC20: MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL FRIC
  // MU_LO MU_HI VISC_LO VISC_HI FILM_H VDC BETA_MIN CT
  d.kw("*USER_INTERFACE_FRICTION").card(id, 20, 0);
  d.card(1, cn, smax, smax, 100.0, 200.0, 1e-9, 0.0);
  d.card(0.0, 1.0, 1e-3, 0, 0.0, 0.0, 0.0, 0.0);
  d.card(0.0, 0.0, 1e-3, 0.0);
}

struct DeckRun {
  engine::RunResult result;
  RecordingSink sink;
  /// Cohesive results of the slave nodes at each nodout time: (time, results).
  std::vector<std::pair<double, std::vector<contact::SlaveNodeResult>>> cohesive;
  std::vector<std::pair<double, std::vector<double>>> uz;  ///< nodout: uz of history nodes
  /// nodout: every node's temperature.
  std::vector<std::pair<double, std::vector<double>>> temperature;
};

/// Reads, validates, builds and runs `text`; fails the test (and returns an empty run) on any
/// deck error.
inline void run_deck(const std::string& text, DeckRun& out, int threads = 1) {
  TempDir dir;
  const auto read = keyword::read_deck(dir.write("deck.k", text));
  ASSERT_TRUE(read.ok()) << read.errors.front().to_string();
  const auto errors = setup::validate(read.model);
  ASSERT_TRUE(errors.empty()) << errors.front().to_string();
  auto built = setup::build(read.model);
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  const core::Model& m = *built.model;
  // A test's own nodout probe (set before the call) runs after the recording.
  std::function<void(const engine::Snapshot&)> probe = std::move(out.sink.on_nodout);
  out.sink.on_nodout = [&](const engine::Snapshot& s) {
    if (probe)
      probe(s);
    if (s.contact != nullptr) {
      out.cohesive.emplace_back(s.time, std::vector<contact::SlaveNodeResult>{});
      s.contact->cohesive_results(out.cohesive.back().second);
    }
    std::vector<double> uz;
    for (core::Index i : m.output.history_nodes)
      uz.push_back(s.nodes->uz[static_cast<std::size_t>(i)]);
    out.uz.emplace_back(s.time, uz);
    out.temperature.emplace_back(s.time, s.nodes->temperature);
  };
  engine::SolverOptions options;
  options.threads = threads;
  out.result = engine::run(m, out.sink, options);
  ASSERT_TRUE(out.result.ok) << out.result.error;
}

}  // namespace plyform::test
