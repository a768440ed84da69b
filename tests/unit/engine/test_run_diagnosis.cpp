// What a run leaves behind and what it says when it fails:
// - a non-finite velocity is named at its node even when that node is constrained (the
//   constraints overwrote its velocity before the search, which then named another node),
//   and a non-finite angular velocity stops the run too;
// - the thread count a run sets is the caller's again after it (omp_set_num_threads changed
//   it for everything the caller ran later).
#include <gtest/gtest.h>
#include <omp.h>

#include <limits>
#include <string>

#include "recording_sink.hpp"
#include "shell_models.hpp"

namespace plyform {
namespace {

const core::ElasticMaterial kSteel{7.85e-9, 210000.0, 0.3};

// A 2 x 2 plate under a load whose scale is NaN on node `node` along `direction` (0-2 forces,
// 3-5 moments when the model takes them), that node held in x, y and z.
core::Model plate_with_nan_load(core::Index node, int direction) {
  core::Model m = test::plate(10.0, 10.0, 2, 2, 1.0, kSteel, 3);
  m.curves.push_back(core::LoadCurve{{0.0, 1.0}, {1.0, 1.0}});
  m.loads.push_back({node, direction, 0, std::numeric_limits<double>::quiet_NaN()});
  m.fixed.push_back(core::FixedDofs{node, core::dof_x | core::dof_y | core::dof_z});
  m.controls.end_time = 1e-5;
  return m;
}

TEST(RunDiagnosis, NonFiniteVelocityAtAConstrainedNodeNamesThatNode) {
  // Node index 4 (id 5), the plate's centre; a NaN force along z, which the SPC then holds.
  const core::Model m = plate_with_nan_load(4, 2);
  test::RecordingSink sink;
  const engine::RunResult r = engine::run(m, sink, {});
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.error.find("at node 5 "), std::string::npos) << r.error;
}

TEST(RunDiagnosis, TheRunGivesTheCallerItsThreadCountBack) {
  omp_set_num_threads(1);
  core::Model m = test::plate(10.0, 10.0, 2, 2, 1.0, kSteel, 3);
  m.controls.end_time = 1e-6;
  test::RecordingSink sink;
  engine::SolverOptions o;
  o.threads = 2;
  const engine::RunResult r = engine::run(m, sink, o);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(omp_get_max_threads(), 1);
}

}  // namespace
}  // namespace plyform
