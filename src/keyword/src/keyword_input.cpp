#include "keyword_input.hpp"

#include <utility>

#include "reader_session.hpp"
#include "text_utils.hpp"

namespace plyform::keyword {

KeywordInput::KeywordInput(ReaderSession& session, const Block& block, std::string_view option,
                           const std::string& file, const std::filesystem::path& folder)
    : session_(session), block_(block), option_(option), file_(file), folder_(folder) {}

std::optional<DataLine> KeywordInput::next_line() {
  if (next_ >= block_.data.size()) {
    return std::nullopt;
  }
  return block_.data[next_++];
}

std::optional<DataLine> KeywordInput::next_nonblank_line() {
  while (next_ < block_.data.size() && is_blank_line(block_.data[next_].text)) {
    ++next_;
  }
  return next_line();
}

CardValues KeywordInput::read(const CardSpec& card, const DataLine& line, int repeat) {
  auto result = read_card(card, line.text, session_.parameters(), repeat);
  if (auto* error = std::get_if<FieldError>(&result)) {
    fail(line.line, std::move(error->field), std::move(error->message));
  }
  return std::move(std::get<CardValues>(result));
}

CardValues KeywordInput::next_card(const CardSpec& card, std::string_view what) {
  const std::optional<DataLine> line = next_line();
  if (!line) {
    fail(block_.keyword.line, "", "missing " + std::string(what));
  }
  return read(card, *line);
}

std::span<const DataLine> KeywordInput::remaining() const {
  return std::span<const DataLine>(block_.data).subspan(next_);
}

Diagnostic KeywordInput::diagnostic(int line, std::string field, std::string message) const {
  return Diagnostic{where(line), block_.keyword.display(), std::move(field), std::move(message)};
}

void KeywordInput::fail(int line, std::string field, std::string message) const {
  throw KeywordError{diagnostic(line, std::move(field), std::move(message))};
}

void KeywordInput::report(int line, std::string field, std::string message) {
  session_.report_error(diagnostic(line, std::move(field), std::move(message)));
}

void KeywordInput::warn(int line, std::string field, std::string message) {
  session_.report_warning(diagnostic(line, std::move(field), std::move(message)));
}

model::ModelDesc& KeywordInput::model() {
  return session_.model();
}

ParameterTable& KeywordInput::parameters() {
  return session_.parameters();
}

}  // namespace plyform::keyword
