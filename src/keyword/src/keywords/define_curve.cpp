// *DEFINE_CURVE(_TITLE): a load curve of points.
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
              .description = "title of the curve",
              .rest_of_line = true},
};
constexpr std::array kHeaderFields{
    FieldSpec{.name = "LCID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "curve id",
              .required = true},
    FieldSpec{.name = "SIDR",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 2,
              .unit = "-",
              .description = "0: transient analysis only, 1: stress initialisation only, 2: both"},
    FieldSpec{.name = "SFA",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "-",
              .description = "scale factor of the abscissa values (0 is read as 1)"},
    FieldSpec{.name = "SFO",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "-",
              .description = "scale factor of the ordinate values (0 is read as 1)"},
    FieldSpec{.name = "OFFA",
              .type = FieldType::kReal,
              .description = "offset of the abscissa values, applied before SFA: "
                             "x = SFA (a + OFFA); in abscissa units"},
    FieldSpec{.name = "OFFO",
              .type = FieldType::kReal,
              .description = "offset of the ordinate values, applied before SFO: "
                             "y = SFO (o + OFFO); in ordinate units"},
    FieldSpec{.name = "DATTYP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "data type (0: general curve); kept as written"},
    FieldSpec{
        .name = "LCINT",
        .type = FieldType::kInteger,
        .min_value = 0,
        .unit = "-",
        .description = "number of discretisation points (0: solver default); kept as written"},
};
constexpr std::array kPointFields{
    FieldSpec{.name = "A",
              .type = FieldType::kReal,
              .width = 20,
              .description = "abscissa; strictly increasing from point to point"},
    FieldSpec{.name = "O", .type = FieldType::kReal, .width = 20, .description = "ordinate"},
};
constexpr std::array kCards{
    CardSpec{.title = "Title card", .fields = kTitleFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kHeaderFields, .presence = "required"},
    CardSpec{.title = "Point cards",
             .fields = kPointFields,
             .presence = "one per point, at least 2, until the next keyword (blank lines are "
                         "skipped)",
             .numbering = FieldNumbering::kPerCard},
};

void read_define_curve(KeywordInput& in) {
  model::CurveDesc curve;
  curve.where = in.keyword_where();
  if (in.option() == "TITLE") {
    curve.title = in.next_card(kCards[0], "title card").text("TITLE");
  }
  const CardValues header =
      in.next_card(kCards[1], "card 1 (LCID SIDR SFA SFO OFFA OFFO DATTYP LCINT)");
  curve.id = header.integer("LCID");
  curve.sidr = header.integer("SIDR");
  curve.sfa = header.real("SFA");
  curve.sfo = header.real("SFO");
  curve.offa = header.real("OFFA");
  curve.offo = header.real("OFFO");
  curve.dattyp = header.integer("DATTYP");
  curve.lcint = header.integer("LCINT");

  int point = 0;
  while (const auto line = in.next_nonblank_line()) {
    const CardValues values = in.read(kCards[2], *line, point);
    const double a = values.real("A");
    if (!curve.abscissa.empty() && !(a > curve.abscissa.back())) {
      in.fail(line->line, fmt::format("A{}", point + 1),
              fmt::format("abscissa {} does not increase (point {} has {}); abscissa values must "
                          "strictly increase",
                          a, point, curve.abscissa.back()));
    }
    curve.abscissa.push_back(a);
    curve.ordinate.push_back(values.real("O"));
    ++point;
  }
  if (point < 2) {
    in.fail(in.keyword().line, "", fmt::format("a curve needs at least 2 points, got {}", point));
  }
  in.model().curves.push_back(std::move(curve));
}

}  // namespace

KeywordSpec define_curve_keyword() {
  return {.name = "DEFINE_CURVE",
          .options = kOptions,
          .handler = read_define_curve,
          .cards = kCards,
          .summary =
              "A curve of points (a, o). The values are stored as written; the curve used "
              "is x = SFA (a + OFFA), y = SFO (o + OFFO) (`model::effective_points`). "
              "Point cards have two 20-character fields in fixed format."};
}

}  // namespace plyform::keyword
