#pragma once
// *MAT_RIGID (020): the part moves as one rigid body (src/rigid); the element kernels skip it.
// E and nu scale the contact stiffness only.

#include "plyform/material/laws/law_traits.hpp"

namespace plyform::material {

struct RigidLaw {
  using Parameters = core::RigidMaterial;
  static constexpr LawInfo info{"*MAT_RIGID", 20, "rigid body"};
  static constexpr bool for_solids = false, for_shells = false;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = false;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 0> results{};
  static Moduli moduli(const Parameters& m) { return isotropic_moduli(m.young, m.poisson); }
};

}  // namespace plyform::material
