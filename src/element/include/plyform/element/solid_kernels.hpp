#pragma once
// Internal forces of 8-node solid elements, block by block: ELFORM 1 (one point, uniform
// gradient, Flanagan-Belytschko hourglass control) and ELFORM 2 (2x2x2 Gauss, selective
// reduced: deviatoric part at the points, volumetric part from the element mean).
//
// The kernel adds each element's 8 nodal forces to the nodal force arrays. Called on the
// elements of one colour at a time (core::SolidBlock::colour_start), it can run on several
// threads without races, and every node sums its contributions in the same order whatever the
// number of threads.

#include <cstddef>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::element {

/// Nodal arrays the kernels read (all of length node_count).
struct NodalView {
  const double *x, *y, *z;     ///< current coordinates (t_{n+1})
  const double *x0, *y0, *z0;  ///< reference coordinates
  const double *vx, *vy, *vz;  ///< velocities (t_{n+1/2})
  /// x, y, z, vx, vy, vz of each node side by side (6 per node): an element gathers each node
  /// from one cache line instead of six. The shell kernels read the current state from it only
  /// and need it; the solid kernels read it when given, else x, y, z, vx, vy, vz above (which
  /// may be stale when it is given).
  const double* packed = nullptr;
  /// Nodal temperatures at t_n (length node_count): read by the blocks whose state keeps
  /// element temperatures (laws that need them, thermal expansion). May be null otherwise.
  const double* temperature = nullptr;
  /// Thick thermal shells: the bottom and top faces' temperatures (null: none).
  const double* temperature_bottom = nullptr;
  const double* temperature_top = nullptr;
};

/// One element's share of its kernel call's books (SolidResult's and ShellResult's energies and
/// powers of the step). A kernel's result sums them over its elements in order, so the books of
/// a range can be summed again from its elements' shares, whoever computed them (the ranks of a
/// run over MPI, docs/parallel.md).
struct ElementBooks {
  double internal = 0.0, hourglass = 0.0;
  double start_power = 0.0, end_power = 0.0;
  double hourglass_start_power = 0.0, hourglass_end_power = 0.0;
};

/// Nodal internal force accumulators (length node_count), added to by the kernels.
struct NodalForces {
  double *fx, *fy, *fz;
  /// Optional: each element's plastic dissipation of the step (sigma_eq d eps_p over its
  /// points, energy) added to its nodes in equal shares, for the heat of plastic work.
  double* plastic_work = nullptr;
  /// Optional: each element's books (indexed by the element's place in its block).
  ElementBooks* books = nullptr;
};

/// State of one solid block: stresses per integration point (xx, yy, zz, xy, yz, zx) and
/// stiffness-hourglass displacements per element.
struct SolidBlockState {
  int points = 1;  ///< integration points per element
  std::vector<double> s[6];
  std::vector<double> eps_p;      ///< effective plastic strain per point (plasticity laws)
  std::vector<double> hourglass;  ///< 12 per element (IHQ 4/5)
  /// The bulk viscosity's pressure of each element's last update (its work is booked by the
  /// midpoint rule, as the stress's).
  std::vector<double> bulk_q;
  std::vector<double> volume;  ///< current volume per element
  /// sqrt(scaled mass / physical mass) per element (mass scaling): the element's stable step
  /// grows by this factor. 1 without mass scaling.
  std::vector<double> dt_factor;

  /// The law's own history (material::history_per_point values per point, point-major).
  std::vector<double> history;
  /// Per element, the mean temperature of its nodes at its last update, for laws that read
  /// temperatures and for thermal expansion (the step's change); empty when neither applies.
  std::vector<double> temperature;
  void resize(const core::SolidBlock& block, std::size_t history_per_point = 0);
};

/// What a kernel call reports for its element range.
struct SolidResult {
  double dt_min = 1e300;          ///< smallest stable step of the range (without TSSFAC)
  std::size_t dt_element = 0;     ///< element (index in the block) that sets it
  double hourglass_energy = 0.0;  ///< hourglass work of this cycle
  double internal_energy = 0.0;   ///< stress work of this cycle, from the elements' stresses
  /// The range's stress power at the step's start and end, sum of sigma_n : D V and of
  /// sigma_{n+1} : D V over its elements (D the step's rate): the engine books each stress on
  /// the mean of the two steps around it (docs/energy.md).
  double start_power = 0.0, end_power = 0.0;
  /// The same of the hourglass forces (their own book).
  double hourglass_start_power = 0.0, hourglass_end_power = 0.0;
  bool failed = false;                ///< a non-positive volume or Jacobian
  bool unsupported_material = false;  ///< failed: the material has no solid kernel
  std::size_t failed_element = 0;
};

/// Updates the stresses of elements [begin, end) of `block` for a step `dt` (from t_n to
/// t_{n+1}; dt = 0 computes the forces of the current stress only) and adds their internal
/// forces to `forces`. [begin, end) must lie within one colour when threads share `forces`.
SolidResult solid_forces(const core::SolidBlock& block, const core::Material& material,
                         SolidBlockState& state, const NodalView& nodes, double dt,
                         std::size_t begin, std::size_t end, const NodalForces& forces);

/// True for the material laws the solid kernels integrate.
bool supports_solids(const core::Material& material);

/// The stable step of element e alone (geometry and material), for reports.
double solid_stable_dt(const core::SolidBlock& block, const core::Material& material,
                       const NodalView& nodes, std::size_t e);

/// Reference volume of element e.
double solid_reference_volume(const core::SolidBlock& block, const NodalView& nodes, std::size_t e);

}  // namespace plyform::element
