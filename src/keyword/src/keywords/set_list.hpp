#pragma once
// What the set keywords need once the whole deck is read.

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::keyword {

/// Turns the ranges of every _GENERATE node and part set into the ids of the nodes and parts
/// the deck defines in them (they may come after the set, or from an include); a set whose
/// ranges hold none is an error.
void expand_generated_sets(model::ModelDesc& model, std::vector<Diagnostic>& errors);

}  // namespace plyform::keyword
