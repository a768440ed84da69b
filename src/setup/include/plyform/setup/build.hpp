#pragma once
// The build step of the starter: a validated ModelDesc -> the runtime model of flat arrays.
// Deck ids are turned into local indices here, and only here.

#include <optional>
#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

struct BuildResult {
  std::optional<core::Model> model;         ///< set when there is no error
  std::vector<keyword::Diagnostic> errors;  ///< what validation could not know (located)
  std::vector<keyword::Diagnostic> warnings;
};

/// Builds the runtime model. Call after validate() reported no error.
[[nodiscard]] BuildResult build(const model::ModelDesc& desc);

}  // namespace plyform::setup
