#pragma once
// The Belytschko-Lin-Tsay shell (LS-DYNA ELFORM 2): co-rotational, one in-plane integration
// point, NIP points through the thickness, Mindlin transverse shear, viscous (IHQ 1-3) or
// stiffness (IHQ 4-5) hourglass control.
// Like the solid kernels it adds each element's nodal forces and moments straight to the
// nodes, one colour at a time.

#include <cstddef>
#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/element/solid_kernels.hpp"

namespace plyform::element {

/// Nodal moment accumulators (length node_count).
struct NodalMoments {
  double *mx, *my, *mz;
};

/// Angular velocities of the nodes at t_{n+1/2} (length node_count).
struct NodalSpin {
  const double *wx, *wy, *wz;
};

/// State of a shell block: stresses in the element's co-rotational frame at every
/// through-thickness point (xx, yy, xy, yz, zx), effective plastic strain, current thickness.
/// ELFORM 16 keeps every in-plane Gauss point's column: arrays of points hold
/// points_per_element() values per element, Gauss point major (point g, thickness point k at
/// e * points_per_element() + g * nip + k).
struct ShellBlockState {
  int nip = 2;
  int inplane = 1;  ///< in-plane integration points: 1 (ELFORM 2) or 4 (ELFORM 16)
  [[nodiscard]] std::size_t points_per_element() const {
    return static_cast<std::size_t>(nip) * static_cast<std::size_t>(inplane);
  }
  std::vector<double> s[5];
  std::vector<double> eps_p;
  std::vector<double> thickness;  ///< per element
  std::vector<double> dt_factor;  ///< mass scaling, as for solids
  std::vector<double> area;       ///< current area per element
  /// The generalised hourglass forces of a BT element's four modes in its co-rotational frame
  /// (membrane x, y; out of plane; rotations x, y): accumulated from their rates (stiffness
  /// control, IHQ 4-5) or the last step's (viscous, IHQ 1-3: for the midpoint rule of their
  /// work). Empty for ELFORM 16.
  std::vector<double> hourglass[5];
  /// The membrane bulk viscosity's pressure of each in-plane point at its last update (its work
  /// is booked by the midpoint rule, as the stress's).
  std::vector<double> bulk_q;

  /// The law's own history (material::history_per_point values per point, point-major).
  std::vector<double> history;
  /// As SolidBlockState::temperature, per thickness point (nip per element): a thin thermal
  /// shell's one temperature, a thick one's profile through its thickness.
  std::vector<double> temperature;
  void resize(const core::ShellBlock& block, std::size_t history_per_point = 0);
};

/// Through-thickness integration points on [-1, 1] and their weights (sum 2).
void thickness_rule(core::ThicknessRule rule, int nip, double* zeta, double* weight);

struct ShellResult {
  double dt_min = 1e300;
  std::size_t dt_element = 0;
  double hourglass_energy = 0.0;
  double internal_energy = 0.0;  ///< stress work of the step, from the elements' stresses
  /// The range's stress power at the step's start and end (as SolidResult's).
  double start_power = 0.0, end_power = 0.0;
  double hourglass_start_power = 0.0, hourglass_end_power = 0.0;
  bool failed = false;                ///< a collapsed element (zero area or thickness)
  bool unsupported_material = false;  ///< failed: the material has no shell kernel
  std::size_t failed_element = 0;
};

/// Updates elements [begin, end) of `block` over `dt` and adds their internal forces and
/// moments to the nodes ([begin, end) within one colour when threads share the arrays).
ShellResult shell_forces(const core::ShellBlock& block, const core::Material& material,
                         ShellBlockState& state, const NodalView& nodes, const NodalSpin& spin,
                         double dt, std::size_t begin, std::size_t end, const NodalForces& forces,
                         const NodalMoments& moments);

/// The fully integrated kernel (ELFORM 16, shell_full.cpp); shell_forces dispatches to it.
ShellResult shell_full_forces(const core::ShellBlock& block, const core::Material& material,
                              ShellBlockState& state, const NodalView& nodes, const NodalSpin& spin,
                              double dt, std::size_t begin, std::size_t end,
                              const NodalForces& forces, const NodalMoments& moments);

/// Stable step of element e alone (LS-DYNA's shell length: area over the longest side), from
/// the reference configuration.
double shell_stable_dt(const core::ShellBlock& block, const core::Material& material,
                       const NodalView& nodes, std::size_t e);

/// Reference area of element e.
double shell_reference_area(const core::ShellBlock& block, const NodalView& nodes, std::size_t e);

/// The co-rotational frame of element e at the given coordinates (e1, e2 in the shell, e3 its
/// normal), in which ShellBlockState keeps the stresses. False for a collapsed element.
bool shell_frame(const core::ShellBlock& block, const double* x, const double* y, const double* z,
                 std::size_t e, double e1[3], double e2[3], double e3[3]);

/// True for the material laws the shell kernel integrates.
bool supports_shells(const core::Material& material);

}  // namespace plyform::element
