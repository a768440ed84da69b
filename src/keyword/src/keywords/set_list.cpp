// *SET_NODE_LIST(_TITLE), *SET_PART_LIST(_TITLE), *SET_SHELL_LIST(_TITLE), their _GENERATE
// forms and *SET_SEGMENT(_TITLE).
#include "set_list.hpp"

#include <algorithm>
#include <array>
#include <unordered_set>

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
constexpr std::string_view kShellIdText = "shell element id (blank or 0: none)";
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

constexpr std::array kShellIdFields{
    id_field("EID", kShellIdText), id_field("EID", kShellIdText), id_field("EID", kShellIdText),
    id_field("EID", kShellIdText), id_field("EID", kShellIdText), id_field("EID", kShellIdText),
    id_field("EID", kShellIdText), id_field("EID", kShellIdText),
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

constexpr std::array kShellCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Element cards",
             .fields = kShellIdFields,
             .presence = "eight shell element ids per card, until the next keyword",
             .numbering = FieldNumbering::kSequential},
};

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

constexpr FieldSpec range_end(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .unit = "-",
                   .description = description};
}
constexpr std::string_view kBeginText = "first id of a range (blank or 0 with its end: none)";
constexpr std::string_view kEndText = "last id of the range (>= its first)";
constexpr std::array kRangeFields{
    range_end("B1BEG", kBeginText), range_end("B1END", kEndText),   range_end("B2BEG", kBeginText),
    range_end("B2END", kEndText),   range_end("B3BEG", kBeginText), range_end("B3END", kEndText),
    range_end("B4BEG", kBeginText), range_end("B4END", kEndText),
};
constexpr std::string_view kRangePresence =
    "four ranges per card, until the next keyword (on later cards the ranges are numbered on: "
    "B5BEG ...)";
constexpr std::array kNodeGenerateCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Range cards", .fields = kRangeFields, .presence = kRangePresence},
};
constexpr std::array kPartGenerateCards = kNodeGenerateCards;
constexpr std::array kShellGenerateCards = kNodeGenerateCards;

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
  set.keyword = in.keyword().display();
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

/// The ranges of a _GENERATE set, checked one by one; the reader turns them into ids once the
/// whole deck is read (expand_generated_sets), since the nodes and parts may come later.
model::SetListDesc read_generated_set(KeywordInput& in, std::span<const CardSpec> cards) {
  model::SetListDesc set = read_set_header(in, cards);
  int card = 0;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues values = in.read(cards[2], *line, card);
    for (int k = 0; k < 4; ++k) {
      const int first = static_cast<int>(values.at(static_cast<std::size_t>(2 * k)).integer);
      const int last = static_cast<int>(values.at(static_cast<std::size_t>(2 * k + 1)).integer);
      const int number = 4 * card + k + 1;  // B<number>BEG on the card's k-th pair
      if (first == 0 && last == 0)
        continue;
      if (first == 0 || last == 0) {
        in.fail(line->line, fmt::format("B{}{}", number, first == 0 ? "BEG" : "END"),
                fmt::format("range {} has only one end ({} to {}): give both its first and last "
                            "id, or neither",
                            number, first, last));
      }
      if (first > last) {
        in.fail(line->line, fmt::format("B{}END", number),
                fmt::format("range {} is reversed: B{}END = {} is below B{}BEG = {}", number,
                            number, last, number, first));
      }
      set.ranges.push_back({first, last, in.where(line->line)});
    }
    ++card;
  }
  if (set.ranges.empty()) {
    in.fail(set.where.line, "B1BEG", "no range given: a generated set needs at least one");
  }
  return set;
}

void read_set_node_list(KeywordInput& in) {
  in.model().node_sets.push_back(read_set(in, kNodeCards));
}

void read_set_part_list(KeywordInput& in) {
  in.model().part_sets.push_back(read_set(in, kPartCards));
}

void read_set_shell_list(KeywordInput& in) {
  in.model().shell_sets.push_back(read_set(in, kShellCards));
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

void read_set_node_generate(KeywordInput& in) {
  in.model().node_sets.push_back(read_generated_set(in, kNodeGenerateCards));
}

void read_set_part_generate(KeywordInput& in) {
  in.model().part_sets.push_back(read_generated_set(in, kPartGenerateCards));
}

void read_set_shell_generate(KeywordInput& in) {
  in.model().shell_sets.push_back(read_generated_set(in, kShellGenerateCards));
}

/// The ids of `sets`' ranges that `defined` (sorted) holds, in range order, each once; a set
/// whose ranges hold none is an error on its card 1.
void expand(std::vector<model::SetListDesc>& sets, const std::vector<int>& defined,
            std::string_view what, std::vector<Diagnostic>& errors) {
  for (model::SetListDesc& set : sets) {
    if (set.ranges.empty())
      continue;
    std::unordered_set<int> seen;
    for (const model::IdRange& r : set.ranges) {
      const auto begin = std::lower_bound(defined.begin(), defined.end(), r.first);
      const auto end = std::upper_bound(begin, defined.end(), r.last);
      for (auto it = begin; it != end; ++it) {
        if (seen.insert(*it).second) {
          set.ids.push_back(*it);
          set.ids_where.push_back(r.where);
        }
      }
    }
    // A single range may hold nothing (LS-PrePost writes "every part but one" as ranges up to
    // 99999999); a whole set that names nothing is a mistake.
    if (set.ids.empty()) {
      errors.push_back(
          {set.where, set.keyword, "B1BEG",
           fmt::format("set {}: its ranges hold no {} defined in the deck", set.id, what)});
    }
  }
}

}  // namespace

void expand_generated_sets(model::ModelDesc& model, std::vector<Diagnostic>& errors) {
  const auto sorted_ids = [](const auto& items) {
    std::vector<int> ids;
    ids.reserve(items.size());
    for (const auto& item : items)
      ids.push_back(item.id);
    std::sort(ids.begin(), ids.end());
    return ids;
  };
  const auto needs = [](const std::vector<model::SetListDesc>& sets) {
    return std::any_of(sets.begin(), sets.end(), [](const auto& s) { return !s.ranges.empty(); });
  };
  if (needs(model.node_sets))
    expand(model.node_sets, sorted_ids(model.nodes), "node", errors);
  if (needs(model.part_sets))
    expand(model.part_sets, sorted_ids(model.parts), "part", errors);
  if (needs(model.shell_sets))
    expand(model.shell_sets, sorted_ids(model.shells), "shell element", errors);
}

KeywordSpec set_node_list_keyword() {
  return {.name = "SET_NODE_LIST",
          .options = kNoneOrTitle,
          .handler = read_set_node_list,
          .cards = kNodeCards,
          .summary =
              "A set of nodes listed by id (zeros and blanks are skipped). The _ADD form is "
              "not supported."};
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

KeywordSpec set_shell_list_keyword() {
  return {.name = "SET_SHELL_LIST",
          .options = kNoneOrTitle,
          .handler = read_set_shell_list,
          .cards = kShellCards,
          .summary =
              "A set of shell elements listed by id (zeros and blanks are skipped), for "
              "*LOAD_SHELL_SET."};
}

KeywordSpec set_shell_keyword() {
  KeywordSpec spec = set_shell_list_keyword();
  spec.name = "SET_SHELL";
  spec.summary = "The same keyword as *SET_SHELL_LIST (LS-DYNA's short form).";
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

namespace plyform::keyword {

KeywordSpec set_node_generate_keyword() {
  return {.name = "SET_NODE_GENERATE",
          .options = kNoneOrTitle,
          .handler = read_set_node_generate,
          .cards = kNodeGenerateCards,
          .summary =
              "A set of the nodes whose ids lie in ranges B1BEG-B1END, ...: every node the deck "
              "defines in a range (ids missing from the mesh are skipped), in range order, "
              "each once. A range with one end only or reversed is an error, and so is a set "
              "whose ranges hold no node."};
}

KeywordSpec set_node_list_generate_keyword() {
  KeywordSpec spec = set_node_generate_keyword();
  spec.name = "SET_NODE_LIST_GENERATE";
  spec.summary = "The same keyword as *SET_NODE_GENERATE (the spelling LS-PrePost writes).";
  return spec;
}

KeywordSpec set_part_generate_keyword() {
  return {.name = "SET_PART_GENERATE",
          .options = kNoneOrTitle,
          .handler = read_set_part_generate,
          .cards = kPartGenerateCards,
          .summary = "A set of the parts whose ids lie in ranges, as *SET_NODE_GENERATE."};
}

KeywordSpec set_part_list_generate_keyword() {
  KeywordSpec spec = set_part_generate_keyword();
  spec.name = "SET_PART_LIST_GENERATE";
  spec.summary = "The same keyword as *SET_PART_GENERATE (the spelling LS-PrePost writes).";
  return spec;
}

}  // namespace plyform::keyword

namespace plyform::keyword {

KeywordSpec set_shell_generate_keyword() {
  return {.name = "SET_SHELL_GENERATE",
          .options = kNoneOrTitle,
          .handler = read_set_shell_generate,
          .cards = kShellGenerateCards,
          .summary = "A set of the shell elements whose ids lie in ranges, as *SET_NODE_GENERATE."};
}

KeywordSpec set_shell_list_generate_keyword() {
  KeywordSpec spec = set_shell_generate_keyword();
  spec.name = "SET_SHELL_LIST_GENERATE";
  spec.summary = "The same keyword as *SET_SHELL_GENERATE (the spelling LS-PrePost writes).";
  return spec;
}

}  // namespace plyform::keyword
