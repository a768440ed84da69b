#pragma once
// The contact pass of the engine: every interface of the model, each a set of one-way passes
// (slave nodes against master segments). Per cycle: track or search the nearest segment of
// each slave node, measure the surface gap (after thickness offsets) and the tangential slip
// in the segment's plane, run the interface law over all slave nodes at once (law::Law::
// update_batch), and add the tractions to the slave node and, equal and opposite through the
// segment's shape functions, to the master nodes. See docs/contact.md.

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "plyform/comm/communicator.hpp"
#include "plyform/core/model.hpp"
#include "plyform/core/state_archive.hpp"
#include "plyform/law/node_state.hpp"

namespace plyform::contact {

class SlaveShare;

/// Totals of one interface (deck id), at the time of the last pass.
struct InterfaceReport {
  core::GlobalId id = 0;
  std::array<double, 3> force{};  ///< resultant contact force on the slave side, global axes
  /// Resultant on the master side: minus `force` to round-off (the shape functions of a
  /// segment sum to one), kept as a check of the force distribution.
  std::array<double, 3> master_force{};
  double work = 0.0;  ///< contact energy: work the contact forces took from the nodes
  /// Energy the normal tractions took from gap changes that no motion of the nodes made: the
  /// layers' thickness followed by the offsets, a node passing to a segment of another offset
  /// or height, an arrival depth let go, the surface's curvature. work + surface = what the
  /// law booked (stored + damage + viscous + friction + damping).
  double surface = 0.0;
  // The law's books, summed over the slave nodes (energy units).
  double stored = 0.0;         ///< held now: penalty and cohesive springs, stick springs
  double damage = 0.0;         ///< adhesion energy released by damage
  double viscous = 0.0;        ///< viscous dissipation of the adhesion evolution
  double friction = 0.0;       ///< friction dissipation
  double damping = 0.0;        ///< normal damping dissipation
  double healing = 0.0;        ///< adhesion energy restored by re-healing
  std::size_t in_contact = 0;  ///< slave nodes in compressive contact
  std::size_t bonded = 0;      ///< slave nodes separating with adhesion (beta > 0)
  /// A tied contact (a constraint): `force` is the reaction its master surface applies to the
  /// tied nodes; it has no energy books (interface_energy.csv leaves it out).
  bool tied = false;
};

/// One slave node of a cohesive interface at the time of the last pass.
struct SlaveNodeResult {
  core::Index node = 0;
  core::GlobalId interface = 0;
  law::NodeState state = law::NodeState::approaching;
  double gap = 0.0;       ///< surface gap [length] (NaN: no master segment in reach)
  double pressure = 0.0;  ///< normal traction, positive in compression [stress]
  double tau = 0.0;       ///< magnitude of the tangential traction [stress]
  double beta = 0.0;      ///< adhesion intensity
};

/// A slave node that penetrates its master segment at t = 0 in an interface with IGNORE = 0, and
/// the move that clears it (along the contact normal, by the depth).
struct InitialPenetration {
  core::Index node = 0;
  std::size_t interface = 0;  ///< index into Model::contacts
  double depth = 0.0;         ///< > 0
  std::array<double, 3> move{};
};

/// Where an interface's share of the run's wall time went (all its passes together), seconds
/// since the set-up: the search (the move check and the bucket sorts), the projection and
/// kinematics (segments, points, normals, gaps and slips), the law, and the forces (tractions
/// to forces, their work, the scatter to the nodes).
struct InterfaceTiming {
  std::size_t index = 0;  ///< in Model::contacts
  core::GlobalId id = 0;  ///< the deck's (_ID keywords; 0 without)
  double search = 0.0;
  double projection = 0.0;
  double law = 0.0;
  double forces = 0.0;
};

struct PassRuntime;  // src/pass_runtime.hpp

/// The rotational freedoms of the model's nodes (shells): angular velocities of the step just
/// taken, the internal-moment arrays (the engine's convention: w gains -I^-1 m dt) and the
/// lumped rotary inertia (0 where a node has no rotation).
struct Rotations {
  const double* wx = nullptr;
  const double* wy = nullptr;
  const double* wz = nullptr;
  double* mx = nullptr;
  double* my = nullptr;
  double* mz = nullptr;
  const double* inertia = nullptr;
};

class ContactSet {
 public:
  /// `mass`: the lumped nodal masses; `rigid`: 1 at nodes of rigid bodies (may be null);
  /// `dt0`: the elements' first stable step (SOFT = 1); `tssfac`: the step scale factor.
  ContactSet(const core::Model& model, const std::vector<double>& mass, const unsigned char* rigid,
             double dt0, double tssfac);
  ~ContactSet();
  ContactSet(const ContactSet&) = delete;
  ContactSet& operator=(const ContactSet&) = delete;

  [[nodiscard]] bool empty() const { return passes_.empty(); }

  /// The current thickness of every shell, numbered across the model's shell blocks in order
  /// (pointers into the engine's shell states, read every cycle): passes whose offsets follow
  /// the thickness (THKCHG = 1, cohesive interfaces) use it.
  void follow_shell_thickness(std::vector<const double*> thickness);

  /// The nodes' rotations (pointers into the engine's arrays, read and written every cycle).
  /// An offset contact surface point slides with its node's rotation: the tangential part of
  /// w x r enters the slip, and the tangential part F_t of a contact force on it puts the
  /// moment r x F_t on the node (the layers of a bonded stack then act as one section in
  /// bending and shear). Without them (null) the surface points follow the nodes' translation
  /// only. The step vote counts the rotary inertia.
  void follow_rotations(const Rotations& rotations);

  /// t = 0: the first search, then initially bonded nodes (BOND_TOL) bond. `packed`: x y z vx
  /// vy vz per node.
  /// `track_leftovers`: IGNORE 0's penetrations that setup could not move clear are tracked
  /// (as IGNORE 1); false where start() only measures them (contact::initial_penetrations).
  void start(const double* packed, bool track_leftovers = true);

  /// One cycle: positions of t (and velocities of the step dt just taken) in `packed`, nodal
  /// temperatures (null: 0). The contact forces are subtracted from the internal-force arrays
  /// f (the engine's convention: a = (f_ext - f) / m).
  void apply(double t, double dt, const double* packed, const double* temperature, double* fx,
             double* fy, double* fz);

  /// Over several MPI ranks (docs/parallel.md): from now on each rank runs the kinematics, the
  /// law and the forces of the slave nodes it owns (`node_owner`: per model node, its rank; -1
  /// for a node no deformable element touches, whose slave places are shared out in turn), and
  /// apply() hands what the scatter and the books read to every rank.
  void share_slaves(const comm::Communicator& comm, std::span<const int> node_owner);
  /// Over several ranks, before anything reads the passes' whole state (reports, cohesive
  /// results, heat, the checkpoint): every slave node's state from its owner. Once per apply().
  void gather_state();

  /// The contact's stable step vote (infinity when no slave node is near a segment).
  [[nodiscard]] double stable_step() const;
  /// Total contact energy (all interfaces): the glstat `contact` column.
  [[nodiscard]] double energy() const;
  [[nodiscard]] std::vector<InterfaceReport> report() const;
  /// Slave nodes of the cohesive and the tiebreak interfaces (beta: 1 tied, 0 failed), pass by
  /// pass.
  void cohesive_results(std::vector<SlaveNodeResult>& out) const;
  /// The slave nodes of the _THERMAL interfaces within LMAX of a master segment, pass by pass
  /// (a two-way interface's two passes each carry half the area; a one-way one (ALGO 1) only
  /// its first pass).
  /// `packed`: the current positions (x y z vx vy vz per node). A link's area is the slave
  /// node's share of its faces projected on the segment's plane.
  void heat_links(const double* packed, std::vector<core::ContactHeatLink>& out) const;
  /// Adds to `energy` (per node) the friction heat of the _THERMAL interfaces with FRCENG 1
  /// since the last call: of each slave node's friction dissipation, FTOSA to the deck's slave
  /// side and the rest to its master side (a segment's nodes by the shape functions).
  void take_friction_heat(std::vector<double>& energy);
  [[nodiscard]] std::size_t slave_count() const;
  /// Over several ranks, the wall seconds of apply()'s exchange of the slave nodes' forces.
  [[nodiscard]] double exchange_seconds() const { return exchange_seconds_; }
  /// The wall seconds of apply()'s work per slave node (kinematics, law, forces): the part
  /// that over several ranks each rank runs for its own slave nodes (the re-balancing weighs it).
  [[nodiscard]] double shared_seconds() const { return shared_seconds_; }
  /// Full searches done so far (all passes).
  [[nodiscard]] long searches() const { return searches_; }
  /// Of the slave node-cycles of the passes in their birth-death window so far (this rank's
  /// nodes over several ranks), the share the kinematics, the law and the forces passed over
  /// because the node rested clear of the master (resting_nodes.hpp); 0 before any.
  [[nodiscard]] double rested_share() const {
    return node_cycles_ > 0 ? static_cast<double>(rested_) / static_cast<double>(node_cycles_)
                            : 0.0;
  }
  /// Each interface's wall seconds in apply() by stage, in the model's order.
  [[nodiscard]] std::vector<InterfaceTiming> timing() const;
  /// Saves or restores what the passes carry from cycle to cycle (checkpoints): each slave
  /// node's law history, segment, shape functions, frame, slip and forces, the candidate lists
  /// of the last search and the positions it was made at, the energy books.
  void visit_state(core::StateArchive& archive);
  /// After start(): the slave nodes of interfaces with IGNORE = 0 and no cohesive law that
  /// penetrate their segment (tied and bonded nodes excepted), each with its move; for a rigid
  /// slave node, the deformable nodes of its segment, moved the other way.
  void initial_penetrations(std::vector<InitialPenetration>& out) const;
  /// Things the user should know (initial penetrations, ...), set by start().
  [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  const core::Model& model_;
  const std::vector<double>& mass_;
  const unsigned char* rigid_;
  void follow_thickness(PassRuntime& pr) const;
  std::vector<std::unique_ptr<PassRuntime>> passes_;
  // Per model node: how many tiebreak passes hold it (empty without one). Their springs share
  // one spring's stability budget at the node (penalty.cpp, tie_share).
  std::vector<std::uint8_t> tie_passes_at_;
  void count_tie_passes();
  std::vector<const double*> shell_thickness_;
  Rotations rot_;
  std::vector<std::string> warnings_;
  long searches_ = 0;
  long rested_ = 0, node_cycles_ = 0;  // rested_share()
  double tssfac_ = 0.9;
  // Over several ranks: per pass, its slave nodes shared out (empty on one rank); how many
  // apply() calls ran, and at which gather_state() last brought the state home.
  std::vector<std::unique_ptr<SlaveShare>> shares_;
  std::vector<unsigned char> active_;  // apply(): the passes in their birth-death window
  // apply(): whether, and in which order, the passes run side by side (passes_in_parallel());
  // per pass, its seconds so far, and this cycle's shared seconds and searches.
  bool passes_in_parallel();
  void apply_pass(std::size_t ip, double t, double dt, const double* packed,
                  const double* temperature);
  std::vector<std::size_t> pass_order_;
  std::vector<double> pass_cost_, pass_shared_, seconds_before_;
  std::vector<long> pass_searches_, pass_rested_, pass_node_cycles_;
  double exchange_seconds_ = 0.0;  // apply()'s exchange over the ranks
  double shared_seconds_ = 0.0;    // apply()'s work per slave node (shared_seconds())
  long applies_ = 0;
  long gathered_at_ = 0;
};

}  // namespace plyform::contact
