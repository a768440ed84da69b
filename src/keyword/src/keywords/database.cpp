// *DATABASE_BINARY_D3PLOT, *DATABASE_BINARY_D3DUMP, *DATABASE_GLSTAT, *DATABASE_NODOUT,
// *DATABASE_RCFORC, *DATABASE_BNDOUT, *DATABASE_TPRINT, *DATABASE_HISTORY_NODE(_ID),
// *DATABASE_ELOUT, *DATABASE_HISTORY_SHELL(_ID), *DATABASE_HISTORY_SOLID(_ID).
#include <array>

#include "database_histories.hpp"

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<std::string_view, 3> kNoneOrIdOrSet{"", "ID", "SET"};

// --- *DATABASE_BINARY_D3PLOT
constexpr std::array kD3plotFields{
    FieldSpec{.name = "DT",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "time",
              .description = "interval between states"},
    FieldSpec{.name = "LCDT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of the interval: must be 0 (not supported yet)"},
    FieldSpec{.name = "BEAM",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "beam output option; kept as written"},
    FieldSpec{.name = "NPLTC",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "number of states: if > 0, DT = ENDTIM / NPLTC"},
    FieldSpec{.name = "PSETID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "part set written (0: every part)"},
};
constexpr std::array kD3plotCard2Fields{
    FieldSpec{.name = "IOOPT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "kept as written"},
    FieldSpec{.name = "RATE",
              .type = FieldType::kReal,
              .description = "filtering: must be 0 (not supported)"},
    FieldSpec{.name = "CUTOFF",
              .type = FieldType::kReal,
              .description = "filtering: must be 0 (not supported)"},
    FieldSpec{.name = "WINDOW",
              .type = FieldType::kReal,
              .description = "filtering: must be 0 (not supported)"},
    FieldSpec{.name = "TYPE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "filtering: must be 0 (not supported)"},
    FieldSpec{.name = "PSET",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "filtering: must be 0 (not supported)"},
};
constexpr std::array kD3plotCards{
    CardSpec{.title = "Card 1", .fields = kD3plotFields, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kD3plotCard2Fields, .presence = "optional"},
};

void read_d3plot(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (DT LCDT BEAM NPLTC PSETID)");
  }
  const CardValues v = in.read(kD3plotCards[0], *line);
  model::DatabaseBinaryD3plotDesc d{.dt = v.real("DT"),
                                    .lcdt = v.integer("LCDT"),
                                    .beam = v.integer("BEAM"),
                                    .npltc = v.integer("NPLTC"),
                                    .part_set_id = v.integer("PSETID"),
                                    .where = in.where(line->line)};
  require_zero(in, line->line, "LCDT", d.lcdt, "a curve of the output interval");
  if (const auto line2 = in.next_line()) {
    const CardValues c = in.read(kD3plotCards[1], *line2);
    for (std::string_view name : {"RATE", "CUTOFF", "WINDOW", "TYPE", "PSET"}) {
      require_zero(in, line2->line, name, c.real(name), "filtering of the output");
    }
  }
  if (in.model().d3plot) {
    in.warn(in.keyword().line, "",
            fmt::format("*DATABASE_BINARY_D3PLOT given again: this one replaces the one at {}:{}",
                        in.model().d3plot->where.file, in.model().d3plot->where.line));
  }
  in.model().d3plot = d;
}

// --- *DATABASE_BINARY_D3DUMP
constexpr std::array kD3dumpFields{
    FieldSpec{.name = "CYCL",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "cycles between checkpoints",
              .required = true},
    FieldSpec{.name = "NR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "number of checkpoint files kept: must be 0 (plyform keeps one, "
                             "replaced atomically)"},
    FieldSpec{
        .name = "BEAM", .type = FieldType::kInteger, .unit = "-", .description = "kept as written"},
    FieldSpec{.name = "NPLTC",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "must be 0 (the interval is CYCL)"},
    FieldSpec{.name = "PSETID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "must be 0 (a checkpoint holds the whole model)"},
};
constexpr std::array kD3dumpCards{
    CardSpec{.title = "Card 1", .fields = kD3dumpFields, .presence = "required"},
};

void read_d3dump(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (CYCL NR BEAM NPLTC PSETID)");
  }
  const CardValues v = in.read(kD3dumpCards[0], *line);
  require_zero(in, line->line, "NR", v.integer("NR"), "more than one checkpoint file");
  require_zero(in, line->line, "NPLTC", v.integer("NPLTC"), "a number of checkpoints");
  require_zero(in, line->line, "PSETID", v.integer("PSETID"), "a checkpoint of some parts");
  if (in.model().d3dump) {
    in.warn(in.keyword().line, "",
            fmt::format("*DATABASE_BINARY_D3DUMP given again: this one replaces the one at {}:{}",
                        in.model().d3dump->where.file, in.model().d3dump->where.line));
  }
  in.model().d3dump =
      model::DatabaseBinaryD3dumpDesc{.cycles = v.integer("CYCL"), .where = in.where(line->line)};
}

// --- *DATABASE_GLSTAT, *DATABASE_NODOUT, *DATABASE_RCFORC
constexpr std::array kAsciiFields{
    FieldSpec{.name = "DT",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "time",
              .description = "interval between lines"},
    FieldSpec{.name = "BINARY",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 3,
              .unit = "-",
              .description = "LS-DYNA's file kind; plyform writes CSV whatever it is"},
    FieldSpec{.name = "LCUR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of the interval: must be 0 (not supported yet)"},
    FieldSpec{.name = "IOOPT",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "kept as written"},
};
constexpr std::array kAsciiCards{
    CardSpec{.title = "Card 1", .fields = kAsciiFields, .presence = "required"},
};

void read_ascii(KeywordInput& in, std::string_view name) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (DT BINARY LCUR IOOPT)");
  }
  const CardValues v = in.read(kAsciiCards[0], *line);
  model::DatabaseAsciiDesc d{.name = std::string(name),
                             .dt = v.real("DT"),
                             .binary = v.integer("BINARY"),
                             .lcur = v.integer("LCUR"),
                             .ioopt = v.integer("IOOPT"),
                             .where = in.where(line->line)};
  require_zero(in, line->line, "LCUR", d.lcur, "a curve of the output interval");
  for (const model::DatabaseAsciiDesc& other : in.model().ascii_outputs) {
    if (other.name == name) {
      in.warn(in.keyword().line, "",
              fmt::format("*DATABASE_{} given again: the one at {}:{} is also kept; the "
                          "solver uses the last",
                          name, other.where.file, other.where.line));
    }
  }
  in.model().ascii_outputs.push_back(std::move(d));
}

// --- *DATABASE_TPRINT: the card of the ASCII outputs, but once per deck (it sets the interval
// of two files, tprint.csv and heat.csv, rather than naming one output among several).
void read_tprint(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (DT BINARY LCUR IOOPT)");
  }
  const CardValues v = in.read(kAsciiCards[0], *line);
  const model::DatabaseTprintDesc d{.dt = v.real("DT"),
                                    .binary = v.integer("BINARY"),
                                    .lcur = v.integer("LCUR"),
                                    .ioopt = v.integer("IOOPT"),
                                    .where = in.where(line->line)};
  require_zero(in, line->line, "LCUR", d.lcur, "a curve of the output interval");
  store_once(in, in.model().tprint, d);
}

// --- *DATABASE_HISTORY_NODE(_ID)
constexpr std::string_view kHistoryId = "node id (blank or 0: none)";
constexpr FieldSpec history_field() {
  return FieldSpec{.name = "NID",
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .unit = "-",
                   .description = kHistoryId};
}
constexpr std::array kHistoryFields{history_field(), history_field(), history_field(),
                                    history_field(), history_field(), history_field(),
                                    history_field(), history_field()};
constexpr std::array kHistoryIdFields{
    FieldSpec{.name = "ID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "node id",
              .required = true},
    FieldSpec{.name = "HEADING",
              .type = FieldType::kText,
              .width = 70,
              .description = "a name for the node's history",
              .rest_of_line = true},
};
constexpr FieldSpec history_set_field() {
  return FieldSpec{.name = "NSID",
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .unit = "-",
                   .description = "node set id (blank or 0: none)"};
}
constexpr std::array kHistorySetFields{
    history_set_field(), history_set_field(), history_set_field(), history_set_field(),
    history_set_field(), history_set_field(), history_set_field(), history_set_field()};
constexpr std::array kHistoryCards{
    CardSpec{.title = "Node cards",
             .fields = kHistoryFields,
             .presence = "without _ID: eight node ids per card, until the next keyword",
             .numbering = FieldNumbering::kSequential},
    CardSpec{.title = "Node cards (_ID)",
             .fields = kHistoryIdFields,
             .presence = "with _ID: one node per card, until the next keyword"},
    CardSpec{.title = "Node set cards (_SET)",
             .fields = kHistorySetFields,
             .presence = "with _SET: eight node set ids per card, until the next keyword",
             .numbering = FieldNumbering::kSequential},
};

void read_history_node(KeywordInput& in) {
  model::DatabaseHistoryNodeDesc d;
  d.where = in.keyword_where();
  const bool with_id = in.option() == "ID";
  const bool with_set = in.option() == "SET";
  int card = 0;
  while (const auto line = in.next_nonblank_line()) {
    if (with_set) {
      const CardValues v = in.read(kHistoryCards[2], *line, card++);
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (const int id = static_cast<int>(v.at(i).integer); id != 0) {
          d.set_ids.push_back(id);
          d.sets_where.push_back(in.where(line->line));
        }
      }
      continue;
    }
    if (with_id) {
      const CardValues v = in.read(kHistoryCards[1], *line);
      d.node_ids.push_back(v.integer("ID"));
      d.headings.push_back(v.text("HEADING"));
      d.ids_where.push_back(in.where(line->line));
      continue;
    }
    const CardValues v = in.read(kHistoryCards[0], *line, card++);
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (const int id = static_cast<int>(v.at(i).integer); id != 0) {
        d.node_ids.push_back(id);
        d.ids_where.push_back(in.where(line->line));
      }
    }
  }
  in.model().history_nodes.push_back(std::move(d));
}

// --- *DATABASE_ELOUT: the ASCII card with LS-DYNA's four extra-variable counts.
constexpr FieldSpec elout_option(std::string_view name, std::string_view what) {
  return FieldSpec{
      .name = name, .type = FieldType::kInteger, .min_value = 0, .unit = "-", .description = what};
}
constexpr std::array kEloutFields{
    kAsciiFields[0],
    kAsciiFields[1],
    kAsciiFields[2],
    kAsciiFields[3],
    elout_option("OPTION1",
                 "extra history variables per solid integration point: none written (a value "
                 "> 0 is warned about; the plastic strain is always written)"),
    elout_option("OPTION2",
                 "extra history variables per shell integration point: none written (a value "
                 "> 0 is warned about)"),
    elout_option("OPTION3",
                 "extra history variables per thick-shell point: plyform has no thick shells "
                 "(a value > 0 is warned about)"),
    elout_option("OPTION4",
                 "extra history variables per beam point: plyform has no beams (a value > 0 "
                 "is warned about)"),
};
constexpr std::array kEloutCards{
    CardSpec{.title = "Card 1", .fields = kEloutFields, .presence = "required"},
};

void read_elout(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "", "missing card 1 (DT BINARY LCUR IOOPT OPTION1..OPTION4)");
  }
  const CardValues v = in.read(kEloutCards[0], *line);
  model::DatabaseEloutDesc d{.dt = v.real("DT"),
                             .binary = v.integer("BINARY"),
                             .lcur = v.integer("LCUR"),
                             .ioopt = v.integer("IOOPT"),
                             .option1 = v.integer("OPTION1"),
                             .option2 = v.integer("OPTION2"),
                             .option3 = v.integer("OPTION3"),
                             .option4 = v.integer("OPTION4"),
                             .where = in.where(line->line)};
  require_zero(in, line->line, "LCUR", d.lcur, "a curve of the output interval");
  // Extra history variables change only what LS-DYNA adds to its file: elout.csv is written
  // with its own columns, so a request for them is a warning, not an error.
  const std::array<std::pair<std::string_view, int>, 4> options{{{"OPTION1", d.option1},
                                                                 {"OPTION2", d.option2},
                                                                 {"OPTION3", d.option3},
                                                                 {"OPTION4", d.option4}}};
  for (const auto& [name, value] : options) {
    if (value != 0) {
      in.warn(line->line, std::string(name),
              fmt::format("{} extra history variable{} per integration point not written: "
                          "elout.csv holds the stresses and the effective plastic strain only{}",
                          value, value == 1 ? "" : "s",
                          name == "OPTION3"   ? " (plyform has no thick shells)"
                          : name == "OPTION4" ? " (plyform has no beams)"
                                              : ""));
    }
  }
  store_once(in, in.model().elout, d);
}

// --- *DATABASE_HISTORY_SHELL(_ID), *DATABASE_HISTORY_SOLID(_ID)
constexpr FieldSpec history_element_field() {
  return FieldSpec{.name = "EID",
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .unit = "-",
                   .description = "element id (blank or 0: none)"};
}
constexpr std::array kHistoryElementFields{history_element_field(), history_element_field(),
                                           history_element_field(), history_element_field(),
                                           history_element_field(), history_element_field(),
                                           history_element_field(), history_element_field()};
constexpr std::array kHistoryElementIdFields{
    FieldSpec{.name = "ID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "element id",
              .required = true},
    FieldSpec{.name = "HEADING",
              .type = FieldType::kText,
              .width = 70,
              .description = "a name for the element's history (not written)",
              .rest_of_line = true},
};
constexpr std::array kHistoryElementCards{
    CardSpec{.title = "Element cards",
             .fields = kHistoryElementFields,
             .presence = "without _ID: eight element ids per card, until the next keyword",
             .numbering = FieldNumbering::kSequential},
    CardSpec{.title = "Element cards (_ID)",
             .fields = kHistoryElementIdFields,
             .presence = "with _ID: one element per card, until the next keyword"},
};

void read_history_element(KeywordInput& in, bool shell) {
  model::DatabaseHistoryElementDesc d;
  d.shell = shell;
  d.where = in.keyword_where();
  const bool with_id = in.option() == "ID";
  int card = 0;
  while (const auto line = in.next_nonblank_line()) {
    if (with_id) {
      const CardValues v = in.read(kHistoryElementCards[1], *line);
      d.element_ids.push_back(v.integer("ID"));
      d.headings.push_back(v.text("HEADING"));
      d.ids_where.push_back(in.where(line->line));
      continue;
    }
    const CardValues v = in.read(kHistoryElementCards[0], *line, card++);
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (const int id = static_cast<int>(v.at(i).integer); id != 0) {
        d.element_ids.push_back(id);
        d.ids_where.push_back(in.where(line->line));
      }
    }
  }
  in.model().history_elements.push_back(std::move(d));
}

}  // namespace

void warn_unpaired_element_histories(const model::ModelDesc& model,
                                     std::vector<Diagnostic>& warnings) {
  std::size_t ids = 0;
  for (const model::DatabaseHistoryElementDesc& h : model.history_elements)
    ids += h.element_ids.size();
  if (model.elout && ids == 0) {
    warnings.push_back({model.elout->where, "*DATABASE_ELOUT", "",
                        "nothing to write: no *DATABASE_HISTORY_SHELL or *DATABASE_HISTORY_SOLID "
                        "element, so elout.csv is not written"});
  }
  if (!model.elout) {
    for (const model::DatabaseHistoryElementDesc& h : model.history_elements) {
      if (h.element_ids.empty())
        continue;
      warnings.push_back(
          {h.where, h.shell ? "*DATABASE_HISTORY_SHELL" : "*DATABASE_HISTORY_SOLID", "",
           fmt::format("{} element{} kept, but no elout.csv is written without *DATABASE_ELOUT "
                       "(its DT sets the interval)",
                       h.element_ids.size(), h.element_ids.size() == 1 ? "" : "s")});
    }
  }
}

KeywordSpec database_binary_d3plot_keyword() {
  return {.name = "DATABASE_BINARY_D3PLOT",
          .options = kNoOptions,
          .handler = read_d3plot,
          .cards = kD3plotCards,
          .summary =
              "The interval of full states (results_NNNN.vtu). Given twice, the last "
              "one is used (with a warning)."};
}

KeywordSpec database_binary_d3dump_keyword() {
  return {.name = "DATABASE_BINARY_D3DUMP",
          .options = kNoOptions,
          .handler = read_d3dump,
          .cards = kD3dumpCards,
          .summary =
              "Checkpoints: OUTDIR/d3dump every CYCL cycles and at the end of the run, for "
              "`plyform run DECK -o OUTDIR --restart` (written atomically; a run stopped by "
              "SIGINT or SIGTERM writes one too)."};
}

KeywordSpec database_glstat_keyword() {
  return {.name = "DATABASE_GLSTAT",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_ascii(in, "GLSTAT"); },
          .cards = kAsciiCards,
          .summary = "The interval of glstat.csv (global energies)."};
}

KeywordSpec database_nodout_keyword() {
  return {.name = "DATABASE_NODOUT",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_ascii(in, "NODOUT"); },
          .cards = kAsciiCards,
          .summary =
              "The interval of nodout.csv (the *DATABASE_HISTORY_NODE nodes). LS-DYNA's "
              "further fields (DTHF, BINHF) are not read."};
}

KeywordSpec database_rcforc_keyword() {
  return {.name = "DATABASE_RCFORC",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_ascii(in, "RCFORC"); },
          .cards = kAsciiCards,
          .summary = "The interval of rcforc.csv (the resultant force of each contact)."};
}

KeywordSpec database_bndout_keyword() {
  return {.name = "DATABASE_BNDOUT",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_ascii(in, "BNDOUT"); },
          .cards = kAsciiCards,
          .summary =
              "The interval of bndout.csv (the force each prescribed-motion node receives "
              "from its constraint: the load it takes to impose the motion)."};
}

KeywordSpec database_spcforc_keyword() {
  return {.name = "DATABASE_SPCFORC",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_ascii(in, "SPCFORC"); },
          .cards = kAsciiCards,
          .summary =
              "The interval of spcforc.csv: the reaction force of each node held by "
              "*BOUNDARY_SPC (the force the constraint applies to the node, on its constrained "
              "translations; rotations' moments are not written)."};
}

KeywordSpec database_sleout_keyword() {
  return {.name = "DATABASE_SLEOUT",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_ascii(in, "SLEOUT"); },
          .cards = kAsciiCards,
          .summary =
              "The interval of sleout.csv: each contact interface's energy (the work its "
              "forces took from the model, the contact energy of glstat.csv split by interface) "
              "and the part of it that friction dissipated."};
}

KeywordSpec database_rwforc_keyword() {
  return {.name = "DATABASE_RWFORC",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_ascii(in, "RWFORC"); },
          .cards = kAsciiCards,
          .summary =
              "The interval of rwforc.csv: each *RIGIDWALL_PLANAR's force on the structure "
              "(normal and tangential, and its global components), its cumulative impulse and "
              "work, the nodes it holds, and a moving wall's position and velocity."};
}

KeywordSpec database_matsum_keyword() {
  return {.name = "DATABASE_MATSUM",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_ascii(in, "MATSUM"); },
          .cards = kAsciiCards,
          .summary =
              "The interval of matsum.csv: the energies of each part (internal, kinetic, "
              "hourglass) and, for rigid parts, their momentum; the parts' sums are glstat.csv's "
              "books."};
}

KeywordSpec database_tprint_keyword() {
  return {.name = "DATABASE_TPRINT",
          .options = kNoOptions,
          .handler = read_tprint,
          .cards = kAsciiCards,
          .summary =
              "The interval of tprint.csv (the temperatures of the *DATABASE_HISTORY_NODE "
              "nodes) and heat.csv (the heat ledger; without *DATABASE_TPRINT it follows the "
              "glstat interval) when temperatures are computed (docs/thermal.md). Given twice, "
              "the last one is used (with a warning)."};
}

KeywordSpec database_history_node_keyword() {
  return {.name = "DATABASE_HISTORY_NODE",
          .options = kNoneOrIdOrSet,
          .handler = read_history_node,
          .cards = kHistoryCards,
          .summary =
              "Nodes written to nodout.csv (and tprint.csv): by id, by id with a heading "
              "(_ID), or every node of node sets (_SET)."};
}

KeywordSpec database_elout_keyword() {
  return {.name = "DATABASE_ELOUT",
          .options = kNoOptions,
          .handler = read_elout,
          .cards = kEloutCards,
          .summary =
              "The interval of elout.csv: the stresses (global axes) and effective plastic "
              "strain of the *DATABASE_HISTORY_SHELL and *DATABASE_HISTORY_SOLID elements at "
              "their integration points (docs/outputs.md). Without history elements it is "
              "warned about and nothing is written. Given twice, the last one is used (with a "
              "warning)."};
}

KeywordSpec database_history_shell_keyword() {
  return {.name = "DATABASE_HISTORY_SHELL",
          .options = kNoneOrId,
          .handler = [](KeywordInput& in) { read_history_element(in, true); },
          .cards = kHistoryElementCards,
          .summary =
              "Shell elements written to elout.csv (every through-thickness point): by id, or "
              "by id with a heading (_ID). An id no *ELEMENT_SHELL defines is an error. _SET "
              "is not read (plyform has no shell sets): warned about as an output request."};
}

KeywordSpec database_history_solid_keyword() {
  return {.name = "DATABASE_HISTORY_SOLID",
          .options = kNoneOrId,
          .handler = [](KeywordInput& in) { read_history_element(in, false); },
          .cards = kHistoryElementCards,
          .summary =
              "Solid elements written to elout.csv (one row per element: the point of ELFORM "
              "1, the mean of the eight points of ELFORM 2): by id, or by id with a heading "
              "(_ID). An id no *ELEMENT_SOLID defines is an error. _SET is not read (plyform "
              "has no solid sets): warned about as an output request."};
}

}  // namespace plyform::keyword
