#pragma once
// What every material law unit provides (laws/*.hpp), and the point views its updates get.
//
// A law is one struct, listed once in law_registry.hpp:
//   using Parameters = core::...;            its constants (the runtime model's variant member)
//   static constexpr LawInfo info;           keyword, LS-DYNA number, a one-line summary
//   static constexpr bool for_solids, for_shells;
//   static constexpr bool needs_deformation_gradient;  solids: F from the reference configuration
//                                                       (a total, hyperelastic law), else D and W
//   static constexpr bool needs_material_axes;          shells: the angle of its axis a per point
//   static constexpr bool needs_temperature;            optional (false when absent): the
//                                                       points' temperatures (SolidPoints,
//                                                       ShellPoints ::temperature)
//   static constexpr std::array<std::string_view, N> history;  names of its per-point history
//                                                       (beyond the stress and the effective
//                                                       plastic strain, which every block keeps)
//   static constexpr std::array<std::string_view, M> results;  the result fields it fills
//   static Moduli moduli(const Parameters&);  small-strain bulk and shear moduli (time step,
//                                             contact stiffness, hourglass scaling)
//   static void update_solid(const Parameters&, const SolidPoints&);   when for_solids
//   static void update_shell(const Parameters&, std::size_t n, const ShellPoints&);
//                                       when for_shells: the chunk's n points
//   static MaterialAxes axes(const Parameters&);                        when needs_material_axes
//   static const auto& cards(const model::ModelDesc&);  the deck's cards of its keyword
//   static Parameters from_card(const Card&, const DeckCurve&);  their values as parameters
//                                       (or from_card(const Card&, const DeckCurve&, const
//                                       DeckTable&) for laws whose cards may name tables)
//   static constexpr bool needs_spin;   optional (false when absent): shells, the in-plane
//                                       rotation of the material relative to the co-rotational
//                                       frame over the step (ShellPoints::spin), for laws that
//                                       carry directions in their history
//   static constexpr bool needs_frame_turn;  optional (false when absent): shells, the
//                                       material's own spin and the frame's exact turn over the
//                                       step (ShellPoints::material_spin, frame_turn), for laws
//                                       whose directions must stay material lines to round-off
// The element kernels read only these traits: a new law needs no edit to a kernel.

#include <array>
#include <cstddef>
#include <functional>
#include <string_view>

#include "plyform/core/curve_table.hpp"
#include "plyform/core/load_curve.hpp"
#include "plyform/model/model_desc.hpp"

#include "plyform/material/constitutive.hpp"
#include "plyform/material/shell.hpp"

namespace plyform::material {

struct LawInfo {
  std::string_view keyword;  ///< "*MAT_ELASTIC"
  int number = 0;            ///< LS-DYNA's material number (001)
  std::string_view summary;
};

/// Small-strain moduli (stress units).
struct Moduli {
  double bulk = 0.0;
  double shear = 0.0;
};

inline Moduli isotropic_moduli(double young, double poisson) {
  return {young / (3.0 * (1.0 - 2.0 * poisson)), young / (2.0 * (1.0 + poisson))};
}

/// A deck curve by its id (the runtime model's copy), for laws whose cards refer to curves.
using DeckCurve = std::function<const core::LoadCurve&(int id)>;
/// A deck table (*DEFINE_TABLE) by its id; null when `id` is no table (then it is a curve).
using DeckTable = std::function<const core::CurveTable*(int id)>;

/// n solid integration points of one call (structure of arrays).
struct SolidPoints {
  std::size_t n = 0;
  ConstSymView d{};                  ///< rate of deformation (tensor shear), 1/time
  const double* w[3] = {};           ///< spin W_12, W_23, W_31
  const double* const* f = nullptr;  ///< 9 arrays F_ij (needs_deformation_gradient only)
  double dt = 0.0;
  SymView sigma{};            ///< Cauchy stress, in/out
  double* eps_p = nullptr;    ///< effective plastic strain, in/out
  double* history = nullptr;  ///< the law's history, history.size() per point, point-major
  const double* temperature = nullptr;  ///< per point, at t_{n+1} (needs_temperature only)
};

/// Whether a law reads the points' temperatures (its optional needs_temperature).
template <class Law>
constexpr bool law_needs_temperature() {
  if constexpr (requires { Law::needs_temperature; })
    return Law::needs_temperature;
  else
    return false;
}

/// Whether a shell law reads the in-plane spin relative to the frame (its optional needs_spin).
template <class Law>
constexpr bool law_needs_spin() {
  if constexpr (requires { Law::needs_spin; })
    return Law::needs_spin;
  else
    return false;
}

/// Whether a shell law reads the material's spin and the frame's exact turn (its optional
/// needs_frame_turn).
template <class Law>
constexpr bool law_needs_frame_turn() {
  if constexpr (requires { Law::needs_frame_turn; })
    return Law::needs_frame_turn;
  else
    return false;
}

/// A shell law's material axis a: AOPT 0 along the element's edge from node 1 to node 2, AOPT 2
/// the global vector `a`, AOPT 3 the cross product of the global vector `v` with the shell's
/// normal, all projected on the shell; AOPT 0 and 3 then turned about the normal by `angle`
/// (or by the element card's BETA where that is not zero).
struct MaterialAxes {
  int aopt = 0;
  const double* a = nullptr;  ///< 3 components (AOPT 2)
  const double* v = nullptr;  ///< 3 components (AOPT 3)
  double angle = 0.0;         ///< radians (AOPT 0 and 3)
};

}  // namespace plyform::material
