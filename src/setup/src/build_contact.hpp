#pragma once
// The build step of the contact interfaces and of the nodal temperatures: deck sides (parts,
// part sets, node sets, segment sets) -> slave nodes and master segments with their offsets,
// areas and penalty stiffnesses (docs/contact.md gives the formulas).

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

/// Fills model.contacts. The model's nodes, parts, materials and element blocks must be built.
void build_contacts(const model::ModelDesc& desc, core::Model& model,
                    std::vector<keyword::Diagnostic>& errors,
                    std::vector<keyword::Diagnostic>& warnings);

/// Fills model.temperature0 and model.temperature_histories.
void build_temperatures(const model::ModelDesc& desc, core::Model& model,
                        std::vector<keyword::Diagnostic>& errors);

}  // namespace plyform::setup
