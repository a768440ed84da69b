#pragma once
// Contact interfaces of the runtime model: slave nodes against master segments, with every
// geometric and stiffness datum the contact pass needs precomputed by setup (flat arrays,
// local node indices). The interlayer law (src/law) gives the tractions of every interface: a
// *USER_INTERFACE_FRICTION puts the cohesive law on it; otherwise the law runs as a plain
// penalty-Coulomb contact (no adhesion, friction FS/FD/DC/VC, damping VDC). docs/contact.md.

#include <array>
#include <string>
#include <vector>

#include "plyform/core/types.hpp"
#include "plyform/law/parameters.hpp"

namespace plyform::core {

enum class ContactKind : int {
  one_way,            ///< *CONTACT_ONE_WAY_SURFACE_TO_SURFACE
  two_way,            ///< *CONTACT_SURFACE_TO_SURFACE
  forming,            ///< *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE
  automatic,          ///< *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE
  automatic_one_way,  ///< *CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE
  single_surface,     ///< *CONTACT_AUTOMATIC_SINGLE_SURFACE
};

/// How the penalty stiffness is found (SOFT of the contact).
enum class PenaltyKind : int {
  material = 0,  ///< SOFT = 0: from the bulk modulus and the element geometry
  mass = 1,      ///< SOFT = 1: the larger of that and SOFSCL m*/(2 dt0^2)
};

/// One sweep of slave nodes against master segments. A one-way contact has one, a two-way
/// contact two (the second with the sides swapped).
struct ContactPass {
  // Slave nodes and what they carry into the contact.
  std::vector<Index> slave_nodes;
  std::vector<double> slave_offset;     ///< contact half-thickness at the node [length]
  std::vector<double> slave_area;       ///< tributary area [length^2]
  std::vector<double> slave_stiffness;  ///< SOFT = 0 node stiffness [force/length]
  // Master segments: 4 node indices each, a triangle repeats its third node.
  std::vector<Index> segments;
  std::vector<double> segment_offset;  ///< contact half-thickness [length]
  /// Per segment: 1 for an exterior face of solids (one-sided: a node is always on its outward
  /// side, penetration is inside the body), 0 for a shell (touched from either side).
  std::vector<char> segment_one_sided;
  /// Per one-sided segment: the depth of its element behind it (V / A); a node more than half
  /// of it behind the face has not come through it (it is on the body's far side).
  std::vector<double> segment_depth;
  std::vector<double> segment_stiffness;  ///< SOFT = 0 segment stiffness [force/length]
  // Offsets that follow the current shell thickness (THKCHG = 1; cohesive interfaces always):
  // offset = factor * thickness, the thickness of a slave node the mean over its shells.
  // Shells are numbered across the model's shell blocks in order (block 0 first). A factor of
  // 0 keeps the fixed offset above (solid faces, SST/MST given, rigid shells).
  bool offsets_follow_thickness = false;
  std::vector<Index> segment_shell;            ///< per segment: its shell, -1 for none
  std::vector<double> segment_offset_factor;   ///< per segment
  std::vector<std::size_t> slave_shell_start;  ///< CSR per slave node into slave_shells
  std::vector<Index> slave_shells;
  std::vector<double> slave_offset_factor;  ///< per slave node
  // The faces of the slave surface (4 node indices each, like `segments`) and, per slave node,
  // those around it (CSR into slave_faces): the node's surface normal, along which its offset
  // surface point lies, is their mean.
  std::vector<Index> slave_faces;
  std::vector<std::size_t> slave_face_start;
  std::vector<Index> slave_face_index;
  // Self contact (single surface: the slave nodes are the master segments' nodes): per slave
  // node the segments it never meets (CSR, sorted): those around it and their neighbours, which
  // touch it through the mesh. Empty for other passes.
  std::vector<std::size_t> exclude_start;
  std::vector<Index> exclude;
  /// Self contact: a rigid node never meets a rigid segment (rigid bodies move as wholes).
  bool skip_rigid_pairs = false;
  /// +1 when the slave nodes are the interface's slave side (rcforc sums the force on them),
  /// -1 in the swapped pass of a two-way contact (the master nodes are the slave side then).
  int slave_side_sign = 1;
  /// The guard of a cohesive interface: its master's nodes against its slave's segments,
  /// pressure only (no adhesion, friction or heat: the law's state is the first pass's), and
  /// only beyond a tenth of the two offsets' depth, so that it keeps the layers in order where
  /// a node of the master would pass through the slave between its nodes without stiffening
  /// the bonded interface in compression.
  bool guard = false;
  [[nodiscard]] std::size_t slave_count() const { return slave_nodes.size(); }
  [[nodiscard]] std::size_t segment_count() const { return segments.size() / 4; }
};

/// Heat across an interface (the _THERMAL option of its keyword): the conductance of a
/// slave node's gap g to its master segment is H0 (or the curve of the contact pressure) for
/// g <= LMIN, K / g + FRAD (T_s^2 + T_m^2)(T_s + T_m) for LMIN < g <= LMAX, 0 beyond.
struct ContactHeat {
  bool enabled = false;
  double k = 0.0;
  double frad = 0.0;
  double h0 = 0.0;
  Index h0_curve = -1;  ///< H0 < 0: conductance against pressure (index into Model::curves)
  double lmin = 0.0;
  double lmax = 0.0;
  double ftosa = 0.5;
  bool one_way = false;  ///< ALGO 1: the contact leaves the master's temperature unchanged
  /// BC_FLG 1: convection, radiation and flux are off at the nodes in contact (a slave node
  /// with a closed gap, gap <= LMIN, and its segment's nodes).
  bool boundaries_off_in_contact = false;
  /// *CONTROL_CONTACT FRCENG 1: the law's friction dissipation heats the sides, FTOSA of it
  /// the slave's (its nodes), the rest the master's (through the segment's shape functions).
  bool friction_heat = false;
};

/// A slave node's link to its master segment across a _THERMAL interface, as the contact
/// last measured it: what the heat solver needs to set the link's conductance.
struct ContactHeatLink {
  Index slave = 0;
  std::array<Index, 4> master{};   ///< the segment's nodes
  std::array<double, 4> weight{};  ///< the projection's shape functions (sum 1)
  double area = 0.0;               ///< the slave node's area, over the interface's passes
  double gap = 0.0;                ///< surface gap (<= 0: in contact)
  double pressure = 0.0;           ///< contact pressure, positive in compression
  const ContactHeat* heat = nullptr;
};

/// LS-DYNA's built-in tiebreak (the _TIEBREAK option of the automatic contacts), instead of the
/// cohesive law: a tied slave node is held to its point of the master surface by the penalty
/// springs, in tension as in compression, until a stress criterion fails it; from then on it is
/// an ordinary penalty-Coulomb contact node and never ties again. docs/contact.md.
struct Tiebreak {
  int option = 0;  ///< 0: no tiebreak; 1-4 as LS-DYNA's OPTION
  double nfls = 0.0;
  double sfls = 0.0;
  bool sfls_is_friction_limit = false;  ///< OPTION 4, PARAM = 1
  [[nodiscard]] bool enabled() const { return option > 0; }
  /// Nodes that come into contact later tie too (OPTION 1 and 3).
  [[nodiscard]] bool ties_on_contact() const { return option == 1 || option == 3; }
  /// A stress criterion fails the tie (OPTION 2-4).
  [[nodiscard]] bool can_fail() const { return option >= 2; }
  /// Tangential motion is held while tied (OPTION 1-3); OPTION 4 lets the node slide.
  [[nodiscard]] bool holds_tangential() const { return option != 4; }
};

struct ContactInterface {
  GlobalId id = 0;      ///< CID of the deck (0 when the deck gave none)
  std::string keyword;  ///< the *CONTACT_ keyword, for messages
  ContactKind kind = ContactKind::one_way;
  std::vector<ContactPass> passes;
  PenaltyKind penalty = PenaltyKind::material;
  double sofscl = 0.1;  ///< SOFSCL (SOFT = 1)
  /// 1 min(slave, master), 2 master, 3 slave stiffness; 0: a layer interface's rule (a
  /// cohesive interface whose deck leaves PENOPT blank): the stiffer side's, held to the
  /// stiffness whose frequency is half the first step's, never below the softer side's
  int penopt = 1;
  double maxpar = 1.025;    ///< a projection this far outside a segment still counts
  int search_interval = 0;  ///< cycles between full searches (0: only when motion asks)
  double birth = 0.0;
  double death = 1e20;
  bool cohesive = false;  ///< the law has adhesion (a *USER_INTERFACE_FRICTION names it)
  Tiebreak tiebreak;      ///< the _TIEBREAK option (the law is then penalty-Coulomb)
  /// Initial penetrations (IGNORE): 0 pushed out by the penalty, 1 tracked (the penalty acts
  /// beyond the depth at t = 0 only, the depth shrinking as the node comes out), 2 as 1 with
  /// each node listed in the warnings.
  int ignore = 0;
  /// Setup moved this interface's initial penetrations out (IGNORE 0,
  /// setup::build_contacts): what it could not clear is tracked at the start, as IGNORE 1.
  bool leftovers_tracked = false;
  ContactHeat heat;     ///< the _THERMAL option
  law::Parameters law;  ///< the interface law (cohesive, or penalty-Coulomb)
};

/// A prescribed temperature history T(t) = scale * curve(t) (curve < 0: constant scale).
struct TemperatureHistory {
  Index node = 0;
  Index curve = -1;
  double scale = 1.0;
  double birth = 0.0;
  double death = 1e20;
  int loc = 0;  ///< LOC: on a thick thermal shell node the bottom (-1), middle (0) or top (1)
};

}  // namespace plyform::core
