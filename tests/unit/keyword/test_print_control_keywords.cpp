// *CONTROL_ACCURACY, *CONTROL_OUTPUT, *CONTROL_RIGID and *CONTROL_BULK_VISCOSITY as LS-PrePost
// writes them: every card read, the values kept, and the fields that would ask plyform for what
// it does not do rejected by name with their line.
#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, expect_error

TEST(ControlAccuracy, ReadsOsuAndInnWithTheirDefaults) {
  const ReadResult r = read_ok(
      "*CONTROL_ACCURACY\n$#     osu       inn    pidosu      iacc\n"
      "         1         4         0         0       0.0\n");
  ASSERT_TRUE(r.model.accuracy.has_value());
  EXPECT_EQ(r.model.accuracy->osu, 1);
  EXPECT_EQ(r.model.accuracy->inn, 4);
  EXPECT_EQ(r.model.accuracy->where.line, 3);
  const ReadResult blank = read_ok("*CONTROL_ACCURACY\n\n");
  EXPECT_EQ(blank.model.accuracy->osu, 0);
  EXPECT_EQ(blank.model.accuracy->inn, 1);
  EXPECT_EQ(read_ok("*CONTROL_ACCURACY\n0,0\n").model.accuracy->inn, 1);  // 0: the default
  expect_error("*CONTROL_ACCURACY\n0,5\n", 2, "*CONTROL_ACCURACY", "INN", "must be one of");
  expect_error("*CONTROL_ACCURACY\n2\n", 2, "*CONTROL_ACCURACY", "OSU", "must be one of");
  expect_error("*CONTROL_ACCURACY\n0,1,0,0,0.5\n", 2, "*CONTROL_ACCURACY", "EXACC", "range");
}

TEST(ControlOutput, ReadsTheFiveCardsLsPrePostWrites) {
  const ReadResult r = read_ok(
      "*CONTROL_OUTPUT\n"
      "         1         3         0         1       0.0         0       100         0\n"
      "         0         0         2        50         0       0.0         0         0\n"
      "         2         0         1         0         0         0      10.0\n"
      "         0         0         0         0         0         0         0         0\n"
      "         0         0         0         0         0\n"
      "*CONTROL_OUTPUT\n1,3\n");
  EXPECT_TRUE(r.ok());
  expect_error("*CONTROL_OUTPUT\n1\n0,1\n", 3, "*CONTROL_OUTPUT", "IERODE", "erode");
  expect_error("*CONTROL_OUTPUT\n\n\n\n\n\n1\n", 7, "*CONTROL_OUTPUT", "", "cards 6");
}

TEST(ControlRigid, MetalFormingUpdateAcceptedSelectiveMassScalingRejected) {
  const ReadResult r = read_ok(
      "*CONTROL_RIGID\n"
      "$#     lmf      jntf    orthmd     partm    sparse    metalf    plotel     rbsms\n"
      "         0         0         0         0         0         1         0         0\n"
      "$#  norbic   gjadstf   gjadvsc    tjastf   tjadvsc   rcvlr2d\n"
      "         0       0.0       0.0       0.0       0.0         0\n");
  EXPECT_TRUE(r.ok());
  expect_error("*CONTROL_RIGID\n0,0,0,0,0,2\n", 2, "*CONTROL_RIGID", "METALF", "must be one of");
  expect_error("*CONTROL_RIGID\n0,0,0,0,0,0,0,1\n", 2, "*CONTROL_RIGID", "RBSMS",
               "selective mass scaling");
}

TEST(ControlBulkViscosity, ReadsTheCoefficientsAndTheShellTypes) {
  const ReadResult r = read_ok(
      "*CONTROL_BULK_VISCOSITY\n$#      q1        q2      type     btype    tstype\n"
      "       2.0      0.10         1         0         0\n");
  ASSERT_TRUE(r.model.bulk_viscosity.has_value());
  EXPECT_DOUBLE_EQ(r.model.bulk_viscosity->q1, 2.0);
  EXPECT_DOUBLE_EQ(r.model.bulk_viscosity->q2, 0.1);
  EXPECT_EQ(r.model.bulk_viscosity->where.line, 3);
  const ReadResult blank = read_ok("*CONTROL_BULK_VISCOSITY\n\n");
  EXPECT_DOUBLE_EQ(blank.model.bulk_viscosity->q1, 1.5);
  EXPECT_DOUBLE_EQ(blank.model.bulk_viscosity->q2, 0.06);
  EXPECT_EQ(blank.model.bulk_viscosity->type, 1);
  EXPECT_EQ(read_ok("*CONTROL_BULK_VISCOSITY\n1.5,0.06,-1\n").model.bulk_viscosity->type, -1);
  EXPECT_EQ(read_ok("*CONTROL_BULK_VISCOSITY\n1.5,0.06,-2\n").model.bulk_viscosity->type, -2);
  expect_error("*CONTROL_BULK_VISCOSITY\n1.5,0.06,2\n", 2, "*CONTROL_BULK_VISCOSITY", "TYPE",
               "Richards-Wilkins");
  expect_error("*CONTROL_BULK_VISCOSITY\n-1.0\n", 2, "*CONTROL_BULK_VISCOSITY", "Q1", "range");
}

}  // namespace
}  // namespace plyform::keyword

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok

// *SET_PART and *SET_NODE: LS-DYNA's short forms of *SET_PART_LIST and *SET_NODE_LIST (with
// _TITLE), as LS-PrePost writes them; the _LIST forms are still themselves.
TEST(SetShortForms, SetPartAndSetNodeReadAsTheirListForms) {
  const ReadResult r = read_ok(
      "*SET_PART\n5\n1,2,3\n*SET_PART_TITLE\nblank parts\n6\n4\n*SET_NODE\n7\n10,11\n"
      "*SET_PART_LIST_TITLE\ntools\n8\n9\n");
  ASSERT_EQ(r.model.part_sets.size(), 3u);
  EXPECT_EQ(r.model.part_sets[0].id, 5);
  EXPECT_EQ(r.model.part_sets[0].ids, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(r.model.part_sets[1].title, "blank parts");
  EXPECT_EQ(r.model.part_sets[2].id, 8);
  ASSERT_EQ(r.model.node_sets.size(), 1u);
  EXPECT_EQ(r.model.node_sets[0].ids, (std::vector<int>{10, 11}));
}

}  // namespace
}  // namespace plyform::keyword

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, expect_error

// *CONTROL_TIMESTEP card 2 as LS-PrePost writes it (at its defaults) is read; the
// mass-scaling refinements it could ask for are rejected by name.
TEST(ControlTimestepCard2, DefaultsReadRefinementsRejectedByName) {
  const ReadResult r = read_ok(
      "*CONTROL_TIMESTEP\n"
      "$#  dtinit    tssfac      isdo    tslimt     dt2ms      lctm     erode     ms1st\n"
      "       0.0       0.1         0 -5.000E-5       0.5         0         0         0\n"
      "$#  dt2msf   dt2mslc     imscl    unused    unused     rmscl    unused      ihdo\n"
      "       0.0         0         0                           0.0                   0\n");
  ASSERT_TRUE(r.model.timestep.has_value());
  EXPECT_DOUBLE_EQ(r.model.timestep->tssfac, 0.1);
  expect_error("*CONTROL_TIMESTEP\n0.0,0.9\n0.5\n", 3, "*CONTROL_TIMESTEP", "DT2MSF", "range");
  expect_error("*CONTROL_TIMESTEP\n0.0,0.9\n0,0,1\n", 3, "*CONTROL_TIMESTEP", "IMSCL",
               "selective mass scaling");
  expect_error("*CONTROL_TIMESTEP\n0.0,0.9\n0,0,0,,,0,,1\n", 3, "*CONTROL_TIMESTEP", "IHDO",
               "IHDO 1");
  expect_error("*CONTROL_TIMESTEP\n0.0,0.9\n\n1\n", 4, "*CONTROL_TIMESTEP", "", "card 3");
}

}  // namespace
}  // namespace plyform::keyword

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, expect_error

TEST(InitialVelocityNode, ReadsEachNodesVelocities) {
  const ReadResult r = read_ok(
      "*INITIAL_VELOCITY_NODE\n"
      "   1000001       0.0       0.0  100.0000       0.0       0.0       0.0\n"
      "         2 0.0000000-7000.0000 0.0000000\n"
      "3,1,2,3,0.1,0.2,0.3\n");
  ASSERT_EQ(r.model.initial_node_velocities.size(), 3u);
  EXPECT_EQ(r.model.initial_node_velocities[0].node_id, 1000001);
  EXPECT_DOUBLE_EQ(r.model.initial_node_velocities[0].vz, 100.0);
  EXPECT_DOUBLE_EQ(r.model.initial_node_velocities[1].vy, -7000.0);
  EXPECT_DOUBLE_EQ(r.model.initial_node_velocities[2].vzr, 0.3);
  EXPECT_EQ(r.model.initial_node_velocities[2].where.line, 4);
  expect_error("*INITIAL_VELOCITY_NODE\n,1.0\n", 2, "*INITIAL_VELOCITY_NODE", "NID", "required");
}

}  // namespace
}  // namespace plyform::keyword

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, expect_error

// *CONTROL_ADAPTIVE and a part's ADPOPT: read, and warned about (the run keeps its mesh); the
// cards after the first pass over whatever layout the LS-DYNA version gave them.
TEST(ControlAdaptive, ReadAndWarnedAboutWithThePartsThatAskForIt) {
  const ReadResult r = read_ok(
      "*CONTROL_ADAPTIVE\n"
      "     0.001       0.2         2         3       0.01.00000E20         0         1\n"
      "       0.0         0         0       0.0       0.0         0         0         0\n"
      "        -1                           0.0         0         0                    \n"
      "       0.0         0         0         00                  0         0         0\n"
      "*PART\nsheet\n1,1,1,0,0,0,1\n");
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[0].keyword, "*CONTROL_ADAPTIVE");
  EXPECT_NE(r.warnings[0].message.find("initial mesh"), std::string::npos);
  EXPECT_EQ(r.warnings[1].keyword, "*PART");
  EXPECT_EQ(r.warnings[1].field, "ADPOPT");
  ASSERT_EQ(r.model.parts.size(), 1u);
  expect_error("*CONTROL_ADAPTIVE\nx\n", 2, "*CONTROL_ADAPTIVE", "ADPFREQ", "expected a real");
}

}  // namespace
}  // namespace plyform::keyword
