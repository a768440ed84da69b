#include "plyform/keyword/read_deck.hpp"

#include "reader_session.hpp"

namespace plyform::keyword {

ReadResult read_deck(const std::filesystem::path& deck) {
  ReaderSession session(deck.parent_path());
  session.read_file(deck, deck.string(), {});
  return session.take_result();
}

ReadResult read_deck_text(std::string_view text, std::string_view file_name) {
  const std::filesystem::path path(file_name);
  ReaderSession session(path.parent_path());
  session.read_text(text, std::string(file_name), path.parent_path(), canonical_or_normal(path));
  return session.take_result();
}

}  // namespace plyform::keyword
