// *INTERFACE_SPRINGBACK_LSDYNA: the request for LS-DYNA's springback file (dynain: the formed
// part's nodes, elements, stresses and history, for a springback run). plyform does not write
// that file: like any other output request it is read and named in a warning, never an error.
// Its restart file (--restart) carries the state for continuing a run instead.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kCard1{
    FieldSpec{.name = "PSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "part set of the springback file"},
    FieldSpec{.name = "NSHV",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "history variables written per point"},
    FieldSpec{
        .name = "FTYPE", .type = FieldType::kInteger, .unit = "-", .description = "file format"},
    FieldSpec{.name = "UNUSED", .type = FieldType::kText, .description = "not used"},
    FieldSpec{.name = "FTENSR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "tensor history written"},
    FieldSpec{.name = "NTHHSV",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "thermal history variables written"},
    FieldSpec{.name = "RFLAG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "reference geometry written"},
    FieldSpec{.name = "INTSTRN",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "strains written"},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1",
             .fields = kCard1,
             .presence = "required; the optional card and the node cards (NID TC RC) after it "
                         "are passed over"},
};

void read_interface_springback(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", "missing card 1 (PSID NSHV FTYPE ...)");
  (void)in.read(kCards[0], *line);
  in.skip_rest();
  in.warn(in.keyword().line, "",
          "output request not written by plyform: the springback file (dynain) is LS-DYNA's; "
          "plyform's restart file (--restart) carries the formed state");
}

}  // namespace

KeywordSpec interface_springback_lsdyna_keyword() {
  return {.name = "INTERFACE_SPRINGBACK_LSDYNA",
          .options = kNoOptions,
          .handler = read_interface_springback,
          .cards = kCards,
          .summary =
              "Request for LS-DYNA's springback file (dynain): read and warned about, "
              "as every output request plyform does not write."};
}

}  // namespace plyform::keyword
