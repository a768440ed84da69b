// The solver-core keywords: fixed and free format, defaults, _TITLE and _ID options.
#include <string>

#include <gtest/gtest.h>

#include "deck_text_checks.hpp"
#include "plyform/keyword/read_deck.hpp"

namespace plyform::keyword {
namespace {

using namespace test;  // read_ok, single_error, expect_error, ...

TEST(SolverKeywords, NodeFixedWidthsAndFreeFormat) {
  const ReadResult r = read_ok(
      "*NODE\n"
      "$#   nid               x               y               z      tc      rc\n"
      "     101             1.5            -2.0         3.0e-01       7       0\n"
      "12345678  123456789.0125             0.0             0.0\n"
      "7,0.5,,2.5\n");
  const auto& n = r.model.nodes;
  ASSERT_EQ(n.size(), 3u);
  EXPECT_EQ(n[0].id, 101);
  EXPECT_DOUBLE_EQ(n[0].x, 1.5);
  EXPECT_DOUBLE_EQ(n[0].y, -2.0);
  EXPECT_DOUBLE_EQ(n[0].z, 0.3);
  EXPECT_EQ(n[0].tc, 7);
  EXPECT_EQ(n[0].where.line, 3);
  EXPECT_EQ(n[1].id, 12345678);  // 8-character NID field, 16-character X
  EXPECT_DOUBLE_EQ(n[1].x, 123456789.0125);
  EXPECT_EQ(n[2].id, 7);
  EXPECT_DOUBLE_EQ(n[2].y, 0.0);
  EXPECT_DOUBLE_EQ(n[2].z, 2.5);
  EXPECT_EQ(n[2].tc, 0);
}

TEST(SolverKeywords, ElementSolidOneAndTwoCardForms) {
  const ReadResult r = read_ok(
      "*ELEMENT_SOLID\n"
      "$#   eid     pid      n1      n2      n3      n4      n5      n6      n7      n8\n"
      "       1       2      11      12      13      14      15      16      17      18\n"
      "2,2,1,2,3,4,5,5,6,6\n"
      "       3       2\n"
      "      21      22      23      24      24      24      24      24\n");
  const auto& e = r.model.solids;
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].id, 1);
  EXPECT_EQ(e[0].part_id, 2);
  EXPECT_EQ(e[0].nodes[7], 18);
  EXPECT_EQ(e[0].where.line, 3);
  EXPECT_EQ(e[1].nodes[5], 5);
  EXPECT_EQ(e[2].id, 3);
  EXPECT_EQ(e[2].nodes[0], 21);
  EXPECT_EQ(e[2].nodes[7], 24);
  EXPECT_EQ(e[2].where.line, 6);
}

TEST(SolverKeywords, PartSectionMaterials) {
  const ReadResult r = read_ok(
      "*PART\n"
      "Rubber block\n"
      "$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid\n"
      "         1         1         5         0         3\n"
      "*PART\n"
      "\n"
      "2,2,6\n"
      "*SECTION_SOLID\n"
      "         1\n"
      "*SECTION_SOLID_TITLE\n"
      "full\n"
      "         2         2\n"
      "*MAT_ELASTIC_TITLE\n"
      "steel\n"
      "         6    7.8e-9  210000.0       0.3\n"
      "*MAT_001\n"
      "7,1e-9,100.0\n"
      "*MAT_MOONEY-RIVLIN_RUBBER\n"
      "         5    1.1e-9     0.499       0.4       0.1\n"
      "\n"
      "*MAT_027_TITLE\n"
      "soft\n"
      "8,1e-9,0.49,0.2\n"
      "*HOURGLASS_TITLE\n"
      "viscous\n"
      "         3         1      0.05\n"
      "*HOURGLASS\n"
      "4,6,,,,,0.2\n");
  const model::ModelDesc& m = r.model;
  ASSERT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(m.parts[0].title, "Rubber block");
  EXPECT_EQ(m.parts[0].id, 1);
  EXPECT_EQ(m.parts[0].material_id, 5);
  EXPECT_EQ(m.parts[0].hourglass_id, 3);
  EXPECT_EQ(m.parts[0].where.line, 4);
  EXPECT_EQ(m.parts[1].title, "");
  EXPECT_EQ(m.parts[1].section_id, 2);
  ASSERT_EQ(m.solid_sections.size(), 2u);
  EXPECT_EQ(m.solid_sections[0].elform, 1);  // blank: 1
  EXPECT_EQ(m.solid_sections[1].elform, 2);
  EXPECT_EQ(m.solid_sections[1].title, "full");
  ASSERT_EQ(m.elastic_materials.size(), 2u);
  EXPECT_EQ(m.elastic_materials[0].title, "steel");
  EXPECT_DOUBLE_EQ(m.elastic_materials[0].youngs_modulus, 210000.0);
  EXPECT_DOUBLE_EQ(m.elastic_materials[0].poisson_ratio, 0.3);
  EXPECT_EQ(m.elastic_materials[1].id, 7);
  EXPECT_DOUBLE_EQ(m.elastic_materials[1].poisson_ratio, 0.0);
  ASSERT_EQ(m.mooney_rivlin_materials.size(), 2u);
  EXPECT_DOUBLE_EQ(m.mooney_rivlin_materials[0].a, 0.4);
  EXPECT_DOUBLE_EQ(m.mooney_rivlin_materials[0].b, 0.1);
  EXPECT_EQ(m.mooney_rivlin_materials[1].title, "soft");
  EXPECT_DOUBLE_EQ(m.mooney_rivlin_materials[1].b, 0.0);
  ASSERT_EQ(m.hourglasses.size(), 2u);
  EXPECT_EQ(m.hourglasses[0].title, "viscous");
  EXPECT_DOUBLE_EQ(m.hourglasses[0].qm, 0.05);
  EXPECT_DOUBLE_EQ(m.hourglasses[0].q1, 1.5);
  EXPECT_DOUBLE_EQ(m.hourglasses[0].q2, 0.06);
  EXPECT_DOUBLE_EQ(m.hourglasses[0].qb, 0.05);  // blank QB, QW: QM
  EXPECT_DOUBLE_EQ(m.hourglasses[0].qw, 0.05);
  EXPECT_EQ(m.hourglasses[1].ihq, 6);
  EXPECT_DOUBLE_EQ(m.hourglasses[1].qm, 0.1);
  EXPECT_DOUBLE_EQ(m.hourglasses[1].qb, 0.2);
}

TEST(SolverKeywords, SetsAndBoundaryConditions) {
  const ReadResult r = read_ok(
      "*SET_NODE_LIST_TITLE\n"
      "bottom\n"
      "$#     sid       da1       da2       da3       da4    solver\n"
      "         1       0.0       0.0       0.0       0.0MECH\n"
      "         1         2         3         4         5         6         7         8\n"
      "         9\n"
      "*SET_PART_LIST\n"
      "2\n"
      "1,2\n"
      "*BOUNDARY_SPC_NODE\n"
      "         4         0         1         1         1         0         0         0\n"
      "5,0,0,0,1\n"
      "*BOUNDARY_SPC_SET_ID\n"
      "$#      id                                                               heading\n"
      "        10fixed bottom\n"
      "         1         0         1         1         1         1         1         1\n"
      "*BOUNDARY_PRESCRIBED_MOTION_SET_ID\n"
      "         0                                                      LOAD_APPLICATION\n"
      "         1         3         2         1      -1.0         01.00000E28       0.0\n"
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n"
      "9,1,0,1\n"
      "*LOAD_NODE_POINT\n"
      "         8         3         1      -2.5\n"
      "*LOAD_NODE_SET\n"
      "1,1,1\n"
      "*INITIAL_VELOCITY_GENERATION\n"
      "$      sid      styp     omega        vx        vy        vz\n"
      "         2         1           1.246E-01 0.000E+00-3.339E-02\n"
      "*INITIAL_VELOCITY_GENERATION\n"
      "1,3,10.0\n"
      "0,0,0,0,0,1\n");
  const model::ModelDesc& m = r.model;
  ASSERT_EQ(m.node_sets.size(), 1u);
  EXPECT_EQ(m.node_sets[0].title, "bottom");
  EXPECT_EQ(m.node_sets[0].solver, "MECH");
  ASSERT_EQ(m.node_sets[0].ids.size(), 9u);
  EXPECT_EQ(m.node_sets[0].ids[8], 9);
  EXPECT_EQ(m.node_sets[0].ids_where[8].line, 6);
  ASSERT_EQ(m.part_sets.size(), 1u);
  EXPECT_EQ(m.part_sets[0].solver, "MECH");  // blank
  EXPECT_EQ(m.part_sets[0].ids.size(), 2u);

  ASSERT_EQ(m.spcs.size(), 3u);
  EXPECT_EQ(m.spcs[0].target, model::NodeTarget::kNode);
  EXPECT_EQ(m.spcs[0].target_id, 4);
  EXPECT_TRUE(m.spcs[0].fixed[2]);
  EXPECT_FALSE(m.spcs[0].fixed[3]);
  EXPECT_TRUE(m.spcs[1].fixed[2]);
  EXPECT_FALSE(m.spcs[1].fixed[0]);
  EXPECT_EQ(m.spcs[2].target, model::NodeTarget::kSet);
  EXPECT_EQ(m.spcs[2].id, 10);
  EXPECT_EQ(m.spcs[2].heading, "fixed bottom");
  EXPECT_EQ(m.spcs[2].where.line, 16);

  ASSERT_EQ(m.prescribed_motions.size(), 2u);
  const model::PrescribedMotionDesc& pm = m.prescribed_motions[0];
  EXPECT_EQ(pm.heading, "LOAD_APPLICATION");
  EXPECT_EQ(pm.dof, 3);
  EXPECT_EQ(pm.vad, 2);
  EXPECT_EQ(pm.curve_id, 1);
  EXPECT_DOUBLE_EQ(pm.scale, -1.0);
  EXPECT_DOUBLE_EQ(pm.death, 1e28);
  const model::PrescribedMotionDesc& pn = m.prescribed_motions[1];
  EXPECT_EQ(pn.target, model::NodeTarget::kNode);
  EXPECT_DOUBLE_EQ(pn.scale, 1.0);  // defaults
  EXPECT_DOUBLE_EQ(pn.death, 1e28);

  ASSERT_EQ(m.nodal_loads.size(), 2u);
  EXPECT_DOUBLE_EQ(m.nodal_loads[0].scale, -2.5);
  EXPECT_EQ(m.nodal_loads[1].target, model::NodeTarget::kSet);
  EXPECT_DOUBLE_EQ(m.nodal_loads[1].scale, 1.0);

  ASSERT_EQ(m.initial_velocities.size(), 2u);
  EXPECT_EQ(m.initial_velocities[0].styp, 1);
  EXPECT_DOUBLE_EQ(m.initial_velocities[0].vx, 0.1246);
  EXPECT_DOUBLE_EQ(m.initial_velocities[0].vz, -0.03339);
  EXPECT_DOUBLE_EQ(m.initial_velocities[1].omega, 10.0);
  EXPECT_DOUBLE_EQ(m.initial_velocities[1].nz, 1.0);
}

TEST(SolverKeywords, ControlAndDatabase) {
  const ReadResult r = read_ok(
      "*CONTROL_TERMINATION\n"
      "    0.0100\n"
      "*CONTROL_TIMESTEP\n"
      "       0.0       0.0         0       0.0   -1.0e-6\n"
      "*CONTROL_ENERGY\n"
      "         2         0\n"
      "*CONTROL_HOURGLASS\n"
      "         0      0.05\n"
      "*CONTROL_UNITS\n"
      "mm        ms        kg        K\n"
      "*DATABASE_BINARY_D3PLOT\n"
      "$#      dt      lcdt      beam     npltc    psetid\n"
      "   1.0e-03\n"
      "$#   ioopt\n"
      "         0\n"
      "*DATABASE_GLSTAT\n"
      "1.0e-4\n"
      "*DATABASE_NODOUT\n"
      "1.0e-4,1\n"
      "*DATABASE_HISTORY_NODE\n"
      "         1         2         3         4         5         6         7         8\n"
      "        11\n"
      "*DATABASE_HISTORY_NODE_ID\n"
      "        21tip\n");
  const model::ModelDesc& m = r.model;
  ASSERT_TRUE(m.termination);
  EXPECT_DOUBLE_EQ(m.termination->end_time, 0.01);
  ASSERT_TRUE(m.timestep);
  EXPECT_DOUBLE_EQ(m.timestep->tssfac, 0.9);  // written 0: 0.9
  EXPECT_DOUBLE_EQ(m.timestep->dt2ms, -1.0e-6);
  ASSERT_TRUE(m.energy);
  EXPECT_EQ(m.energy->hgen, 2);
  EXPECT_EQ(m.energy->rwen, 2);  // written 0: default
  EXPECT_EQ(m.energy->slnten, 1);
  ASSERT_TRUE(m.control_hourglass);
  EXPECT_EQ(m.control_hourglass->ihq, 1);
  EXPECT_DOUBLE_EQ(m.control_hourglass->qh, 0.05);
  ASSERT_TRUE(m.units);
  EXPECT_EQ(m.units->length, "mm");
  EXPECT_EQ(m.units->temp, "K");
  ASSERT_TRUE(m.d3plot);
  EXPECT_DOUBLE_EQ(m.d3plot->dt, 1.0e-3);
  ASSERT_EQ(m.ascii_outputs.size(), 2u);
  EXPECT_EQ(m.ascii_outputs[0].name, "GLSTAT");
  EXPECT_EQ(m.ascii_outputs[0].ioopt, 1);
  EXPECT_EQ(m.ascii_outputs[1].name, "NODOUT");
  EXPECT_EQ(m.ascii_outputs[1].binary, 1);
  ASSERT_EQ(m.history_nodes.size(), 2u);
  EXPECT_EQ(m.history_nodes[0].node_ids.size(), 9u);
  EXPECT_EQ(m.history_nodes[1].node_ids.at(0), 21);
  EXPECT_EQ(m.history_nodes[1].headings.at(0), "tip");
}

TEST(SolverKeywords, TimestepTssfacKeptWhenGiven) {
  const ReadResult r = read_ok("*CONTROL_TIMESTEP\n,0.67\n");
  EXPECT_DOUBLE_EQ(r.model.timestep->tssfac, 0.67);
  const ReadResult twice =
      read_deck_text("*CONTROL_TIMESTEP\n,0.5\n*CONTROL_TIMESTEP\n,0.6\n", "t.k");
  ASSERT_TRUE(twice.ok());
  EXPECT_DOUBLE_EQ(twice.model.timestep->tssfac, 0.6);
  ASSERT_EQ(twice.warnings.size(), 1u);
  EXPECT_EQ(twice.warnings[0].where.line, 3);
}

}  // namespace
}  // namespace plyform::keyword
