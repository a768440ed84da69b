// *INTERFACE_SPRINGBACK_LSDYNA's dynain file:
// - round trip: a patch of bilinear J2 shells (*MAT_024; ELFORM 2 and 16, NIP 3 and 5) in a
//   tilted plane, clamped at one edge, its other edge pulled along the patch and pushed across
//   it into plastic stretch and bending. Its dynain, read back by plyform's keyword reader,
//   holds every node at its end position, every shell's end thickness and every point's
//   stress and plastic strain as the run held them at the end (the stress turned to global
//   axes here, by the test's own rotation) to the printed precision; a deck of that dynain then
//   starts (t = 0) with the same co-rotational stresses, plastic strains and thicknesses.
// - *INITIAL_STRESS_SHELL applied at t = 0 against the closed form: the card's points
//   interpolated in T to the section's points and turned into the element's frame, NPLANE 1
//   and 4 on ELFORM 2 and 16.
// - card layout: the written text parsed by LS-DYNA's column positions (*NODE,
//   *ELEMENT_SHELL_THICKNESS, *INITIAL_STRESS_SHELL and *INITIAL_STRAIN_SHELL with LARGE 1 in
//   16-character fields, as OpenRadioss's reader of LS-DYNA decks takes them), the point
//   coordinates T against the Gauss rule's closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "dynain_decks.hpp"
#include "plyform/app/dynain_writer.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"
#include "temp_dir.hpp"

namespace plyform {
namespace {

using test::Dynain;
using test::DynainShell;

constexpr double kEnd = 2.0e-4;
constexpr int kNx = 4, kNy = 2;
constexpr double kL = 10.0, kW = 5.0, kH = 0.5;

/// The patch's axes: along it d, across it w, its normal n (turned 30 degrees about z, then
/// tilted 20 degrees about d, so that every global stress component is non-zero).
struct Axes {
  double d[3], w[3], n[3];
};
Axes patch_axes() {
  const double a = std::numbers::pi / 6.0, b = std::numbers::pi / 9.0;
  const double w0[3] = {-std::sin(a), std::cos(a), 0.0};
  Axes x{};
  x.d[0] = std::cos(a), x.d[1] = std::sin(a), x.d[2] = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double n0 = i == 2 ? 1.0 : 0.0;
    x.w[i] = std::cos(b) * w0[i] + std::sin(b) * n0;
    x.n[i] = -std::sin(b) * w0[i] + std::cos(b) * n0;
  }
  return x;
}

int nid(int i, int j) {
  return 1 + i + (kNx + 1) * j;
}

std::string patch_deck(int elform, int nip) {
  const Axes ax = patch_axes();
  std::ostringstream os;
  os.precision(17);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n"
     << kEnd << ",\n*INTERFACE_SPRINGBACK_LSDYNA\n0,\n"
     << test::j2_part(elform, nip, kH) << "*NODE\n";
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i) {
      os << nid(i, j);
      for (int c = 0; c < 3; ++c)
        os << "," << kL * i / kNx * ax.d[c] + kW * j / kNy * ax.w[c];
      os << "\n";
    }
  os << "*ELEMENT_SHELL\n";
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i)
      os << 101 + i + kNx * j << ",1," << nid(i, j) << "," << nid(i + 1, j) << ","
         << nid(i + 1, j + 1) << "," << nid(i, j + 1) << "\n";
  os << "*BOUNDARY_SPC_NODE\n";
  for (int j = 0; j <= kNy; ++j)
    os << nid(0, j) << ",0,1,1,1,1,1,1\n";
  // The far edge: 0.3 mm along the patch (3 %) and 1.5 mm across it, the speed ramped up over
  // the first quarter of the run.
  const double along = 0.3 / (0.875 * kEnd), across = 1.5 / (0.875 * kEnd);
  os << "*DEFINE_CURVE\n1,\n0,0\n" << kEnd / 4 << ",1\n" << kEnd << ",1\n";
  os << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int j = 0; j <= kNy; ++j)
    for (int c = 0; c < 3; ++c)
      os << nid(kNx, j) << "," << c + 1 << ",0,1," << along * ax.d[c] + across * ax.n[c] << "\n";
  os << "*END\n";
  return os.str();
}

/// What the run held at its end, and its dynain written there.
struct EndState : test::RecordingSink {
  std::filesystem::path file;
  std::vector<double> x, y, z;
  std::vector<element::ShellBlockState> shells;
  void end_of_run(const engine::Snapshot& s) override {
    x = s.nodes->x, y = s.nodes->y, z = s.nodes->z;
    shells = *s.shells;
    app::write_dynain(file, *s.model, s);
  }
};

/// Reads, validates and builds a deck (no error allowed).
core::Model build(const std::filesystem::path& deck) {
  const auto read = keyword::read_deck(deck);
  EXPECT_TRUE(read.ok()) << read.errors.front().to_string();
  const auto errors = setup::validate(read.model);
  EXPECT_TRUE(errors.empty()) << errors.front().to_string();
  auto built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  return std::move(*built.model);
}

/// sigma_g = sum_ab e_a l_ab e_b, written out (xx yy zz xy yz zx).
std::array<double, 6> to_global(const double e[3][3], const element::ShellBlockState& st,
                                std::size_t q) {
  const double l[3][3] = {{st.s[0][q], st.s[2][q], st.s[4][q]},
                          {st.s[2][q], st.s[1][q], st.s[3][q]},
                          {st.s[4][q], st.s[3][q], 0.0}};
  const int pair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  std::array<double, 6> g{};
  for (int c = 0; c < 6; ++c)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        g[static_cast<std::size_t>(c)] += e[a][pair[c][0]] * l[a][b] * e[b][pair[c][1]];
  return g;
}

struct Case {
  int elform, nip;
};

class DynainRoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(DynainRoundTrip, HoldsTheEndStateAndStartsTheNextRunFromIt) {
  const Case c = GetParam();
  test::TempDir dir;
  const core::Model m = build(dir.write("patch.k", patch_deck(c.elform, c.nip)));
  ASSERT_TRUE(m.output.dynain.write);
  EndState end;
  end.file = dir.path() / "dynain";
  engine::SolverOptions options;
  const engine::RunResult run = engine::run(m, end, options);
  ASSERT_TRUE(run.ok) << run.error;
  ASSERT_TRUE(std::filesystem::exists(end.file));
  const Dynain d = test::read_dynain(end.file);

  // Nodes: 10 significant digits (16-character fields).
  ASSERT_EQ(d.nodes.size(), m.node_count());
  for (std::size_t i = 0; i < m.node_count(); ++i) {
    const auto& p = d.nodes.at(static_cast<int>(m.node_id[i]));
    EXPECT_NEAR(p[0], end.x[i], 1e-9 * (std::abs(end.x[i]) + 1e-3));
    EXPECT_NEAR(p[1], end.y[i], 1e-9 * (std::abs(end.y[i]) + 1e-3));
    EXPECT_NEAR(p[2], end.z[i], 1e-9 * (std::abs(end.z[i]) + 1e-3));
  }
  // Shells: thickness, and every point's global stress and plastic strain (14 digits).
  const core::ShellBlock& blk = m.shell_blocks[0];
  const element::ShellBlockState& st = end.shells[0];
  const auto nip = static_cast<std::size_t>(st.nip);
  const auto inplane = static_cast<std::size_t>(st.inplane);
  std::vector<double> zeta(nip), weight(nip);
  element::thickness_rule(blk.rule, c.nip, zeta.data(), weight.data());
  double sigma_max = 0.0, eps_max = 0.0;
  for (std::size_t q = 0; q < st.eps_p.size(); ++q) {
    for (int k = 0; k < 5; ++k)
      sigma_max = std::max(sigma_max, std::abs(st.s[k][q]));
    eps_max = std::max(eps_max, st.eps_p[q]);
  }
  EXPECT_GT(eps_max, 0.005);  // the patch is plastic
  EXPECT_GT(sigma_max, 0.9 * test::kDynainSigmaY);
  ASSERT_EQ(d.shells.size(), blk.size());
  for (std::size_t e = 0; e < blk.size(); ++e) {
    const DynainShell& s = d.shells.at(static_cast<int>(blk.element_id[e]));
    EXPECT_EQ(s.part, 1);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(s.nodes[static_cast<std::size_t>(k)],
                m.node_id[static_cast<std::size_t>(
                    blk.connectivity[4 * e + static_cast<std::size_t>(k)])]);
      EXPECT_NEAR(s.thickness[static_cast<std::size_t>(k)], st.thickness[e],
                  1e-9 * st.thickness[e]);
    }
    ASSERT_TRUE(s.has_stress && s.has_strain);
    EXPECT_EQ(s.stress.nplane, static_cast<int>(inplane));
    EXPECT_EQ(s.stress.nthick, c.nip);
    EXPECT_TRUE(s.stress.large);
    double frame[3][3];
    ASSERT_TRUE(element::shell_frame(blk, end.x.data(), end.y.data(), end.z.data(), e, frame[0],
                                     frame[1], frame[2]));
    for (std::size_t k = 0; k < nip; ++k) {
      for (std::size_t g = 0; g < inplane; ++g) {
        const model::InitialStressPoint& p = s.stress.points[k * inplane + g];
        const std::size_t q = e * st.points_per_element() + g * nip + k;
        // LARGE 1 prints 9 significant digits (docs/outputs.md).
        EXPECT_NEAR(p.t, zeta[k], 1e-8);
        const std::array<double, 6> sg = to_global(frame, st, q);
        for (std::size_t cc = 0; cc < 6; ++cc)
          EXPECT_NEAR(p.sigma[cc], sg[cc], 1e-8 * sigma_max) << "element " << e << " point " << q;
        EXPECT_NEAR(p.eps, st.eps_p[q], 1e-8 * eps_max);
      }
    }
    // The surfaces' strains: the thickness stretch along the centre's normal (t1 x t2 of the
    // bilinear map), nothing else along it.
    ASSERT_EQ(s.strain.points.size(), 2u);
    const double thick = std::log(st.thickness[e] / kH);
    double t1[3], t2[3], n[3];
    const auto& p0 = d.nodes.at(s.nodes[0]);
    const auto& p1 = d.nodes.at(s.nodes[1]);
    const auto& p2 = d.nodes.at(s.nodes[2]);
    const auto& p3 = d.nodes.at(s.nodes[3]);
    for (std::size_t i = 0; i < 3; ++i) {
      t1[i] = -p0[i] + p1[i] + p2[i] - p3[i];
      t2[i] = -p0[i] - p1[i] + p2[i] + p3[i];
    }
    n[0] = t1[1] * t2[2] - t1[2] * t2[1];
    n[1] = t1[2] * t2[0] - t1[0] * t2[2];
    n[2] = t1[0] * t2[1] - t1[1] * t2[0];
    const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& v : n)
      v /= norm;
    EXPECT_EQ(s.strain.points[0].t, -1.0);
    EXPECT_EQ(s.strain.points[1].t, 1.0);
    for (const model::InitialStrainPoint& p : s.strain.points) {
      const double t[3][3] = {{p.eps[0], p.eps[3], p.eps[5]},
                              {p.eps[3], p.eps[1], p.eps[4]},
                              {p.eps[5], p.eps[4], p.eps[2]}};
      for (int i = 0; i < 3; ++i) {
        const double en = t[i][0] * n[0] + t[i][1] * n[1] + t[i][2] * n[2];
        EXPECT_NEAR(en, thick * n[i], 1e-8);
      }
    }
  }

  // The dynain as a deck: it starts with the end's state.
  const std::string next = "*KEYWORD\n*CONTROL_TERMINATION\n1.0e-9,\n*INCLUDE\n" +
                           end.file.string() + "\n" + test::j2_part(c.elform, c.nip, 1.0) +
                           "*END\n";
  const core::Model m2 = build(dir.write("next.k", next));
  ASSERT_EQ(m2.initial_shell_stresses.size(), blk.size());
  test::RecordingSink start;
  std::vector<element::ShellBlockState> first;
  start.on_state = [&](const engine::Snapshot& s) {
    if (first.empty())
      first = *s.shells;
  };
  ASSERT_TRUE(engine::run(m2, start, options).ok);
  ASSERT_EQ(first.size(), 1u);
  const core::ShellBlock& blk2 = m2.shell_blocks[0];
  std::map<core::GlobalId, std::size_t> at;
  for (std::size_t e = 0; e < blk2.size(); ++e)
    at[blk2.element_id[e]] = e;
  double worst_stress = 0.0, worst_eps = 0.0, worst_h = 0.0;
  for (std::size_t e = 0; e < blk.size(); ++e) {
    const std::size_t e2 = at.at(blk.element_id[e]);
    worst_h = std::max(worst_h, std::abs(first[0].thickness[e2] - st.thickness[e]) / kH);
    for (std::size_t p = 0; p < st.points_per_element(); ++p) {
      const std::size_t q = e * st.points_per_element() + p;
      const std::size_t q2 = e2 * st.points_per_element() + p;
      for (int k = 0; k < 5; ++k)
        worst_stress = std::max(worst_stress, std::abs(first[0].s[k][q2] - st.s[k][q]));
      worst_eps = std::max(worst_eps, std::abs(first[0].eps_p[q2] - st.eps_p[q]));
    }
  }
  std::printf(
      "ELFORM %d NIP %d: max |stress| %.4g, max eps_p %.4g; restarted from dynain: "
      "stress off by %.3g of the max, eps_p by %.3g, thickness by %.3g of h0\n",
      c.elform, c.nip, sigma_max, eps_max, worst_stress / sigma_max, worst_eps, worst_h);
  EXPECT_LT(worst_stress, 2e-8 * sigma_max);
  EXPECT_LT(worst_eps, 1e-8 * eps_max);
  EXPECT_LT(worst_h, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(ElformNip, DynainRoundTrip,
                         ::testing::Values(Case{2, 3}, Case{2, 5}, Case{16, 3}, Case{16, 5}),
                         [](const auto& param) {
                           return "Elform" + std::to_string(param.param.elform) + "Nip" +
                                  std::to_string(param.param.nip);
                         });

// --- Springback from the dynain: the patch's dynain run as a deck with only its clamped edge
// held. The initial stresses' elastic energy is the internal energy of t = 0 (here against
// sum over the points of [(1 + nu) sigma : sigma - nu (tr sigma)^2] / (2 E) times the point's
// volume, from the file's global stresses, areas and thicknesses), and as the patch springs
// back it turns into kinetic energy and back within the energy balance (without it in the
// books the balance read energy from nowhere and stopped the run). The release is sudden: the
// patch starts from rest under unbalanced forces that reach every mode of the mesh, and the
// central differences conserve 1/2 v_-1/2 M v_1/2 + U, which for a start from rest under the
// accelerations a_0 is 1/8 sum m (a_0 dt)^2 below the booked U (the same first-step effect as
// a velocity that jumps, docs/energy.md): the balance lost 9 % in the first steps at the
// default TSSFAC 0.9 and then held; at TSSFAC 0.3, used here, 0.9 % (the (omega dt)^2 scaling).

class DynainSpringback : public ::testing::TestWithParam<Case> {};

TEST_P(DynainSpringback, TheInitialStressesEnergyIsBookedAndGivenBack) {
  const Case c = GetParam();
  test::TempDir dir;
  const core::Model m = build(dir.write("patch.k", patch_deck(c.elform, c.nip)));
  EndState end;
  end.file = dir.path() / "dynain";
  ASSERT_TRUE(engine::run(m, end, engine::SolverOptions{}).ok);
  const Dynain d = test::read_dynain(end.file);
  const double gauss_weight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  ASSERT_EQ(c.nip, 3);
  double stored = 0.0;
  for (const auto& [id, s] : d.shells) {
    const auto& p0 = d.nodes.at(s.nodes[0]);
    const auto& p1 = d.nodes.at(s.nodes[1]);
    const auto& p2 = d.nodes.at(s.nodes[2]);
    const auto& p3 = d.nodes.at(s.nodes[3]);
    const double a[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const double b[3] = {p3[0] - p1[0], p3[1] - p1[1], p3[2] - p1[2]};
    const double area = 0.5 * std::hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                         a[0] * b[1] - a[1] * b[0]);
    for (std::size_t k = 0; k < s.stress.points.size(); ++k) {
      const model::InitialStressPoint& p = s.stress.points[k];
      const double* v = p.sigma.data();
      const double contracted =
          v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + 2.0 * (v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
      const double trace = v[0] + v[1] + v[2];
      const double w = ((1.0 + test::kDynainNu) * contracted - test::kDynainNu * trace * trace) /
                       (2.0 * test::kDynainE);
      const double share =
          gauss_weight[k / static_cast<std::size_t>(s.stress.nplane)] / 2.0 / s.stress.nplane;
      stored += w * area * s.thickness[0] * share;
    }
  }
  std::ostringstream next;
  next << "*KEYWORD\n*CONTROL_TERMINATION\n1.0e-4,\n*CONTROL_TIMESTEP\n0,0.3\n*DATABASE_GLSTAT\n1."
          "0e-6,\n*INCLUDE\n"
       << end.file.string() << "\n"
       << test::j2_part(c.elform, c.nip, 1.0) << "*BOUNDARY_SPC_NODE\n";
  for (int j = 0; j <= kNy; ++j)
    next << nid(0, j) << ",0,1,1,1,1,1,1\n";
  next << "*END\n";
  const core::Model m2 = build(dir.write("springback.k", next.str()));
  test::RecordingSink sink;
  const engine::RunResult r = engine::run(m2, sink, engine::SolverOptions{});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_FALSE(sink.energies.empty());
  const engine::Energies& first = sink.energies.front();
  double most_kinetic = 0.0, worst_ratio = 0.0;
  for (const engine::Energies& e : sink.energies) {
    most_kinetic = std::max(most_kinetic, e.kinetic);
    worst_ratio = std::max(worst_ratio, std::abs(e.ratio - 1.0));
  }
  std::printf(
      "ELFORM %d: initial stresses' energy %.6g (closed form %.6g); springback: most "
      "kinetic %.4g, energy ratio within 1 +- %.3g\n",
      c.elform, first.internal, stored, most_kinetic, worst_ratio);
  EXPECT_NEAR(first.internal, stored, 1e-6 * stored);
  EXPECT_GT(most_kinetic, 0.05 * stored);  // it springs back
  EXPECT_LT(worst_ratio, 0.015);
}

INSTANTIATE_TEST_SUITE_P(Elform, DynainSpringback, ::testing::Values(Case{2, 3}, Case{16, 3}),
                         [](const auto& param) {
                           return "Elform" + std::to_string(param.param.elform);
                         });

// --- *INITIAL_STRESS_SHELL applied at t = 0, against the closed form: a unit square shell
// turned 25 degrees about z (its frame e1 along N1-N2: (cos, sin, 0)), given global stresses
// at T = -0.5 and T = 1 (NTHICK 2) for a section of NIP 3 Gauss points: each point's stress is
// the linear interpolation in T (the end value below T = -0.5), turned into the frame,
// l_ab = e_a . sigma . e_b; NPLANE 4 gives ELFORM 2 the mean of the four, ELFORM 16 each its
// own; NPLANE 1 gives ELFORM 16 the same at its four points.

struct Applied {
  int elform, nplane;
};

class InitialStressApplied : public ::testing::TestWithParam<Applied> {};

TEST_P(InitialStressApplied, InterpolatesInTAndTurnsIntoTheFrame) {
  const Applied a = GetParam();
  const double th = 25.0 * std::numbers::pi / 180.0, c = std::cos(th), s = std::sin(th);
  // Global stress at the two T, per in-plane point g (g scales it: 1 + g / 10).
  const double bottom[6] = {100.0, -40.0, 7.0, 25.0, 3.0, -2.0};
  const double top[6] = {-60.0, 80.0, -5.0, -15.0, 1.0, 4.0};
  const double t_given[2] = {-0.5, 1.0}, eps_given[2] = {0.02, 0.05};
  std::ostringstream os;
  os.precision(17);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n1e-9,\n"
     << test::j2_part(a.elform, 3, 0.5) << "*NODE\n"
     << "1,0,0,0\n2," << c << "," << s << ",0\n3," << c - s << "," << s + c << ",0\n4," << -s << ","
     << c << ",0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n*INITIAL_STRESS_SHELL\n1," << a.nplane << ",2\n";
  for (int k = 0; k < 2; ++k)
    for (int g = 0; g < a.nplane; ++g) {
      const double* v = k == 0 ? bottom : top;
      const double f = 1.0 + g / 10.0;
      os << t_given[k];
      for (int i = 0; i < 6; ++i)
        os << "," << f * v[i];
      os << "," << f * eps_given[k] << "\n";
    }
  os << "*END\n";
  test::TempDir dir;
  const core::Model m = build(dir.write("one.k", os.str()));
  test::RecordingSink sink;
  std::vector<element::ShellBlockState> first;
  sink.on_state = [&](const engine::Snapshot& snap) {
    if (first.empty())
      first = *snap.shells;
  };
  ASSERT_TRUE(engine::run(m, sink, engine::SolverOptions{}).ok);
  ASSERT_EQ(first.size(), 1u);
  const element::ShellBlockState& st = first[0];
  const double e[3][3] = {{c, s, 0.0}, {-s, c, 0.0}, {0.0, 0.0, 1.0}};
  const double zeta[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const int pair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  const int inplane = a.elform == 16 ? 4 : 1;
  for (int g = 0; g < inplane; ++g) {
    // The in-plane factor the point gets: its own, the mean of the four, or the one given.
    const double f = a.nplane == 1 ? 1.0 : inplane == 4 ? 1.0 + g / 10.0 : 1.15;
    for (int k = 0; k < 3; ++k) {
      const double w = std::clamp((zeta[k] - t_given[0]) / (t_given[1] - t_given[0]), 0.0, 1.0);
      double sigma[3][3];
      for (int i = 0; i < 6; ++i) {
        const double v = f * (bottom[i] + w * (top[i] - bottom[i]));
        sigma[pair[i][0]][pair[i][1]] = sigma[pair[i][1]][pair[i][0]] = v;
      }
      const auto local = [&](int p, int q) {
        double v = 0.0;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            v += e[p][i] * sigma[i][j] * e[q][j];
        return v;
      };
      const std::size_t q = static_cast<std::size_t>(g * 3 + k);
      EXPECT_NEAR(st.s[0][q], local(0, 0), 1e-11) << "g " << g << " k " << k;
      EXPECT_NEAR(st.s[1][q], local(1, 1), 1e-11);
      EXPECT_NEAR(st.s[2][q], local(0, 1), 1e-11);
      EXPECT_NEAR(st.s[3][q], local(1, 2), 1e-11);
      EXPECT_NEAR(st.s[4][q], local(2, 0), 1e-11);
      EXPECT_NEAR(st.eps_p[q], f * (eps_given[0] + w * (eps_given[1] - eps_given[0])), 1e-15);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ElformNplane, InitialStressApplied,
                         ::testing::Values(Applied{2, 1}, Applied{2, 4}, Applied{16, 1},
                                           Applied{16, 4}),
                         [](const auto& param) {
                           return "Elform" + std::to_string(param.param.elform) + "Nplane" +
                                  std::to_string(param.param.nplane);
                         });

// --- The card layout against LS-DYNA's manual.

/// A field of a card: its name, first column (1-based) and width, as the manual gives them, and
/// whether it holds an integer.
struct Field {
  const char* name;
  int column, width;
  bool integer;
};
using Card = std::vector<Field>;

// *NODE: NID I8, X Y Z E16.0 (TC, RC F8.0 follow, left blank).
const Card kNode{
    {"NID", 1, 8, true}, {"X", 9, 16, false}, {"Y", 25, 16, false}, {"Z", 41, 16, false}};
// *ELEMENT_SHELL_THICKNESS: EID PID N1..N4 (I8), then THIC1..THIC4 (E16.0).
const Card kElement{{"EID", 1, 8, true}, {"PID", 9, 8, true}, {"N1", 17, 8, true},
                    {"N2", 25, 8, true}, {"N3", 33, 8, true}, {"N4", 41, 8, true}};
const Card kThickness{{"THIC1", 1, 16, false},
                      {"THIC2", 17, 16, false},
                      {"THIC3", 33, 16, false},
                      {"THIC4", 49, 16, false}};
// *INITIAL_STRESS_SHELL: EID NPLANE NTHICK NHISV NTENSR LARGE NTHINT NTHHSV (I10); with
// LARGE 1 each point on two cards of 16-character fields: T SIGXX SIGYY SIGZZ SIGXY, then
// SIGYZ SIGZX EPS.
const Card kStressHeader{{"EID", 1, 10, true},     {"NPLANE", 11, 10, true},
                         {"NTHICK", 21, 10, true}, {"NHISV", 31, 10, true},
                         {"NTENSR", 41, 10, true}, {"LARGE", 51, 10, true},
                         {"NTHINT", 61, 10, true}, {"NTHHSV", 71, 10, true}};
const Card kStressLarge1{{"T", 1, 16, false},
                         {"SIGXX", 17, 16, false},
                         {"SIGYY", 33, 16, false},
                         {"SIGZZ", 49, 16, false},
                         {"SIGXY", 65, 16, false}};
const Card kStressLarge2{{"SIGYZ", 1, 16, false}, {"SIGZX", 17, 16, false}, {"EPS", 33, 16, false}};
// *INITIAL_STRAIN_SHELL: EID NPLANE NTHICK LARGE (I10), columns 41-70 unused, ILOCAL 71-80;
// with LARGE 1: EPSXX EPSYY EPSZZ EPSXY EPSYZ, then EPSZX T (16 characters).
const Card kStrainHeader{{"EID", 1, 10, true},
                         {"NPLANE", 11, 10, true},
                         {"NTHICK", 21, 10, true},
                         {"LARGE", 31, 10, true},
                         {"ILOCAL", 71, 10, true}};
const Card kStrainLarge1{{"EPSXX", 1, 16, false},
                         {"EPSYY", 17, 16, false},
                         {"EPSZZ", 33, 16, false},
                         {"EPSXY", 49, 16, false},
                         {"EPSYZ", 65, 16, false}};
const Card kStrainLarge2{{"EPSZX", 1, 16, false}, {"T", 17, 16, false}};

/// The card's values from a line by column: each field right-aligned in its columns with no
/// blank inside it (a number that overflowed its field would break that), a whole integer or a
/// whole real number, and nothing past the card's last field.
std::vector<double> parse(const std::string& line, const Card& card, int line_number) {
  std::vector<double> values;
  const Field& last = card.back();
  EXPECT_LE(static_cast<int>(line.size()), last.column + last.width - 1)
      << "line " << line_number << ": text past " << last.name;
  for (const Field& f : card) {
    const auto begin = static_cast<std::size_t>(f.column - 1);
    const std::string text =
        begin < line.size() ? line.substr(begin, static_cast<std::size_t>(f.width)) : "";
    const std::size_t first = text.find_first_not_of(' ');
    EXPECT_NE(first, std::string::npos) << "line " << line_number << ": " << f.name << " blank";
    if (first == std::string::npos) {
      values.push_back(0.0);
      continue;
    }
    const std::string token = text.substr(first);
    EXPECT_EQ(static_cast<int>(text.size()), f.width)
        << "line " << line_number << ": " << f.name << " not right-aligned in its columns";
    EXPECT_EQ(token.find(' '), std::string::npos) << "line " << line_number << ": " << f.name;
    std::size_t used = 0;
    const double v =
        f.integer ? static_cast<double>(std::stol(token, &used)) : std::stod(token, &used);
    EXPECT_EQ(used, token.size()) << "line " << line_number << ": " << f.name << " '" << token
                                  << "'";
    values.push_back(v);
  }
  return values;
}

TEST(DynainLayout, CardsSitInTheManualsColumns) {
  test::TempDir dir;
  const core::Model m = build(dir.write("patch.k", patch_deck(16, 3)));
  EndState end;
  end.file = dir.path() / "dynain";
  ASSERT_TRUE(engine::run(m, end, engine::SolverOptions{}).ok);
  std::ifstream in(end.file);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);)
    lines.push_back(l);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.front(), "*KEYWORD");
  EXPECT_EQ(lines.back(), "*END");
  // The data lines of each keyword, in order.
  std::map<std::string, std::vector<std::pair<int, std::string>>> data;
  std::vector<std::string> order;
  std::string current;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].empty() || lines[i][0] == '$')
      continue;
    if (lines[i][0] == '*') {
      current = lines[i];
      order.push_back(current);
      continue;
    }
    data[current].emplace_back(static_cast<int>(i + 1), lines[i]);
  }
  EXPECT_EQ(order,
            (std::vector<std::string>{"*KEYWORD", "*NODE", "*ELEMENT_SHELL_THICKNESS",
                                      "*INITIAL_STRESS_SHELL", "*INITIAL_STRAIN_SHELL", "*END"}));
  for (const auto& [n, text] : data["*NODE"])
    parse(text, kNode, n);
  EXPECT_EQ(data["*NODE"].size(), m.node_count());
  const auto& elements = data["*ELEMENT_SHELL_THICKNESS"];
  ASSERT_EQ(elements.size(), 2 * m.shell_count());
  for (std::size_t i = 0; i < elements.size(); i += 2) {
    parse(elements[i].second, kElement, elements[i].first);
    const auto h = parse(elements[i + 1].second, kThickness, elements[i + 1].first);
    EXPECT_TRUE(h[0] > 0.0 && h[0] == h[1] && h[1] == h[2] && h[2] == h[3]);
  }
  // 2 x 2 Gauss points in the plane, NIP 3 Gauss points through the thickness:
  // T = -sqrt(3/5), 0, +sqrt(3/5) (the closed form of the 3-point rule).
  const double gauss[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const auto& stress = data["*INITIAL_STRESS_SHELL"];
  ASSERT_EQ(stress.size(), m.shell_count() * (1 + 4 * 3 * 2));
  for (std::size_t i = 0; i < stress.size();) {
    const auto header = parse(stress[i].second, kStressHeader, stress[i].first);
    EXPECT_EQ(header[1], 4);  // NPLANE
    EXPECT_EQ(header[2], 3);  // NTHICK
    EXPECT_EQ(header[3], 0);  // NHISV
    EXPECT_EQ(header[5], 1);  // LARGE
    ++i;
    for (int k = 0; k < 3; ++k) {
      for (int g = 0; g < 4; ++g, i += 2) {
        const auto a = parse(stress[i].second, kStressLarge1, stress[i].first);
        const auto b = parse(stress[i + 1].second, kStressLarge2, stress[i + 1].first);
        EXPECT_NEAR(a[0], gauss[k], 1e-8);  // 9 significant digits
        EXPECT_GE(b[2], 0.0);               // EPS
        // A blank leads every field, so that a reader splitting at blanks finds them too.
        for (std::size_t c = 0; c < 5; ++c)
          EXPECT_EQ(stress[i].second[16 * c], ' ') << "line " << stress[i].first;
      }
    }
  }
  const auto& strain = data["*INITIAL_STRAIN_SHELL"];
  ASSERT_EQ(strain.size(), m.shell_count() * (1 + 2 * 2));
  for (std::size_t i = 0; i < strain.size(); i += 5) {
    const auto header = parse(strain[i].second, kStrainHeader, strain[i].first);
    EXPECT_EQ(header[1], 1);  // NPLANE
    EXPECT_EQ(header[2], 2);  // NTHICK: inner and outer surfaces
    EXPECT_EQ(header[3], 1);  // LARGE
    EXPECT_EQ(header[4], 0);  // ILOCAL: global axes
    for (int k = 0; k < 2; ++k) {
      parse(strain[i + 1 + 2 * k].second, kStrainLarge1, strain[i + 1 + 2 * k].first);
      const auto b =
          parse(strain[i + 2 + 2 * k].second, kStrainLarge2, strain[i + 2 + 2 * k].first);
      EXPECT_EQ(b[1], k == 0 ? -1.0 : 1.0);
    }
  }
}

}  // namespace
}  // namespace plyform
