#include "plyform/material/law_registry.hpp"

#include <string_view>
#include <vector>

namespace plyform::material {

std::optional<core::Material> material_from_deck(const model::ModelDesc& deck, int id,
                                                 const DeckCurve& curve, const DeckTable& table) {
  std::optional<core::Material> found;
  for_each_law([&](auto tag) {
    using Law = typename decltype(tag)::type;
    for (const auto& card : Law::cards(deck)) {
      if (card.id != id)
        continue;
      if constexpr (requires { Law::from_card(card, curve, table); })
        found = core::Material{Law::from_card(card, curve, table)};
      else
        found = core::Material{Law::from_card(card, curve)};
    }
  });
  return found;
}

const LawInfo& law_info(const core::Material& m) {
  return visit_law(
      m, [](auto tag, const auto&) -> const LawInfo& { return decltype(tag)::type::info; });
}

Moduli moduli(const core::Material& m) {
  return visit_law(m, [](auto tag, const auto& p) { return decltype(tag)::type::moduli(p); });
}

double density(const core::Material& m) {
  return std::visit([](const auto& p) { return p.density; }, m);
}

double bulk_modulus(const core::Material& m) {
  return moduli(m).bulk;
}

double shear_modulus(const core::Material& m) {
  return moduli(m).shear;
}

bool law_for_solids(const core::Material& m) {
  return visit_law(m, [](auto tag, const auto&) { return decltype(tag)::type::for_solids; });
}

bool law_for_shells(const core::Material& m) {
  return visit_law(m, [](auto tag, const auto&) { return decltype(tag)::type::for_shells; });
}

bool law_reads_temperature(const core::Material& m) {
  return visit_law(m, [](auto tag, const auto&) {
    return law_needs_temperature<typename decltype(tag)::type>();
  });
}

std::size_t history_per_point(const core::Material& m) {
  return visit_law(m, [](auto tag, const auto&) { return decltype(tag)::type::history.size(); });
}

std::string law_keywords(bool solids) {
  std::vector<std::string_view> names;
  for_each_law([&](auto tag) {
    using Law = typename decltype(tag)::type;
    if (solids ? Law::for_solids : Law::for_shells)
      names.push_back(Law::info.keyword);
  });
  names.push_back("*MAT_RIGID");  // a rigid part takes either element
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ");
    out += names[i];
  }
  return out;
}

}  // namespace plyform::material
