// *CONTROL_BULK_VISCOSITY: the coefficients of the bulk viscosity of every part without a
// *HOURGLASS of its own (that card's Q1 and Q2 take precedence, as in LS-DYNA).
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kTypes{-2, -1, 0, 1};

constexpr std::array kFields{
    FieldSpec{.name = "Q1",
              .default_value = 1.5,
              .min_value = 0.0,
              .unit = "-",
              .description = "quadratic coefficient"},
    FieldSpec{.name = "Q2",
              .default_value = 0.06,
              .min_value = 0.0,
              .unit = "-",
              .description = "linear coefficient"},
    FieldSpec{.name = "TYPE",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "1 (or 0): standard bulk viscosity of the solids; -1 and -2: of "
                             "the solids and the shells (the membrane's in-plane compression); "
                             "plyform books its work in the internal energy for both (LS-DYNA "
                             "does so for -2 only)",
              .allowed = kTypes,
              .allowed_note = "the Richards-Wilkins form (2) is not implemented"},
    FieldSpec{.name = "BTYPE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "beams' bulk viscosity (plyform has no beams), as written"},
    FieldSpec{.name = "TSTYPE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "thick shells' bulk viscosity (plyform has no thick shells), "
                             "as written"},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1", .fields = kFields, .presence = "required"},
};

void read_control_bulk_viscosity(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", "missing card 1 (Q1 Q2 TYPE BTYPE TSTYPE)");
  const CardValues v = in.read(kCards[0], *line);
  store_once(in, in.model().bulk_viscosity,
             model::ControlBulkViscosityDesc{
                 .q1 = v.real("Q1"),
                 .q2 = v.real("Q2"),
                 .type = v.integer("TYPE") == 0 ? 1 : static_cast<int>(v.integer("TYPE")),
                 .btype = v.integer("BTYPE"),
                 .tstype = v.integer("TSTYPE"),
                 .where = in.where(line->line)});
}

}  // namespace

KeywordSpec control_bulk_viscosity_keyword() {
  return {.name = "CONTROL_BULK_VISCOSITY",
          .options = kNoOptions,
          .handler = read_control_bulk_viscosity,
          .cards = kCards,
          .summary =
              "Bulk viscosity of the solids: in compression a pressure "
              "q = rho l |tr D| (Q1 l |tr D| + Q2 c), l the cube root of the element's volume, "
              "c its wave speed; the stable step becomes L / (Q + sqrt(Q^2 + c^2)) with "
              "Q = Q1 l |tr D| + Q2 c. Without this keyword, Q1 1.5 and Q2 0.06 (LS-DYNA's "
              "defaults); a part's *HOURGLASS Q1 and Q2 replace these for its elements. TYPE -1 "
              "and -2 also put it in the shells' membrane (l = sqrt(A), c the plate wave "
              "speed; docs/materials.md)."};
}

}  // namespace plyform::keyword
