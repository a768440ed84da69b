// *HOURGLASS(_TITLE) and *CONTROL_HOURGLASS.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kHourglassFields{
    FieldSpec{.name = "HGID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "hourglass id (a part's HGID)",
              .required = true},
    FieldSpec{.name = "IHQ",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 10,
              .unit = "-",
              .description = "hourglass control type (0: the *CONTROL_HOURGLASS type)"},
    FieldSpec{.name = "QM",
              .type = FieldType::kReal,
              .default_value = 0.1,
              .min_value = 0.0,
              .unit = "-",
              .description = "hourglass coefficient"},
    FieldSpec{.name = "IBQ",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "not used by LS-DYNA's explicit solver; kept as written"},
    FieldSpec{.name = "Q1",
              .type = FieldType::kReal,
              .default_value = 1.5,
              .min_value = 0.0,
              .unit = "-",
              .description = "quadratic bulk viscosity coefficient of the part's solids "
                             "(replaces *CONTROL_BULK_VISCOSITY's)"},
    FieldSpec{.name = "Q2",
              .type = FieldType::kReal,
              .default_value = 0.06,
              .min_value = 0.0,
              .unit = "-",
              .description = "linear bulk viscosity coefficient of the part's solids "
                             "(replaces *CONTROL_BULK_VISCOSITY's)"},
    FieldSpec{.name = "QB",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "-",
              .description = "bending hourglass coefficient (VDC for IHQ 10); blank: QM"},
    FieldSpec{.name = "QW",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "-",
              .description = "warping hourglass coefficient; blank: QM"},
};
constexpr std::array kHourglassCards{
    CardSpec{.title = "Title card", .fields = kTitleCardFields, .presence = "with _TITLE only"},
    CardSpec{.title = "Card 1",
             .fields = kHourglassFields,
             .presence = "required; may repeat (with the title card before each under _TITLE)"},
};

constexpr std::array kControlFields{
    FieldSpec{.name = "IHQ",
              .type = FieldType::kInteger,
              .default_value = 1,
              .min_value = 0,
              .max_value = 10,
              .unit = "-",
              .description = "default hourglass control type (0 is read as 1)"},
    FieldSpec{.name = "QH",
              .type = FieldType::kReal,
              .default_value = 0.1,
              .min_value = 0.0,
              .unit = "-",
              .description = "default hourglass coefficient"},
};
constexpr std::array kControlCards{
    CardSpec{.title = "Card 1", .fields = kControlFields, .presence = "required"},
};

void read_hourglass(KeywordInput& in) {
  do {
    model::HourglassDesc hg;
    if (in.option() == "TITLE") {
      hg.title = in.next_card(kHourglassCards[0], "title card").text("TITLE");
    }
    const auto line = in.next_line();
    if (!line) {
      in.fail(in.keyword().line, "", "missing card 1 (HGID IHQ QM IBQ Q1 Q2 QB QW)");
    }
    const CardValues v = in.read(kHourglassCards[1], *line);
    hg.id = v.integer("HGID");
    hg.ihq = v.integer("IHQ");
    hg.qm = v.real("QM");
    hg.ibq = v.integer("IBQ");
    hg.q1 = v.real("Q1");
    hg.q2 = v.real("Q2");
    hg.qb = v.blank("QB") ? hg.qm : v.real("QB");
    hg.qw = v.blank("QW") ? hg.qm : v.real("QW");
    hg.where = in.where(line->line);
    in.model().hourglasses.push_back(std::move(hg));
  } while (has_more_cards(in));
}

void read_control_hourglass(KeywordInput& in) {
  const auto line = in.next_line();
  model::ControlHourglassDesc desc;
  desc.where = in.keyword_where();
  if (line) {
    const CardValues v = in.read(kControlCards[0], *line);
    desc.ihq = v.integer("IHQ") == 0 ? 1 : v.integer("IHQ");
    desc.qh = v.real("QH");
    desc.where = in.where(line->line);
  }
  if (in.model().control_hourglass) {
    in.warn(in.keyword().line, "",
            "*CONTROL_HOURGLASS given again: this one replaces the one at line " +
                std::to_string(in.model().control_hourglass->where.line));
  }
  in.model().control_hourglass = desc;
}

}  // namespace

KeywordSpec hourglass_keyword() {
  return {.name = "HOURGLASS",
          .options = kNoneOrTitle,
          .handler = read_hourglass,
          .cards = kHourglassCards,
          .summary =
              "Hourglass and bulk viscosity controls referenced by a part's HGID. "
              "Values are kept as written (blank QB and QW take QM, as LS-DYNA); which "
              "IHQ types the solver implements is checked when the model is built."};
}

KeywordSpec control_hourglass_keyword() {
  return {.name = "CONTROL_HOURGLASS",
          .options = kNoOptions,
          .handler = read_control_hourglass,
          .cards = kControlCards,
          .summary =
              "The default hourglass control of parts without an HGID. Given twice, the "
              "last one is used (with a warning)."};
}

}  // namespace plyform::keyword
