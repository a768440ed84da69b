// *INTERFACE_SPRINGBACK_LSDYNA: write LS-DYNA's springback file, OUTDIR/dynain, at the end of
// the run: the formed shells' nodes, elements with their current thickness, every point's
// stress and plastic strain and the surfaces' strains (app/dynain_writer.hpp,
// docs/outputs.md), so that a next operation (springback, a second draw, trimming) starts from
// the formed part in LS-DYNA, OpenRadioss or plyform.
#include <array>

#include <fmt/format.h>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 3> kFileTypes{0, 1, 2};

constexpr std::array kCard1{
    FieldSpec{.name = "PSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "part set of the shells written (0: every deformable shell part)"},
    FieldSpec{.name = "NSHV",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "history values per point written: plyform writes none (NHISV 0); "
                             "a value other than 0 is warned about"},
    FieldSpec{.name = "FTYPE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0: the keyword (ASCII) file; 2 (ASCII and binary): the ASCII "
                             "file only, warned about; 1 (binary only) is refused",
              .allowed = kFileTypes},
    FieldSpec{.name = "UNUSED", .type = FieldType::kText, .description = "not used"},
    FieldSpec{.name = "FTENSR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "tensor history written: none is (a value other than 0 is warned "
                             "about)"},
    FieldSpec{.name = "NTHHSV",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "thermal history values written: none is (warned about)"},
    FieldSpec{.name = "RFLAG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "reference geometry written: it is not (warned about)"},
    FieldSpec{.name = "INTSTRN",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "strains at every point: plyform writes the inner and outer "
                             "surfaces' (1 is warned about)"},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1",
             .fields = kCard1,
             .presence = "required; node cards after it (NID TC RC: the springback run's "
                         "constraints) are not written into dynain, with a warning"},
};

void warn_unless_zero(KeywordInput& in, int line, std::string_view field, int value,
                      std::string_view what) {
  if (value != 0)
    in.warn(line, std::string(field), fmt::format("{} = {}: {}", field, value, what));
}

void read_interface_springback(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", "missing card 1 (PSID NSHV FTYPE ...)");
  const CardValues v = in.read(kCards[0], *line);
  model::InterfaceSpringbackDesc d{.psid = v.integer("PSID"),
                                   .nshv = v.integer("NSHV"),
                                   .ftype = v.integer("FTYPE"),
                                   .ftensr = v.integer("FTENSR"),
                                   .nthhsv = v.integer("NTHHSV"),
                                   .rflag = v.integer("RFLAG"),
                                   .intstrn = v.integer("INTSTRN"),
                                   .where = in.where(line->line)};
  if (d.ftype == 1) {
    in.fail(line->line, "FTYPE",
            "FTYPE = 1 (a binary dynain only) is not supported: plyform writes the keyword "
            "file (FTYPE 0)");
  }
  if (d.ftype == 2) {
    in.warn(line->line, "FTYPE",
            "FTYPE = 2: the binary file is not written, only the keyword file OUTDIR/dynain");
  }
  warn_unless_zero(in, line->line, "NSHV", d.nshv,
                   "no history values are written (NHISV 0): each point's stress and effective "
                   "plastic strain only");
  warn_unless_zero(in, line->line, "FTENSR", d.ftensr, "no tensor history is written");
  warn_unless_zero(in, line->line, "NTHHSV", d.nthhsv, "no thermal history is written");
  warn_unless_zero(in, line->line, "RFLAG", d.rflag, "the reference geometry is not written");
  warn_unless_zero(in, line->line, "INTSTRN", d.intstrn,
                   "the strains are written at the inner and outer surfaces only");
  if (const auto more = in.next_nonblank_line()) {
    in.warn(more->line, "NID",
            "the node cards (NID TC RC) are not written into dynain: give the springback run's "
            "constraints in its own deck");
    in.skip_rest();
  }
  store_once(in, in.model().springback, d);
}

}  // namespace

KeywordSpec interface_springback_lsdyna_keyword() {
  return {.name = "INTERFACE_SPRINGBACK_LSDYNA",
          .options = kNoOptions,
          .handler = read_interface_springback,
          .cards = kCards,
          .summary =
              "Writes LS-DYNA's springback file OUTDIR/dynain when the run reaches its "
              "end: *NODE, *ELEMENT_SHELL_THICKNESS, *INITIAL_STRESS_SHELL (every "
              "point's stress in global axes and plastic strain, LARGE format) and "
              "*INITIAL_STRAIN_SHELL (the inner and outer surfaces) of the shells of the "
              "part set PSID (docs/outputs.md). What it does not carry (velocities, "
              "contact, laws' other history) is listed there."};
}

}  // namespace plyform::keyword
