// Mass, centre of mass and inertia tensor of rigid parts against closed forms; setup errors.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "plyform/rigid/mass_properties.hpp"
#include "plyform/rigid/rigid_bodies.hpp"
#include "rigid_models.hpp"

namespace plyform {
namespace {

using Mat = std::array<double, 9>;

// Q I Q^T.
Mat rotate(const Mat& q, const Mat& i) {
  Mat qi{}, out{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        qi[3 * r + c] += q[3 * r + k] * i[3 * k + c];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        out[3 * r + c] += qi[3 * r + k] * q[3 * c + k];
  return out;
}

Mat box_inertia(double m, double a, double b, double c) {
  return {m * (b * b + c * c) / 12, 0, 0, 0, m * (a * a + c * c) / 12, 0, 0, 0,
          m * (a * a + b * b) / 12};
}

void expect_inertia(const Mat& got, const Mat& want, double tol) {
  double scale = 0.0;
  for (double v : want)
    scale = std::max(scale, std::abs(v));
  for (std::size_t k = 0; k < 9; ++k)
    EXPECT_NEAR(got[k], want[k], tol * scale) << "entry " << k;
}

TEST(RigidMass, BoxMassCentreInertia) {
  const double a = 2.0, b = 3.0, c = 4.0, rho = 7850.0;
  core::Model m = test::box(a, b, c, 3, 2, 5, test::rigid_material(rho));
  test::place(m, test::axis_rotation({1, 0, 0}, 0.0), {10.0, -20.0, 5.0});
  const rigid::MassProperties p = rigid::part_mass_properties(m, 0, rho);
  const double mass = rho * a * b * c;
  EXPECT_NEAR(p.mass, mass, 1e-13 * mass);
  EXPECT_NEAR(p.centre[0], 11.0, 1e-13);
  EXPECT_NEAR(p.centre[1], -18.5, 1e-13);
  EXPECT_NEAR(p.centre[2], 7.0, 1e-13);
  expect_inertia(p.inertia, box_inertia(mass, a, b, c), 1e-13);
  EXPECT_EQ(p.nodes.size(), m.node_count());
  double sum = 0.0;
  for (double n : p.nodal_mass)
    sum += n;
  EXPECT_NEAR(sum, mass, 1e-13 * mass);
}

TEST(RigidMass, RotatedBoxHasTheRotatedTensor) {
  const double a = 1.0, b = 2.0, c = 3.0, rho = 1000.0;
  core::Model m = test::box(a, b, c, 2, 3, 4, test::rigid_material(rho));
  const Mat q = test::axis_rotation({1.0, 2.0, -0.5}, 0.7);
  test::place(m, q, {-3.0, 4.0, 100.0});
  const rigid::MassProperties p = rigid::part_mass_properties(m, 0, rho);
  const double mass = rho * a * b * c;
  EXPECT_NEAR(p.mass, mass, 1e-12 * mass);
  const std::array<double, 3> h = {0.5 * a, 0.5 * b, 0.5 * c};
  for (int i = 0; i < 3; ++i) {
    const double want = std::array<double, 3>{-3.0, 4.0, 100.0}[static_cast<std::size_t>(i)] +
                        q[3 * static_cast<std::size_t>(i)] * h[0] +
                        q[3 * static_cast<std::size_t>(i) + 1] * h[1] +
                        q[3 * static_cast<std::size_t>(i) + 2] * h[2];
    EXPECT_NEAR(p.centre[static_cast<std::size_t>(i)], want, 1e-12);
  }
  expect_inertia(p.inertia, rotate(q, box_inertia(mass, a, b, c)), 1e-12);
}

// Interior nodes moved anywhere and face nodes moved within their face leave the union of the
// elements the same box: the exact integrals are the box's. The Jacobian of the distorted
// hexahedra varies, so 2x2x2 Gauss would miss the second moments; 3x3x3 does not.
TEST(RigidMass, DistortedMeshStillIntegratesTheBoxExactly) {
  const double a = 2.0, b = 1.0, c = 1.5, rho = 2700.0;
  const int nx = 4, ny = 3, nz = 3;
  core::Model m = test::box(a, b, c, nx, ny, nz, test::rigid_material(rho));
  const double hx = a / nx, hy = b / ny, hz = c / nz;
  std::size_t moved = 0;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const bool bx = std::abs(m.x0[i]) < 1e-12 || std::abs(m.x0[i] - a) < 1e-12;
    const bool by = std::abs(m.y0[i]) < 1e-12 || std::abs(m.y0[i] - b) < 1e-12;
    const bool bz = std::abs(m.z0[i]) < 1e-12 || std::abs(m.z0[i] - c) < 1e-12;
    if (static_cast<int>(bx) + static_cast<int>(by) + static_cast<int>(bz) >= 2)
      continue;  // edges and corners stay
    const double s = static_cast<double>(i);
    if (!bx)
      m.x0[i] += 0.3 * hx * std::sin(1.7 * s);
    if (!by)
      m.y0[i] += 0.3 * hy * std::cos(2.3 * s);
    if (!bz)
      m.z0[i] += 0.3 * hz * std::sin(0.9 * s + 1.0);
    ++moved;
  }
  ASSERT_GT(moved, 20u);
  const rigid::MassProperties p = rigid::part_mass_properties(m, 0, rho);
  const double mass = rho * a * b * c;
  EXPECT_NEAR(p.mass, mass, 1e-13 * mass);
  EXPECT_NEAR(p.centre[0], 0.5 * a, 1e-13);
  EXPECT_NEAR(p.centre[1], 0.5 * b, 1e-13);
  EXPECT_NEAR(p.centre[2], 0.5 * c, 1e-13);
  expect_inertia(p.inertia, box_inertia(mass, a, b, c), 1e-13);
}

TEST(RigidMass, ShellPlateIsAThinBox) {
  const double a = 0.8, b = 0.5, t = 0.01, rho = 7800.0;
  core::Model m = test::plate(
      a, b, 4, 3, [&](double, double) { return t; }, test::rigid_material(rho));
  const Mat q = test::axis_rotation({0.3, -1.0, 0.4}, 1.1);
  test::place(m, q, {1.0, 2.0, 3.0});
  const rigid::MassProperties p = rigid::part_mass_properties(m, 0, rho);
  const double mass = rho * a * b * t;
  EXPECT_NEAR(p.mass, mass, 1e-13 * mass);
  // Mid-surface at z = 0: the thin plate is the box a x b x t centred on it.
  expect_inertia(p.inertia, rotate(q, box_inertia(mass, a, b, t)), 1e-12);
}

TEST(RigidMass, ShellThicknessVaryingLinearly) {
  // t = t0 (1 + x / a): m = rho b t0 3a/2, x_c = int x t / int t = 5a/9.
  const double a = 1.0, b = 0.5, t0 = 0.02, rho = 1000.0;
  core::Model m = test::plate(
      a, b, 5, 2, [&](double x, double) { return t0 * (1.0 + x / a); }, test::rigid_material(rho));
  const rigid::MassProperties p = rigid::part_mass_properties(m, 0, rho);
  EXPECT_NEAR(p.mass, rho * b * t0 * 1.5 * a, 1e-13);
  EXPECT_NEAR(p.centre[0], 5.0 * a / 9.0, 1e-13);
  EXPECT_NEAR(p.centre[1], 0.5 * b, 1e-13);
  EXPECT_NEAR(p.centre[2], 0.0, 1e-15);
  // I_yy = rho b int t(x) ((x - x_c)^2 + t^2/12) dx; with t linear in x, integrated exactly.
  double iyy = 0.0;  // Simpson on a fine grid of a polynomial of degree 3 in x: exact
  const int n = 10;
  for (int k = 0; k <= n; ++k) {
    const double x = a * k / n;
    const double tt = t0 * (1.0 + x / a);
    const double f = tt * ((x - 5.0 * a / 9.0) * (x - 5.0 * a / 9.0) + tt * tt / 12.0);
    const double wgt = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    iyy += wgt * f;
  }
  iyy *= rho * b * (a / n) / 3.0;
  EXPECT_NEAR(p.inertia[4], iyy, 1e-12 * iyy);
}

TEST(RigidMass, ShellTriangleAsDegenerateQuad) {
  // A right triangle with legs a, b: m = rho t a b / 2, centre (a/3, b/3).
  const double a = 0.6, b = 0.9, t = 0.003, rho = 2000.0;
  core::Model m;
  m.node_id = {1, 2, 3};
  m.x0 = {0.0, a, 0.0};
  m.y0 = {0.0, 0.0, b};
  m.z0 = {0.0, 0.0, 0.0};
  core::ShellBlock s;
  s.element_id = {1};
  s.connectivity = {0, 1, 2, 2};
  s.thickness = {t, t, t, t};
  m.shell_blocks.push_back(s);
  m.materials.push_back(test::rigid_material(rho));
  m.parts.push_back(core::Part{7, "triangle", 0});
  const rigid::MassProperties p = rigid::part_mass_properties(m, 0, rho);
  const double mass = 0.5 * rho * t * a * b;
  EXPECT_NEAR(p.mass, mass, 1e-13 * mass);
  EXPECT_NEAR(p.centre[0], a / 3.0, 1e-13);
  EXPECT_NEAR(p.centre[1], b / 3.0, 1e-13);
  // I_zz about the centroid of a right triangle: m (a^2 + b^2) / 18.
  EXPECT_NEAR(p.inertia[8], mass * (a * a + b * b) / 18.0, 1e-12 * mass);
  EXPECT_EQ(p.nodes.size(), 3u);
}

TEST(RigidBodies, FindsRigidPartsAndTheirNodesOnly) {
  core::Model m = test::box(1.0, 1.0, 2.0, 1, 1, 2, test::rigid_material(1000.0));
  // Second part (elastic) on the upper element, sharing the middle layer of nodes.
  m.materials.push_back(core::ElasticMaterial{1000.0, 1e9, 0.3});
  m.parts.push_back(core::Part{2, "sheet", 1});
  core::SolidBlock upper = m.solid_blocks[0];
  core::SolidBlock& lower = m.solid_blocks[0];
  lower.element_id.resize(1);
  lower.connectivity.resize(8);
  upper.element_id.erase(upper.element_id.begin());
  upper.connectivity.erase(upper.connectivity.begin(), upper.connectivity.begin() + 8);
  upper.part = 1;
  upper.material = 1;
  m.solid_blocks.push_back(upper);
  const rigid::RigidBodies rb(m);
  ASSERT_EQ(rb.size(), 1u);
  EXPECT_FALSE(rb.empty());
  std::size_t count = 0;
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    EXPECT_EQ(rb.is_rigid_node()[i] != 0, m.z0[i] < 1.5) << "node " << i;
    count += rb.is_rigid_node()[i];
  }
  EXPECT_EQ(count, 8u);
  EXPECT_EQ(rb.rigid_nodes().size(), 8u);
  EXPECT_NEAR(rb.mass_properties(0).mass, 1000.0, 1e-10);
  EXPECT_NEAR(rb.kinetic_energy(), 0.0, 0.0);
}

TEST(RigidBodies, NoRigidPartIsEmpty) {
  const core::Model m = test::box(1, 1, 1, 1, 1, 1, core::ElasticMaterial{1000.0, 1e9, 0.3});
  const rigid::RigidBodies rb(m);
  EXPECT_TRUE(rb.empty());
  EXPECT_EQ(rb.is_rigid_node().size(), m.node_count());
}

void expect_invalid(const core::Model& m, const std::string& words) {
  try {
    const rigid::RigidBodies rb(m);
    ADD_FAILURE() << "no exception, expected: " << words;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(RigidBodies, RejectsBadParts) {
  core::Model m = test::box(1, 1, 1, 1, 1, 1, test::rigid_material(1000.0));
  m.parts.push_back(core::Part{42, "empty tool", 0});
  expect_invalid(m, "rigid part 42 (empty tool) has no element");

  core::Model z = test::box(1, 1, 1, 1, 1, 1, test::rigid_material(0.0));
  expect_invalid(z, "rigid part 1 (box) has no mass");

  core::Model local = test::box(1, 1, 1, 1, 1, 1, test::rigid_material(1000.0, -1, 0, 0));
  expect_invalid(local, "CMO = -1");

  core::Model code = test::box(1, 1, 1, 1, 1, 1, test::rigid_material(1000.0, 1, 8, 0));
  expect_invalid(code, "CON1 = 8");

  core::Model motion = test::box(1, 1, 1, 1, 1, 1, core::ElasticMaterial{1000.0, 1e9, 0.3});
  motion.curves.push_back(core::LoadCurve{{0.0, 1.0}, {1.0, 1.0}});
  motion.rigid_motions.push_back(core::RigidMotion{0, 0, core::MotionKind::velocity, 0});
  expect_invalid(motion, "not a rigid part");

  core::Model dof = test::box(1, 1, 1, 1, 1, 1, test::rigid_material(1000.0));
  dof.curves.push_back(core::LoadCurve{{0.0, 1.0}, {1.0, 1.0}});
  dof.rigid_loads.push_back(core::RigidLoad{0, 6, 0, 1.0});
  expect_invalid(dof, "dof 6");

  core::Model inverted = test::box(1, 1, 1, 1, 1, 1, test::rigid_material(1000.0));
  std::swap(inverted.solid_blocks[0].connectivity[1], inverted.solid_blocks[0].connectivity[3]);
  std::swap(inverted.solid_blocks[0].connectivity[5], inverted.solid_blocks[0].connectivity[7]);
  expect_invalid(inverted, "non-positive Jacobian");
}

TEST(RigidBodies, RejectsANodeSharedByTwoRigidParts) {
  core::Model m = test::box(1.0, 1.0, 2.0, 1, 1, 2, test::rigid_material(1000.0));
  m.parts.push_back(core::Part{2, "die", 0});
  core::SolidBlock upper = m.solid_blocks[0];
  m.solid_blocks[0].element_id.resize(1);
  m.solid_blocks[0].connectivity.resize(8);
  upper.element_id.erase(upper.element_id.begin());
  upper.connectivity.erase(upper.connectivity.begin(), upper.connectivity.begin() + 8);
  upper.part = 1;
  m.solid_blocks.push_back(upper);
  expect_invalid(m, "shares node");
}

}  // namespace
}  // namespace plyform
