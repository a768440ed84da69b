#pragma once
// The deck's tables (*DEFINE_TABLE) as runtime tables of curves.

#include <unordered_map>

#include "plyform/core/curve_table.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

/// Each table by its id, with its effective values and the effective points of its curves
/// (validated decks: every value has its curve).
[[nodiscard]] std::unordered_map<int, core::CurveTable> build_tables(const model::ModelDesc& deck);

}  // namespace plyform::setup
