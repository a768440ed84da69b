#pragma once
// The runtime model: everything the engine needs, laid out in flat arrays with local indices.
// Built once by setup::build from a ModelDesc; the engine never sees a string or a deck id in
// its loop (ids are kept only to write results).

#include <array>
#include <string>
#include <vector>

#include "plyform/core/contact.hpp"
#include "plyform/core/load_curve.hpp"
#include "plyform/core/material.hpp"
#include "plyform/core/rigid_wall.hpp"
#include "plyform/core/thermal.hpp"
#include "plyform/core/tied_interface.hpp"
#include "plyform/core/types.hpp"

namespace plyform::core {

/// Solid element formulations of *SECTION_SOLID.
enum class SolidFormulation : int {
  one_point = 1,          ///< ELFORM 1: constant stress, hourglass control
  selective_reduced = 2,  ///< ELFORM 2: 2x2x2 Gauss, mean dilatation (selective reduced)
};

/// *HOURGLASS / *CONTROL_HOURGLASS for ELFORM 1.
struct HourglassControl {
  int ihq = 1;      ///< 1-3: viscous (Flanagan-Belytschko), 4-5: stiffness
  double qm = 0.1;  ///< coefficient
};

/// Bulk viscosity (*CONTROL_BULK_VISCOSITY, or the part's *HOURGLASS Q1 and Q2): in
/// compression a pressure q = rho l |tr D| (Q1 l |tr D| + Q2 c) (docs/materials.md).
struct BulkViscosity {
  double q1 = 1.5;   ///< quadratic coefficient
  double q2 = 0.06;  ///< linear coefficient
};

/// Elements of one formulation and one material (and part), in blocks for the kernels.
struct SolidBlock {
  SolidFormulation formulation = SolidFormulation::one_point;
  Index part = 0;      ///< index into Model::parts
  Index material = 0;  ///< index into Model::materials
  HourglassControl hourglass;
  BulkViscosity bulk_viscosity;
  std::vector<GlobalId> element_id;
  std::vector<Index> connectivity;  ///< 8 node indices per element, LS-DYNA order
  /// Elements are ordered by colour: no two elements of a colour share a node, so a colour's
  /// elements add their forces to the nodes in parallel without races, and each node receives
  /// its contributions in colour order whatever the number of threads. Colour c is the range
  /// [colour_start[c], colour_start[c + 1]). Set by colour_element_blocks().
  std::vector<std::size_t> colour_start;
  /// Thermal expansion: the tangent coefficient alpha against temperature (1/temperature);
  /// the thermal strain increment of a step is alpha(T_mid) (T_{n+1} - T_n). Empty: none.
  LoadCurve expansion;
  [[nodiscard]] std::size_t size() const { return element_id.size(); }
};

/// Shell formulations of *SECTION_SHELL.
enum class ShellFormulation : int {
  belytschko_tsay = 2,  ///< ELFORM 2: co-rotational, one in-plane point, hourglass control
  /// ELFORM 16: co-rotational, 2 x 2 in-plane Gauss points, assumed natural strain transverse
  /// shear (MITC4); no hourglass modes, so no hourglass control.
  fully_integrated = 16,
};

/// Through-thickness integration rule of *SECTION_SHELL (QR/IRID).
enum class ThicknessRule : int { gauss = 0, lobatto = 1 };

/// Shell elements of one formulation, one material and one section: quadrilaterals, and
/// triangles written as quadrilaterals with N3 = N4.
struct ShellBlock {
  ShellFormulation formulation = ShellFormulation::belytschko_tsay;
  Index part = 0;
  Index material = 0;
  HourglassControl hourglass;
  int nip = 2;  ///< integration points through the thickness
  ThicknessRule rule = ThicknessRule::gauss;
  double shear_factor = 5.0 / 6.0;  ///< SHRF
  /// Bulk viscosity of the membrane (*CONTROL_BULK_VISCOSITY TYPE -1/-2): in in-plane
  /// compression the pressure q of the solids' form with l = sqrt(A), work to internal energy.
  bool bulk_viscosity_on = false;
  BulkViscosity bulk_viscosity;
  std::vector<GlobalId> element_id;
  std::vector<Index> connectivity;        ///< 4 node indices per element
  std::vector<double> thickness;          ///< initial thickness at the 4 nodes of each element
  std::vector<std::size_t> colour_start;  ///< as SolidBlock::colour_start
  LoadCurve expansion;                    ///< as SolidBlock::expansion
  /// The element card's material angle BETA, radians, per element (empty when no element of
  /// the block has one): turns the material axes of AOPT 0 and 3 instead of the material's.
  std::vector<double> material_angle;
  [[nodiscard]] std::size_t size() const { return element_id.size(); }
};

struct Part {
  GlobalId id = 0;
  std::string title;
  Index material = 0;
  Index thermal_material = -1;  ///< index into Model::thermal_materials (-1: no conduction)
};

/// Degrees of freedom as bits: x, y, z translations and rotations about x, y, z (shell nodes).
enum Dof : unsigned { dof_x = 1u, dof_y = 2u, dof_z = 4u, dof_rx = 8u, dof_ry = 16u, dof_rz = 32u };

/// *BOUNDARY_SPC_NODE/_SET (and *NODE TC, RC): fixed degrees of freedom of one node, along
/// and about the global axes or, when `local`, the axes of a coordinate system (CID).
struct FixedDofs {
  Index node = 0;
  unsigned dofs = 0;   ///< Dof bits, of the local axes when `local`
  bool local = false;  ///< the bits name the axes below
  /// The local unit axes, rows x, y, z in global components (orthonormal, right-handed).
  std::array<std::array<double, 3>, 3> axes{};
};

enum class MotionKind : int { velocity = 0, acceleration = 1, displacement = 2 };

/// *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET: one node, one translational direction, or (DOF
/// 9-11) its turning about an axis parallel to a global one.
struct PrescribedMotion {
  Index node = 0;
  /// 0, 1, 2: translation along x, y, z. 3, 4, 5: the node turns about an axis parallel to
  /// x, y, z through `axis`; its two translations across the axis are prescribed, the one
  /// along it stays free. The curve then gives the angle (radians, right-handed about the
  /// positive axis), the angular velocity or the angular acceleration.
  int direction = 0;
  /// Directions 3-5: the axis's coordinates along the two global axes across it, in cyclic
  /// order: (y, z) about x, (z, x) about y, (x, y) about z (LS-DYNA's OFFSET1, OFFSET2).
  std::array<double, 2> axis{};
  MotionKind kind = MotionKind::velocity;
  Index curve = 0;  ///< index into Model::curves
  double scale = 1.0;
  double birth = 0.0;
  double death = 1e28;
};

/// *LOAD_NODE_POINT/_SET: a force on one node in one direction.
struct NodalLoad {
  Index node = 0;
  int direction = 0;
  Index curve = 0;
  double scale = 1.0;
};

/// *LOAD_SEGMENT(_SET), *LOAD_SHELL_ELEMENT/_SET: a pressure of a curve on segments, on their
/// current area and against their current normal (N1 -> N2 -> N3, right-handed): a follower
/// load, zero before its arrival time.
struct PressureLoad {
  Index curve = 0;
  double scale = 1.0;
  double arrival = 0.0;
  std::size_t first = 0;  ///< its segments: Model::pressure_segments[first, first + count)
  std::size_t count = 0;
};

/// *BOUNDARY_PRESCRIBED_MOTION_RIGID: a rigid part's translation (dof 0-2) or rotation about a
/// global axis through its centre of mass (dof 3-5).
struct RigidMotion {
  Index part = 0;  ///< index into Model::parts (a part with RigidMaterial)
  int dof = 0;     ///< 0, 1, 2: x, y, z translation; 3, 4, 5: rotation about x, y, z
  MotionKind kind = MotionKind::velocity;
  Index curve = 0;
  double scale = 1.0;
  double birth = 0.0;
  double death = 1e28;
};

/// *LOAD_RIGID_BODY: a force (dof 0-2) or moment (dof 3-5) on a rigid part's centre of mass.
struct RigidLoad {
  Index part = 0;
  int dof = 0;
  Index curve = 0;
  double scale = 1.0;
};

struct Controls {
  double end_time = 0.0;    ///< *CONTROL_TERMINATION ENDTIM
  long end_cycle = 0;       ///< ENDCYC (0: none)
  double dt_min_ratio = 0;  ///< DTMIN: stop when dt < DTMIN * dt0 (0: default 1e-3... see engine)
  /// ENDENG as a fraction: the run stops once its energy ratio leaves 1 +- this (0: the
  /// engine's default band, `docs/energy.md`).
  double energy_change_limit = 0.0;
  double tssfac = 0.9;  ///< *CONTROL_TIMESTEP
  double dt2ms = 0.0;   ///< > 0: mass scaling to reach dt = |DT2MS| * TSSFAC
  double dt_init = 0.0;
  /// LCTM: the curve (index in Model::curves) of the largest step against time; -1: none.
  Index max_step_curve = -1;
  bool hourglass_energy = true;  ///< *CONTROL_ENERGY HGEN
};

/// An element of a block (elout.csv): the block's index in Model::solid_blocks or
/// shell_blocks and the element's index in it (after colouring).
struct BlockElement {
  Index block = 0;
  Index element = 0;
};

/// *INITIAL_STRESS_SHELL, resolved by setup: one shell's stress and effective plastic strain at
/// t = 0 at the points the card gives: `thickness_points` through the thickness (their T,
/// increasing) times `in_plane` (1 or 4) in-plane points, thickness point major
/// (k * in_plane + g), the stress in global axes (xx yy zz xy yz zx). The engine interpolates
/// them to the block's points and turns them into the element's co-rotational frame of t = 0
/// (engine/initial_shell_stress.hpp).
struct InitialShellStress {
  BlockElement shell;
  int in_plane = 1;
  std::vector<double> t;               ///< per thickness point, in [-1, 1], increasing
  std::vector<double> stress;          ///< 6 per point
  std::vector<double> plastic_strain;  ///< 1 per point
};

/// *INTERFACE_SPRINGBACK_LSDYNA: the dynain file written at the end of the run.
struct DynainRequest {
  bool write = false;
  std::vector<Index> shell_blocks;  ///< the deformable shell blocks written, in block order
};

struct OutputRequests {
  double d3plot_dt = 0.0;            ///< *DATABASE_BINARY_D3PLOT (0: first and last state only)
  double glstat_dt = 0.0;            ///< *DATABASE_GLSTAT (0: none)
  double nodout_dt = 0.0;            ///< *DATABASE_NODOUT (0: none); also cohesive.csv
  double rcforc_dt = 0.0;            ///< *DATABASE_RCFORC (0: none)
  double bndout_dt = 0.0;            ///< *DATABASE_BNDOUT (0: none)
  double spcforc_dt = 0.0;           ///< *DATABASE_SPCFORC (0: none): spcforc.csv
  double sleout_dt = 0.0;            ///< *DATABASE_SLEOUT (0: none): sleout.csv
  double rwforc_dt = 0.0;            ///< *DATABASE_RWFORC (0: none): rwforc.csv
  double matsum_dt = 0.0;            ///< *DATABASE_MATSUM (0: none): matsum.csv
  double elout_dt = 0.0;             ///< *DATABASE_ELOUT (0: none or no element): elout.csv
  long d3dump_cycles = 0;            ///< *DATABASE_BINARY_D3DUMP CYCL (0: none)
  std::vector<Index> history_nodes;  ///< *DATABASE_HISTORY_NODE
  double tprint_dt = 0.0;            ///< *DATABASE_TPRINT (0: none): tprint.csv, heat.csv
  /// *DATABASE_HISTORY_SHELL and _SOLID (elout.csv), in deck order.
  std::vector<BlockElement> history_shells;
  std::vector<BlockElement> history_solids;
  /// *DATABASE_EXTENT_BINARY: the arrays each state (results_NNNN.vtu) holds.
  struct StateFields {
    bool shell_stress = true, solid_stress = true;                  ///< SIGFLG
    bool shell_plastic_strain = true, solid_plastic_strain = true;  ///< EPSFLG
    bool thickness = true;                                          ///< ENGFLG
    bool strain = false;                                            ///< STRFLG c = 1
  } state_fields;
  DynainRequest dynain;  ///< *INTERFACE_SPRINGBACK_LSDYNA: OUTDIR/dynain at the end
};

struct Model {
  std::string title;
  // Nodes (reference configuration).
  std::vector<GlobalId> node_id;
  std::vector<double> x0, y0, z0;
  // Elements, parts, materials.
  std::vector<Part> parts;
  std::vector<Material> materials;
  std::vector<SolidBlock> solid_blocks;
  std::vector<ShellBlock> shell_blocks;
  // Loads and constraints.
  std::vector<LoadCurve> curves;
  std::vector<FixedDofs> fixed;
  std::vector<PrescribedMotion> motions;
  std::vector<NodalLoad> loads;
  std::vector<PressureLoad> pressure_loads;
  /// The pressure loads' segments: local node indices N1..N4 (N4 = N3 for a triangle).
  std::vector<std::array<Index, 4>> pressure_segments;
  std::vector<RigidMotion> rigid_motions;
  std::vector<RigidLoad> rigid_loads;
  std::vector<RigidWall> rigid_walls;  ///< *RIGIDWALL_PLANAR, in deck order
  std::vector<double> v0x, v0y, v0z;   ///< initial velocities (empty: at rest)
  std::vector<double> w0x, w0y, w0z;   ///< initial angular velocities of shell nodes (empty: none)
  std::vector<InitialShellStress> initial_shell_stresses;  ///< *INITIAL_STRESS_SHELL
  // Temperatures (the law reads the slave node's): *INITIAL_TEMPERATURE, *BOUNDARY_TEMPERATURE.
  std::vector<double> temperature0;  ///< per node at t = 0 (empty: 0 everywhere)
  std::vector<TemperatureHistory> temperature_histories;
  // Heat transfer: *CONTROL_SOLUTION SOLN 1 or 2 (thermal.hpp).
  ThermalControls thermal;
  std::vector<ThermalMaterial> thermal_materials;
  std::vector<HeatBoundary> heat_boundaries;
  // Contact interfaces, in deck order.
  std::vector<ContactInterface> contacts;
  /// Tied contacts, in deck order (constraints: not in `contacts`).
  std::vector<TiedInterface> tied;
  Controls controls;
  OutputRequests output;

  [[nodiscard]] std::size_t node_count() const { return node_id.size(); }
  [[nodiscard]] std::size_t solid_count() const;
  [[nodiscard]] std::size_t shell_count() const;
  /// Solids and shells whose material is not rigid: the elements the cycle integrates (a
  /// rigid part's elements only give it mass, inertia and a contact surface).
  [[nodiscard]] std::size_t deformable_element_count() const;
};

/// Reorders the elements of every solid and shell block by colour (greedy, in element order;
/// within a colour along a Morton curve through the block) and fills colour_start. Returns false
/// when a node is shared by more elements than the colouring supports (128 colours).
bool colour_element_blocks(Model& model);

/// Whether every block's colouring holds: its colour ranges cover the block in order, its node
/// indices are in range, and no two elements of a colour share a node (what lets a colour's
/// elements add their forces to the nodes in parallel). Checked at the start of a run in the
/// builds that check invariants (invariant.hpp).
[[nodiscard]] bool colouring_is_independent(const Model& model);

}  // namespace plyform::core
