#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "deck_blocks.hpp"
#include "plyform/keyword/card_reader.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::keyword {

class ReaderSession;

/// Thrown by a handler (through KeywordInput::fail) to abandon its block.
struct KeywordError {
  Diagnostic diagnostic;
};

/// What a keyword handler sees: its block's data lines, one card at a time, and the session
/// (model, parameters, includes). Errors carry the file, line, keyword and field.
class KeywordInput {
 public:
  KeywordInput(ReaderSession& session, const Block& block, std::string_view option,
               const std::string& file, const std::filesystem::path& folder);

  const KeywordLine& keyword() const { return block_.keyword; }
  std::string_view option() const { return option_; }
  const std::string& file() const { return file_; }
  /// Folder of the file being read (relative includes resolve against it).
  const std::filesystem::path& folder() const { return folder_; }
  model::SourceLocation where(int line) const { return {file_, line}; }
  model::SourceLocation keyword_where() const { return where(block_.keyword.line); }

  /// The next data line; a blank line is a card whose fields are all blank.
  std::optional<DataLine> next_line();
  /// The next data line that is not blank (for cards repeated until the next keyword).
  std::optional<DataLine> next_nonblank_line();
  /// Reads a line as the given card; a bad field abandons the block.
  CardValues read(const CardSpec& card, const DataLine& line, int repeat = 0);
  /// Reads the next line as the given card; if there is none, abandons the block with
  /// "missing <what>".
  CardValues next_card(const CardSpec& card, std::string_view what);
  /// Consumes the rest of the block unread (*COMMENT, *END).
  void skip_rest() { next_ = block_.data.size(); }
  std::span<const DataLine> remaining() const;

  /// Abandons the block with a located error.
  [[noreturn]] void fail(int line, std::string field, std::string message) const;
  /// Records a located error and goes on with the block.
  void report(int line, std::string field, std::string message);
  void warn(int line, std::string field, std::string message);

  ReaderSession& session() { return session_; }
  model::ModelDesc& model();
  ParameterTable& parameters();

  /// Stops reading the current file after this block (*END).
  void stop_file() { stop_file_ = true; }
  bool file_stopped() const { return stop_file_; }

 private:
  Diagnostic diagnostic(int line, std::string field, std::string message) const;

  ReaderSession& session_;
  const Block& block_;
  std::string_view option_;
  const std::string& file_;
  const std::filesystem::path& folder_;
  std::size_t next_ = 0;
  bool stop_file_ = false;
};

}  // namespace plyform::keyword
