#pragma once
// The formability arrays of the states (docs/outputs.md, "Formability"): for every shell cell
// the principal true strains at its bottom, middle and top surfaces
// (element/shell_surface_strain.hpp) and its thinning (h0 - h) / h0. What does not change
// during a run is set up once: the edge neighbours each shell's curvature is fitted to (shells
// of the same part sharing an edge with it and with no third shell), their orientation, and
// the reference curvatures. A state then costs one pass over the shells, into the arrays held
// here (nothing allocated per state).

#include <cstdint>
#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/element/shell_kernels.hpp"
#include "plyform/element/shell_surface_strain.hpp"
#include "plyform/engine/nodal_state.hpp"

namespace plyform::app {

class ShellFormability {
 public:
  /// `cells`: the states' cell count; the shells are the last cells, block after block.
  ShellFormability(const core::Model& model, std::size_t cells);

  /// Fills the arrays from the current node positions and shell thicknesses. Solid cells, the
  /// shells of rigid parts and collapsed shells hold NaN.
  void compute(const engine::NodalState& nodes,
               const std::vector<element::ShellBlockState>& shells);

  /// After compute(): shell s's (its index among all shells, block after block) strain tensors
  /// at its bottom and top surfaces in global axes, with ln(h/h0) along the normal
  /// (element::shell_surface_strain_tensors): the dynain file's *INITIAL_STRAIN_SHELL. False
  /// (nothing written) for a collapsed shell or one of a rigid part.
  bool surface_strain_tensors(std::size_t s, double thickness, double bottom[6],
                              double top[6]) const;

  /// Per cell. [0] bottom (z = -h/2), [1] middle, [2] top (z = +h/2).
  std::vector<double> major[3], minor[3];
  std::vector<double> thinning;

 private:
  /// The centre of shell s (its index among all shells) at the given coordinates.
  bool centre(std::size_t s, const double* x, const double* y, const double* z,
              element::ShellCentre& out) const;
  /// The covariant curvature of shell s from its neighbours' centres in `centres`.
  void curvature(std::size_t s, const std::vector<element::ShellCentre>& centres,
                 const std::vector<char>& valid, double b[3]) const;

  const core::Model& model_;
  std::size_t first_shell_cell_ = 0;
  std::vector<const core::Index*> connectivity_;  // per shell: its 4 nodes
  std::vector<double> initial_thickness_;         // per shell: h0, the mean of its nodes'
  std::vector<char> deformable_;                  // per shell: not of a rigid part
  // Per shell, up to 4 edge neighbours (-1: none) and +1 / -1: the neighbour's normal faces
  // the same side / the other side (its nodes run the other way round).
  std::vector<std::int64_t> neighbour_;
  std::vector<signed char> side_;
  std::vector<element::ShellCentre> reference_, current_;
  std::vector<char> reference_valid_, current_valid_;
  std::vector<double> reference_curvature_;  // 3 per shell (b0_11, b0_22, b0_12)
};

}  // namespace plyform::app
