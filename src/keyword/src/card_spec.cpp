#include "plyform/keyword/card_spec.hpp"

namespace plyform::keyword {

std::string field_display_name(const CardSpec& card, std::size_t index, int repeat) {
  std::string name(card.fields[index].name);
  switch (card.numbering) {
    case FieldNumbering::kPlain:
      break;
    case FieldNumbering::kPerCard:
      name += std::to_string(repeat + 1);
      break;
    case FieldNumbering::kSequential:
      name += std::to_string(static_cast<std::size_t>(repeat) * card.fields.size() + index + 1);
      break;
  }
  return name;
}

}  // namespace plyform::keyword
