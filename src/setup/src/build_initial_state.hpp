#pragma once
// The build step of the formed part handed on (docs/outputs.md, "dynain"): the shells'
// *INITIAL_STRESS_SHELL resolved to block elements (core::InitialShellStress), the
// *INITIAL_STRAIN_SHELL cards checked, and *INTERFACE_SPRINGBACK_LSDYNA's part set resolved to
// the shell blocks the dynain file holds.

#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

/// Fills model.initial_shell_stresses and model.output.dynain. The blocks must be built and
/// coloured (colouring reorders a block's elements). Errors name the card and field: an element
/// that is not a shell, a shell of a rigid part, an element given twice, in-plane points that
/// disagree on T, a part set that does not exist.
void build_initial_state(const model::ModelDesc& desc, core::Model& model,
                         std::vector<keyword::Diagnostic>& errors,
                         std::vector<keyword::Diagnostic>& warnings);

}  // namespace plyform::setup
