#pragma once
// The material laws plyform knows: one line each in `Laws`. Everything that depends on the law
// of a block (its kernel, its moduli, its name in `plyform check`, its history layout) comes
// from here, chosen once per block, never per point. Adding a law: docs/materials.md, "Adding a
// law".

#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "plyform/core/material.hpp"
#include "plyform/material/laws/barlat89_plastic.hpp"
#include "plyform/material/laws/elastic.hpp"
#include "plyform/material/laws/elastic_plastic_thermal.hpp"
#include "plyform/material/laws/hill_3r_plastic.hpp"
#include "plyform/material/laws/mooney_rivlin.hpp"
#include "plyform/material/laws/orthotropic_elastic.hpp"
#include "plyform/material/laws/piecewise_linear_plasticity.hpp"
#include "plyform/material/laws/plastic_kinematic.hpp"
#include "plyform/material/laws/power_law_plasticity.hpp"
#include "plyform/material/laws/reinforced_thermoplastic.hpp"
#include "plyform/material/laws/rigid.hpp"
#include "plyform/material/laws/transversely_anisotropic_plastic.hpp"

namespace plyform::material {

template <class... L>
struct LawList {};

/// The registry.
using Laws = LawList<ElasticLaw, OrthotropicElasticLaw, PowerLawPlasticityLaw, RigidLaw,
                     PiecewiseLinearPlasticityLaw, MooneyRivlinLaw, ElasticPlasticThermalLaw,
                     ReinforcedThermoplasticLaw, PlasticKinematicLaw,
                     TransverselyAnisotropicPlasticLaw, Barlat89PlasticLaw, Hill3RPlasticLaw>;

namespace detail {
template <class P, class List>
struct LawOf {
  using type = void;
};
template <class P, class First, class... Rest>
struct LawOf<P, LawList<First, Rest...>> {
  using type = std::conditional_t<std::is_same_v<P, typename First::Parameters>, First,
                                  typename LawOf<P, LawList<Rest...>>::type>;
};
template <class V>
struct EveryAlternativeHasALaw;
template <class... P>
struct EveryAlternativeHasALaw<std::variant<P...>> {
  static constexpr bool value = (!std::is_void_v<typename LawOf<P, Laws>::type> && ...);
};
}  // namespace detail

/// The law whose parameters are P.
template <class P>
using LawOf = typename detail::LawOf<P, Laws>::type;

static_assert(detail::EveryAlternativeHasALaw<core::Material>::value,
              "every member of core::Material needs its law in material::Laws");

template <class Law>
struct LawTag {
  using type = Law;
};

/// f(LawTag<Law>{}, parameters) for the law of `m` (the same return type for every law).
template <class F>
decltype(auto) visit_law(const core::Material& m, F&& f) {
  return std::visit(
      [&](const auto& p) -> decltype(auto) {
        using Law = LawOf<std::decay_t<decltype(p)>>;
        return f(LawTag<Law>{}, p);
      },
      m);
}

/// f(LawTag<Law>{}) for every law of the registry, in its order.
template <class F>
void for_each_law(F&& f) {
  [&]<class... L>(LawList<L...>) { (f(LawTag<L>{}), ...); }(Laws{});
}

/// The runtime parameters of deck material `id` (any *MAT_ keyword of the registry), through the
/// laws' from_card (curves by id, tables by id for the laws that read them); none when no law's
/// cards have that id.
[[nodiscard]] std::optional<core::Material> material_from_deck(const model::ModelDesc& deck, int id,
                                                               const DeckCurve& curve,
                                                               const DeckTable& table);

[[nodiscard]] const LawInfo& law_info(const core::Material& m);
[[nodiscard]] Moduli moduli(const core::Material& m);
[[nodiscard]] double density(const core::Material& m);
[[nodiscard]] double bulk_modulus(const core::Material& m);
[[nodiscard]] double shear_modulus(const core::Material& m);
[[nodiscard]] bool law_for_solids(const core::Material& m);
[[nodiscard]] bool law_for_shells(const core::Material& m);
/// Whether the law reads the points' temperatures (law_needs_temperature).
[[nodiscard]] bool law_reads_temperature(const core::Material& m);
/// Values of the law's own history per integration point (law::history.size()).
[[nodiscard]] std::size_t history_per_point(const core::Material& m);
/// The keywords of the laws for solids (or for shells), "*MAT_ELASTIC, ... or *MAT_RIGID", in
/// the registry's order: for the messages that name what a part may use.
[[nodiscard]] std::string law_keywords(bool solids);

}  // namespace plyform::material
