#include "plyform/keyword/read_deck.hpp"

#include "keywords/database_histories.hpp"
#include "keywords/set_list.hpp"
#include "reader_session.hpp"

namespace plyform::keyword {
namespace {

/// What needs the whole deck once every file is read.
ReadResult finish(ReaderSession& session) {
  ReadResult result = session.take_result();
  expand_generated_sets(result.model, result.errors);
  warn_unpaired_element_histories(result.model, result.warnings);
  return result;
}

}  // namespace

ReadResult read_deck(const std::filesystem::path& deck) {
  ReaderSession session(deck.parent_path());
  session.read_file(deck, deck.string(), {});
  return finish(session);
}

ReadResult read_deck_text(std::string_view text, std::string_view file_name) {
  const std::filesystem::path path(file_name);
  ReaderSession session(path.parent_path());
  session.read_text(text, std::string(file_name), path.parent_path(), canonical_or_normal(path));
  return finish(session);
}

}  // namespace plyform::keyword
