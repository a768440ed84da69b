// *DEFINE_TABLE(_TITLE): curves indexed by a value (temperature, strain rate). As in LS-DYNA,
// the table's curves are the *DEFINE_CURVE keywords that follow it, one per value, in order.
#include <array>

#include <fmt/format.h>

#include "../keyword_input.hpp"
#include "../keyword_registry.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<std::string_view, 2> kOptions{"", "TITLE"};

constexpr std::array kTitleFields{
    FieldSpec{.name = "TITLE",
              .type = FieldType::kText,
              .width = 80,
              .description = "title of the table",
              .rest_of_line = true},
};
constexpr std::array kHeaderFields{
    FieldSpec{.name = "TBID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "table id (shares the id space of the curves)",
              .required = true},
    FieldSpec{.name = "SFA",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "-",
              .description = "scale factor of the values (0 is read as 1)"},
    FieldSpec{.name = "OFFA",
              .type = FieldType::kReal,
              .description = "offset of the values, applied before SFA: v = SFA (VALUE + OFFA)"},
};
constexpr std::array kValueFields{
    FieldSpec{.name = "VALUE",
              .type = FieldType::kReal,
              .width = 20,
              .description = "the value (temperature, strain rate) of the next curve; strictly "
                             "increasing from card to card"},
    FieldSpec{
        .name = "LCID",
        .type = FieldType::kInteger,
        .width = 20,
        .unit = "-",
        .description =
            "curve id as written; LS-DYNA does not use it (the curves that "
            "follow the table are its curves); a written id that is not that curve's is an error"},
};
constexpr std::array kCards{
    CardSpec{.title = "Title card", .fields = kTitleFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kHeaderFields, .presence = "required"},
    CardSpec{.title = "Value cards",
             .fields = kValueFields,
             .presence = "one per curve, at least 1, until the next keyword; the curves follow "
                         "as *DEFINE_CURVE keywords in the same order",
             .numbering = FieldNumbering::kPerCard},
};

void read_define_table(KeywordInput& in) {
  model::DefineTableDesc table;
  table.where = in.keyword_where();
  if (in.option() == "TITLE")
    table.title = in.next_card(kCards[0], "title card").text("TITLE");
  const CardValues header = in.next_card(kCards[1], "card 1 (TBID SFA OFFA)");
  table.id = header.integer("TBID");
  table.sfa = header.real("SFA");
  table.offa = header.real("OFFA");
  int k = 0;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues values = in.read(kCards[2], *line, k);
    const double v = values.real("VALUE");
    if (!table.values.empty() && !(v > table.values.back())) {
      in.fail(line->line, fmt::format("VALUE{}", k + 1),
              fmt::format("value {} does not increase (card {} has {}); the values of a table "
                          "must strictly increase",
                          v, k, table.values.back()));
    }
    table.values.push_back(v);
    table.lcid_written.push_back(values.integer("LCID"));
    table.value_where.push_back(in.where(line->line));
    ++k;
  }
  if (k == 0)
    in.fail(in.keyword().line, "VALUE", "a table needs at least one value card");
  table.first_curve = in.model().curves.size();
  in.model().tables.push_back(std::move(table));
}

}  // namespace

KeywordSpec define_table_keyword() {
  return {.name = "DEFINE_TABLE",
          .options = kOptions,
          .handler = read_define_table,
          .cards = kCards,
          .summary =
              "A table of curves y(x) indexed by a value v (temperature, strain rate): the n-th "
              "*DEFINE_CURVE after the table is its curve at the n-th value. Between two values "
              "a material reads the two curves linearly in v; outside the values the first or "
              "last curve. Value cards have two 20-character fields in fixed format."};
}

}  // namespace plyform::keyword
