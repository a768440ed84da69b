// *CONTACT_ONE_WAY_SURFACE_TO_SURFACE, *CONTACT_SURFACE_TO_SURFACE,
// *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE, *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE and
// *CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE, each with _ID or _TITLE (the ID card first), the
// automatic ones also with _TIEBREAK (its card right after card 3; with _TIEBREAK_THERMAL the
// thermal card follows it). Cards 1-3 and optional card A,
// as LS-DYNA lays them out; cards 2, 3 and A may be left out at the end of the keyword (defaults).
// Fields plyform does not implement must keep their defaults: each other value is an error naming
// the field.

#include <array>
#include <utility>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

// Each with its _MPP form: the MPP cards (LS-DYNA's distributed search) right after the ID card.
constexpr std::array<std::string_view, 12> kContactOptions{
    "",    "ID",     "TITLE",     "THERMAL",     "THERMAL_ID",     "THERMAL_TITLE",
    "MPP", "ID_MPP", "TITLE_MPP", "THERMAL_MPP", "THERMAL_ID_MPP", "THERMAL_TITLE_MPP"};
// The automatic contacts also come as LS-DYNA's built-in tiebreak (the alternative to the
// cohesive law that the seed paper names).
constexpr std::array<std::string_view, 24> kAutomaticOptions{"",
                                                             "ID",
                                                             "TITLE",
                                                             "THERMAL",
                                                             "THERMAL_ID",
                                                             "THERMAL_TITLE",
                                                             "TIEBREAK",
                                                             "TIEBREAK_ID",
                                                             "TIEBREAK_TITLE",
                                                             "TIEBREAK_THERMAL",
                                                             "TIEBREAK_THERMAL_ID",
                                                             "TIEBREAK_THERMAL_TITLE",
                                                             "MPP",
                                                             "ID_MPP",
                                                             "TITLE_MPP",
                                                             "THERMAL_MPP",
                                                             "THERMAL_ID_MPP",
                                                             "THERMAL_TITLE_MPP",
                                                             "TIEBREAK_MPP",
                                                             "TIEBREAK_ID_MPP",
                                                             "TIEBREAK_TITLE_MPP",
                                                             "TIEBREAK_THERMAL_MPP",
                                                             "TIEBREAK_THERMAL_ID_MPP",
                                                             "TIEBREAK_THERMAL_TITLE_MPP"};

constexpr std::array kSlaveTypes{0, 2, 3, 4};
constexpr std::array kMasterTypes{0, 2, 3};
constexpr std::array kPrintFlags{0, 1, 2};
constexpr std::array kSofts{0, 1};
constexpr std::array kSegmentOptions{0, 2};
constexpr std::array kFrcfrqs{0, 1};
constexpr std::array kZeroOrOne{0, 1};
constexpr std::array kIgaps{0, 1, 2};

// A field of optional cards B-D that plyform reads only at LS-DYNA's default (LS-PrePost writes
// these cards with their defaults): anything else is an error naming it.
constexpr FieldSpec default_only(std::string_view name, FieldType type, std::string_view what) {
  return FieldSpec{.name = name, .type = type, .unit = "-", .description = what};
}

constexpr std::array kIdFields{
    FieldSpec{.name = "CID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "contact id (*USER_INTERFACE_FRICTION's NOSID names it); unique "
                             "when not 0"},
    FieldSpec{.name = "HEADING",
              .type = FieldType::kText,
              .width = 70,
              .description = "a name for the contact",
              .rest_of_line = true},
};

constexpr std::array kCard1{
    FieldSpec{.name = "SSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "slave side: a segment set, part set, part or node set id (SSTYP); "
                             "0 (all) is an error"},
    FieldSpec{.name = "MSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "master side: a segment set, part set or part id (MSTYP); 0 (all) "
                             "is an error"},
    FieldSpec{.name = "SSTYP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "what SSID is: 0 segment set, 2 part set, 3 part, 4 node set",
              .allowed = kSlaveTypes,
              .allowed_note = "shell element sets (1), all parts (5), exclusions (6) and the "
                              "other codes are not supported"},
    FieldSpec{.name = "MSTYP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "what MSID is: 0 segment set, 2 part set, 3 part",
              .allowed = kMasterTypes,
              .allowed_note = "shell element sets (1), all parts (5), exclusions (6) and the "
                              "other codes are not supported"},
    FieldSpec{.name = "SBOXID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "box of the slave side: must be 0 (boxes are not supported yet)"},
    FieldSpec{.name = "MBOXID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "box of the master side: must be 0 (boxes are not supported yet)"},
    FieldSpec{.name = "SPR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "slave side in LS-DYNA's interface force file (0-2); plyform "
                             "writes no such file (rcforc.csv has the resultants): a non-zero "
                             "value gets a warning",
              .allowed = kPrintFlags},
    FieldSpec{.name = "MPR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "master side in LS-DYNA's interface force file (0-2); plyform "
                             "writes no such file (rcforc.csv has the resultants): a non-zero "
                             "value gets a warning",
              .allowed = kPrintFlags},
};

constexpr std::array kSingleSurfaceTypes{0, 2, 3, 5};
// Card 1 of *CONTACT_AUTOMATIC_SINGLE_SURFACE: one side, every node of it against every
// segment of it.
constexpr std::array kSingleCard1{
    FieldSpec{.name = "SSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "the surface: a part set or part id (SSTYP); 0: every part of the "
                             "model"},
    FieldSpec{.name = "MSID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 0,
              .unit = "-",
              .description = "not used by a single-surface contact: blank or 0"},
    FieldSpec{.name = "SSTYP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "what SSID is: 2 part set, 3 part; 0 or 5 with SSID = 0: every part",
              .allowed = kSingleSurfaceTypes,
              .allowed_note = "segment and shell element sets (0 with SSID > 0, 1), exclusions "
                              "(6) and the other codes are not supported"},
    FieldSpec{.name = "MSTYP",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 0,
              .unit = "-",
              .description = "not used by a single-surface contact: blank or 0"},
    kCard1[4],
    kCard1[5],
    kCard1[6],
    kCard1[7],
};

constexpr std::array kCard2{
    FieldSpec{.name = "FS",
              .min_value = 0.0,
              .unit = "-",
              .description = "static friction coefficient (the *PART_CONTACT and table forms, "
                             "FS < 0, are not supported)"},
    FieldSpec{
        .name = "FD", .min_value = 0.0, .unit = "-", .description = "dynamic friction coefficient"},
    FieldSpec{.name = "DC",
              .min_value = 0.0,
              .unit = "time/length",
              .description = "exponential decay coefficient from static to dynamic friction"},
    FieldSpec{.name = "VC",
              .min_value = 0.0,
              .unit = "stress",
              .description = "viscous friction limit (0: none)"},
    FieldSpec{.name = "VDC",
              .min_value = 0.0,
              .max_value = 100.0,
              .unit = "-",
              .description = "normal viscous damping, percent of critical"},
    FieldSpec{.name = "PENCHK",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "small penetration check: must be 0 (not supported yet)"},
    FieldSpec{.name = "BT", .min_value = 0.0, .unit = "time", .description = "birth time"},
    FieldSpec{.name = "DT",
              .default_value = 1e20,
              .min_value = 0.0,
              .unit = "time",
              .description = "death time (0 is read as 1e20)"},
};

constexpr std::array kCard3{
    FieldSpec{.name = "SFS",
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "slave penalty scale factor (0 is read as 1)"},
    FieldSpec{.name = "SFM",
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "master penalty scale factor (0 is read as 1)"},
    FieldSpec{.name = "SST",
              .min_value = 0.0,
              .unit = "length",
              .description = "slave contact thickness (0: the shell thickness)"},
    FieldSpec{.name = "MST",
              .min_value = 0.0,
              .unit = "length",
              .description = "master contact thickness (0: the shell thickness)"},
    FieldSpec{.name = "SFST",
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "scale factor of the slave thickness (0 is read as 1)"},
    FieldSpec{.name = "SFMT",
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "scale factor of the master thickness (0 is read as 1)"},
    FieldSpec{.name = "FSF",
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "scale factor of the friction coefficients (0 is read as 1)"},
    FieldSpec{.name = "VSF",
              .default_value = 1.0,
              .min_value = 0.0,
              .unit = "-",
              .description = "scale factor of the viscous friction (0 is read as 1)"},
};

constexpr std::array kCardA{
    FieldSpec{.name = "SOFT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "penalty stiffness: 0 from the material, 1 also from the nodal "
                             "masses and the time step (soft constraint)",
              .allowed = kSofts,
              .allowed_note = "segment-based contact (SOFT = 2) and the other options are not "
                              "supported"},
    FieldSpec{.name = "SOFSCL",
              .default_value = 0.1,
              .min_value = 0.0,
              .unit = "-",
              .description = "scale factor of the SOFT = 1 stiffness (0 is read as 0.1)"},
    FieldSpec{.name = "LCIDAB",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "airbag curve: must be 0 (not supported)"},
    FieldSpec{.name = "MAXPAR",
              .default_value = 1.025,
              .min_value = 0.0,
              .unit = "-",
              .description = "parametric extension of a master segment in the projection (0 is "
                             "read as 1.025)"},
    FieldSpec{.name = "SBOPT",
              .unit = "-",
              .description = "segment-based contact option (SOFT = 2 only): blank, 0 or 2 "
                             "(LS-DYNA's default)",
              .allowed = kSegmentOptions,
              .allowed_note = "SBOPT applies to segment-based contact (SOFT = 2), which plyform "
                              "does not support"},
    FieldSpec{.name = "DEPTH",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "segment-based search depth (SOFT = 2 only): blank, 0 or 2 "
                             "(LS-DYNA's default)",
              .allowed = kSegmentOptions,
              .allowed_note = "DEPTH applies to segment-based contact (SOFT = 2), which plyform "
                              "does not support"},
    FieldSpec{.name = "BSORT",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "cycles between bucket sorts (0: automatic)"},
    FieldSpec{.name = "FRCFRQ",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "cycles between contact force updates: 0 or 1 (every cycle)",
              .allowed = kFrcfrqs,
              .allowed_note = "contact forces are updated every cycle"},
};

constexpr std::array kCardB{
    default_only("PENMAX", FieldType::kReal, "maximum penetration distance: must be 0"),
    default_only("THKOPT", FieldType::kInteger, "thickness option: must be 0"),
    default_only("SHLTHK", FieldType::kInteger,
                 "per-contact SHLTHK (with THKOPT = 1 only): must be 0"),
    FieldSpec{.name = "SNLOG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "shooting-node logic: 0 or 1 (plyform has none to disable)",
              .allowed = kZeroOrOne,
              .allowed_note = "only 0 and 1 exist"},
    default_only("ISYM", FieldType::kInteger, "symmetry plane option: must be 0"),
    default_only("I2D3D", FieldType::kInteger, "2D/3D segment search option: must be 0"),
    default_only("SLDTHK", FieldType::kReal, "solid element contact thickness: must be 0"),
    default_only("SLDSTF", FieldType::kReal, "solid element contact stiffness: must be 0"),
};

constexpr std::array kCardC{
    FieldSpec{.name = "IGAP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "implicit convergence option: 0, 1 or 2, read and without effect "
                             "in an explicit run",
              .allowed = kIgaps,
              .allowed_note = "IGAP takes 0, 1 or 2"},
    FieldSpec{.name = "IGNORE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "initial penetrations: 0 as *CONTROL_CONTACT IGNORE says (pushed "
                             "out by default), 1 tracked (the penalty acts only beyond the depth "
                             "at t = 0), 2 as 1 with each node listed",
              .allowed = kIgaps,
              .allowed_note = "IGNORE takes 0, 1 or 2"},
    default_only("DPRFAC", FieldType::kReal, "penetration reduction factor (SOFT = 2): must be 0"),
    default_only("DTSTIF", FieldType::kReal, "time step of the SOFT = 1 stiffness: must be 0"),
    default_only("EDGEK", FieldType::kReal, "edge stiffness scale (SOFT = 2): must be 0"),
    default_only("UNUSED", FieldType::kReal, "not used by LS-DYNA: blank or 0"),
    default_only("FLANGL", FieldType::kReal, "angle tolerance (SOFT = 2): must be 0"),
    default_only("CID_RCF", FieldType::kInteger,
                 "coordinate system of the rcforc output: must be 0 (global axes)"),
};

constexpr std::array kCardD{
    default_only("Q2TRI", FieldType::kInteger, "quadrilaterals split into triangles: must be 0"),
    default_only("DTPCHK", FieldType::kReal, "time step of the penetration check: must be 0"),
    default_only("SFNBR", FieldType::kReal, "neighbour segment stiffness scale: must be 0"),
    default_only("FNLSCL", FieldType::kReal, "nonlinear penalty scale: must be 0"),
    default_only("DNLSCL", FieldType::kReal, "nonlinear penalty depth: must be 0"),
    default_only("TCSO", FieldType::kInteger, "segment orientation option: must be 0"),
    default_only("TIEDID", FieldType::kInteger, "tied incremental option: must be 0"),
    default_only("SHLEDG", FieldType::kInteger, "shell edge option: must be 0"),
};

constexpr std::array kAlgos{0, 1};
constexpr std::array kThermalCard{
    FieldSpec{.name = "K",
              .min_value = 0.0,
              .unit = "power/(length temperature)",
              .description = "conductivity of the medium in an open gap: h = K / gap (a "
                             "negative K, a curve against temperature, is not supported)"},
    FieldSpec{
        .name = "FRAD",
        .min_value = 0.0,
        .unit = "power/(area temperature^4)",
        .description = "radiation factor across an open gap: h = FRAD (T1^2 + T2^2)(T1 + T2)"},
    FieldSpec{.name = "H0",
              .unit = "power/(area temperature)",
              .description = "conductance of a closed gap (gap <= LMIN, or in contact); < 0: -H0 "
                             "is a curve of the conductance against the contact pressure"},
    FieldSpec{.name = "LMIN",
              .min_value = 0.0,
              .unit = "length",
              .description = "gaps up to LMIN are closed (conductance H0)"},
    FieldSpec{.name = "LMAX",
              .min_value = 0.0,
              .unit = "length",
              .description = "no heat crosses a gap wider than LMAX"},
    FieldSpec{.name = "FTOSA",
              .default_value = 0.5,
              .min_value = 0.0,
              .max_value = 1.0,
              .unit = "-",
              .description = "share of the friction heat to the slave side (0: 0.5)"},
    FieldSpec{.name = "BC_FLG",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "thermal boundary conditions (convection, radiation, flux) of the "
                             "nodes in contact: 0 on, 1 off",
              .allowed = kZeroOrOne},
    FieldSpec{.name = "ALGO",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0 two-way (heat flows to both sides), 1 one-way (the master's "
                             "temperature is not changed by the contact)",
              .allowed = kAlgos,
              .allowed_note = "ALGO takes 0 or 1"},
};

// MPP card 1 (_MPP): the parallel search of LS-DYNA's MPP version. plyform's search is its
// own (bucket sort, docs/contact.md): these tune nothing here and are read; IGNORE is the
// contact's (as on optional card C).
constexpr std::array kZeroToTwoIgnore{0, 1, 2};
constexpr std::array kMppFields{
    FieldSpec{.name = "IGNORE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "initial penetrations, as IGNORE of optional card C (0-2)",
              .allowed = kZeroToTwoIgnore,
              .allowed_note = "IGNORE takes 0, 1 or 2"},
    FieldSpec{.name = "BCKT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "MPP bucket sort interval (read; plyform re-searches when the "
                             "surfaces have moved half a segment)"},
    FieldSpec{.name = "LCBCKT",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "curve of the MPP bucket sort interval (read)"},
    FieldSpec{.name = "NS2TRK",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "MPP segments tracked per node (read; plyform keeps every "
                             "candidate of the search)"},
    FieldSpec{.name = "INITITR",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "MPP initial penetration iterations (read)"},
    FieldSpec{.name = "PARMAX",
              .unit = "-",
              .description = "MPP parametric extension of segments (read; MAXPAR of optional "
                             "card A is plyform's)"},
    FieldSpec{.name = "UNUSED", .type = FieldType::kText, .description = "not used"},
    FieldSpec{.name = "CHKSEGS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "MPP check of degenerate segments (read)"},
    FieldSpec{
        .name = "PENSF", .unit = "-", .description = "MPP penetration scale of IGNORE (read)"},
    FieldSpec{.name = "GRPABLE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "MPP grouping of contacts (read)"},
};
constexpr CardSpec kMppCard{
    .title = "MPP card 1",
    .fields = kMppFields,
    .presence =
        "with _MPP only: right after the ID card; a second MPP card (beginning with "
        "'&') is passed over"};

constexpr std::array kCards{
    CardSpec{.title = "ID card", .fields = kIdFields, .presence = "with _ID or _TITLE only"},
    CardSpec{.title = "Card 1", .fields = kCard1, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kCard2,
             .presence = "optional at the end of the keyword; defaults when left out"},
    CardSpec{.title = "Card 3",
             .fields = kCard3,
             .presence = "optional at the end of the keyword; defaults when left out"},
    CardSpec{.title = "Optional card A", .fields = kCardA, .presence = "optional"},
    CardSpec{.title = "Optional card B",
             .fields = kCardB,
             .presence = "optional; read at LS-DYNA's defaults only"},
    CardSpec{.title = "Optional card C",
             .fields = kCardC,
             .presence = "optional; read at LS-DYNA's defaults only"},
    CardSpec{.title = "Optional card D",
             .fields = kCardD,
             .presence = "optional; read at LS-DYNA's defaults only; cards E and after are not "
                         "supported"},
    CardSpec{.title = "Thermal card",
             .fields = kThermalCard,
             .presence = "with _THERMAL only: required, right after card 3 (cards 2 and 3 "
                         "must then be given), or after the tiebreak card with _TIEBREAK_THERMAL"},
    kMppCard,
};
constexpr std::size_t kThermalCardIndex = 8;

constexpr std::array kTiebreakOptions{1, 2, 3, 4};
constexpr std::array kTiebreakCard{
    FieldSpec{.name = "OPTION",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "1: nodes in contact at t = 0 and nodes that come into contact are "
                             "tied for good (normal and tangential); 2: nodes in contact at t = 0 "
                             "are tied until (sigma_n / NFLS)^2 + (tau / SFLS)^2 >= 1, then "
                             "frictional contact; 3: as 1, with the failure of 2; 4: as 2 with "
                             "frictional sliding while tied and the normal criterion "
                             "sigma_n >= NFLS only. A failed node never ties again",
              .allowed = kTiebreakOptions,
              .allowed_note = "the moment-transferring (-1 to -3), damage (5, 6, 8, 13, 14) and "
                              "discrete-crack (7, 9-11) options are not supported; the cohesive "
                              "law (*USER_INTERFACE_FRICTION) is plyform's damage model"},
    FieldSpec{.name = "NFLS",
              .min_value = 0.0,
              .unit = "stress",
              .description = "normal (tensile) failure stress; required (> 0) by OPTION 2-4"},
    FieldSpec{.name = "SFLS",
              .min_value = 0.0,
              .unit = "stress",
              .description = "shear failure stress, required (> 0) by OPTION 2 and 3; with "
                             "OPTION 4 and PARAM = 1 the frictional stress limit"},
    FieldSpec{.name = "PARAM",
              .unit = "-",
              .description = "OPTION 4: 1 makes SFLS the frictional stress limit (independent "
                             "of the normal stress); other options: must be 0"},
    default_only("ERATEN", FieldType::kReal,
                 "normal energy release rate (OPTION 7, 9-11 only): must be 0"),
    default_only("ERATES", FieldType::kReal,
                 "shear energy release rate (OPTION 7, 9-11 only): must be 0"),
    default_only("CT2CN", FieldType::kReal,
                 "tangential to normal stiffness ratio (OPTION 9, 11 only): must be 0"),
    default_only("CN", FieldType::kReal, "normal stiffness (OPTION 9, 11, 13, 14 only): must be 0"),
};
constexpr CardSpec kTiebreakCardSpec{
    .title = "Tiebreak card",
    .fields = kTiebreakCard,
    .presence =
        "with _TIEBREAK only: required, right after card 3 (cards 2 and 3 must then be "
        "given)"};
constexpr std::array kSingleSurfaceCards{
    kCards[0], CardSpec{.title = "Card 1", .fields = kSingleCard1, .presence = "required"},
    kCards[2], kCards[3],
    kCards[4], kCards[5],
    kCards[6], kCards[7],
    kCards[8], kMppCard,
};
constexpr std::array kAutomaticCards{
    kCards[0], kCards[1], kCards[2], kCards[3],         kCards[4], kCards[5],
    kCards[6], kCards[7], kCards[8], kTiebreakCardSpec, kMppCard,
};

/// The tiebreak card: what each OPTION needs, and PARAM only where it means something.
void read_tiebreak_card(KeywordInput& in, model::ContactDesc& c) {
  const auto line = in.next_line();
  if (!line) {
    in.fail(in.keyword().line, "",
            "_TIEBREAK needs its card (OPTION NFLS SFLS PARAM ...) after cards 2 and 3");
  }
  const CardValues v = in.read(kTiebreakCardSpec, *line);
  c.tiebreak = true;
  c.tiebreak_card = in.where(line->line);
  c.tiebreak_option = static_cast<int>(v.integer("OPTION"));
  c.nfls = v.real("NFLS");
  c.sfls = v.real("SFLS");
  c.param = v.real("PARAM");
  for (const std::string_view f : {"ERATEN", "ERATES", "CT2CN", "CN"})
    require_zero(in, line->line, f, v.real(f), "a field of the discrete-crack options");
  const int o = c.tiebreak_option;
  if (o >= 2 && c.nfls <= 0.0) {
    in.fail(line->line, "NFLS",
            fmt::format("OPTION {} fails a tie at the normal stress NFLS: give NFLS > 0", o));
  }
  if ((o == 2 || o == 3) && c.sfls <= 0.0) {
    in.fail(line->line, "SFLS",
            fmt::format("OPTION {} fails a tie at the shear stress SFLS: give SFLS > 0", o));
  }
  if (o == 4 && c.param != 0.0 && c.param != 1.0) {
    in.fail(line->line, "PARAM",
            fmt::format("PARAM = {}: OPTION 4 takes 0 (Coulomb friction while tied) or 1 (SFLS "
                        "is the frictional stress limit)",
                        c.param));
  }
  if (o == 4 && c.param == 1.0 && c.sfls <= 0.0) {
    in.fail(line->line, "SFLS", "OPTION 4 with PARAM = 1 needs the friction limit SFLS > 0");
  }
  if (o != 4 && c.param != 0.0) {
    in.fail(line->line, "PARAM",
            fmt::format("PARAM = {}: with OPTION {} plyform reads PARAM only at 0 (OPTION 2's "
                        "PARAM = 1, shell offsets ignored, is not supported)",
                        c.param, o));
  }
}

/// Optional cards B-D: every field must keep its default (the table says which values count).
CardValues read_default_card(KeywordInput& in, const CardSpec& card, const DataLine& line) {
  CardValues v = in.read(card, line);
  for (const FieldSpec& f : card.fields) {
    if (!f.allowed.empty())
      continue;  // checked by the table
    const double value = f.type == FieldType::kInteger ? v.integer(f.name) : v.real(f.name);
    require_zero(in, line.line, f.name, value, f.description);
  }
  return v;
}

void read_contact(KeywordInput& in, model::ContactKind kind) {
  const bool single = kind == model::ContactKind::automatic_single_surface;
  model::ContactDesc c;
  c.kind = kind;
  c.keyword = in.keyword().display();
  c.where = in.keyword_where();
  const std::string_view option = in.option();
  // _THERMAL alone or after _TIEBREAK (LS-DYNA's order: the contact type, then THERMAL).
  c.thermal = option.starts_with("THERMAL") || option.starts_with("TIEBREAK_THERMAL");
  const bool tiebreak = option.starts_with("TIEBREAK");
  const std::string_view base =
      option.ends_with("MPP")
          ? option.substr(0, option.size() - std::min<std::size_t>(option.size(), 4))
          : option;
  if (base.ends_with("ID") || base.ends_with("TITLE")) {
    const CardValues id = in.next_card(kCards[0], "ID card (CID HEADING)");
    c.id = id.integer("CID");
    c.heading = id.text("HEADING");
  }
  if (option.ends_with("MPP")) {
    const CardValues mpp = in.next_card(kMppCard, "MPP card 1 (IGNORE BCKT LCBCKT ...)");
    c.ignore = static_cast<int>(mpp.integer("IGNORE"));
    if (const auto rest = in.remaining(); !rest.empty() && rest.front().text.starts_with("&")) {
      const auto line2 = in.next_line();  // MPP card 2: the MPP search's own switches
      in.warn(line2->line, "",
              "MPP card 2 passed over: its fields tune LS-DYNA's distributed search, which "
              "plyform's own search has no use for");
    }
  }
  const auto line1 = in.next_line();
  if (!line1) {
    in.fail(in.keyword().line, "", "missing card 1 (SSID MSID SSTYP MSTYP ...)");
  }
  const CardValues c1 = in.read(single ? kSingleSurfaceCards[1] : kCards[1], *line1);
  c.card1 = in.where(line1->line);
  c.ssid = c1.integer("SSID");
  c.msid = c1.integer("MSID");
  c.sstyp = static_cast<model::ContactSideType>(c1.integer("SSTYP"));
  c.mstyp = static_cast<model::ContactSideType>(c1.integer("MSTYP"));
  c.spr = c1.integer("SPR");
  c.mpr = c1.integer("MPR");
  for (const auto& [field, value] : {std::pair{"SPR", c.spr}, std::pair{"MPR", c.mpr}}) {
    if (value != 0) {
      in.warn(line1->line, field,
              "the interface force file (intfor) is not written; rcforc.csv holds the "
              "contact's resultant force");
    }
  }
  if (single && c.ssid > 0 && c.sstyp == model::ContactSideType::segment_set) {
    in.fail(line1->line, "SSTYP",
            fmt::format("SSTYP 0 with SSID = {}: a segment set as a single surface is not "
                        "supported; name a part (3) or part set (2), or SSID = 0 for every part",
                        c.ssid));
  }
  if (single && c.ssid > 0 && static_cast<int>(c.sstyp) == 5) {
    in.fail(line1->line, "SSID",
            fmt::format("SSTYP 5 is every part: SSID = {} must then be 0", c.ssid));
  }
  require_zero(in, line1->line, "SBOXID", c1.integer("SBOXID"), "a box of the slave side");
  require_zero(in, line1->line, "MBOXID", c1.integer("MBOXID"), "a box of the master side");

  if (const auto line2 = in.next_line()) {
    const CardValues c2 = in.read(kCards[2], *line2);
    c.fs = c2.real("FS");
    c.fd = c2.real("FD");
    c.dc = c2.real("DC");
    c.vc = c2.real("VC");
    c.vdc = c2.real("VDC");
    c.birth = c2.real("BT");
    c.death = zero_means(c2.real("DT"), 1e20);
    require_zero(in, line2->line, "PENCHK", c2.integer("PENCHK"), "the small penetration check");
    if (c.death <= c.birth) {
      in.fail(line2->line, "DT", fmt::format("DT = {} is not after BT = {}", c.death, c.birth));
    }
  }
  if (const auto line3 = in.next_line()) {
    const CardValues c3 = in.read(kCards[3], *line3);
    c.sfs = zero_means(c3.real("SFS"), 1.0);
    c.sfm = zero_means(c3.real("SFM"), 1.0);
    c.sst = c3.real("SST");
    c.mst = c3.real("MST");
    c.sfst = zero_means(c3.real("SFST"), 1.0);
    c.sfmt = zero_means(c3.real("SFMT"), 1.0);
    c.fsf = zero_means(c3.real("FSF"), 1.0);
    c.vsf = zero_means(c3.real("VSF"), 1.0);
  }
  if (tiebreak) {
    read_tiebreak_card(in, c);
  }
  if (c.thermal) {
    const auto line_t = in.next_line();
    if (!line_t) {
      in.fail(in.keyword().line, "",
              "_THERMAL needs its thermal card (K FRAD H0 LMIN LMAX FTOSA BC_FLG ALGO) after "
              "cards 2 and 3");
    }
    const CardValues th = in.read(kCards[kThermalCardIndex], *line_t);
    c.k = th.real("K");
    c.frad = th.real("FRAD");
    c.h0 = th.real("H0");
    c.lmin = th.real("LMIN");
    c.lmax = th.real("LMAX");
    c.ftosa = zero_means(th.real("FTOSA"), 0.5);
    c.bc_flg = th.integer("BC_FLG");
    c.algo = th.integer("ALGO");
    if (c.lmax < c.lmin) {
      in.fail(line_t->line, "LMAX",
              fmt::format("LMAX = {} is below LMIN = {}: no gap could carry heat", c.lmax, c.lmin));
    }
  }
  if (const auto line_a = in.next_line()) {
    const CardValues a = in.read(kCards[4], *line_a);
    c.soft = a.integer("SOFT");
    c.sofscl = zero_means(a.real("SOFSCL"), 0.1);
    c.maxpar = zero_means(a.real("MAXPAR"), 1.025);
    c.bsort = a.integer("BSORT");
    require_zero(in, line_a->line, "LCIDAB", a.integer("LCIDAB"), "an airbag curve");
  }
  for (std::size_t k = 5; k < kThermalCardIndex; ++k) {
    if (const auto line = in.next_line()) {
      const CardValues v = read_default_card(in, kCards[k], *line);
      if (k == 6)
        if (v.integer("IGNORE") != 0)
          c.ignore = static_cast<int>(v.integer("IGNORE"));
    }
  }
  if (has_more_cards(in)) {
    const auto extra = in.next_nonblank_line();
    in.fail(extra->line, "",
            "optional cards E.. (SHAREC CPARM8 ...) are not supported; end the keyword after "
            "optional card D");
  }
  in.model().contacts.push_back(std::move(c));
}

}  // namespace

KeywordSpec contact_one_way_surface_to_surface_keyword() {
  return {.name = "CONTACT_ONE_WAY_SURFACE_TO_SURFACE",
          .options = kContactOptions,
          .handler =
              [](KeywordInput& in) {
                read_contact(in, model::ContactKind::one_way_surface_to_surface);
              },
          .cards = kCards,
          .summary =
              "Penalty contact of the slave nodes against the master segments (one way)."
              " SSID/MSID name the slave and master sides by SSTYP/MSTYP: 0 segment set "
              "(*SET_SEGMENT), 2 part set, 3 part, 4 node set (slave side only); 0 (all) is an "
              "error. Cards 2, 3 and optional cards A-D may be left out at the end (B-D only at "
              "LS-DYNA's defaults); cards E and after, boxes, PENCHK, SOFT = 2 and airbag curves "
              "are errors."};
}

KeywordSpec contact_surface_to_surface_keyword() {
  return {
      .name = "CONTACT_SURFACE_TO_SURFACE",
      .options = kContactOptions,
      .handler = [](KeywordInput& in) { read_contact(in, model::ContactKind::surface_to_surface); },
      .cards = kCards,
      .summary =
          "Penalty contact both ways: slave nodes against master segments and master "
          "nodes against slave segments."
          " SSID/MSID name the slave and master sides by SSTYP/MSTYP: 0 segment set "
          "(*SET_SEGMENT), 2 part set, 3 part, 4 node set (slave side only); 0 (all) is an error. "
          "Cards 2, 3 and optional cards A-D may be left out at the end (B-D only at LS-DYNA's "
          "defaults); cards E and after, boxes, PENCHK, SOFT = 2 and airbag curves are errors."};
}

KeywordSpec contact_forming_one_way_surface_to_surface_keyword() {
  return {.name = "CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE",
          .options = kContactOptions,
          .handler =
              [](KeywordInput& in) {
                read_contact(in, model::ContactKind::forming_one_way_surface_to_surface);
              },
          .cards = kCards,
          .summary =
              "One-way penalty contact of a sheet (slave) against a forming tool "
              "(master)."
              " SSID/MSID name the slave and master sides by SSTYP/MSTYP: 0 segment set "
              "(*SET_SEGMENT), 2 part set, 3 part, 4 node set (slave side only); 0 (all) is an "
              "error. Cards 2, 3 and optional cards A-D may be left out at the end (B-D only at "
              "LS-DYNA's defaults); cards E and after, boxes, PENCHK, SOFT = 2 and airbag curves "
              "are errors."};
}

KeywordSpec contact_automatic_surface_to_surface_keyword() {
  return {.name = "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE",
          .options = kAutomaticOptions,
          .handler =
              [](KeywordInput& in) {
                read_contact(in, model::ContactKind::automatic_surface_to_surface);
              },
          .cards = kAutomaticCards,
          .summary =
              "Penalty contact both ways (LS-DYNA's automatic contact), with the cards "
              "and rules of *CONTACT_SURFACE_TO_SURFACE. SSID/MSID name the slave and "
              "master sides by SSTYP/MSTYP: 0 segment set (*SET_SEGMENT), 2 part set, 3 "
              "part, 4 node set (slave side only); 0 (all) is an error. Cards 2, 3 and "
              "optional cards A-D may be left out at the end (B-D only at LS-DYNA's "
              "defaults); cards E and after, boxes, PENCHK, SOFT = 2 and airbag curves are "
              "errors. _TIEBREAK: LS-DYNA's built-in tiebreak (OPTION 1-4), its card right "
              "after card 3 (docs/contact.md)."};
}

KeywordSpec contact_automatic_single_surface_keyword() {
  return {
      .name = "CONTACT_AUTOMATIC_SINGLE_SURFACE",
      .options = kContactOptions,
      .handler =
          [](KeywordInput& in) { read_contact(in, model::ContactKind::automatic_single_surface); },
      .cards = kSingleSurfaceCards,
      .summary =
          "Self contact of a surface (a sheet folding or wrinkling onto itself, flanges "
          "touching, parts of it meeting others): every node of the surface against every "
          "segment of it except those around the node, shells touched on both faces at half "
          "their thickness, rigid shells included (rigid against rigid is skipped). SSID: a "
          "part (SSTYP 3) or part set (2), or 0 for every part of the model; MSID and MSTYP "
          "are not used. Cards 2, 3 and optional cards A-D as for "
          "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE (docs/contact.md)."};
}

KeywordSpec contact_automatic_one_way_surface_to_surface_keyword() {
  return {.name = "CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE",
          .options = kAutomaticOptions,
          .handler =
              [](KeywordInput& in) {
                read_contact(in, model::ContactKind::automatic_one_way_surface_to_surface);
              },
          .cards = kAutomaticCards,
          .summary =
              "Penalty contact of the slave nodes against the master segments (one way), "
              "shell surfaces offset by half their thickness on both sides (rigid tools "
              "included), as LS-DYNA's automatic contacts; the cards and rules of "
              "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE. With _TIEBREAK it is the one-way "
              "tiebreak that can stand in for a cohesive interface (*USER_INTERFACE_FRICTION "
              "may name it, without _TIEBREAK)."};
}

namespace {

constexpr std::array<std::string_view, 6> kTiedOptions{"",       "ID",        "TITLE",
                                                       "OFFSET", "OFFSET_ID", "OFFSET_TITLE"};

void read_tied(KeywordInput& in, model::ContactKind kind) {
  read_contact(in, kind);
  model::ContactDesc& c = in.model().contacts.back();
  c.offset = in.option().starts_with("OFFSET");
  // A tie is a constraint: friction, damping and penalty scales have nothing to act on.
  const std::pair<const char*, bool> unused[] = {
      {"FS", c.fs != 0.0},   {"FD", c.fd != 0.0},   {"DC", c.dc != 0.0},
      {"VC", c.vc != 0.0},   {"VDC", c.vdc != 0.0}, {"SFS", c.sfs != 1.0},
      {"SFM", c.sfm != 1.0}, {"SOFT", c.soft != 0}, {"IGNORE", c.ignore != 0}};
  for (const auto& [field, given] : unused) {
    if (given) {
      in.warn(c.card1.line, field,
              fmt::format("{} has no use in a tied contact (a constraint: no friction, damping "
                          "or penalty): passed over",
                          field));
    }
  }
}

}  // namespace

KeywordSpec contact_tied_nodes_to_surface_keyword() {
  return {
      .name = "CONTACT_TIED_NODES_TO_SURFACE",
      .options = kTiedOptions,
      .handler = [](KeywordInput& in) { read_tied(in, model::ContactKind::tied_nodes_to_surface); },
      .cards = kCards,
      .summary =
          "Ties slave nodes to the master surface for the whole run: each slave node within "
          "the search distance of a master segment at t = 0 (0.6 times the sum of the two "
          "sides' thicknesses, SST and MST where given; 5 % of the segment's diagonal at "
          "least) follows the point of the segment it projects to, a constraint that moves "
          "its mass and forces onto the segment's nodes (momentum is conserved exactly). Its "
          "translations only: a shell node's rotations stay free. SSID: node set (SSTYP 4), "
          "part (3), part set (2) or segment set (0, its nodes); MSID: segment set, part or "
          "part set. The node keeps its distance to the surface (with or without _OFFSET: "
          "plyform does not move it onto the surface). Slave nodes out of reach stay free "
          "(counted in a warning); friction, penalty and thermal fields are not used "
          "(docs/contact.md, \"Tied contacts\")."};
}

KeywordSpec contact_tied_shell_edge_to_surface_keyword() {
  return {
      .name = "CONTACT_TIED_SHELL_EDGE_TO_SURFACE",
      .options = kTiedOptions,
      .handler =
          [](KeywordInput& in) { read_tied(in, model::ContactKind::tied_shell_edge_to_surface); },
      .cards = kCards,
      .summary =
          "As *CONTACT_TIED_NODES_TO_SURFACE, and the slave shell nodes' rotations are tied "
          "too: each turns with its master segment, and a slave node at a distance from the "
          "surface (_OFFSET, or a shell's offset) moves as a point rigidly linked to it, so "
          "the tie carries moments (a shell edge welded onto a surface). The master segments "
          "must be shells (nodes with rotations)."};
}

}  // namespace plyform::keyword
