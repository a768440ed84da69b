#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::keyword {

/// What reading a deck gives: the model as far as it could be read, and every error found
/// (after an error in a keyword block the reader skips to the next keyword and goes on).
struct ReadResult {
  model::ModelDesc model;
  std::vector<Diagnostic> errors;
  std::vector<Diagnostic> warnings;  ///< e.g. a parameter defined twice
  bool ok() const { return errors.empty(); }
};

/// Reads a keyword deck and the files it includes.
ReadResult read_deck(const std::filesystem::path& deck);

/// Reads deck text held in memory; file_name is used in diagnostics, and relative *INCLUDEs
/// resolve against its folder.
ReadResult read_deck_text(std::string_view text, std::string_view file_name);

}  // namespace plyform::keyword
