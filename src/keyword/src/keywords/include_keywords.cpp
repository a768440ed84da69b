// *INCLUDE and *INCLUDE_PATH(_RELATIVE): reading other files.
#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "../keyword_input.hpp"
#include "../keyword_registry.hpp"
#include "../reader_session.hpp"
#include "../text_utils.hpp"

namespace plyform::keyword {
namespace {
namespace fs = std::filesystem;

constexpr std::array<std::string_view, 1> kIncludeOptions{""};
constexpr std::array<std::string_view, 2> kIncludePathOptions{"", "RELATIVE"};

constexpr std::array kFileFields{
    FieldSpec{.name = "FILENAME",
              .type = FieldType::kText,
              .width = 80,
              .description = "file to read here; relative names resolve against the folder of "
                             "the including file, then the *INCLUDE_PATH folders. A line ending "
                             "in ' +' continues on the next line. Backslashes are read as '/'",
              .rest_of_line = true},
};
constexpr std::array kIncludeCards{
    CardSpec{.title = "File cards",
             .fields = kFileFields,
             .presence = "one per file, until the next keyword"},
};

constexpr std::array kFolderFields{
    FieldSpec{.name = "PATH",
              .type = FieldType::kText,
              .width = 80,
              .description = "folder searched for included files; relative to the main deck's "
                             "folder, or with _RELATIVE to the folder of this file",
              .rest_of_line = true},
};
constexpr std::array kIncludePathCards{
    CardSpec{.title = "Folder cards",
             .fields = kFolderFields,
             .presence = "one per folder, until the next keyword"},
};

/// The lines of a card list joined where a line ends with " +"; each with its first line.
template <typename Consume>
void for_each_joined_name(KeywordInput& in, const CardSpec& card, Consume consume) {
  std::string name;
  int first_line = 0;
  while (const auto line = in.next_nonblank_line()) {
    std::string part = in.read(card, *line).text(card.fields[0].name);
    if (first_line == 0) {
      first_line = line->line;
    }
    const bool continued =
        part.size() >= 2 && part.back() == '+' && is_blank_char(part[part.size() - 2]);
    if (continued) {
      part = std::string(trim(std::string_view(part).substr(0, part.size() - 1)));
      name += part;
      continue;
    }
    name += part;
    consume(name, first_line);
    name.clear();
    first_line = 0;
  }
  if (!name.empty()) {
    consume(name, first_line);
  }
}

void read_include(KeywordInput& in) {
  int files = 0;
  for_each_joined_name(in, kIncludeCards[0], [&](const std::string& written, int line) {
    ++files;
    std::string name = written;
    std::replace(name.begin(), name.end(), '\\', '/');
    ReaderSession& session = in.session();
    const std::optional<fs::path> found = session.resolve_include(name, in.folder());
    if (!found) {
      std::string looked;
      for (const fs::path& folder : session.include_folders(in.folder())) {
        looked +=
            (looked.empty() ? "" : ", ") + (folder.empty() ? std::string(".") : folder.string());
      }
      in.report(line, "FILENAME",
                fs::path(name).is_absolute()
                    ? fmt::format("include file '{}' not found", written)
                    : fmt::format("include file '{}' not found (looked in: {})", written, looked));
      return;
    }
    session.read_file(*found, found->string(), in.where(line));
  });
  if (files == 0) {
    in.fail(in.keyword().line, "FILENAME", "no file name given");
  }
}

void read_include_path(KeywordInput& in) {
  const bool relative = in.option() == "RELATIVE";
  int folders = 0;
  for_each_joined_name(in, kIncludePathCards[0], [&](std::string name, int /*line*/) {
    ++folders;
    std::replace(name.begin(), name.end(), '\\', '/');
    const fs::path folder(name);
    const fs::path base = relative ? in.folder() : in.session().main_folder();
    in.session().add_include_path(folder.is_absolute() ? folder
                                                       : (base / folder).lexically_normal());
  });
  if (folders == 0) {
    in.fail(in.keyword().line, "PATH", "no folder given");
  }
}

}  // namespace

KeywordSpec include_keyword() {
  return {.name = "INCLUDE",
          .options = kIncludeOptions,
          .handler = read_include,
          .cards = kIncludeCards,
          .summary =
              "Reads other files at this place, in order. A file that cannot be found is "
              "an error on its file card; an include cycle is an error. *PARAMETER "
              "values defined before the *INCLUDE are seen in the included files."};
}

KeywordSpec include_path_keyword() {
  return {.name = "INCLUDE_PATH",
          .options = kIncludePathOptions,
          .handler = read_include_path,
          .cards = kIncludePathCards,
          .summary =
              "Adds folders where *INCLUDE looks for relative file names, after the "
              "folder of the including file."};
}

}  // namespace plyform::keyword
