#pragma once

#include <span>
#include <string>
#include <string_view>

#include "plyform/keyword/card_spec.hpp"

namespace plyform::keyword {

class KeywordInput;

/// Turns one keyword block into ModelDesc entries; reports problems by throwing KeywordError
/// (through KeywordInput), which abandons the block.
using KeywordHandler = void (*)(KeywordInput&);

/// One supported keyword: its name, options, handler and card tables.
struct KeywordSpec {
  std::string_view name;                      ///< without '*': "DEFINE_CURVE"
  std::span<const std::string_view> options;  ///< supported option suffixes; "" = none
  KeywordHandler handler = nullptr;
  std::span<const CardSpec> cards;  ///< the cards in deck order (reading and the reference)
  std::string_view summary;         ///< one paragraph for the reference
  bool takes_line_text = false;     ///< text may follow the name on the keyword line
};

/// All supported keywords, in the order of the reference.
std::span<const KeywordSpec> keyword_registry();

struct KeywordLookup {
  const KeywordSpec* spec = nullptr;  ///< null: no supported keyword has this name
  std::string option;                 ///< the option suffix found ("" for none)
  bool option_supported = false;
};

/// Finds a keyword by its upper-case name with options ("DEFINE_CURVE_TITLE"): the longest
/// registered name that the name starts with, followed by '_' and an option suffix.
KeywordLookup find_keyword(std::string_view name);

}  // namespace plyform::keyword
