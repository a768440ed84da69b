// *CONTROL_TERMINATION, *CONTROL_TIMESTEP, *CONTROL_ENERGY, *CONTROL_UNITS.
#include <array>
#include <optional>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

// --- *CONTROL_TERMINATION
constexpr std::array kTerminationFields{
    FieldSpec{.name = "ENDTIM",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "time",
              .description = "termination time"},
    FieldSpec{.name = "ENDCYC",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "termination cycle (0: none)"},
    FieldSpec{.name = "DTMIN",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "-",
              .description = "stop when the step falls below DTMIN x the initial step (0: 1e-4, "
                             "plyform's default floor)"},
    FieldSpec{.name = "ENDENG",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "percent change of the energy ratio that stops the run (0: plyform's "
                             "band, 50 %)"},
    FieldSpec{.name = "ENDMAS",
              .type = FieldType::kReal,
              .unit = "-",
              .description = "mass change limit (mass scaling); kept as written"},
    FieldSpec{.name = "NOSOL",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 1,
              .unit = "-",
              .description = "1: read and check only"},
};
constexpr std::array kTerminationCards{
    CardSpec{.title = "Card 1", .fields = kTerminationFields, .presence = "required"},
};

void read_control_termination(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (ENDTIM ENDCYC DTMIN ENDENG ENDMAS NOSOL)");
  }
  const CardValues v = in.read(kTerminationCards[0], *line);
  store_once(in, in.model().termination,
             model::ControlTerminationDesc{.end_time = v.real("ENDTIM"),
                                           .end_cycle = v.integer("ENDCYC"),
                                           .dtmin = v.real("DTMIN"),
                                           .endeng = v.real("ENDENG"),
                                           .endmas = v.real("ENDMAS"),
                                           .nosol = v.integer("NOSOL"),
                                           .where = in.where(line->line)});
}

// --- *CONTROL_TIMESTEP
constexpr std::array kTimestepFields{
    FieldSpec{.name = "DTINIT",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "time",
              .description = "initial time step (0: the solver chooses)"},
    FieldSpec{.name = "TSSFAC",
              .type = FieldType::kReal,
              .default_value = 0.9,
              .min_value = 0.0,
              .unit = "-",
              .description = "scale factor of the stable time step (0 is read as 0.9)"},
    FieldSpec{.name = "ISDO",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 3,
              .unit = "-",
              .description = "shell characteristic length option; kept as written"},
    FieldSpec{.name = "TSLIMT",
              .type = FieldType::kReal,
              .unit = "time",
              .description = "shell minimum time step; kept as written"},
    FieldSpec{.name = "DT2MS",
              .type = FieldType::kReal,
              .unit = "time",
              .description = "mass scaling: time step to keep (negative: mass added only to "
                             "elements below |DT2MS|; 0: none)"},
    FieldSpec{.name = "LCTM",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of the largest time step against time (0: none)"},
    FieldSpec{.name = "ERODE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "erosion of elements below DTMIN; kept as written"},
    FieldSpec{.name = "MS1ST",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "mass scaling at the first step only; kept as written"},
};
// Card 2 (LS-PrePost writes it at its defaults): mass-scaling refinements plyform does not have,
// each accepted at its default only.
constexpr std::array kZeroInt{0};
constexpr std::array kTimestepCard2Fields{
    FieldSpec{.name = "DT2MSF",
              .min_value = 0.0,
              .max_value = 0.0,
              .unit = "-",
              .description = "mass scaling to a factor of the initial step (0 only: not "
                             "implemented; give the step as DT2MS)"},
    FieldSpec{.name = "DT2MSLC",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of DT2MS against time",
              .allowed = kZeroInt,
              .allowed_note = "a curve of the mass-scaling step is not implemented"},
    FieldSpec{.name = "IMSCL",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "selective mass scaling",
              .allowed = kZeroInt,
              .allowed_note = "selective mass scaling is not implemented"},
    FieldSpec{.name = "UNUSED4", .type = FieldType::kText, .description = "unused"},
    FieldSpec{.name = "UNUSED5", .type = FieldType::kText, .description = "unused"},
    FieldSpec{.name = "RMSCL",
              .min_value = 0.0,
              .max_value = 0.0,
              .unit = "-",
              .description = "rotational option of selective mass scaling (0 only: not "
                             "implemented)"},
    FieldSpec{.name = "UNUSED7", .type = FieldType::kText, .description = "unused"},
    FieldSpec{.name = "IHDO",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "how the solids' step is found (0: plyform's, from the element's "
                             "characteristic length)",
              .allowed = kZeroInt,
              .allowed_note = "the alternative solid step of IHDO 1 is not implemented"},
};
constexpr std::array kTimestepCards{
    CardSpec{.title = "Card 1", .fields = kTimestepFields, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kTimestepCard2Fields, .presence = "optional"},
};

void read_control_timestep(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "",
            "missing card 1 (DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST)");
  }
  const CardValues v = in.read(kTimestepCards[0], *line);
  model::ControlTimestepDesc d{.dtinit = v.real("DTINIT"),
                               .tssfac = v.real("TSSFAC") == 0.0 ? 0.9 : v.real("TSSFAC"),
                               .isdo = v.integer("ISDO"),
                               .tslimt = v.real("TSLIMT"),
                               .dt2ms = v.real("DT2MS"),
                               .lctm = v.integer("LCTM"),
                               .erode = v.integer("ERODE"),
                               .ms1st = v.integer("MS1ST"),
                               .where = in.where(line->line)};
  if (const auto card2 = in.next_line())
    (void)in.read(kTimestepCards[1], *card2);
  if (const auto card3 = in.next_nonblank_line()) {
    in.fail(card3->line, "",
            "card 3 of *CONTROL_TIMESTEP (IGADO ...) is not read (plyform reads cards 1-2)");
  }
  store_once(in, in.model().timestep, d);
}

// --- *CONTROL_ENERGY
constexpr FieldSpec energy_flag(std::string_view name, double default_value,
                                std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .default_value = default_value,
                   .min_value = 0,
                   .max_value = 2,
                   .unit = "-",
                   .description = description};
}
constexpr std::array kEnergyFields{
    energy_flag("HGEN", 1, "hourglass energy: 1 not computed, 2 computed (0: default)"),
    energy_flag("RWEN", 2, "rigid wall energy: 1 not computed, 2 computed"),
    energy_flag("SLNTEN", 1, "sliding interface energy: 1 not computed, 2 computed"),
    energy_flag("RYLEN", 1, "Rayleigh damping energy: 1 not computed, 2 computed"),
    energy_flag("IRGEN", 2, "initial reference geometry energy: 1 not computed, 2 computed"),
};
constexpr std::array kEnergyCards{
    CardSpec{.title = "Card 1", .fields = kEnergyFields, .presence = "required"},
};

int energy_value(const CardValues& v, std::string_view name, int default_value) {
  const int value = v.integer(name);
  return value == 0 ? default_value : value;
}

void read_control_energy(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (HGEN RWEN SLNTEN RYLEN IRGEN)");
  }
  const CardValues v = in.read(kEnergyCards[0], *line);
  store_once(in, in.model().energy,
             model::ControlEnergyDesc{.hgen = energy_value(v, "HGEN", 1),
                                      .rwen = energy_value(v, "RWEN", 2),
                                      .slnten = energy_value(v, "SLNTEN", 1),
                                      .rylen = energy_value(v, "RYLEN", 1),
                                      .irgen = energy_value(v, "IRGEN", 2),
                                      .where = in.where(line->line)});
}

// --- *CONTROL_UNITS
constexpr std::array kUnitsFields{
    FieldSpec{.name = "LENGTH",
              .type = FieldType::kText,
              .description = "length unit (m, mm, cm, in, ft)"},
    FieldSpec{
        .name = "TIME", .type = FieldType::kText, .description = "time unit (sec, ms, micro_s)"},
    FieldSpec{.name = "MASS",
              .type = FieldType::kText,
              .description = "mass unit (kg, g, mg, lb, slug, mtrc_ton)"},
    FieldSpec{
        .name = "TEMP", .type = FieldType::kText, .description = "temperature unit (K, C, F, R)"},
};
constexpr std::array kUnitsCards{
    CardSpec{.title = "Card 1", .fields = kUnitsFields, .presence = "required"},
};

void read_control_units(KeywordInput& in) {
  const CardValues v = in.next_card(kUnitsCards[0], "card 1 (LENGTH TIME MASS TEMP)");
  if (const auto card2 = in.next_nonblank_line()) {
    in.fail(card2->line, "",
            "card 2 of *CONTROL_UNITS (user-defined unit factors) is not supported");
  }
  store_once(in, in.model().units,
             model::ControlUnitsDesc{.length = v.text("LENGTH"),
                                     .time = v.text("TIME"),
                                     .mass = v.text("MASS"),
                                     .temp = v.text("TEMP"),
                                     .where = in.keyword_where()});
}

}  // namespace

KeywordSpec control_termination_keyword() {
  return {.name = "CONTROL_TERMINATION",
          .options = kNoOptions,
          .handler = read_control_termination,
          .cards = kTerminationCards,
          .summary = "When the run stops. Given twice, the last one is used (with a warning)."};
}

KeywordSpec control_timestep_keyword() {
  return {.name = "CONTROL_TIMESTEP",
          .options = kNoOptions,
          .handler = read_control_timestep,
          .cards = kTimestepCards,
          .summary =
              "Time step control: TSSFAC, DT2MS (mass scaling), DTINIT and LCTM (a curve "
              "of the largest step against time) are used; a blank or 0 TSSFAC is 0.9 as "
              "in LS-DYNA. Card 2 is read at its defaults only."};
}

KeywordSpec control_energy_keyword() {
  return {.name = "CONTROL_ENERGY",
          .options = kNoOptions,
          .handler = read_control_energy,
          .cards = kEnergyCards,
          .summary =
              "Which energies are computed for glstat (1 no, 2 yes); a written 0 takes "
              "the default."};
}

KeywordSpec control_units_keyword() {
  return {.name = "CONTROL_UNITS",
          .options = kNoOptions,
          .handler = read_control_units,
          .cards = kUnitsCards,
          .summary =
              "Names of the deck's units, kept as text and shown by `plyform check`; "
              "nothing is converted (the deck's units stay consistent units)."};
}

}  // namespace plyform::keyword
