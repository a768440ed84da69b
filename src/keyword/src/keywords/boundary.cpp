// *BOUNDARY_SPC_NODE/_SET(_ID) and *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET/_RIGID(_ID).
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr FieldSpec target_field(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = 1,
                   .unit = "-",
                   .description = description,
                   .required = true};
}
constexpr FieldSpec dof_flag(std::string_view name, std::string_view description) {
  return FieldSpec{.name = name,
                   .type = FieldType::kInteger,
                   .min_value = 0,
                   .max_value = 1,
                   .unit = "-",
                   .description = description};
}
constexpr FieldSpec kCid{.name = "CID",
                         .type = FieldType::kInteger,
                         .min_value = 0,
                         .unit = "-",
                         .description =
                             "coordinate system id (*DEFINE_COORDINATE_SYSTEM or _VECTOR) whose "
                             "axes the flags below name; 0: global axes"};

template <std::size_t N>
constexpr std::array<FieldSpec, 8> spc_fields(const char (&target)[N],
                                              std::string_view description) {
  return {target_field(std::string_view(target, N - 1), description),
          kCid,
          dof_flag("DOFX", "1: translation along (local) x fixed"),
          dof_flag("DOFY", "1: translation along (local) y fixed"),
          dof_flag("DOFZ", "1: translation along (local) z fixed"),
          dof_flag("DOFRX", "1: rotation about (local) x fixed"),
          dof_flag("DOFRY", "1: rotation about (local) y fixed"),
          dof_flag("DOFRZ", "1: rotation about (local) z fixed")};
}
constexpr std::array kSpcNodeFields = spc_fields("NID", "node id");
constexpr std::array kSpcSetFields = spc_fields("NSID", "node set id");

constexpr std::string_view kRepeatWithId =
    "one per constraint, until the next keyword; under _ID each is preceded by its ID card";
constexpr std::array kSpcNodeCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kSpcNodeFields, .presence = kRepeatWithId},
};
constexpr std::array kSpcSetCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kSpcSetFields, .presence = kRepeatWithId},
};

constexpr std::array<int, 6> kMotionDofs{1, 2, 3, 9, 10, 11};
constexpr std::array<int, 3> kVads{0, 1, 2};

template <std::size_t N>
constexpr std::array<FieldSpec, 8> motion_fields(const char (&target)[N],
                                                 std::string_view description) {
  return {target_field(std::string_view(target, N - 1), description),
          FieldSpec{.name = "DOF",
                    .type = FieldType::kInteger,
                    .unit = "-",
                    .description = "degree of freedom, LS-DYNA's code: 1, 2, 3 = x, y, z "
                                   "translation; 9, 10, 11 = the node turns about an axis "
                                   "parallel to x, y, z through (OFFSET1, OFFSET2) of card 2: "
                                   "its two translations across the axis are prescribed",
                    .required = true,
                    .allowed = kMotionDofs,
                    .allowed_note = "motion along a vector (4, -4, 8, -8), nodal rotations "
                                    "(5-7), turning with free radial motion (-9, -10, -11) and "
                                    "the other codes are not supported yet"},
          FieldSpec{.name = "VAD",
                    .type = FieldType::kInteger,
                    .unit = "-",
                    .description = "0 velocity, 1 acceleration, 2 displacement (DOF 9-11: "
                                   "angular velocity, angular acceleration, angle in radians)",
                    .allowed = kVads,
                    .allowed_note = "VAD 3 and 4 are not supported"},
          FieldSpec{.name = "LCID",
                    .type = FieldType::kInteger,
                    .min_value = 1,
                    .unit = "-",
                    .description = "curve of the motion against time",
                    .required = true},
          FieldSpec{.name = "SF",
                    .type = FieldType::kReal,
                    .default_value = 1.0,
                    .unit = "-",
                    .description = "scale factor of the curve's ordinate"},
          FieldSpec{.name = "VID",
                    .type = FieldType::kInteger,
                    .unit = "-",
                    .description = "vector id (DOF 4 and 8 only): must be 0"},
          FieldSpec{.name = "DEATH",
                    .type = FieldType::kReal,
                    .default_value = 1.0e28,
                    .unit = "time",
                    .description = "time the motion ends (0 is read as 1e28)"},
          FieldSpec{.name = "BIRTH",
                    .type = FieldType::kReal,
                    .min_value = 0.0,
                    .unit = "time",
                    .description = "time the motion starts"}};
}
constexpr std::array<int, 6> kRigidMotionDofs{1, 2, 3, 5, 6, 7};
constexpr std::array kMotionRigidFields{
    target_field("PID", "part id of the rigid body (its material is *MAT_RIGID)"),
    FieldSpec{.name = "DOF",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "degree of freedom, LS-DYNA's code: 1, 2, 3 = x, y, z translation; "
                             "5, 6, 7 = rotation about x, y, z",
              .required = true,
              .allowed = kRigidMotionDofs,
              .allowed_note = "motion along or about a vector (4, -4, 8, -8), a body turning "
                              "about an offset axis (9-11) and the other codes are not "
                              "supported yet"},
    FieldSpec{.name = "VAD",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0 velocity, 1 acceleration, 2 displacement",
              .allowed = kVads,
              .allowed_note = "VAD 3 (velocity against displacement) and 4 (relative "
                              "displacement) are not supported"},
    FieldSpec{.name = "LCID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "curve of the motion against time",
              .required = true},
    FieldSpec{.name = "SF",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "-",
              .description = "scale factor of the curve's ordinate"},
    FieldSpec{.name = "VID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "vector id (DOF 4, 8) or -coordinate system id: must be 0"},
    FieldSpec{.name = "DEATH",
              .type = FieldType::kReal,
              .default_value = 1.0e28,
              .unit = "time",
              .description = "time the motion ends (0 is read as 1e28)"},
    FieldSpec{.name = "BIRTH",
              .type = FieldType::kReal,
              .min_value = 0.0,
              .unit = "time",
              .description = "time the motion starts"}};
constexpr std::array kMotionRigidCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1",
             .fields = kMotionRigidFields,
             .presence = "one per motion, until the next keyword; under _ID each is preceded "
                         "by its ID card"},
};
constexpr std::array kMotionNodeFields = motion_fields("NID", "node id");
constexpr std::array kMotionSetFields = motion_fields("NSID", "node set id");
constexpr std::string_view kMotionRepeat =
    "one per motion, until the next keyword; under _ID each is preceded by its ID card";
constexpr FieldSpec relative_motion_field(std::string_view name, std::string_view description) {
  return FieldSpec{
      .name = name, .type = FieldType::kInteger, .unit = "-", .description = description};
}
// Card 2 follows card 1 when |DOF| is 9-11 (LS-DYNA also reads it for VAD 4, which is
// rejected on card 1).
constexpr std::array kMotionCard2Fields{
    FieldSpec{.name = "OFFSET1",
              .type = FieldType::kReal,
              .unit = "length",
              .description = "DOF 9, 10, 11: the axis's y, z, x coordinate"},
    FieldSpec{.name = "OFFSET2",
              .type = FieldType::kReal,
              .unit = "length",
              .description = "DOF 9, 10, 11: the axis's z, x, y coordinate"},
    relative_motion_field("MRB",
                          "rigid body that a relative motion (VAD 4) is measured from: must be 0"),
    relative_motion_field("NODE1", "orientation node of a relative motion: must be 0"),
    relative_motion_field("NODE2", "orientation node of a relative motion: must be 0"),
};
constexpr std::array kMotionNodeCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kMotionNodeFields, .presence = kMotionRepeat},
    CardSpec{.title = "Card 2",
             .fields = kMotionCard2Fields,
             .presence = "after card 1 when DOF is 9, 10 or 11, only then"},
};
constexpr std::array kMotionSetCards{
    CardSpec{.title = "ID card", .fields = kIdCardFields, .presence = "with _ID only"},
    CardSpec{.title = "Card 1", .fields = kMotionSetFields, .presence = kMotionRepeat},
    CardSpec{.title = "Card 2",
             .fields = kMotionCard2Fields,
             .presence = "after card 1 when DOF is 9, 10 or 11, only then"},
};

/// True for LS-DYNA's codes of a node turning about an offset axis, which take card 2.
constexpr bool turns_about_offset_axis(int dof) {
  return dof == 9 || dof == 10 || dof == 11;
}

void read_spc(KeywordInput& in, model::NodeTarget target, std::span<const CardSpec> cards) {
  const std::string target_name = target == model::NodeTarget::kNode ? "NID" : "NSID";
  for (IdAndLine item = next_item(in, cards); item.line; item = next_item(in, cards)) {
    const CardValues v = in.read(cards[1], *item.line);
    model::BoundarySpcDesc spc;
    spc.target = target;
    spc.target_id = v.integer(target_name);
    spc.id = item.id;
    spc.heading = std::move(item.heading);
    spc.cid = v.integer("CID");
    constexpr std::array<std::string_view, 6> kDofs{"DOFX",  "DOFY",  "DOFZ",
                                                    "DOFRX", "DOFRY", "DOFRZ"};
    for (std::size_t i = 0; i < kDofs.size(); ++i) {
      spc.fixed[i] = v.integer(kDofs[i]) == 1;
    }
    spc.where = in.where(item.line->line);
    in.model().spcs.push_back(std::move(spc));
  }
}

void read_motion(KeywordInput& in, model::NodeTarget target, std::span<const CardSpec> cards) {
  const std::string target_name = target == model::NodeTarget::kNode ? "NID" : "NSID";
  for (IdAndLine item = next_item(in, cards); item.line; item = next_item(in, cards)) {
    const CardValues v = in.read(cards[1], *item.line);
    model::PrescribedMotionDesc m;
    m.target = target;
    m.target_id = v.integer(target_name);
    m.id = item.id;
    m.heading = std::move(item.heading);
    m.dof = v.integer("DOF");
    m.vad = v.integer("VAD");
    m.curve_id = v.integer("LCID");
    m.scale = v.real("SF");
    m.vid = v.integer("VID");
    m.death = v.real("DEATH") == 0.0 ? 1.0e28 : v.real("DEATH");
    m.birth = v.real("BIRTH");
    m.where = in.where(item.line->line);
    require_zero(in, item.line->line, "VID", m.vid, "a motion along a vector");
    if (m.death <= m.birth) {
      in.fail(item.line->line, "DEATH",
              fmt::format("DEATH = {} is not after BIRTH = {}", m.death, m.birth));
    }
    if (turns_about_offset_axis(m.dof)) {
      const auto line = in.next_line();
      if (!line) {
        in.fail(item.line->line, "OFFSET1",
                fmt::format("missing card 2 (OFFSET1 OFFSET2 MRB NODE1 NODE2): DOF {} turns "
                            "the nodes about an axis through (OFFSET1, OFFSET2)",
                            m.dof));
      }
      const CardValues c2 = in.read(cards[2], *line);
      m.offset1 = c2.real("OFFSET1");
      m.offset2 = c2.real("OFFSET2");
      for (const std::string_view field : {"MRB", "NODE1", "NODE2"}) {
        require_zero(in, line->line, field, c2.integer(field), "a motion relative to a body");
      }
    }
    in.model().prescribed_motions.push_back(std::move(m));
  }
}

void read_motion_rigid(KeywordInput& in) {
  const std::span<const CardSpec> cards = kMotionRigidCards;
  for (IdAndLine item = next_item(in, cards); item.line; item = next_item(in, cards)) {
    const CardValues v = in.read(cards[1], *item.line);
    model::PrescribedMotionRigidDesc m;
    m.part_id = v.integer("PID");
    m.id = item.id;
    m.heading = std::move(item.heading);
    m.dof = v.integer("DOF");
    m.vad = v.integer("VAD");
    m.curve_id = v.integer("LCID");
    m.scale = v.real("SF");
    m.vid = v.integer("VID");
    m.death = v.real("DEATH") == 0.0 ? 1.0e28 : v.real("DEATH");
    m.birth = v.real("BIRTH");
    m.where = in.where(item.line->line);
    require_zero(in, item.line->line, "VID", m.vid, "a vector or local coordinate system");
    if (m.death <= m.birth) {
      in.fail(item.line->line, "DEATH",
              fmt::format("DEATH = {} is not after BIRTH = {}", m.death, m.birth));
    }
    in.model().rigid_motions.push_back(std::move(m));
  }
}

}  // namespace

KeywordSpec boundary_spc_node_keyword() {
  return {
      .name = "BOUNDARY_SPC_NODE",
      .options = kNoneOrId,
      .handler = [](KeywordInput& in) { read_spc(in, model::NodeTarget::kNode, kSpcNodeCards); },
      .cards = kSpcNodeCards,
      .summary =
          "Fixed degrees of freedom of single nodes, in global axes or in the axes of a "
          "coordinate system (CID): a fixed local direction keeps the node's velocity "
          "along it at 0, the others stay free (docs/boundary-conditions.md)."};
}

KeywordSpec boundary_spc_set_keyword() {
  return {.name = "BOUNDARY_SPC_SET",
          .options = kNoneOrId,
          .handler = [](KeywordInput& in) { read_spc(in, model::NodeTarget::kSet, kSpcSetCards); },
          .cards = kSpcSetCards,
          .summary =
              "Fixed degrees of freedom of the nodes of a node set, in global axes or "
              "in the axes of a coordinate system (CID), as *BOUNDARY_SPC_NODE."};
}

KeywordSpec boundary_prescribed_motion_node_keyword() {
  return {.name = "BOUNDARY_PRESCRIBED_MOTION_NODE",
          .options = kNoneOrId,
          .handler =
              [](KeywordInput& in) { read_motion(in, model::NodeTarget::kNode, kMotionNodeCards); },
          .cards = kMotionNodeCards,
          .summary =
              "A velocity, acceleration or displacement of a node along a global axis, or "
              "(DOF 9-11) its turning about an axis parallel to a global axis through a point, "
              "given by a curve against time: the angle (VAD 2), the angular velocity (VAD 0) "
              "or acceleration (VAD 1); the node's two translations across the axis follow the "
              "turn, its translation along the axis and its rotations stay free "
              "(docs/boundary-conditions.md)."};
}

KeywordSpec boundary_prescribed_motion_set_keyword() {
  return {.name = "BOUNDARY_PRESCRIBED_MOTION_SET",
          .options = kNoneOrId,
          .handler =
              [](KeywordInput& in) { read_motion(in, model::NodeTarget::kSet, kMotionSetCards); },
          .cards = kMotionSetCards,
          .summary = "As *BOUNDARY_PRESCRIBED_MOTION_NODE, for every node of a node set."};
}

KeywordSpec boundary_prescribed_motion_rigid_keyword() {
  return {.name = "BOUNDARY_PRESCRIBED_MOTION_RIGID",
          .options = kNoneOrId,
          .handler = read_motion_rigid,
          .cards = kMotionRigidCards,
          .summary =
              "A velocity, acceleration or displacement of a rigid body (a part whose "
              "material is *MAT_RIGID) along or about a global axis through its centre of "
              "mass, given by a curve against time. The second card of DOF 9-11 and VAD 4 is "
              "not read (those codes are errors); _LOCAL is not supported."};
}

}  // namespace plyform::keyword
