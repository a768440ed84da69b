#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "deck_blocks.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/keyword/parameter_table.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {

/// The path made absolute and normal where possible (to compare files in the include chain).
std::filesystem::path canonical_or_normal(const std::filesystem::path& path);

/// The state of reading one deck: the model being filled, the parameters, the include search
/// paths and the chain of files being read (for cycle detection). One per read_deck call.
class ReaderSession {
 public:
  explicit ReaderSession(std::filesystem::path main_folder);

  /// Reads a file. included_from is the *INCLUDE card line (line 0 for the main deck).
  void read_file(const std::filesystem::path& path, const std::string& display_name,
                 const model::SourceLocation& included_from);
  /// Reads text already in memory as the file display_name in folder; canonical identifies
  /// the file in the include chain.
  void read_text(std::string_view text, const std::string& display_name,
                 const std::filesystem::path& folder, const std::filesystem::path& canonical);

  /// The file an *INCLUDE name refers to: absolute as is; relative against the including
  /// file's folder, then each include path in order. nullopt when none exists.
  std::optional<std::filesystem::path> resolve_include(
      std::string_view name, const std::filesystem::path& including_folder) const;
  /// Where resolve_include looks for a relative name, for messages.
  std::vector<std::filesystem::path> include_folders(
      const std::filesystem::path& including_folder) const;
  void add_include_path(std::filesystem::path folder);
  const std::filesystem::path& main_folder() const { return main_folder_; }

  model::ModelDesc& model() { return result_.model; }
  ParameterTable& parameters() { return parameters_; }
  void report_error(Diagnostic diagnostic) { result_.errors.push_back(std::move(diagnostic)); }
  void report_warning(Diagnostic diagnostic) { result_.warnings.push_back(std::move(diagnostic)); }

  ReadResult take_result() { return std::move(result_); }

 private:
  static constexpr std::size_t kMaxIncludeDepth = 64;

  /// Returns true when the file must stop (*END).
  bool read_block(const Block& block, const std::string& file, const std::filesystem::path& folder);

  struct OpenFile {
    std::filesystem::path canonical;
    std::string display_name;
  };

  std::filesystem::path main_folder_;
  ReadResult result_;
  ParameterTable parameters_;
  std::vector<std::filesystem::path> include_paths_;
  std::vector<OpenFile> open_files_;  ///< the include chain, main deck first
};

}  // namespace plyform::keyword
