// *BOUNDARY_SPC_SET in a local coordinate system (CID) against the closed form. A free shell
// square, every node pushed by the same constant force f, held by an SPC in a tilted system:
// with local y and z fixed it may only slide along local x, u = (f . e_x) t^2 / (2 m) e_x;
// with local z fixed it moves in the local x-y plane, u = (f - (f . e_z) e_z) t^2 / (2 m).
// (All nodes move alike, so the element does no work and the central differences are exact
// for a constant acceleration at a constant step.) The reactions, normal to the motion, do no
// work: the books close on the loads' work alone.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "plyform/keyword/read_deck.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "recording_sink.hpp"

namespace plyform {
namespace test_deck_local_spc {

using Vec = std::array<double, 3>;

constexpr double kEnd = 1.0e-4;
constexpr Vec kForce{3.0, -1.0, 2.0};  // N on every node

double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// `system`: the *DEFINE_COORDINATE_SYSTEM or _VECTOR keyword defining CID 7; `dofs`: the
/// SPC's DOFX..DOFZ flags.
std::string deck(const std::string& system, const std::string& dofs) {
  std::ostringstream os;
  os << "*KEYWORD\n*CONTROL_TERMINATION\n"
     << kEnd << ",\n*DATABASE_GLSTAT\n"
     << kEnd / 20 << ",\n*DATABASE_BINARY_D3PLOT\n"
     << kEnd / 20 << ",\n"
     << "*PART\nsquare\n1,1,1\n*SECTION_SHELL\n1,2,0.8333,3\n1.0,1.0,1.0,1.0\n"
     << "*MAT_ELASTIC\n1,7.85e-9,210000.0,0.3\n"
     << "*NODE\n1,0,0,0\n2,10,0,0\n3,10,10,0\n4,0,10,0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n"
     << "*SET_NODE_LIST\n1\n1,2,3,4\n"
     << system << "*BOUNDARY_SPC_SET\n1,7," << dofs << "\n"
     << "*DEFINE_CURVE\n1\n0.0,1.0\n1.0,1.0\n";
  for (int d = 0; d < 3; ++d)
    os << "*LOAD_NODE_SET\n1," << d + 1 << ",1," << kForce[static_cast<std::size_t>(d)] << "\n";
  os << "*END\n";
  return os.str();
}

struct Result {
  double worst = 0.0;    // largest |u - closed form| over nodes and states, mm
  double largest = 0.0;  // largest |u|, mm
  double gap = 1.0;      // |total - W| / W at the end
  double kinetic = 0.0;  // 1/2 m v^2 of the last state's velocities
  std::size_t states = 0;
};

/// Runs the deck and compares every node's displacement with `direction_of_motion(f) t^2/2m`.
Result run(const std::string& text, const Vec& acceleration_direction_force) {
  const keyword::ReadResult read = keyword::read_deck_text(text, "square.k");
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().to_string());
  const auto invalid = setup::validate(read.model);
  EXPECT_TRUE(invalid.empty()) << invalid.front().to_string();
  const setup::BuildResult built = setup::build(read.model);
  EXPECT_TRUE(built.errors.empty()) << built.errors.front().to_string();
  Result out;
  if (!built.model)
    return out;
  test::RecordingSink sink;
  sink.on_state = [&](const engine::Snapshot& s) {
    ++out.states;
    const engine::NodalState& st = *s.nodes;
    out.kinetic = 0.0;
    for (std::size_t i = 0; i < st.mass.size(); ++i)
      out.kinetic += 0.5 * st.mass[i] *
                     (st.vnx[i] * st.vnx[i] + st.vny[i] * st.vny[i] + st.vnz[i] * st.vnz[i]);
    for (std::size_t i = 0; i < 4; ++i) {
      const double c = 0.5 * s.time * s.time / st.mass[i];
      const Vec u{st.ux[i], st.uy[i], st.uz[i]};
      for (std::size_t d = 0; d < 3; ++d) {
        out.worst = std::max(out.worst, std::abs(u[d] - c * acceleration_direction_force[d]));
        out.largest = std::max(out.largest, std::abs(u[d]));
      }
    }
  };
  const engine::RunResult r = engine::run(*built.model, sink, {});
  EXPECT_TRUE(r.ok) << r.error;
  const engine::Energies& e = sink.energies.back();
  // The books against 1/2 m v^2 of the velocities at the end: a body under a constant force
  // gains exactly the trapezoidal work of the force in that energy. (glstat's kinetic book is
  // the one the central differences conserve, 1/8 m (a dt)^2 below it here: docs/energy.md.)
  out.gap = std::abs(e.total - e.kinetic + out.kinetic - e.external_work) / e.external_work;
  return out;
}

TEST(DeckLocalSpc, SlidesOnlyAlongTheFreeLocalDirections) {
  // CID 7 by three points: origin (1, 2, 3), x along (1, 2, 2) / 3, the x-y point off it.
  const std::string system = "*DEFINE_COORDINATE_SYSTEM\n7,1,2,3,2,4,5\n1,2,4\n";
  const Vec ex{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  // Local y and z fixed: along e_x only.
  const double along = dot(kForce, ex);
  const Result slide = run(deck(system, "0,1,1"), {along * ex[0], along * ex[1], along * ex[2]});
  EXPECT_GT(slide.states, 10u);
  EXPECT_GT(slide.largest, 1e-3);
  EXPECT_LT(slide.worst, 1e-12 * slide.largest);
  EXPECT_LT(slide.gap, 1e-9);
  std::printf("along e_x: |u| up to %.4e mm, error %.2e mm, energy gap %.2e\n", slide.largest,
              slide.worst, slide.gap);
  // The same system by two vectors (*DEFINE_COORDINATE_VECTOR, origin at 0: a system's origin
  // does not matter to directions), local z fixed: in the local x-y plane. e_z is normal to
  // e_x and to the x-y vector (0, 1, 1): e_x x (0, 1, 1) = (0, -1/3, 1/3), normalised.
  const std::string vectors = "*DEFINE_COORDINATE_VECTOR\n7,1,2,2,0,1,1\n";
  const Vec ez{0.0, -std::sqrt(0.5), std::sqrt(0.5)};
  const double normal = dot(kForce, ez);
  const Result plane =
      run(deck(vectors, "0,0,1"),
          {kForce[0] - normal * ez[0], kForce[1] - normal * ez[1], kForce[2] - normal * ez[2]});
  EXPECT_GT(plane.largest, 1e-3);
  EXPECT_LT(plane.worst, 1e-12 * plane.largest);
  EXPECT_LT(plane.gap, 1e-9);
  std::printf("in the x-y plane: |u| up to %.4e mm, error %.2e mm, energy gap %.2e\n",
              plane.largest, plane.worst, plane.gap);
}

}  // namespace test_deck_local_spc
}  // namespace plyform
