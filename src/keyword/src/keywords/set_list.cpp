// *SET_NODE_LIST(_TITLE) and *SET_PART_LIST(_TITLE).
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr int kIdsPerCard = 8;

constexpr std::array kCard1Fields{
    FieldSpec{.name = "SID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "set id",
              .required = true},
    FieldSpec{.name = "DA1", .type = FieldType::kReal, .description = "attribute; kept"},
    FieldSpec{.name = "DA2", .type = FieldType::kReal, .description = "attribute; kept"},
    FieldSpec{.name = "DA3", .type = FieldType::kReal, .description = "attribute; kept"},
    FieldSpec{.name = "DA4", .type = FieldType::kReal, .description = "attribute; kept"},
    FieldSpec{.name = "SOLVER",
              .type = FieldType::kText,
              .description = "MECH (or blank); other solvers are not supported"},
};

constexpr FieldSpec id_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .unit = "-",
                   .description = description};
}
constexpr std::string_view kNodeIdText = "node id (blank or 0: none)";
constexpr std::string_view kPartIdText = "part id (blank or 0: none)";
constexpr std::array kNodeIdFields{
    id_field("NID", kNodeIdText), id_field("NID", kNodeIdText), id_field("NID", kNodeIdText),
    id_field("NID", kNodeIdText), id_field("NID", kNodeIdText), id_field("NID", kNodeIdText),
    id_field("NID", kNodeIdText), id_field("NID", kNodeIdText),
};
constexpr std::array kPartIdFields{
    id_field("PID", kPartIdText), id_field("PID", kPartIdText), id_field("PID", kPartIdText),
    id_field("PID", kPartIdText), id_field("PID", kPartIdText), id_field("PID", kPartIdText),
    id_field("PID", kPartIdText), id_field("PID", kPartIdText),
};

constexpr std::array kNodeCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Node cards",
             .fields = kNodeIdFields,
             .presence = "eight node ids per card, until the next keyword",
             .numbering = FieldNumbering::kSequential},
};
constexpr std::array kPartCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Part cards",
             .fields = kPartIdFields,
             .presence = "eight part ids per card, until the next keyword",
             .numbering = FieldNumbering::kSequential},
};

model::SetListDesc read_set(KeywordInput& in, std::span<const CardSpec> cards) {
  model::SetListDesc set;
  if (in.option() == "TITLE") {
    set.title = in.next_card(cards[0], "title card").text("TITLE");
  }
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (SID DA1 DA2 DA3 DA4 SOLVER)");
  }
  const CardValues v = in.read(cards[1], *line);
  set.id = v.integer("SID");
  set.da1 = v.real("DA1");
  set.da2 = v.real("DA2");
  set.da3 = v.real("DA3");
  set.da4 = v.real("DA4");
  set.solver = v.blank("SOLVER") ? "MECH" : v.text("SOLVER");
  set.where = in.where(line->line);
  if (set.solver != "MECH" && set.solver != "mech") {
    in.fail(line->line, "SOLVER",
            fmt::format("SOLVER = {} is not supported: plyform has the mechanical solver (MECH) "
                        "only",
                        set.solver));
  }
  int card = 0;
  while (const auto ids = in.next_nonblank_line()) {
    const CardValues values = in.read(cards[2], *ids, card);
    for (int i = 0; i < kIdsPerCard; ++i) {
      const int id = static_cast<int>(values.at(static_cast<std::size_t>(i)).integer);
      if (id != 0) {
        set.ids.push_back(id);
        set.ids_where.push_back(in.where(ids->line));
      }
    }
    ++card;
  }
  return set;
}

void read_set_node_list(KeywordInput& in) {
  in.model().node_sets.push_back(read_set(in, kNodeCards));
}

void read_set_part_list(KeywordInput& in) {
  in.model().part_sets.push_back(read_set(in, kPartCards));
}

}  // namespace

KeywordSpec set_node_list_keyword() {
  return {.name = "SET_NODE_LIST",
          .options = kNoneOrTitle,
          .handler = read_set_node_list,
          .cards = kNodeCards,
          .summary =
              "A set of nodes listed by id (zeros and blanks are skipped). The _GENERATE "
              "and _ADD forms are not supported."};
}

KeywordSpec set_part_list_keyword() {
  return {.name = "SET_PART_LIST",
          .options = kNoneOrTitle,
          .handler = read_set_part_list,
          .cards = kPartCards,
          .summary = "A set of parts listed by id (zeros and blanks are skipped)."};
}

}  // namespace plyform::keyword
