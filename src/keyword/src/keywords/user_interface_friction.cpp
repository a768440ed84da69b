// *USER_INTERFACE_FRICTION: the constants of a user contact law for one contact.
#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "../keyword_input.hpp"
#include "../keyword_registry.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<std::string_view, 1> kOptions{""};
constexpr int kConstantsPerCard = 8;

constexpr std::array kCard1Fields{
    FieldSpec{.name = "NOSID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "id of the contact interface the law applies to",
              .required = true},
    FieldSpec{.name = "NOC",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "number of constants UC1..UCnoc that follow"},
    FieldSpec{.name = "NOCI",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "number of constants to initialise; kept as written"},
};
constexpr std::string_view kConstantDescription =
    "constant of the law; blank: unset (the law's default applies)";
constexpr std::array kConstantFields{
    FieldSpec{.name = "UC", .type = FieldType::kReal, .description = kConstantDescription},
    FieldSpec{.name = "UC", .type = FieldType::kReal, .description = kConstantDescription},
    FieldSpec{.name = "UC", .type = FieldType::kReal, .description = kConstantDescription},
    FieldSpec{.name = "UC", .type = FieldType::kReal, .description = kConstantDescription},
    FieldSpec{.name = "UC", .type = FieldType::kReal, .description = kConstantDescription},
    FieldSpec{.name = "UC", .type = FieldType::kReal, .description = kConstantDescription},
    FieldSpec{.name = "UC", .type = FieldType::kReal, .description = kConstantDescription},
    FieldSpec{.name = "UC", .type = FieldType::kReal, .description = kConstantDescription},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Constant cards",
             .fields = kConstantFields,
             .presence = "ceil(NOC/8) cards, eight constants per card; the meaning of each "
                         "constant is the law's (product.md)",
             .numbering = FieldNumbering::kSequential},
};

void read_user_interface_friction(KeywordInput& in) {
  model::UserInterfaceFrictionDesc desc;
  desc.where = in.keyword_where();
  const CardValues card1 = in.next_card(kCards[0], "card 1 (NOSID NOC NOCI)");
  desc.contact_id = card1.integer("NOSID");
  desc.noc = card1.integer("NOC");
  desc.noci = card1.integer("NOCI");

  const int cards = (desc.noc + kConstantsPerCard - 1) / kConstantsPerCard;
  for (int card = 0; card < cards; ++card) {
    const int first = card * kConstantsPerCard;
    const int count = std::min(kConstantsPerCard, desc.noc - first);
    const auto line = in.next_line();
    if (!line) {
      in.fail(in.keyword().line, "",
              fmt::format("missing card {} (constants UC{}..UC{}): NOC = {} needs {} card(s) of "
                          "constants after card 1",
                          card + 2, first + 1, first + count, desc.noc, cards));
    }
    const CardValues values = in.read(kCards[1], *line, card);
    for (int i = 0; i < kConstantsPerCard; ++i) {
      const FieldValue& value = values.at(static_cast<std::size_t>(i));
      if (i >= count) {
        if (!value.blank) {
          in.fail(line->line, fmt::format("UC{}", first + i + 1),
                  fmt::format("a constant is given beyond NOC = {}", desc.noc));
        }
        continue;
      }
      desc.constants.push_back(value.blank ? std::nullopt : std::optional(value.real));
      desc.constant_where.push_back(in.where(line->line));
    }
  }
  in.model().user_interface_frictions.push_back(std::move(desc));
}

}  // namespace

KeywordSpec user_interface_friction_keyword() {
  return {.name = "USER_INTERFACE_FRICTION",
          .options = kOptions,
          .handler = read_user_interface_friction,
          .cards = kCards,
          .summary =
              "Constants of a user contact law (plyform's cohesive law) for the contact "
              "NOSID. Values are kept as written, blank ones unset; their meaning and "
              "ranges are checked by the law."};
}

}  // namespace plyform::keyword
