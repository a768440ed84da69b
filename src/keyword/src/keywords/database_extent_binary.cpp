// *DATABASE_EXTENT_BINARY: what LS-DYNA puts into each d3plot state, read as what plyform puts
// into each results_NNNN.vtu. The fields that map onto plyform's arrays are honoured (SIGFLG,
// EPSFLG, ENGFLG's thickness, STRFLG's strain tensor); fields that only shape LS-DYNA's file
// (compression, one file per state) change nothing; a request for data plyform does not write
// is read and warned about by name, never an error: it is an output request.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kOneTwoThree{0, 1, 2, 3};
constexpr std::array kOneTwo{0, 1, 2};

constexpr FieldSpec integer(std::string_view name, std::string_view what, double fallback = 0.0) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .default_value = fallback,
                   .unit = "-",
                   .description = what};
}

constexpr std::array kExtent1{
    integer("NEIPH", "extra history variables per solid point: not written (> 0 warned)"),
    integer("NEIPS",
            "extra history variables per shell point: not written (> 0 warned; the woven ply's "
            "fibre directions and shear angle are written anyway)"),
    integer("MAXINT",
            "shell thickness points written: plyform writes the middle, top and bottom "
            "(stress, stress_top, stress_bottom); another value than 3 is warned",
            3),
    integer("STRFLG",
            "digits abc: c = 1 writes the strain tensor (cell array `strain`: the logarithmic "
            "strain 1/2 ln(F F^T) in global axes, tensor shear; a shell's at its mid-surface); "
            "b = 1 (plastic strain tensor) and a = 1 (thermal strain tensor) are not written "
            "(warned)"),
    FieldSpec{.name = "SIGFLG",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "stress tensors: 1 written, 2 not (shells and solids), 3 not for "
                             "shells (solids' are)",
              .allowed = kOneTwoThree},
    FieldSpec{.name = "EPSFLG",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "effective plastic strain: 1 written, 2 not (shells and solids), 3 "
                             "not for shells (solids' is)",
              .allowed = kOneTwoThree},
    integer("RLTFLG",
            "shell stress resultants: plyform writes none (the stresses at three points give "
            "them); 2 (not written) agrees, 1 is LS-DYNA's default and passes",
            1),
    FieldSpec{.name = "ENGFLG",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "shell thickness and internal energy density: 1 the thickness is "
                             "written (the energy density is not), 2 neither",
              .allowed = kOneTwo},
};
constexpr std::array kExtent2{
    integer("CMPFLG",
            "stresses of anisotropic materials in their material axes: plyform writes global "
            "axes (non-zero warned)"),
    integer("IEVERP",
            "one file per state: each state is its own results_NNNN.vtu anyway (no effect)"),
    integer("BEAMIP", "beam integration points (plyform has no beams: no effect)"),
    integer("DCOMP", "compression of LS-DYNA's file (no effect)", 1),
    integer("SHGE", "shell hourglass energy density: 2 is not written (warned)", 1),
    integer("STSSZ", "shell time step, mass and added mass: 2-4 are not written (warned)", 1),
    integer("N3THDT", "thick shell energy (plyform has no thick shells: no effect)", 2),
    integer("IALEMAT", "ALE materials (plyform has no ALE: no effect)", 1),
};
constexpr std::array kExtent3{
    integer("NINTSLD",
            "solid integration points written: plyform writes one value per solid (the mean "
            "of its points); 8 is warned",
            1),
    integer("PKP_SEN", "peak pressure and surface energy of segments: 1 is not written (warned)"),
    FieldSpec{.name = "SCLP",
              .default_value = 1.0,
              .unit = "-",
              .description = "scale of PKP_SEN's pressure (no effect)"},
    integer("HYDRO", "hydrostatic (ALE) data: not written (non-zero warned)"),
    integer("MSSCL", "nodal mass added by mass scaling: 1 and 2 are not written (warned)"),
    integer("THERM",
            "thermal data: the temperature is always written (point array `temperature`); "
            "2 and 3 (heat fluxes) are not (warned)"),
    FieldSpec{.name = "INTOUT",
              .type = FieldType::kText,
              .description = "every integration point into LS-DYNA's eloutdet: not written "
                             "(elout.csv has every thickness point of its elements; warned)"},
    FieldSpec{.name = "NODOUT",
              .type = FieldType::kText,
              .description = "extrapolated nodal values into eloutdet: not written (warned)"},
};
constexpr std::array kExtent4{
    integer("DTDT", "temperature rate dT/dt: 1 is not written (warned)"),
    integer("RESPLT", "residual forces: 1 is not written (warned)"),
    integer("NEIPB", "extra history variables of beams (no beams: no effect)"),
    integer("QUADR", "quadratic elements (none in plyform: no effect)"),
    integer("CUBIC", "cubic elements (none in plyform: no effect)"),
};
constexpr std::array kExtentCards{
    CardSpec{.title = "Card 1", .fields = kExtent1, .presence = "optional"},
    CardSpec{.title = "Card 2", .fields = kExtent2, .presence = "optional"},
    CardSpec{.title = "Card 3", .fields = kExtent3, .presence = "optional"},
    CardSpec{.title = "Card 4", .fields = kExtent4, .presence = "optional"},
};

void read_extent_binary(KeywordInput& in) {
  model::DatabaseExtentBinaryDesc d;
  d.where = in.where(in.keyword().line);
  const auto warn = [&](int line, std::string_view field, const std::string& what) {
    in.warn(line, std::string(field), what + " not written by plyform (the rest of the state is)");
  };
  if (const auto line = in.next_line()) {
    const CardValues v = in.read(kExtentCards[0], *line);
    d.neiph = v.integer("NEIPH");
    d.neips = v.integer("NEIPS");
    d.maxint = v.integer("MAXINT");
    d.strflg = v.integer("STRFLG");
    d.sigflg = v.integer("SIGFLG");
    d.epsflg = v.integer("EPSFLG");
    d.rltflg = v.integer("RLTFLG");
    d.engflg = v.integer("ENGFLG");
    if (d.neiph > 0)
      warn(line->line, "NEIPH",
           fmt::format("NEIPH = {}: extra history variables of solids", d.neiph));
    if (d.neips > 0)
      warn(line->line, "NEIPS",
           fmt::format("NEIPS = {}: extra history variables of shells", d.neips));
    if (d.maxint != 3 && d.maxint != 0) {
      in.warn(line->line, "MAXINT",
              fmt::format("MAXINT = {}: plyform writes the middle, top and bottom thickness "
                          "points of each shell (stress, stress_top, stress_bottom), not {} points",
                          d.maxint, d.maxint));
    }
    if (d.strflg < 0 || d.strflg > 111 || d.strflg % 10 > 1 || (d.strflg / 10) % 10 > 1) {
      in.fail(line->line, "STRFLG",
              fmt::format("STRFLG = {}: expected the digits abc, each 0 or 1 (c strain, b "
                          "plastic strain, a thermal strain tensor)",
                          d.strflg));
    }
    if ((d.strflg / 10) % 10 == 1)
      warn(line->line, "STRFLG", "STRFLG b = 1: the plastic strain tensor is");
    if (d.strflg / 100 == 1)
      warn(line->line, "STRFLG", "STRFLG a = 1: the thermal strain tensor is");
  }
  if (const auto line = in.next_line()) {
    const CardValues v = in.read(kExtentCards[1], *line);
    d.cmpflg = v.integer("CMPFLG");
    d.ieverp = v.integer("IEVERP");
    d.beamip = v.integer("BEAMIP");
    d.dcomp = v.integer("DCOMP");
    d.shge = v.integer("SHGE");
    d.stssz = v.integer("STSSZ");
    d.n3thdt = v.integer("N3THDT");
    d.ialemat = v.integer("IALEMAT");
    if (d.cmpflg != 0) {
      in.warn(line->line, "CMPFLG",
              fmt::format("CMPFLG = {}: stresses in material axes are not written; plyform's "
                          "stress arrays are in global axes",
                          d.cmpflg));
    }
    if (d.shge == 2)
      warn(line->line, "SHGE", "SHGE = 2: the shell hourglass energy density is");
    if (d.stssz >= 2 && d.stssz <= 4) {
      constexpr const char* kWhat[3] = {"the shell time step is",
                                        "the shell mass and added mass are",
                                        "the shell time step, mass and added mass are"};
      warn(line->line, "STSSZ", fmt::format("STSSZ = {}: {}", d.stssz, kWhat[d.stssz - 2]));
    }
  }
  if (const auto line = in.next_line()) {
    const CardValues v = in.read(kExtentCards[2], *line);
    d.nintsld = v.integer("NINTSLD");
    d.pkp_sen = v.integer("PKP_SEN");
    d.sclp = v.real("SCLP");
    d.hydro = v.integer("HYDRO");
    d.msscl = v.integer("MSSCL");
    d.therm = v.integer("THERM");
    d.intout = v.text("INTOUT");
    d.nodout = v.text("NODOUT");
    if (d.nintsld > 1) {
      in.warn(line->line, "NINTSLD",
              fmt::format("NINTSLD = {}: plyform writes one value per solid (the mean of its "
                          "integration points)",
                          d.nintsld));
    }
    if (d.pkp_sen != 0)
      warn(line->line, "PKP_SEN",
           "PKP_SEN = 1: the segments' peak pressure and surface energy are");
    if (d.hydro != 0)
      warn(line->line, "HYDRO", fmt::format("HYDRO = {}: hydrostatic data are", d.hydro));
    if (d.msscl != 0)
      warn(line->line, "MSSCL",
           fmt::format("MSSCL = {}: the mass added by mass scaling is", d.msscl));
    if (d.therm >= 2)
      warn(line->line, "THERM", fmt::format("THERM = {}: the heat fluxes are", d.therm));
    if (!d.intout.empty())
      warn(line->line, "INTOUT", fmt::format("INTOUT = {}: eloutdet is", d.intout));
    if (!d.nodout.empty())
      warn(line->line, "NODOUT", fmt::format("NODOUT = {}: eloutdet is", d.nodout));
  }
  if (const auto line = in.next_line()) {
    const CardValues v = in.read(kExtentCards[3], *line);
    d.dtdt = v.integer("DTDT");
    d.resplt = v.integer("RESPLT");
    if (d.dtdt != 0)
      warn(line->line, "DTDT", "DTDT = 1: the temperature rate is");
    if (d.resplt != 0)
      warn(line->line, "RESPLT", "RESPLT = 1: the residual forces are");
  }
  if (const auto more = in.next_nonblank_line()) {
    in.fail(more->line, "",
            "cards 5 and after of *DATABASE_EXTENT_BINARY are not read (plyform reads cards "
            "1-4)");
  }
  store_once(in, in.model().extent_binary, std::move(d));
}

}  // namespace

KeywordSpec database_extent_binary_keyword() {
  return {.name = "DATABASE_EXTENT_BINARY",
          .options = kNoOptions,
          .handler = read_extent_binary,
          .cards = kExtentCards,
          .summary =
              "What each state (results_NNNN.vtu) holds: SIGFLG and EPSFLG drop the stress "
              "arrays and the plastic strain, ENGFLG 2 the thickness, STRFLG 1 adds the cell "
              "array `strain` (logarithmic strain in global axes; a shell's at its "
              "mid-surface). Requests for data plyform does not write are warned about by "
              "name. Given twice, the last one is used (with a warning)."};
}

}  // namespace plyform::keyword
