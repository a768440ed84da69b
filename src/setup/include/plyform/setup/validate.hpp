#pragma once
// Validation across keywords: ids that must be unique, references that must resolve, and the
// contact-law constants. Reports every error, each with file, line and keyword.

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

[[nodiscard]] std::vector<keyword::Diagnostic> validate(const model::ModelDesc& model);

}  // namespace plyform::setup
