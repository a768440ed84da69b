// *CONTROL_CONTACT: the defaults of every contact (penalty scale, stiffness option, shell
// thickness, bucket sort interval, default friction). Cards 2-4 are optional. A field that
// plyform's contacts (penalty, node to segment, surface to surface, no rigid walls, spot welds,
// single-surface, eroding or tied contacts, user routines) do not use is read and ignored when
// no value of it changes them; any other field must keep LS-DYNA's default, else an error names
// it. Cards 5 and after are errors.

#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kZeroOnly{0};
constexpr std::array kZeroOne{0, 1};
constexpr std::array kZeroToTwo{0, 1, 2};
constexpr std::array kZeroToThree{0, 1, 2, 3};
constexpr std::array kZeroToFour{0, 1, 2, 3, 4};
constexpr std::array kPenopts{0, 1, 2, 3, 4};

constexpr std::array kCard1{
    FieldSpec{.name = "SLSFAC",
              .default_value = 0.1,
              .min_value = 0.0,
              .unit = "-",
              .description = "penalty scale factor of every contact (0 is read as 0.1)"},
    FieldSpec{.name = "RWPNAL",
              .unit = "-",
              .description = "rigid wall penalty; read and ignored (plyform has no rigid walls)"},
    FieldSpec{.name = "ISLCHK",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "LS-DYNA's initial penetration check report (0-2); read and ignored",
              .allowed = kZeroToTwo},
    FieldSpec{.name = "SHLTHK",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "shell thickness in the contacts: 0 not considered, 1 considered "
                             "except for rigid bodies, 2 considered also for rigid bodies",
              .allowed = kZeroToTwo},
    FieldSpec{.name = "PENOPT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "penalty stiffness: 1 (or 0) the smaller of slave and master, 2 the "
                             "master segment's, 3 the slave node's, 4 the slave node's weighted "
                             "by the area of its faces (which is how plyform's slave stiffness is "
                             "made: 4 is 3)",
              .allowed = kPenopts,
              .allowed_note = "the slave stiffness inversely proportional to the shell thickness "
                              "(PENOPT 5, which LS-DYNA itself does not recommend) is not "
                              "supported"},
    FieldSpec{.name = "THKCHG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "1: contact offsets follow the current shell thickness (cohesive "
                             "interfaces always do), 0: the initial thickness",
              .allowed = kZeroOne},
    FieldSpec{.name = "ORIEN",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "LS-DYNA's automatic reorientation of segments at the start (0-4); "
                             "read and not needed: plyform tracks the side of each slave node "
                             "(docs/contact.md), whatever the segment order",
              .allowed = kZeroToFour},
    FieldSpec{.name = "ENMASS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "eroded nodes in contact (0-2); read and ignored (no erosion)",
              .allowed = kZeroToTwo},
};

constexpr std::array kCard2{
    FieldSpec{.name = "USRSTR",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "storage of a user interface control routine; read and ignored"},
    FieldSpec{.name = "USRFRC",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "storage of a user friction routine; read and ignored (plyform "
                             "sizes the history of *USER_INTERFACE_FRICTION itself)"},
    FieldSpec{.name = "NSBCS",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "cycles between bucket sorts (0: automatic)"},
    FieldSpec{.name = "INTERM",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "intermittent searching: must be 0",
              .allowed = kZeroOnly,
              .allowed_note = "intermittent contact searching is not supported"},
    FieldSpec{.name = "XPENE",
              .default_value = 4.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "penetration check multiplier of PENCHK; read and ignored (PENCHK "
                             "must be 0)"},
    FieldSpec{.name = "SSTHK",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "shell thickness in single-surface contacts (0, 1); read and "
                             "ignored",
              .allowed = kZeroOne},
    FieldSpec{.name = "ECDT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "time step of eroding contacts (0, 1); read and ignored",
              .allowed = kZeroOne},
    FieldSpec{.name = "TIEDPRJ",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "projection in tied contacts (0, 1); read and ignored",
              .allowed = kZeroOne},
};

constexpr std::array kCard3{
    FieldSpec{.name = "SFRIC",
              .min_value = 0.0,
              .unit = "-",
              .description = "default static friction coefficient"},
    FieldSpec{.name = "DFRIC",
              .min_value = 0.0,
              .unit = "-",
              .description = "default dynamic friction coefficient"},
    FieldSpec{.name = "EDC",
              .min_value = 0.0,
              .unit = "time/length",
              .description = "default exponential decay coefficient"},
    FieldSpec{.name = "VFC",
              .min_value = 0.0,
              .unit = "stress",
              .description = "default viscous friction limit"},
    FieldSpec{.name = "TH",
              .unit = "length",
              .description = "default contact thickness of *PART_CONTACT: must be 0 (not "
                             "supported)"},
    FieldSpec{.name = "TH_SF",
              .unit = "-",
              .description = "default thickness scale factor of *PART_CONTACT: must be 0 (not "
                             "supported)"},
    FieldSpec{.name = "PEN_SF",
              .unit = "-",
              .description = "default penalty scale factor of *PART_CONTACT: must be 0 (not "
                             "supported)"},
    FieldSpec{.name = "PTSCL",
              .default_value = 1.0,
              .unit = "-",
              .description = "contact stress scale on thick shell formulations: blank, 0 or 1"},
};

constexpr std::array kCard4{
    FieldSpec{.name = "IGNORE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "initial penetrations of every contact (unless its own IGNORE, "
                             "optional card C, says otherwise): 0 pushed out by the penalty, 1 "
                             "tracked (the penalty acts only beyond the depth at t = 0, which "
                             "shrinks as the node comes out), 2 as 1 and each node listed with "
                             "its position and the position that would clear it",
              .allowed = kZeroToTwo,
              .allowed_note = "IGNORE takes 0, 1 or 2"},
    FieldSpec{.name = "FRCENG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "frictional energy (0, 1): plyform always books it (glstat.csv, "
                             "interface_energy.csv); with computed temperatures (SOLN 2), 1 "
                             "also turns the friction of the _THERMAL contacts into heat",
              .allowed = kZeroOne},
    FieldSpec{.name = "SKIPRWG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "display of rigid walls (0, 1); read and ignored",
              .allowed = kZeroOne},
    FieldSpec{.name = "OUTSEG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "spot weld output (0, 1); read and ignored",
              .allowed = kZeroOne},
    FieldSpec{.name = "SPOTSTP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "spot weld search failure (0-3); read and ignored (no spot welds)",
              .allowed = kZeroToThree},
    FieldSpec{.name = "SPOTDEL",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "spot weld deletion; read and ignored (no spot welds)"},
    FieldSpec{.name = "SPOTHIN",
              .min_value = 0.0,
              .unit = "-",
              .description = "thickness scale near spot welds; read and ignored (no spot welds)"},
    FieldSpec{.name = "DIR_TIE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "directional tie of tied contacts; read and ignored"},
};

// Cards 5 and 6 (LS-PrePost writes them at their defaults): what concerns rigid walls, spot
// welds, erosion, tied contacts and isogeometric elements, none of which plyform has, is kept;
// what would change plyform's contacts is accepted at its default only.
constexpr FieldSpec kept_int(std::string_view name, std::string_view what) {
  return FieldSpec{.name = name, .type = FieldType::kInteger, .unit = "-", .description = what};
}
constexpr FieldSpec zero_only(std::string_view name, std::string_view what, std::string_view note) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .unit = "-",
                   .description = what,
                   .allowed = kZeroOnly,
                   .allowed_note = note};
}
constexpr std::array kCard5{
    zero_only("ISYM", "symmetry planes of automatic contacts (0 only)",
              "the symmetry-plane treatment of automatic contacts is not implemented"),
    kept_int("NSEROD", "eroding single-surface contact (no erosion in plyform); kept"),
    kept_int("RWGAPS", "rigid wall gap stiffness (no rigid walls); kept"),
    FieldSpec{.name = "RWGDTH", .unit = "length", .description = "rigid wall gap (kept)"},
    FieldSpec{.name = "RWKSF",
              .default_value = 1.0,
              .unit = "-",
              .description = "rigid wall stiffness scale (kept)"},
    zero_only("ICOV", "covariant formulation of forming contacts (0 only)",
              "the covariant formulation (ICOV 1) is not implemented"),
    FieldSpec{.name = "SWRADF", .unit = "-", .description = "spot weld radius scale (kept)"},
    zero_only("ITHOFF", "thickness offsets of thermal contacts (0 only)",
              "thermal contacts take the surfaces' offsets as plyform's contacts do"),
};
constexpr std::array kCard6{
    zero_only("SHLEDG", "shape of shell edges in contact (0 only)",
              "the edge shapes of SHLEDG 1 and 2 are not implemented"),
    zero_only("PSTIFF", "penalty from volumes and areas (0 only)",
              "the penalty from masses and the step (PSTIFF 1) is not implemented"),
    zero_only("ITHCNT", "thermal contact heat transfer method (0 only)",
              "plyform has the conductance of the _THERMAL cards (ITHCNT 0)"),
    kept_int("TDCNOF", "tied contact offsets (no tied contacts); kept"),
    kept_int("FTALL", "force transducers' output; kept"),
    FieldSpec{.name = "UNUSED", .type = FieldType::kText, .description = "unused"},
    FieldSpec{
        .name = "SHLTRW", .unit = "-", .description = "shell thickness at rigid walls (kept)"},
    kept_int("IGACTC", "isogeometric contact (none in plyform); kept"),
};

constexpr std::array kCards{
    CardSpec{.title = "Card 1", .fields = kCard1, .presence = "required"},
    CardSpec{.title = "Card 2", .fields = kCard2, .presence = "optional"},
    CardSpec{.title = "Card 3", .fields = kCard3, .presence = "optional"},
    CardSpec{.title = "Card 4", .fields = kCard4, .presence = "optional"},
    CardSpec{.title = "Card 5", .fields = kCard5, .presence = "optional"},
    CardSpec{.title = "Card 6",
             .fields = kCard6,
             .presence = "optional; cards 7 and after are not read"},
};

void read_control_contact(KeywordInput& in) {
  model::ControlContactDesc desc;
  const auto line1 = in.next_line();
  if (!line1) {
    in.fail(in.keyword().line, "", "missing card 1 (SLSFAC RWPNAL ISLCHK SHLTHK PENOPT ...)");
  }
  const CardValues c1 = in.read(kCards[0], *line1);
  desc.where = in.where(line1->line);
  desc.slsfac = c1.real("SLSFAC") == 0.0 ? 0.1 : c1.real("SLSFAC");
  desc.shlthk = c1.integer("SHLTHK");
  // PENOPT 4 (the slave node's stiffness weighted by area) is PENOPT 3 in plyform: a slave
  // node's stiffness is already the area-weighted share of its faces' (docs/contact.md).
  // A blank (0) stays 0: the contacts then take their own default (build_contact).
  desc.penopt = c1.integer("PENOPT") == 4 ? 3 : static_cast<int>(c1.integer("PENOPT"));
  desc.thkchg = c1.integer("THKCHG");
  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kCards[1], *line2);
    desc.nsbcs = c2.integer("NSBCS");
  }
  if (const auto line3 = in.next_line()) {
    const CardValues c3 = in.read(kCards[2], *line3);
    desc.sfric = c3.real("SFRIC");
    desc.dfric = c3.real("DFRIC");
    desc.edc = c3.real("EDC");
    desc.vfc = c3.real("VFC");
    for (std::string_view name : {"TH", "TH_SF", "PEN_SF"}) {
      require_zero(in, line3->line, name, c3.real(name), "a default of *PART_CONTACT");
    }
    if (const double ptscl = c3.real("PTSCL"); ptscl != 0.0 && ptscl != 1.0) {
      in.fail(line3->line, "PTSCL",
              fmt::format("PTSCL = {} (a contact stress scale on thick shells) is not supported; "
                          "leave it blank, 0 or 1",
                          ptscl));
    }
  }
  if (const auto line4 = in.next_line()) {
    const CardValues c4 = in.read(kCards[3], *line4);
    desc.frceng = c4.integer("FRCENG");
    desc.ignore = c4.integer("IGNORE");
  }
  for (std::size_t card = 4; card < 6; ++card) {
    if (const auto line = in.next_line())
      (void)in.read(kCards[card], *line);
  }
  if (has_more_cards(in)) {
    const auto extra = in.next_nonblank_line();
    in.fail(extra->line, "",
            "cards 7 and after of *CONTROL_CONTACT are not read; end the keyword after card 6");
  }
  if (in.model().control_contact) {
    in.warn(in.keyword().line, "",
            fmt::format("*CONTROL_CONTACT given again: this one replaces the one at {}:{}",
                        in.model().control_contact->where.file,
                        in.model().control_contact->where.line));
  }
  in.model().control_contact = desc;
}

}  // namespace

KeywordSpec control_contact_keyword() {
  return {.name = "CONTROL_CONTACT",
          .options = kNoOptions,
          .handler = read_control_contact,
          .cards = kCards,
          .summary =
              "Defaults of every contact: SLSFAC, PENOPT (1-3), SHLTHK, NSBCS and the default "
              "friction of card 3. Fields about rigid walls, spot welds, erosion, tied or "
              "single-surface contacts and user routines are read and ignored; INTERM, "
              "TH, TH_SF and PEN_SF must keep their defaults; cards 5 and 6 are read "
              "(ISYM, ICOV, ITHOFF, SHLEDG, PSTIFF and ITHCNT at their defaults). Given twice, the "
              "last one is used (with a warning)."};
}

}  // namespace plyform::keyword
