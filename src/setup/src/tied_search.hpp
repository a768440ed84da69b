#pragma once
// The search of a tied contact at t = 0: for each slave node, the master segment it ties to
// (the nearest one whose projection holds the node's, within the search distance) and the
// segment's shape functions at that point.

#include <array>
#include <span>
#include <vector>

#include "plyform/core/model.hpp"
#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

struct TieFound {
  long segment = -1;  ///< index of the master segment, -1: none within reach
  std::array<double, 4> weight{};
  double distance = 0.0;  ///< the node's distance to the segment
};

/// `segments`: 4 node indices per master segment (N4 = N3: a triangle), `segment_thickness`
/// its shell thickness (0: a solid face); `slave_thickness` per slave node. A node ties to a
/// segment within 0.6 (t_slave + t_master) of it (SST, MST replace the thicknesses where
/// > 0), and never less than 5 % of the segment's diagonal; a segment that holds the node is
/// not a candidate. Uses the reference coordinates.
[[nodiscard]] std::vector<TieFound> find_ties(const core::Model& model,
                                              std::span<const core::Index> slaves,
                                              std::span<const double> slave_thickness,
                                              std::span<const core::Index> segments,
                                              std::span<const double> segment_thickness, double sst,
                                              double mst);

/// Leaves out of the ties (model.tied, made from the deck's tied contacts in order) the slave
/// nodes a rigid body, a constraint or a prescribed motion moves, those that are a master
/// segment's node in some tie (no chains) and those an earlier tie holds; one warning per
/// interface and kind.
void drop_conflicting_slaves(const model::ModelDesc& desc, core::Model& model,
                             std::vector<keyword::Diagnostic>& warnings);

}  // namespace plyform::setup
