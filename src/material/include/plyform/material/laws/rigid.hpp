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
  static const auto& cards(const model::ModelDesc& d) { return d.rigid_materials; }
  static Parameters from_card(const model::MatRigidDesc& c, const DeckCurve&) {
    return {c.density, c.youngs_modulus, c.poisson_ratio, static_cast<double>(c.cmo), c.con1,
            c.con2};
  }
  static Moduli moduli(const Parameters& m) { return isotropic_moduli(m.young, m.poisson); }
};

}  // namespace plyform::material
