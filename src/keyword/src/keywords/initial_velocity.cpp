// *INITIAL_VELOCITY_GENERATION: translational and angular initial velocity of a set;
// *INITIAL_VELOCITY_NODE: node by node.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 3> kStyps{1, 2, 3};
constexpr std::array<int, 1> kPhases{0};

constexpr std::array kCard1Fields{
    FieldSpec{.name = "ID",
              .type = FieldType::kInteger,
              .min_value = 0,
              .unit = "-",
              .description = "part set (STYP 1), part (STYP 2) or node set (STYP 3) id; 0 with "
                             "STYP 1 or 2: every part"},
    FieldSpec{.name = "STYP",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "1 part set, 2 part, 3 node set",
              .required = true,
              .allowed = kStyps},
    FieldSpec{.name = "OMEGA",
              .type = FieldType::kReal,
              .unit = "radian/time",
              .description = "angular velocity about the axis of card 2"},
    FieldSpec{.name = "VX", .type = FieldType::kReal, .unit = "length/time", .description = "x"},
    FieldSpec{.name = "VY", .type = FieldType::kReal, .unit = "length/time", .description = "y"},
    FieldSpec{.name = "VZ", .type = FieldType::kReal, .unit = "length/time", .description = "z"},
    FieldSpec{.name = "IVATN",
              .type = FieldType::kInteger,
              .min_value = 0,
              .max_value = 1,
              .unit = "-",
              .description = "slave nodes of rigid bodies: 0 ignored, 1 included; kept"},
    FieldSpec{.name = "ICID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "local coordinate system: must be 0 (not supported yet)"},
};
constexpr std::array kCard2Fields{
    FieldSpec{
        .name = "XC", .type = FieldType::kReal, .unit = "length", .description = "axis point x"},
    FieldSpec{
        .name = "YC", .type = FieldType::kReal, .unit = "length", .description = "axis point y"},
    FieldSpec{
        .name = "ZC", .type = FieldType::kReal, .unit = "length", .description = "axis point z"},
    FieldSpec{
        .name = "NX", .type = FieldType::kReal, .unit = "-", .description = "axis direction x"},
    FieldSpec{
        .name = "NY", .type = FieldType::kReal, .unit = "-", .description = "axis direction y"},
    FieldSpec{
        .name = "NZ", .type = FieldType::kReal, .unit = "-", .description = "axis direction z"},
    FieldSpec{.name = "PHASE",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "0: at t = 0",
              .allowed = kPhases,
              .allowed_note = "velocities after dynamic relaxation (1) are not supported"},
    FieldSpec{.name = "IRIGID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "rigid body option; kept as written"},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1", .fields = kCard1Fields, .presence = "required"},
    CardSpec{.title = "Card 2",
             .fields = kCard2Fields,
             .presence = "required when OMEGA is not 0, else optional; card 1 and card 2 may "
                         "repeat"},
};

void read_initial_velocity_generation(KeywordInput& in) {
  while (const auto line = in.next_nonblank_line()) {
    const CardValues v = in.read(kCards[0], *line);
    model::InitialVelocityGenerationDesc d;
    d.target_id = v.integer("ID");
    d.styp = v.integer("STYP");
    d.omega = v.real("OMEGA");
    d.vx = v.real("VX");
    d.vy = v.real("VY");
    d.vz = v.real("VZ");
    d.ivatn = v.integer("IVATN");
    d.icid = v.integer("ICID");
    d.where = in.where(line->line);
    require_zero(in, line->line, "ICID", d.icid, "a local coordinate system");
    if (d.styp == 3 && d.target_id == 0) {
      in.fail(line->line, "ID", "STYP 3 needs a node set id");
    }
    if (const auto line2 = in.next_line()) {
      const CardValues c = in.read(kCards[1], *line2);
      d.xc = c.real("XC");
      d.yc = c.real("YC");
      d.zc = c.real("ZC");
      d.nx = c.real("NX");
      d.ny = c.real("NY");
      d.nz = c.real("NZ");
      d.phase = c.integer("PHASE");
      d.irigid = c.integer("IRIGID");
    } else if (d.omega != 0.0) {
      in.fail(in.keyword().line, "",
              "missing card 2 (XC YC ZC NX NY NZ PHASE IRIGID): OMEGA is not 0");
    }
    if (d.omega != 0.0 && d.nx == 0.0 && d.ny == 0.0 && d.nz == 0.0) {
      in.fail(d.where.line, "OMEGA", "OMEGA is not 0 but the axis NX NY NZ is zero");
    }
    in.model().initial_velocities.push_back(std::move(d));
  }
}

// --- *INITIAL_VELOCITY_NODE
constexpr std::array kNodeVelocityFields{
    FieldSpec{.name = "NID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "node id",
              .required = true},
    FieldSpec{.name = "VX", .unit = "length/time", .description = "x velocity"},
    FieldSpec{.name = "VY", .unit = "length/time", .description = "y velocity"},
    FieldSpec{.name = "VZ", .unit = "length/time", .description = "z velocity"},
    FieldSpec{.name = "VXR",
              .unit = "radian/time",
              .description = "angular velocity about x (a node of a shell: its rotation)"},
    FieldSpec{.name = "VYR", .unit = "radian/time", .description = "angular velocity about y"},
    FieldSpec{.name = "VZR", .unit = "radian/time", .description = "angular velocity about z"},
};
constexpr std::array kNodeVelocityCards{
    CardSpec{.title = "Node cards",
             .fields = kNodeVelocityFields,
             .presence = "one node per card, until the next keyword"},
};

void read_initial_velocity_node(KeywordInput& in) {
  while (const auto line = in.next_nonblank_line()) {
    const CardValues v = in.read(kNodeVelocityCards[0], *line);
    in.model().initial_node_velocities.push_back({.node_id = v.integer("NID"),
                                                  .vx = v.real("VX"),
                                                  .vy = v.real("VY"),
                                                  .vz = v.real("VZ"),
                                                  .vxr = v.real("VXR"),
                                                  .vyr = v.real("VYR"),
                                                  .vzr = v.real("VZR"),
                                                  .where = in.where(line->line)});
  }
}

}  // namespace

KeywordSpec initial_velocity_generation_keyword() {
  return {.name = "INITIAL_VELOCITY_GENERATION",
          .options = kNoOptions,
          .handler = read_initial_velocity_generation,
          .cards = kCards,
          .summary =
              "Initial velocity v = (VX, VY, VZ) + OMEGA n x (x - xc) of a part, part "
              "set or node set, at t = 0."};
}

KeywordSpec initial_velocity_node_keyword() {
  return {.name = "INITIAL_VELOCITY_NODE",
          .options = kNoOptions,
          .handler = read_initial_velocity_node,
          .cards = kNodeVelocityCards,
          .summary =
              "The velocity of single nodes at t = 0, translational and (nodes of shells) "
              "angular; it replaces what an *INITIAL_VELOCITY_GENERATION gave the node. An "
              "angular velocity on a node without rotations (solids only) is an error."};
}

}  // namespace plyform::keyword
