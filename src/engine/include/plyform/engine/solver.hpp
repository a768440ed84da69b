#pragma once
// The explicit central-difference engine: lumped mass, stable step from the elements, large
// deformation, boundary conditions, energies, output on schedule. It sees only the runtime
// model (flat arrays, local indices) and reports through an OutputSink.

#include <array>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "plyform/comm/communicator.hpp"
#include "plyform/contact/contact_set.hpp"
#include "plyform/core/model.hpp"
#include "plyform/core/state_archive.hpp"
#include "plyform/domain/resplit.hpp"
#include "plyform/element/shell_kernels.hpp"
#include "plyform/element/solid_kernels.hpp"
#include "plyform/engine/nodal_state.hpp"
#include "plyform/engine/pass_timing.hpp"
#include "plyform/rigid/rigid_bodies.hpp"
#include "plyform/rigid/rigid_walls.hpp"
#include "plyform/thermal/heat_solver.hpp"

namespace plyform::engine {

/// Global energies at one time, as in LS-DYNA's glstat.
struct Energies {
  double time = 0.0;
  double dt = 0.0;
  double kinetic = 0.0;
  double internal = 0.0;  ///< stress work, without hourglass
  double hourglass = 0.0;
  double contact = 0.0;        ///< energy taken by the contact interfaces (stored and dissipated)
  double external_work = 0.0;  ///< loads and reactions of constraints and prescribed motions
  double total = 0.0;          ///< kinetic + internal + hourglass + contact
  /// 1 + (total - (initial total + external work)) / scale, the scale being the largest
  /// initial total + external work of the run so far: LS-DYNA's total / (initial total +
  /// external work) while the energy that entered grows, and still the books' error as a share
  /// of the energy the model held once that energy has been taken back out (docs/energy.md).
  double ratio = 1.0;
};

/// Why a run's results are not to be trusted although it reached its end: a broken book
/// (docs/energy.md), with the time it first held.
struct Distrust {
  std::string reason;
  double time = 0.0;
};

/// One part's books at an output time (matsum.csv): the stress work and hourglass energy of
/// its elements since t = 0, the kinetic energy and momentum of its share of the nodal masses
/// (the nodes a part shares with another split by their elements' mass), or of its rigid body.
struct PartEnergies {
  core::GlobalId part = 0;
  bool rigid = false;
  double internal = 0.0;
  double kinetic = 0.0;
  double hourglass = 0.0;
  std::array<double, 3> momentum{};
};

/// What an output writer sees at an output time.
struct Snapshot {
  double time = 0.0;
  long cycle = 0;
  const core::Model* model = nullptr;
  const NodalState* nodes = nullptr;
  const std::vector<element::SolidBlockState>* solids = nullptr;
  const std::vector<element::ShellBlockState>* shells = nullptr;
  const rigid::RigidBodies* rigid = nullptr;     ///< the rigid bodies (may be empty)
  const contact::ContactSet* contact = nullptr;  ///< the contact interfaces (null: none)
};

class OutputSink {
 public:
  virtual ~OutputSink() = default;
  virtual void state(const Snapshot& s) = 0;   ///< at the d3plot interval, first and last
  virtual void glstat(const Energies& e) = 0;  ///< at the glstat interval
  virtual void nodout(const Snapshot& s) = 0;  ///< at the nodout interval
  /// At the glstat interval when the model has rigid bodies: their resultants and motion.
  virtual void rigid_bodies(double /*time*/, const rigid::RigidBodies& /*bodies*/) {}
  /// At the rwforc interval when the model has rigid walls: each wall's force and motion.
  virtual void rigid_walls(double /*time*/, const rigid::RigidWalls& /*walls*/) {}
  /// At the rcforc interval when the model has contacts: each interface's resultant force on
  /// its slave side and its energy books.
  virtual void contact_forces(double /*time*/,
                              const std::vector<contact::InterfaceReport>& /*interfaces*/) {}
  /// At the bndout interval: the reactions of the prescribed-motion nodes are in
  /// `s.nodes->rx, ry, rz` (the force the constraint applies to each node).
  virtual void boundary_forces(const Snapshot& /*s*/) {}
  /// At the spcforc interval: the reactions of the *BOUNDARY_SPC nodes are in
  /// `s.nodes->rx, ry, rz`.
  virtual void constraint_forces(const Snapshot& /*s*/) {}
  /// At the sleout interval when the model has contacts: each interface's energy books.
  virtual void interface_energies(double /*time*/,
                                  const std::vector<contact::InterfaceReport>& /*interfaces*/) {}
  /// At the matsum interval: each part's books, in the order of the model's parts.
  virtual void part_energies(double /*time*/, const std::vector<PartEnergies>& /*parts*/) {}
  /// At the elout interval when the model has history elements: their stresses and plastic
  /// strains are in `s.solids` and `s.shells` (shells' in their co-rotational frames), the
  /// current positions (for those frames) in `s.nodes->x, y, z`.
  virtual void element_histories(const Snapshot& /*s*/) {}
  /// When temperatures are computed, at the tprint interval (the glstat interval without
  /// *DATABASE_TPRINT) and at the end: the heat books since t = 0.
  virtual void heat(double /*time*/, const thermal::HeatLedger& /*ledger*/) {}
  /// At the tprint interval: the history nodes' temperatures are in `s.nodes->temperature`.
  virtual void temperatures(const Snapshot& /*s*/) {}
  /// Once, when the run reached its end time (not after an instability or a stop): the end
  /// state, positions up to date (the dynain file of *INTERFACE_SPRINGBACK_LSDYNA).
  virtual void end_of_run(const Snapshot& /*s*/) {}
  /// Every cycle (cheap: the sink throttles); wall seconds since the start.
  virtual void progress(double /*time*/, double /*end_time*/, long /*cycle*/, double /*dt*/,
                        double /*wall*/) {}
  /// Saves what the sink needs to go on after a restart (how far each file was written), into
  /// a checkpoint. Restoring is the sink owner's business (it opens the files).
  virtual void save_state(core::StateArchive& /*archive*/) {}
};

struct SolverOptions {
  int threads = 1;
  /// Stop when dt < this fraction of the first step (DTMIN of *CONTROL_TERMINATION overrides).
  double dt_floor_ratio = 1e-4;
  /// Replaces the deck's termination time (`--end-time`: a restart may run past it).
  std::optional<double> end_time;
  /// Checkpoints (*DATABASE_BINARY_D3DUMP, restart): the file (empty: none is written), every
  /// how many cycles (0: only when stopped, and at the end when > 0), and the deck's
  /// fingerprint written into it.
  std::filesystem::path checkpoint;
  long checkpoint_cycles = 0;
  std::uint64_t fingerprint = 0;
  /// Set (non-zero) by a signal handler: the run finishes its cycle and the outputs due, writes
  /// a checkpoint and stops (RunResult::stopped).
  const volatile std::sig_atomic_t* stop = nullptr;
  /// A run over several MPI ranks (docs/parallel.md): the ranks, and per node the rank that owns
  /// it (domain::Decomposition::node_owner; -1 where no deformable element touches it). Without
  /// them, or on one rank, the run is this process's alone.
  const comm::Communicator* ranks = nullptr;
  std::vector<int> node_owner;
  /// Re-balancing over the ranks (rank_balance.hpp): each rank's share of the first split's
  /// estimated cost and the seconds that split took; a new split for given target shares
  /// (unset: the first split stays); 0 splits again when it pays, N > 0 every N cycles or so
  /// whatever the imbalance (`--rebalance N`), -1 never (`--rebalance off`).
  std::vector<double> rank_cost;
  double split_seconds = 0.0;
  std::function<domain::OwnerSplit(std::span<const double>)> resplit;
  long rebalance_every = 0;
};

struct RunResult {
  bool ok = true;
  std::string error;  ///< the diagnosis when !ok (names the element or node and the time)
  long cycles = 0;
  double time = 0.0;
  double wall_seconds = 0.0;
  double element_cycles_per_second = 0.0;
  double dt_first = 0.0;
  double dt_last = 0.0;
  double added_mass = 0.0;  ///< by mass scaling
  double physical_mass = 0.0;
  Energies last;
  std::vector<std::string> warnings;
  /// The books that broke (each once, at the first time it held): a run that reached its end
  /// with any is "completed, results not to be trusted" (plyform run exits 5).
  std::vector<Distrust> distrust;
  long contact_searches = 0;  ///< full contact searches (bucket sorts) done
  /// The share of the contacts' slave node-cycles passed over at rest, clear of the master
  /// (contact::ContactSet::rested_share).
  double contact_rested_share = 0.0;
  /// Times the run dropped to one thread because its cores were shared (thread_governor.hpp),
  /// and the wall seconds it ran so.
  int thread_reductions = 0;
  double reduced_thread_seconds = 0.0;
  /// Over several ranks: how often the model was split again while running, each rank's share
  /// of the estimated cost in the last split, and the imbalance of the ranks' seconds (the
  /// slowest over the mean) at the first and the last look (rank_balance.hpp; 0: no look).
  int resplits = 0;
  std::vector<double> rank_shares;
  double first_imbalance = 0.0, last_imbalance = 0.0;
  /// Over several ranks: the nodes this rank moved at the end (each rank its own and a ring of
  /// its neighbours', docs/parallel.md), or 0 where every rank moved every node, and then why.
  std::size_t moved_nodes = 0;
  std::string every_node_moved_because;
  /// Stopped on request (SolverOptions::stop) before the end time; a checkpoint was written.
  bool stopped = false;
  int checkpoints = 0;     ///< checkpoints written by this run
  std::string checkpoint;  ///< the last one's file (empty: none)
  bool restarted = false;  ///< continued from a checkpoint (Simulation::restore)
  double restart_time = 0.0;
  long restart_cycle = 0;
  /// Heat transfer (*CONTROL_SOLUTION SOLN 1 or 2): thermal steps, conjugate-gradient
  /// iterations (solver 12), and the books at the end.
  long thermal_steps = 0;
  long thermal_iterations = 0;
  thermal::HeatLedger heat;
  /// Where this process's time loop spent its wall time, pass by pass (pass_timing.hpp).
  PassTiming timing;
};

/// The run of one model. It owns the whole state of the run (simulation.cpp, `State`):
/// nodal fields, element block states, rigid bodies, contact passes with their laws' histories,
/// the integrator's scalars, the energy books and the output clocks. A cycle is a short list of
/// named passes (positions, internal forces, loads and temperatures, contact, step vote,
/// velocities and constraints, then outputs); the state saves to and restores from flat
/// records (checkpoints).
class Simulation {
 public:
  /// Sets the run up at t = 0 (mass, rigid bodies, contact, the first element pass and the
  /// first half step); failures are reported by run().
  Simulation(const core::Model& model, OutputSink& sink, const SolverOptions& options);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Takes the state of a checkpoint (the records save() gave, read back) in place of the one
  /// set up at t = 0; run() then continues from there without writing the outputs of t = 0.
  /// Throws core::StateError when the records do not fit this model.
  void restore(const core::StateArchive::Records& records);

  /// Runs to the end time, the first instability or a stop request.
  RunResult run();

  /// The run's state as checkpoint records (the sink's under "outputs/").
  core::StateArchive::Records save();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Runs the model to its termination time (or the first instability) and returns what
/// happened. Output written through `sink` before a failure stays written; on a failure the
/// last state is written too.
RunResult run(const core::Model& model, OutputSink& sink, const SolverOptions& options);

}  // namespace plyform::engine
