#pragma once
// Heat conduction on the nodes of every part with a thermal material: lumped heat capacity,
// conductance of hexahedra and thin shells on the current geometry, convection, flux and
// radiation on faces, prescribed temperatures, heat from the mechanics; advanced by an
// implicit theta step (TIP) that spans many mechanical steps (docs/thermal.md).

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/core/state_archive.hpp"

namespace plyform::thermal {

/// The heat books since t = 0, cumulative: `stored` (sum of C (T - T0)) equals the sum of the
/// others, the heat that entered through each path (prescribed: what holding the prescribed
/// temperatures took).
struct HeatLedger {
  double stored = 0.0;
  double contact = 0.0;
  double friction = 0.0;
  double plastic = 0.0;
  double convection = 0.0;
  double radiation = 0.0;
  double flux = 0.0;
  double prescribed = 0.0;
  double generation = 0.0;
  double moved = 0.0;  ///< sum of the magnitudes of every path's heat per step (a scale)
  [[nodiscard]] double entered() const {
    return contact + friction + plastic + convection + radiation + flux + prescribed + generation;
  }
};

/// The current geometry: node positions (x, y, z at `stride` doubles apart) and each shell
/// block's current thickness per element (null: the section's).
struct Geometry {
  const double* xyz = nullptr;
  std::size_t stride = 3;
  std::vector<const double*> shell_thickness;
};

/// Heat the mechanics gave each node since the last thermal step (energies; null: none).
struct MechanicalHeat {
  const double* contact = nullptr;
  const double* friction = nullptr;
  const double* plastic = nullptr;
};

struct StepReport {
  bool ok = true;
  std::string error;        ///< why not ok (a non-finite temperature, at which node)
  int iterations = 0;       ///< conjugate-gradient iterations (0: direct solver)
  bool converged = true;    ///< the iterative solver reached its tolerance
  double max_change = 0.0;  ///< largest |T_{n+1} - T_n| of a free node
};

class HeatSolver {
 public:
  /// Sets up the nodes that conduct (those of elements whose part has a thermal material),
  /// their heat capacity and the matrix pattern. `temperature` (every node) holds the initial
  /// temperatures; the prescribed ones at t = 0 are written into it.
  HeatSolver(const core::Model& model, std::span<double> temperature);
  ~HeatSolver();
  HeatSolver(const HeatSolver&) = delete;
  HeatSolver& operator=(const HeatSolver&) = delete;

  /// The time of the temperatures last computed.
  [[nodiscard]] double time() const { return time_; }
  /// The length of the next thermal step; `dt_mech` is the mechanical step (0 when there is
  /// no mechanics), which sets TMIN and TMAX when they are 0.
  [[nodiscard]] double step_length(double dt_mech) const;
  /// One thermal step from time() to t1 on geometry `g`; writes the temperatures of the
  /// conducting nodes into `temperature` (every node).
  /// `links`: the slave nodes of the _THERMAL contacts and their segments (contact heat).
  StepReport advance(double t1, const Geometry& g, std::span<double> temperature,
                     const MechanicalHeat& heat, std::span<const core::ContactHeatLink> links,
                     double dt_mech);

  [[nodiscard]] const HeatLedger& ledger() const { return ledger_; }
  [[nodiscard]] long steps() const { return steps_; }
  [[nodiscard]] long iterations() const { return iterations_; }
  /// Wall seconds in the linear solves (factorisation and solution) so far.
  [[nodiscard]] double solve_seconds() const { return solve_seconds_; }
  [[nodiscard]] std::size_t unknowns() const { return nodes_.size(); }
  /// The node of each unknown (local node indices); thick thermal shells' faces after the
  /// nodes' own unknowns.
  [[nodiscard]] const std::vector<core::Index>& nodes() const { return nodes_; }
  /// Whether the model has thick thermal shells (faces with their own temperatures).
  [[nodiscard]] bool has_faces() const { return !bottom_.empty(); }
  /// The bottom and top face temperatures of every conducting node (every node's entry is
  /// written where it conducts: a node without faces gets its one temperature in both).
  void face_temperatures(std::span<double> bottom, std::span<double> top) const;
  /// For the slave node of each contact link of the last step, the temperature of the face it
  /// coupled through (the face turned to its segment); other entries are left as they are.
  void interface_temperatures(std::span<double> temperature) const;

  /// The state a checkpoint holds: temperatures at time(), the step, the books.
  void visit_state(core::StateArchive& a);

 private:
  struct Matrices;
  // The conductance (unscaled by TSF) on the current geometry.
  void assemble(const Geometry& g);
  void build_pattern();
  // The unknown of a node's face (loc -1 bottom, 1 top) or middle (0); the node's own when it
  // has no faces.
  [[nodiscard]] core::Index unknown_at(core::Index node, int loc) const;
  // A thick shell's 12 unknowns: middles, bottoms, tops of its 4 nodes.
  [[nodiscard]] std::array<core::Index, 12> thick_unknowns(const core::Index* c) const;
  void update_normals(const Geometry& g);
  [[nodiscard]] std::array<core::Index, 5> link_unknowns(const core::ContactHeatLink& l,
                                                         const Geometry& g) const;
  const core::Model& model_;
  std::vector<core::Index> nodes_;         // unknown -> node
  std::vector<core::Index> unknown_;       // node -> unknown (-1: none)
  std::vector<signed char> layer_;         // per unknown: -1 bottom, 0 middle, 1 top face
  std::vector<core::Index> bottom_, top_;  // node -> face unknown (-1: none; empty: none at all)
  std::vector<double> normal_;             // 3 per node: thick shells' area-weighted normals
  std::vector<std::array<core::Index, 5>> link_unknowns_;  // scratch of one step
  std::vector<char> covered_;     // scratch: nodes whose boundaries BC_FLG turns off (empty: none)
  std::vector<double> capacity_;  // per unknown
  std::vector<double> temperature_;  // per unknown, at time_
  std::vector<double> initial_;      // per unknown, at t = 0 (the books' reference)
  std::vector<double> change_;       // the last step's T_{n+1} - T_n (the CG's first guess)
  std::vector<std::pair<core::Index, std::size_t>> prescribed_;  // unknown, history
  std::vector<std::pair<core::Index, double>> generation_;       // unknown, volume x material
  std::vector<core::Index> generation_material_;                 // per entry of generation_
  std::unique_ptr<Matrices> m_;
  std::vector<std::array<int, 2>> extra_;  // matrix couplings brought by contact links
  double time_ = 0.0;
  double next_ = 0.0;     // the variable step's next length
  double last_dt_ = 0.0;  // the length the matrix was assembled for
  long steps_ = 0;
  long iterations_ = 0;
  double solve_seconds_ = 0.0;
  long since_assembly_ = 0;
  HeatLedger ledger_;
};

}  // namespace plyform::thermal
