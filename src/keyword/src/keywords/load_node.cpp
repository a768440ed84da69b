// *LOAD_NODE_POINT and *LOAD_NODE_SET: concentrated nodal forces.
#include <array>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array<int, 3> kDofs{1, 2, 3};

template <std::size_t N>
constexpr std::array<FieldSpec, 8> load_fields(const char (&target)[N],
                                               std::string_view description) {
  return {FieldSpec{.name = std::string_view(target, N - 1),
                    .type = FieldType::kInteger,
                    .min_value = 1,
                    .unit = "-",
                    .description = description,
                    .required = true},
          FieldSpec{.name = "DOF",
                    .type = FieldType::kInteger,
                    .unit = "-",
                    .description = "1, 2, 3: force along global x, y, z",
                    .required = true,
                    .allowed = kDofs,
                    .allowed_note = "follower forces (4, 8) and moments (5-7) are not "
                                    "supported yet"},
          FieldSpec{.name = "LCID",
                    .type = FieldType::kInteger,
                    .min_value = 1,
                    .unit = "-",
                    .description = "curve of the force against time",
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
                    .description = "follower force node; kept as written"}};
}
constexpr std::array kPointFields = load_fields("NID", "node id");
constexpr std::array kSetFields = load_fields("NSID", "node set id");
constexpr std::array kPointCards{
    CardSpec{.title = "Card 1",
             .fields = kPointFields,
             .presence = "one per load, until the "
                         "next keyword"},
};
constexpr std::array kSetCards{
    CardSpec{.title = "Card 1",
             .fields = kSetFields,
             .presence = "one per load, until the next "
                         "keyword"},
};

void read_load(KeywordInput& in, model::NodeTarget target, const CardSpec& card) {
  const std::string target_name = target == model::NodeTarget::kNode ? "NID" : "NSID";
  while (const auto line = in.next_nonblank_line()) {
    const CardValues v = in.read(card, *line);
    model::LoadNodeDesc load;
    load.target = target;
    load.target_id = v.integer(target_name);
    load.dof = v.integer("DOF");
    load.curve_id = v.integer("LCID");
    load.scale = v.real("SF");
    load.cid = v.integer("CID");
    load.m1 = v.integer("M1");
    load.m2 = v.integer("M2");
    load.m3 = v.integer("M3");
    load.where = in.where(line->line);
    require_zero(in, line->line, "CID", load.cid, "a local coordinate system");
    in.model().nodal_loads.push_back(std::move(load));
  }
}

}  // namespace

KeywordSpec load_node_point_keyword() {
  return {
      .name = "LOAD_NODE_POINT",
      .options = kNoOptions,
      .handler = [](KeywordInput& in) { read_load(in, model::NodeTarget::kNode, kPointCards[0]); },
      .cards = kPointCards,
      .summary = "A force on one node along a global axis, given by a curve against time."};
}

KeywordSpec load_node_set_keyword() {
  return {.name = "LOAD_NODE_SET",
          .options = kNoOptions,
          .handler = [](KeywordInput& in) { read_load(in, model::NodeTarget::kSet, kSetCards[0]); },
          .cards = kSetCards,
          .summary =
              "A force on each node of a node set along a global axis, given by a curve "
              "against time."};
}

}  // namespace plyform::keyword
