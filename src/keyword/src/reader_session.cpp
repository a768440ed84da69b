#include "reader_session.hpp"

#include <fstream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>

#include "keyword_input.hpp"
#include "keyword_registry.hpp"
#include "text_utils.hpp"

namespace plyform::keyword {
namespace fs = std::filesystem;

namespace {

bool is_existing_file(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

std::string supported_options(const KeywordSpec& spec) {
  std::string list;
  for (std::string_view option : spec.options) {
    if (!option.empty()) {
      list += (list.empty() ? "" : ", ") + fmt::format("_{}", option);
    }
  }
  return list.empty() ? "it takes no option" : "supported: " + list;
}

}  // namespace

fs::path canonical_or_normal(const fs::path& path) {
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(path, error);
  return error ? path.lexically_normal() : canonical;
}

ReaderSession::ReaderSession(fs::path main_folder) : main_folder_(std::move(main_folder)) {}

void ReaderSession::read_file(const fs::path& path, const std::string& display_name,
                              const model::SourceLocation& included_from) {
  const fs::path canonical = canonical_or_normal(path);
  for (std::size_t i = 0; i < open_files_.size(); ++i) {
    if (open_files_[i].canonical == canonical) {
      std::string chain;
      for (std::size_t j = i; j < open_files_.size(); ++j) {
        chain += open_files_[j].display_name + " -> ";
      }
      report_error({included_from, "*INCLUDE", "FILENAME",
                    fmt::format("include cycle: {}{}", chain, display_name)});
      return;
    }
  }
  if (open_files_.size() >= kMaxIncludeDepth) {
    report_error({included_from, "*INCLUDE", "FILENAME",
                  fmt::format("includes nested more than {} deep", kMaxIncludeDepth)});
    return;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  if (in && is_existing_file(path)) {
    contents << in.rdbuf();
  } else {
    if (included_from.line == 0) {
      Diagnostic d;  // built field by field: g++ 12 warns falsely on the aggregate form
      d.where.file = display_name;
      d.message = "cannot open the deck";
      report_error(std::move(d));
    } else {
      report_error({included_from, "*INCLUDE", "FILENAME",
                    fmt::format("cannot open include file '{}'", display_name)});
    }
    return;
  }
  read_text(contents.view(), display_name, path.parent_path(), canonical);
}

void ReaderSession::read_text(std::string_view text, const std::string& display_name,
                              const fs::path& folder, const fs::path& canonical) {
  model().files_read.push_back(display_name);
  for (const char c : text) {
    model().source_fingerprint ^= static_cast<unsigned char>(c);
    model().source_fingerprint *= 1099511628211ull;
  }
  open_files_.push_back({canonical, display_name});
  const DeckBlocks deck = split_into_blocks(text);
  for (const DataLine& line : deck.before_first_keyword) {
    if (!is_blank_line(line.text)) {
      report_error({{display_name, line.line},
                    "",
                    "",
                    "data line before the first keyword (comment lines start with '$')"});
      break;
    }
  }
  parameters_.enter_file();
  for (const Block& block : deck.blocks) {
    if (read_block(block, display_name, folder)) {
      break;
    }
  }
  parameters_.leave_file();
  open_files_.pop_back();
}

bool ReaderSession::read_block(const Block& block, const std::string& file,
                               const fs::path& folder) {
  const KeywordLine& keyword = block.keyword;
  const auto error = [&](std::string message) {
    report_error({{file, keyword.line}, keyword.display(), "", std::move(message)});
  };
  if (keyword.name.empty()) {
    error("a keyword name is missing after '*'");
    return false;
  }
  const KeywordLookup found = find_keyword(keyword.name);
  // An output request plyform does not write changes no result: it is read (its cards are
  // passed over) and named in a warning, never an error, so that a deck written for LS-DYNA
  // runs with the outputs plyform has.
  const bool output_request = keyword.name.starts_with("DATABASE_");
  if (output_request && (found.spec == nullptr || !found.option_supported)) {
    report_warning({{file, keyword.line},
                    keyword.display(),
                    "",
                    "output request not written by plyform (read and passed over; the outputs "
                    "plyform writes are in docs/keywords.md)"});
    return false;
  }
  if (found.spec == nullptr) {
    error("unsupported keyword (not in the keywords plyform reads, docs/keywords.md)");
    return false;
  }
  if (!found.option_supported) {
    error(fmt::format("unsupported option _{} of *{} ({})", found.option, found.spec->name,
                      supported_options(*found.spec)));
    return false;
  }
  if (keyword.format == '+' || keyword.format == '%') {
    error(
        fmt::format("the '{}' format suffix (long or i10 fields) is not supported; write the "
                    "keyword in standard 10-character fields",
                    keyword.format));
    return false;
  }
  if (!keyword.text_after.empty() && !found.spec->takes_line_text) {
    error(fmt::format("unexpected text '{}' after the keyword name", keyword.text_after));
    return false;
  }
  KeywordInput input(*this, block, found.option, file, folder);
  try {
    found.spec->handler(input);
    for (const DataLine& line : input.remaining()) {
      if (!is_blank_line(line.text)) {
        report_error({{file, line.line},
                      keyword.display(),
                      "",
                      "unexpected data line: the keyword has no further cards"});
        break;
      }
    }
  } catch (const KeywordError& failure) {
    report_error(failure.diagnostic);
  }
  return input.file_stopped();
}

std::vector<fs::path> ReaderSession::include_folders(const fs::path& including_folder) const {
  std::vector<fs::path> folders{including_folder};
  folders.insert(folders.end(), include_paths_.begin(), include_paths_.end());
  return folders;
}

std::optional<fs::path> ReaderSession::resolve_include(std::string_view name,
                                                       const fs::path& including_folder) const {
  const fs::path file(name);
  if (file.is_absolute()) {
    return is_existing_file(file) ? std::optional(file) : std::nullopt;
  }
  for (const fs::path& folder : include_folders(including_folder)) {
    fs::path candidate = (folder / file).lexically_normal();
    if (is_existing_file(candidate)) {
      return candidate;
    }
  }
  return std::nullopt;
}

void ReaderSession::add_include_path(fs::path folder) {
  include_paths_.push_back(std::move(folder));
}

}  // namespace plyform::keyword
