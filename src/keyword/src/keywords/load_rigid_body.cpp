// *LOAD_RIGID_BODY: forces and moments on rigid bodies.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 6> kDofs{1, 2, 3, 5, 6, 7};

constexpr std::array kFields{
    FieldSpec{.name = "PID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "part id of the rigid body (its material is *MAT_RIGID)",
              .required = true},
    FieldSpec{.name = "DOF",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "1, 2, 3: force along global x, y, z; 5, 6, 7: moment about global "
                             "x, y, z",
              .required = true,
              .allowed = kDofs,
              .allowed_note = "follower forces and moments (4, 8) are not supported yet"},
    FieldSpec{.name = "LCID",
              .type = FieldType::kInteger,
              .min_value = 1,
              .unit = "-",
              .description = "curve of the force or moment against time",
              .required = true},
    FieldSpec{.name = "SF",
              .type = FieldType::kReal,
              .default_value = 1.0,
              .unit = "-",
              .description = "scale factor of the curve's ordinate"},
    FieldSpec{.name = "CID",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "coordinate system: must be 0 (not supported yet)"},
    FieldSpec{.name = "M1",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "follower force node (DOF 4, 8 only); kept as written"},
    FieldSpec{.name = "M2",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "follower force node; kept as written"},
    FieldSpec{.name = "M3",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "follower force node; kept as written"},
};
constexpr std::array kCards{
    CardSpec{
        .title = "Card 1", .fields = kFields, .presence = "one per load, until the next keyword"},
};

void read_load_rigid_body(KeywordInput& in) {
  while (const auto line = in.next_nonblank_line()) {
    const CardValues v = in.read(kCards[0], *line);
    model::LoadRigidBodyDesc load;
    load.part_id = v.integer("PID");
    load.dof = v.integer("DOF");
    load.curve_id = v.integer("LCID");
    load.scale = v.real("SF");
    load.cid = v.integer("CID");
    load.m1 = v.integer("M1");
    load.m2 = v.integer("M2");
    load.m3 = v.integer("M3");
    load.where = in.where(line->line);
    require_zero(in, line->line, "CID", load.cid, "a local coordinate system");
    in.model().rigid_body_loads.push_back(load);
  }
}

}  // namespace

KeywordSpec load_rigid_body_keyword() {
  return {.name = "LOAD_RIGID_BODY",
          .options = kNoOptions,
          .handler = read_load_rigid_body,
          .cards = kCards,
          .summary =
              "A force or moment on a rigid body (a part whose material is *MAT_RIGID) along "
              "or about a global axis, at its centre of mass, given by a curve against time."};
}

}  // namespace plyform::keyword
