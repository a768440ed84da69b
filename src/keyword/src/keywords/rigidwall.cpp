// *RIGIDWALL_PLANAR with the options _FINITE, _MOVING, _FORCES (in LS-DYNA's order) and _ID:
// a planar rigid wall that the slave nodes cannot cross (the constraint method).
#include <array>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kIdFields{
    FieldSpec{.name = "ID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "rigid wall id (the _ID option; rwforc.csv names the wall by it)"},
    FieldSpec{.name = "TITLE",
              .type = FieldType::kText,
              .width = 70,
              .description = "a name for the wall",
              .rest_of_line = true},
};

constexpr std::array kCard1Fields{
    FieldSpec{.name = "NSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "slave node set (*SET_NODE); 0: every node of the model"},
    FieldSpec{.name = "NSIDEX",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "node set left out of the slaves (0: none)"},
    FieldSpec{.name = "BOXID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "box of slave nodes: must be 0 (*DEFINE_BOX is not read)"},
    FieldSpec{.name = "OFFSET",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "length",
              .description = "> 0: only the slave nodes within this normal distance of the wall "
                             "at t = 0 (0: all)"},
    FieldSpec{.name = "BIRTH",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "time",
              .description = "the wall acts from this time"},
    FieldSpec{.name = "DEATH",
              .type = FieldType::kReal,
              .default_value = 1e20,
              .unit = "time",
              .description = "the wall acts until this time (0 or blank: 1e20)"},
    FieldSpec{.name = "RWKSF",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "stiffness scale of LS-DYNA's penalty form; plyform's wall is a "
                             "constraint (a value other than 1 is warned about)"},
};

constexpr std::array kCard2Fields{
    FieldSpec{.name = "XT",
              .type = FieldType::kReal,
              .unit = "length",
              .description = "x of the normal's tail, a point of the wall"},
    FieldSpec{
        .name = "YT", .type = FieldType::kReal, .unit = "length", .description = "y of the tail"},
    FieldSpec{
        .name = "ZT", .type = FieldType::kReal, .unit = "length", .description = "z of the tail"},
    FieldSpec{.name = "XH",
              .type = FieldType::kReal,
              .unit = "length",
              .description = "x of the normal's head: the normal points from the tail to the "
                             "head, to the side where the slave nodes are"},
    FieldSpec{
        .name = "YH", .type = FieldType::kReal, .unit = "length", .description = "y of the head"},
    FieldSpec{
        .name = "ZH", .type = FieldType::kReal, .unit = "length", .description = "z of the head"},
    FieldSpec{.name = "FRIC",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .max_value = 1.0,
              .unit = "-",
              .description = "0: frictionless; 1: no sliding while in contact; between: Coulomb "
                             "coefficient (2 and 3, welding, are not supported)"},
    FieldSpec{.name = "WVEL",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "length/time",
              .description = "welding's critical normal velocity (FRIC 2 and 3 only: must be 0)"},
};

constexpr std::array kFiniteFields{
    FieldSpec{.name = "XHEV",
              .type = FieldType::kReal,
              .unit = "length",
              .description = "x of the head of the edge vector l (its tail is XT, YT, ZT); l is "
                             "the rectangle's first edge, in the wall's plane"},
    FieldSpec{.name = "YHEV", .type = FieldType::kReal, .unit = "length", .description = "y of it"},
    FieldSpec{.name = "ZHEV", .type = FieldType::kReal, .unit = "length", .description = "z of it"},
    FieldSpec{.name = "LENL",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "length",
              .description = "the rectangle's length along l, from the tail",
              .required = true},
    FieldSpec{.name = "LENM",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "length",
              .description = "its length along m = n x l, from the tail",
              .required = true},
};

constexpr std::array kMovingFields{
    FieldSpec{.name = "MASS",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "mass",
              .description = "the wall's mass (> 0); the wall moves along its normal only",
              .required = true},
    FieldSpec{.name = "V0",
              .type = FieldType::kReal,
              .unit = "length/time",
              .description = "its initial velocity along the normal (positive: towards the "
                             "slave nodes)"},
};

constexpr std::array kForcesFields{
    FieldSpec{.name = "SOFT",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "cycles over which the relative velocity is zeroed: must be 0 (the "
                             "wall stops a node in one cycle)"},
    FieldSpec{.name = "SSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "segment set of the force per area output: must be 0 (not written)"},
    FieldSpec{.name = "N1",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "a node of no element that moves with the wall, to show it (0: "
                             "none)"},
    FieldSpec{.name = "N2",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "as N1"},
    FieldSpec{.name = "N3",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "as N1"},
    FieldSpec{.name = "N4",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "as N1"},
};

constexpr std::array kCards{
    CardSpec{.title = "ID card", .fields = kIdFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kCard1Fields},
    CardSpec{.title = "Card 2", .fields = kCard2Fields},
    CardSpec{.title = "Finite card", .fields = kFiniteFields, .presence = "with _FINITE only"},
    CardSpec{.title = "Moving card", .fields = kMovingFields, .presence = "with _MOVING only"},
    CardSpec{.title = "Forces card", .fields = kForcesFields, .presence = "with _FORCES only"},
};

// Every combination of FINITE, MOVING, FORCES in LS-DYNA's order, with or without _ID.
constexpr std::array<std::string_view, 16> kOptions{
    "",
    "ID",
    "FINITE",
    "FINITE_ID",
    "MOVING",
    "MOVING_ID",
    "FORCES",
    "FORCES_ID",
    "FINITE_MOVING",
    "FINITE_MOVING_ID",
    "FINITE_FORCES",
    "FINITE_FORCES_ID",
    "MOVING_FORCES",
    "MOVING_FORCES_ID",
    "FINITE_MOVING_FORCES",
    "FINITE_MOVING_FORCES_ID",
};

bool has_word(std::string_view option, std::string_view word) {
  for (std::size_t start = 0; start <= option.size();) {
    const std::size_t end = std::min(option.find('_', start), option.size());
    if (option.substr(start, end - start) == word)
      return true;
    start = end + 1;
  }
  return false;
}

DataLine next_required(KeywordInput& in, std::string_view what) {
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", fmt::format("missing {}", what));
  return *line;
}

void read_rigidwall_planar(KeywordInput& in) {
  const std::string_view option = in.option();
  model::RigidWallDesc w;
  w.keyword = in.keyword().display();
  w.where = in.keyword_where();
  w.finite = has_word(option, "FINITE");
  w.moving = has_word(option, "MOVING");
  w.forces = has_word(option, "FORCES");
  if (has_word(option, "ID")) {
    const DataLine line = next_required(in, "ID card (ID TITLE)");
    const CardValues v = in.read(kCards[0], line);
    w.id = v.integer("ID");
    w.heading = v.text("TITLE");
  }
  const DataLine line1 = next_required(in, "card 1 (NSID NSIDEX BOXID OFFSET ...)");
  const CardValues c1 = in.read(kCards[1], line1);
  w.card1 = in.where(line1.line);
  w.nsid = c1.integer("NSID");
  w.nsidex = c1.integer("NSIDEX");
  w.boxid = c1.integer("BOXID");
  require_zero(in, line1.line, "BOXID", w.boxid, "a box of slave nodes, *DEFINE_BOX");
  w.offset = c1.real("OFFSET");
  w.birth = c1.real("BIRTH");
  w.death = zero_means(c1.real("DEATH"), 1e20);
  w.rwksf = c1.real("RWKSF");
  if (w.death <= w.birth) {
    in.fail(line1.line, "DEATH",
            fmt::format("DEATH = {} is not after BIRTH = {}", w.death, w.birth));
  }
  if (w.rwksf != 1.0 && w.rwksf != 0.0) {
    in.warn(line1.line, "RWKSF",
            fmt::format("RWKSF = {} scales LS-DYNA's penalty form; plyform's planar wall is a "
                        "constraint (a node that would cross it is stopped on it), which has no "
                        "stiffness to scale",
                        w.rwksf));
  }
  const DataLine line2 = next_required(in, "card 2 (XT YT ZT XH YH ZH FRIC WVEL)");
  const CardValues c2 = in.read(kCards[2], line2);
  w.card2 = in.where(line2.line);
  w.tail = {c2.real("XT"), c2.real("YT"), c2.real("ZT")};
  w.head = {c2.real("XH"), c2.real("YH"), c2.real("ZH")};
  w.fric = c2.real("FRIC");
  w.wvel = c2.real("WVEL");
  if (w.wvel != 0.0) {
    in.warn(line2.line, "WVEL",
            fmt::format("WVEL = {} is welding's critical velocity, which only FRIC 2 and 3 use "
                        "(not supported): passed over",
                        w.wvel));
  }
  if (w.finite) {
    const DataLine line = next_required(in, "the _FINITE card (XHEV YHEV ZHEV LENL LENM)");
    const CardValues v = in.read(kCards[3], line);
    w.edge = {v.real("XHEV"), v.real("YHEV"), v.real("ZHEV")};
    w.length_l = v.real("LENL");
    w.length_m = v.real("LENM");
    if (w.length_l <= 0.0 || w.length_m <= 0.0) {
      in.fail(line.line, w.length_l <= 0.0 ? "LENL" : "LENM",
              fmt::format("a finite wall needs LENL > 0 and LENM > 0 (got {} and {})", w.length_l,
                          w.length_m));
    }
  }
  if (w.moving) {
    const DataLine line = next_required(in, "the _MOVING card (MASS V0)");
    const CardValues v = in.read(kCards[4], line);
    w.mass = v.real("MASS");
    w.v0 = v.real("V0");
    if (w.mass <= 0.0) {
      in.fail(line.line, "MASS",
              fmt::format("MASS = {}: a moving wall needs a positive mass (a wall that nothing "
                          "slows down: give it a mass far above the model's)",
                          w.mass));
    }
  }
  if (w.forces) {
    // The _FORCES card is optional in LS-DYNA's decks that give it blank.
    if (const auto line = in.next_line()) {
      const CardValues v = in.read(kCards[5], *line);
      w.forces_card = in.where(line->line);
      w.soft = v.integer("SOFT");
      w.ssid = v.integer("SSID");
      require_zero(in, line->line, "SOFT", w.soft,
                   "a relative velocity zeroed over several cycles");
      require_zero(in, line->line, "SSID", w.ssid, "the force per area of a segment set");
      w.display = {v.integer("N1"), v.integer("N2"), v.integer("N3"), v.integer("N4")};
    }
  }
  if (has_more_cards(in)) {
    const auto extra = in.next_nonblank_line();
    in.fail(extra->line, "",
            fmt::format("a card more than {} takes (its options, in order: _FINITE, _MOVING, "
                        "_FORCES; _ORTHO is not supported)",
                        w.keyword));
  }
  in.model().rigid_walls.push_back(std::move(w));
}

}  // namespace

KeywordSpec rigidwall_planar_keyword() {
  return {.name = "RIGIDWALL_PLANAR",
          .options = kOptions,
          .handler = read_rigidwall_planar,
          .cards = kCards,
          .summary =
              "A planar rigid wall (LS-DYNA's constraint method): the slave nodes cannot cross "
              "it from the side its normal points to; a node that would is stopped on it, with "
              "Coulomb friction or none or no sliding (FRIC). _FINITE: a rectangle instead of a "
              "plane; _MOVING: a wall of mass MASS moving along its normal at V0, slowed by the "
              "nodes it stops (momentum is exchanged exactly); _FORCES: nodes that move with "
              "the wall. Nodes held by constraints or rigid bodies are not slaves. The wall's "
              "work on the nodes is external work; rwforc.csv (*DATABASE_RWFORC) has its force "
              "and motion (docs/boundary-conditions.md)."};
}

}  // namespace plyform::keyword
