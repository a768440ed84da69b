// *SET_NODE_LIST(_TITLE), *SET_PART_LIST(_TITLE) and *SET_SEGMENT(_TITLE).
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

constexpr FieldSpec segment_node(std::string_view name, bool required) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = required ? 1 : 0,
                   .unit = "-",
                   .description = required ? "node id" : "node id (blank, 0 or N3: a triangle)",
                   .required = required};
}
constexpr FieldSpec segment_attribute(std::string_view name) {
  return FieldSpec{.name = name, .type = FieldType::kReal, .description = "attribute; ignored"};
}
constexpr std::array kSegmentFields{
    segment_node("N1", true),  segment_node("N2", true), segment_node("N3", true),
    segment_node("N4", false), segment_attribute("A1"),  segment_attribute("A2"),
    segment_attribute("A3"),   segment_attribute("A4"),
};
constexpr std::array kSegmentCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Segment cards",
             .fields = kSegmentFields,
             .presence = "one segment per card, until the next keyword"},
};

/// The title card of _TITLE and card 1 (SID DA1..DA4 SOLVER; MECH only) of every set.
model::SetListDesc read_set_header(KeywordInput& in, std::span<const CardSpec> cards) {
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
  return set;
}

model::SetListDesc read_set(KeywordInput& in, std::span<const CardSpec> cards) {
  model::SetListDesc set = read_set_header(in, cards);
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

void read_set_segment(KeywordInput& in) {
  const model::SetListDesc header = read_set_header(in, kSegmentCards);
  model::SetSegmentDesc set;
  set.id = header.id;
  set.title = header.title;
  set.where = header.where;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues v = in.read(kSegmentCards[2], *line);
    const int n3 = v.integer("N3");
    const int n4 = v.integer("N4");
    set.segments.push_back({v.integer("N1"), v.integer("N2"), n3, n4 == 0 ? n3 : n4});
    set.segments_where.push_back(in.where(line->line));
  }
  in.model().segment_sets.push_back(std::move(set));
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

KeywordSpec set_node_keyword() {
  KeywordSpec spec = set_node_list_keyword();
  spec.name = "SET_NODE";
  spec.summary = "The same keyword as *SET_NODE_LIST (LS-DYNA's short form).";
  return spec;
}

KeywordSpec set_part_keyword() {
  KeywordSpec spec = set_part_list_keyword();
  spec.name = "SET_PART";
  spec.summary = "The same keyword as *SET_PART_LIST (LS-DYNA's short form).";
  return spec;
}

KeywordSpec set_segment_keyword() {
  return {.name = "SET_SEGMENT",
          .options = kNoneOrTitle,
          .handler = read_set_segment,
          .cards = kSegmentCards,
          .summary =
              "A set of segments (quadrilaterals, or triangles with N4 blank, 0 or N3) given by "
              "node ids, for the sides of a contact. The attributes A1..A4 are ignored; the "
              "_GENERATE, _ADD and other forms are not supported."};
}

}  // namespace plyform::keyword
