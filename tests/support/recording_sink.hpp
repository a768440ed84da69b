#pragma once
// An OutputSink for tests: keeps what the engine reports in memory.

#include <functional>
#include <utility>
#include <vector>

#include "plyform/engine/solver.hpp"

namespace plyform::test {

struct RecordingSink : engine::OutputSink {
  std::vector<engine::Energies> energies;
  std::vector<double> state_times;
  /// Called at every state and every nodout time with the snapshot (for custom probes).
  std::function<void(const engine::Snapshot&)> on_state;
  std::function<void(const engine::Snapshot&)> on_nodout;

  void state(const engine::Snapshot& s) override {
    state_times.push_back(s.time);
    if (on_state)
      on_state(s);
  }
  void glstat(const engine::Energies& e) override { energies.push_back(e); }
  /// Contact reports at the rcforc interval: (time, interfaces).
  std::vector<std::pair<double, std::vector<contact::InterfaceReport>>> contact;
  void contact_forces(double time, const std::vector<contact::InterfaceReport>& r) override {
    contact.emplace_back(time, r);
  }
  /// Heat books (computed temperatures): (time, ledger).
  std::vector<std::pair<double, thermal::HeatLedger>> heat_books;
  void heat(double time, const thermal::HeatLedger& h) override {
    heat_books.emplace_back(time, h);
  }
  /// Rigid wall reports at the rwforc interval: (time, one report per wall).
  std::vector<std::pair<double, std::vector<rigid::RigidWalls::Report>>> walls;
  void rigid_walls(double time, const rigid::RigidWalls& w) override {
    walls.emplace_back(time, std::vector<rigid::RigidWalls::Report>{});
    for (std::size_t k = 0; k < w.size(); ++k)
      walls.back().second.push_back(w.report(k));
  }
  void nodout(const engine::Snapshot& s) override {
    if (on_nodout)
      on_nodout(s);
  }
};

/// A RecordingSink that also sums the constraints' reaction along one axis (0 x, 1 y, 2 z) over
/// a set of nodes at every bndout time: `force` holds (time, sum).
struct ReactionSink : RecordingSink {
  std::vector<core::Index> nodes;
  int axis = 0;
  std::vector<std::pair<double, double>> force;
  void boundary_forces(const engine::Snapshot& s) override {
    const std::vector<double>& r = axis == 0 ? s.nodes->rx : axis == 1 ? s.nodes->ry : s.nodes->rz;
    double f = 0.0;
    for (core::Index n : nodes)
      f += r[static_cast<std::size_t>(n)];
    force.emplace_back(s.time, f);
  }
};

}  // namespace plyform::test
