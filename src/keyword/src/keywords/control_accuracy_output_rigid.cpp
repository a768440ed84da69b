// *CONTROL_ACCURACY, *CONTROL_OUTPUT, *CONTROL_RIGID: controls that LS-PrePost writes into
// every deck. Each field is read with LS-DYNA's meaning: where plyform already does what it
// asks (an objective stress update, an exact update of rigid nodes) the value is accepted and
// `plyform check` says so; fields that only shape LS-DYNA's own print files (d3hsp, messag)
// are kept as written; a field that would ask plyform for something it does not do is an
// error naming it.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kZeroOnly{0};
constexpr std::array kZeroOne{0, 1};
constexpr std::array kInn{-4, -2, 0, 1, 2, 3, 4};

// An integer field of LS-DYNA's print control, kept as written.
constexpr FieldSpec kept(std::string_view name, std::string_view what) {
  return FieldSpec{.name = name, .type = FieldType::kInteger, .unit = "-", .description = what};
}
constexpr FieldSpec kept_real(std::string_view name, std::string_view what) {
  return FieldSpec{.name = name, .unit = "-", .description = what};
}

// --- *CONTROL_ACCURACY
constexpr std::array kAccuracyFields{
    FieldSpec{.name = "OSU",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "second-order objective stress update (0 off, 1 on): plyform's "
                             "update is always objective (Hughes-Winget rotation of solids, "
                             "co-rotational shells), so both are met",
              .allowed = kZeroOne},
    FieldSpec{.name = "INN",
              .type = FieldType::kInteger,
              .default_value = 1,
              .unit = "-",
              .description = "invariant node numbering: 1 off, 2 shells, 3 solids, 4 both "
                             "(negative: also for the shells' frame of orthotropic laws); "
                             "`plyform check` says what it means for plyform's elements",
              .allowed = kInn},
    FieldSpec{.name = "PIDOSU",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "part set of OSU (every part is updated objectively)"},
    FieldSpec{.name = "IACC",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "implicit accuracy options (plyform is explicit: no effect)"},
    FieldSpec{.name = "EXACC",
              .min_value = 0.0,
              .max_value = 0.0,
              .unit = "-",
              .description = "explicit accuracy parameter (0 only: plyform has no such mode)"},
};
constexpr std::array kAccuracyCards{
    CardSpec{.title = "Card 1", .fields = kAccuracyFields, .presence = "required"},
};

void read_control_accuracy(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", "missing card 1 (OSU INN PIDOSU IACC EXACC)");
  const CardValues v = in.read(kAccuracyCards[0], *line);
  const int inn = v.integer("INN") == 0 ? 1 : v.integer("INN");
  store_once(in, in.model().accuracy,
             model::ControlAccuracyDesc{.osu = v.integer("OSU"),
                                        .inn = inn,
                                        .pidosu = v.integer("PIDOSU"),
                                        .iacc = v.integer("IACC"),
                                        .exacc = v.real("EXACC"),
                                        .where = in.where(line->line)});
}

// --- *CONTROL_OUTPUT: LS-DYNA's print files; plyform's outputs are its CSV files and states.
constexpr std::array kOutput1{
    kept("NPOPT", "d3hsp print suppression"),
    kept("NEECHO", "d3hsp echo suppression"),
    kept("NREFUP", "beam reference node update"),
    FieldSpec{.name = "IACCOP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "averaged accelerations in nodout (plyform's nodout.csv has "
                             "displacements and velocities only: no effect)"},
    kept_real("OPIFS", "interface file interval"),
    kept("IPNINT", "print of the initial steps"),
    kept("IKEDIT", "problem status interval of d3hsp"),
    kept("IFLUSH", "flush interval of LS-DYNA's files"),
};
constexpr std::array kOutput2{
    kept("IPRTF", "default print flag of rbdout and matsum"),
    FieldSpec{.name = "IERODE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "eroded energies in glstat (plyform erodes no element: 0 only)",
              .allowed = kZeroOnly,
              .allowed_note = "plyform does not erode elements"},
    kept("TET10S8", "ten-node tetrahedron output"),
    kept("MSGMAX", "most warnings of one kind printed"),
    kept("IPCURV", "print of the curves"),
    kept_real("GMDT", "interval of the user output of the general module"),
    kept("IP1DBLT", "output of 1D seatbelt elements"),
    kept("EOCS", "elout coordinate system"),
};
constexpr std::array kOutput3{
    kept("TOLEV", "timing output level"),
    kept("NEWLEG", "new legends of LS-PrePost"),
    kept("FRFREQ", "output frequency of the FRF"),
    kept("MINFO", "penetration info of the contacts"),
    kept("SOLSIG", "extrapolated stresses of solids"),
    kept("MSGFLG", "message file option"),
    kept_real("CDETOL", "tolerance of the contact output"),
};
constexpr std::array kOutput4{
    kept("PHSCHNG", "phase change output"),
    kept("DEMDEN", "DEM density output"),
    kept("ICRFILE", "curve file of ELOUT"),
    kept("SPC2BND", "SPC energy booked as boundary energy"),
    kept("PENOUT", "contact penetration output"),
    kept("SHLSIG", "shell stress output"),
    kept("HISNOUT", "history output of nodes"),
    kept("ENGOUT", "energy output of contacts"),
};
constexpr std::array kOutput5{
    kept("INSF", "shell set file output"),   kept("ISOLSF", "solid set file output"),
    kept("IBSF", "beam set file output"),    kept("ISSF", "segment set file output"),
    kept("MLKBAG", "airbag leakage output"),
};
constexpr std::array kOutputCards{
    CardSpec{.title = "Card 1", .fields = kOutput1, .presence = "optional"},
    CardSpec{.title = "Card 2", .fields = kOutput2, .presence = "optional"},
    CardSpec{.title = "Card 3", .fields = kOutput3, .presence = "optional"},
    CardSpec{.title = "Card 4", .fields = kOutput4, .presence = "optional"},
    CardSpec{.title = "Card 5", .fields = kOutput5, .presence = "optional"},
};

void read_control_output(KeywordInput& in) {
  for (const CardSpec& card : kOutputCards) {
    const auto line = in.next_line();
    if (!line)
      return;
    (void)in.read(card, *line);
  }
  if (const auto more = in.next_nonblank_line()) {
    in.fail(more->line, "",
            "cards 6 and after of *CONTROL_OUTPUT are not read (plyform reads cards 1-5)");
  }
}

// --- *CONTROL_RIGID: joints, modal rigid bodies and the metal-forming update; plyform has no
// joints and no modal bodies, and updates the nodes of every rigid body exactly.
constexpr std::array kRigid1{
    kept("LMF", "joints by Lagrange multipliers (plyform has no joints: no effect)"),
    kept("JNTF", "generalised joint stiffness (no joints: no effect)"),
    kept("ORTHMD", "orthogonalised modes of modal rigid bodies (none in plyform)"),
    kept("PARTM", "global mass of modal rigid bodies (none in plyform)"),
    kept("SPARSE", "sparse matrix of modal rigid bodies (none in plyform)"),
    FieldSpec{.name = "METALF",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "fast update of rigid nodes for metal forming (0 or 1): plyform "
                             "moves every rigid node with its body's exact motion, which 1 "
                             "approximates",
              .allowed = kZeroOne},
    kept("PLOTEL", "plot elements of rigid bodies"),
    FieldSpec{.name = "RBSMS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "rigid bodies in selective mass scaling (plyform has no selective "
                             "mass scaling: 0 only)",
              .allowed = kZeroOnly,
              .allowed_note = "selective mass scaling is not implemented"},
};
constexpr std::array kRigid2{
    kept("NORBIC", "no rigid body inertia change"),
    kept_real("GJADSTF", "joint stiffness (no joints)"),
    kept_real("GJADVSC", "joint damping (no joints)"),
    kept_real("TJASTF", "translational joint stiffness (no joints)"),
    kept_real("TJADVSC", "translational joint damping (no joints)"),
    kept("RCVLR2D", "2D rigid bodies"),
};
constexpr std::array kRigidCards{
    CardSpec{.title = "Card 1", .fields = kRigid1, .presence = "optional"},
    CardSpec{.title = "Card 2", .fields = kRigid2, .presence = "optional"},
};

void read_control_rigid(KeywordInput& in) {
  for (const CardSpec& card : kRigidCards) {
    const auto line = in.next_line();
    if (!line)
      return;
    (void)in.read(card, *line);
  }
  if (const auto more = in.next_nonblank_line()) {
    in.fail(more->line, "",
            "cards 3 and after of *CONTROL_RIGID are not read (plyform reads cards 1-2)");
  }
}

}  // namespace

KeywordSpec control_accuracy_keyword() {
  return {.name = "CONTROL_ACCURACY",
          .options = kNoOptions,
          .handler = read_control_accuracy,
          .cards = kAccuracyCards,
          .summary =
              "Objective stress update and invariant node numbering. plyform's stress update "
              "is always objective; `plyform check` says what OSU and INN mean for the model."};
}

KeywordSpec control_output_keyword() {
  return {.name = "CONTROL_OUTPUT",
          .options = kNoOptions,
          .handler = read_control_output,
          .cards = kOutputCards,
          .summary =
              "Controls of LS-DYNA's print files (d3hsp, messag, nodout accelerations): read "
              "and kept; plyform's outputs are its CSV histories and ParaView states."};
}

KeywordSpec control_rigid_keyword() {
  return {.name = "CONTROL_RIGID",
          .options = kNoOptions,
          .handler = read_control_rigid,
          .cards = kRigidCards,
          .summary =
              "Joints, modal rigid bodies and the metal-forming update of rigid nodes: plyform "
              "has no joints or modal bodies and moves rigid nodes exactly (METALF 0 and 1 "
              "alike)."};
}

}  // namespace plyform::keyword
