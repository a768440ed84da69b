#pragma once

#include <string>

namespace plyform::keyword {

/// The keyword reference (docs/keywords.md), generated from the card tables of the registry.
std::string keyword_reference_markdown();

}  // namespace plyform::keyword
