// Closest-point projection on contact segments (plyform/contact/segment_projection.hpp),
// checked against independent references: the closed form of flat quadrilaterals and
// triangles (orthogonal projection on the plane, barycentric coordinates from signed areas),
// and a brute-force zooming search over the parametric square of warped quadrilaterals.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "plyform/contact/segment_projection.hpp"

namespace {

using plyform::contact::project_quad;
using plyform::contact::project_triangle;
using plyform::contact::SegmentPoint;
using V3 = std::array<double, 3>;

V3 sub(const V3& a, const V3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V3 add(const V3& a, const V3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
V3 scale(double s, const V3& a) {
  return {s * a[0], s * a[1], s * a[2]};
}
double dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const V3& a) {
  return std::sqrt(dot(a, a));
}
V3 unit(const V3& a) {
  return scale(1.0 / norm(a), a);
}
V3 point_of(const SegmentPoint& s) {
  return {s.x[0], s.x[1], s.x[2]};
}
V3 normal_of(const SegmentPoint& s) {
  return {s.normal[0], s.normal[1], s.normal[2]};
}

// A bilinear quadrilateral with its own map and tangents (the reference, not the code's).
struct Quad {
  std::array<V3, 4> c;
  [[nodiscard]] static std::array<double, 4> shape(double xi, double eta) {
    return {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta), 0.25 * (1 + xi) * (1 + eta),
            0.25 * (1 - xi) * (1 + eta)};
  }
  [[nodiscard]] V3 at(double xi, double eta) const {
    const auto n = shape(xi, eta);
    V3 x{0, 0, 0};
    for (int j = 0; j < 4; ++j)
      x = add(x, scale(n[static_cast<std::size_t>(j)], c[static_cast<std::size_t>(j)]));
    return x;
  }
  [[nodiscard]] V3 t_xi(double eta) const {
    return add(scale(0.25 * (1 - eta), sub(c[1], c[0])), scale(0.25 * (1 + eta), sub(c[2], c[3])));
  }
  [[nodiscard]] V3 t_eta(double xi) const {
    return add(scale(0.25 * (1 - xi), sub(c[3], c[0])), scale(0.25 * (1 + xi), sub(c[2], c[1])));
  }
  [[nodiscard]] SegmentPoint project(const V3& p, double xi0 = 0.0, double eta0 = 0.0) const {
    const double* cc[4] = {c[0].data(), c[1].data(), c[2].data(), c[3].data()};
    return project_quad(p.data(), cc, xi0, eta0);
  }
  [[nodiscard]] Quad reversed() const { return Quad{{c[0], c[3], c[2], c[1]}}; }
};

// Parametric coordinates from the 4 shape functions (exact for bilinear shapes).
void parametric(const SegmentPoint& s, double& xi, double& eta) {
  xi = s.shape[1] + s.shape[2] - s.shape[0] - s.shape[3];
  eta = s.shape[2] + s.shape[3] - s.shape[0] - s.shape[1];
}

// Closest point of the parametric square [-1, 1]^2 by dense sampling, zooming in on the best
// sample (11 rounds of 81 x 81 samples).
struct BruteForce {
  double xi = 0.0, eta = 0.0, dist = 0.0;
};
BruteForce brute_force(const Quad& q, const V3& p) {
  BruteForce b;
  double cx = 0.0, cy = 0.0, hw = 1.0;
  constexpr int n = 81;
  double best = 1e300;
  for (int round = 0; round < 11; ++round) {
    const double step = 2.0 * hw / (n - 1);
    double bx = cx, by = cy;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double xi = std::clamp(cx - hw + i * step, -1.0, 1.0);
        const double eta = std::clamp(cy - hw + j * step, -1.0, 1.0);
        const V3 r = sub(p, q.at(xi, eta));
        const double d = dot(r, r);
        if (d < best) {
          best = d;
          bx = xi;
          by = eta;
        }
      }
    cx = bx;
    cy = by;
    hw = 4.0 * step;
  }
  b.xi = cx;
  b.eta = cy;
  b.dist = std::sqrt(best);
  return b;
}

// What every projection must satisfy, whatever the segment.
void check_consistency(const SegmentPoint& s, const V3& p, int nodes, const V3* c) {
  ASSERT_FALSE(s.degenerate);
  double sum = 0.0;
  V3 x{0, 0, 0};
  for (int j = 0; j < nodes; ++j) {
    sum += s.shape[j];
    x = add(x, scale(s.shape[j], c[j]));
  }
  if (nodes == 3) {
    EXPECT_EQ(s.shape[3], 0.0);
  }
  EXPECT_NEAR(sum, 1.0, 1e-14);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(x[k], s.x[k], 1e-12);
  EXPECT_NEAR(norm(normal_of(s)), 1.0, 1e-14);
  EXPECT_NEAR(s.distance, dot(sub(p, point_of(s)), normal_of(s)), 1e-12);
}

TEST(ProjectQuad, FlatSquareMatchesClosedForm) {
  // Square [0, 2]^2 at z = 0.5, counter-clockwise seen from +z: xi = x - 1, eta = y - 1.
  const Quad q{{V3{0, 0, 0.5}, V3{2, 0, 0.5}, V3{2, 2, 0.5}, V3{0, 2, 0.5}}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> in(0.0, 2.0), h(-0.8, 0.8);
  for (int trial = 0; trial < 200; ++trial) {
    const V3 p{in(rng), in(rng), 0.5 + h(rng)};
    const SegmentPoint s = q.project(p);
    check_consistency(s, p, 4, q.c.data());
    EXPECT_NEAR(s.x[0], p[0], 1e-12);
    EXPECT_NEAR(s.x[1], p[1], 1e-12);
    EXPECT_NEAR(s.x[2], 0.5, 1e-12);
    EXPECT_NEAR(s.normal[2], 1.0, 1e-14);
    EXPECT_NEAR(s.distance, p[2] - 0.5, 1e-12);
    const auto ref = Quad::shape(p[0] - 1.0, p[1] - 1.0);
    for (std::size_t j = 0; j < 4; ++j)
      EXPECT_NEAR(s.shape[j], ref[j], 1e-12);
    EXPECT_EQ(s.outside, 0.0);
  }
}

TEST(ProjectQuad, FlatSquareOutsideMeasure) {
  // Outside the square the measure is max(|xi|, |eta|) - 1 of the (unconstrained) plane
  // projection.
  const Quad q{{V3{0, 0, 0}, V3{2, 0, 0}, V3{2, 2, 0}, V3{0, 2, 0}}};
  struct Case {
    double x, y, outside;
  };
  for (const Case c :
       {Case{2.5, 1.0, 0.5}, Case{-0.2, 1.3, 0.2}, Case{1.0, 3.1, 1.1}, Case{-1.0, -0.4, 1.0},
        Case{2.01, 1.99, 0.01}, Case{2.0, 2.0, 0.0}, Case{0.0, 1.0, 0.0}}) {
    const V3 p{c.x, c.y, 0.3};
    const SegmentPoint s = q.project(p);
    check_consistency(s, p, 4, q.c.data());
    EXPECT_NEAR(s.outside, c.outside, 1e-12) << c.x << " " << c.y;
    EXPECT_NEAR(s.x[0], c.x, 1e-12);
    EXPECT_NEAR(s.x[1], c.y, 1e-12);
    EXPECT_NEAR(s.distance, 0.3, 1e-12);
  }
}

TEST(ProjectQuad, FlatTrapezoidInTiltedPlane) {
  // A flat but non-parallelogram quad (the bilinear map is not affine) in a tilted plane: the
  // closest point of an interior projection is the orthogonal projection on the plane.
  const V3 u = unit(V3{1, 0.3, 0.4}), w0{0, 1, 0};
  const V3 w = unit(sub(w0, scale(dot(w0, u), u)));
  const V3 n = cross(u, w);
  const V3 o{0.4, -1.0, 2.0};
  const auto P = [&](double a, double b) { return add(o, add(scale(a, u), scale(b, w))); };
  const Quad q{{P(0, 0), P(3, 0), P(2.2, 1.5), P(0.5, 1.8)}};
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> r01(0.0, 1.0), h(-0.5, 0.5);
  for (int trial = 0; trial < 200; ++trial) {
    // A point inside: a bilinear image of the parametric square, lifted off the plane.
    const double xi = 1.8 * r01(rng) - 0.9, eta = 1.8 * r01(rng) - 0.9, d = h(rng);
    const V3 p = add(q.at(xi, eta), scale(d, n));
    const SegmentPoint s = q.project(p);
    check_consistency(s, p, 4, q.c.data());
    const V3 expect = sub(p, scale(dot(sub(p, o), n), n));
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(s.x[k], expect[k], 1e-10);
    EXPECT_NEAR(dot(normal_of(s), n), 1.0, 1e-12);
    EXPECT_NEAR(s.distance, d, 1e-10);
    const auto ref = Quad::shape(xi, eta);
    for (std::size_t j = 0; j < 4; ++j)
      EXPECT_NEAR(s.shape[j], ref[j], 1e-9);
    EXPECT_EQ(s.outside, 0.0);
  }
}

// Closest points on warped quadrilaterals: compared with the brute-force search, for points
// whose closest point of the square is interior (where the projection's stationary point is
// the minimum), at most `hmax` from the surface.
struct Tolerance {
  double parametric, orthogonal, distance;
};
void check_warped(const Quad& q, unsigned seed, double hmax, Tolerance tol) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> r(-0.85, 0.85), h(-hmax, hmax);
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const double xi = r(rng), eta = r(rng);
    const V3 nn = unit(cross(q.t_xi(eta), q.t_eta(xi)));
    const V3 p = add(q.at(xi, eta), scale(h(rng), add(nn, V3{0.1 * r(rng), 0.1 * r(rng), 0})));
    const BruteForce b = brute_force(q, p);
    if (std::fabs(b.xi) > 0.97 || std::fabs(b.eta) > 0.97)
      continue;  // the minimum is on the boundary: not the unconstrained stationary point
    ++checked;
    const SegmentPoint s = q.project(p);
    check_consistency(s, p, 4, q.c.data());
    double sx = 0.0, se = 0.0;
    parametric(s, sx, se);
    EXPECT_EQ(s.outside, 0.0);
    // The distance is the minimum found by the brute force, at the same point.
    const double ds = norm(sub(p, point_of(s)));
    EXPECT_NEAR(ds, b.dist, tol.distance) << "trial " << trial;
    EXPECT_NEAR(sx, b.xi, tol.parametric) << "trial " << trial;
    EXPECT_NEAR(se, b.eta, tol.parametric) << "trial " << trial;
    // Normal: orthogonal to the tangents at the point, right-handed N1 -> N2 -> N3.
    const V3 txi = q.t_xi(se), teta = q.t_eta(sx);
    const V3 nrm = normal_of(s);
    EXPECT_NEAR(dot(nrm, txi) / norm(txi), 0.0, tol.orthogonal) << "trial " << trial;
    EXPECT_NEAR(dot(nrm, teta) / norm(teta), 0.0, tol.orthogonal) << "trial " << trial;
    EXPECT_GT(dot(nrm, cross(txi, teta)), 0.0);
    EXPECT_NEAR(std::fabs(s.distance), ds, tol.distance);
    // The reversed node order flips the normal and the sign, not the point.
    const SegmentPoint t = q.reversed().project(p);
    EXPECT_NEAR(t.distance, -s.distance, tol.distance);
    EXPECT_NEAR(dot(normal_of(t), nrm), -1.0, tol.orthogonal);
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(t.x[k], s.x[k], tol.parametric);
  }
  EXPECT_GE(checked, 25);
}

// Mildly warped, points up to about a sixth of the segment size away.
const Quad kWarped{{V3{0, 0, 0}, V3{2, 0, 0.3}, V3{2.2, 1.9, -0.25}, V3{-0.1, 1.7, 0.35}}};
// Strongly skewed (about 50 degrees between the edges) and warped, in a general position.
const Quad kSkewed{{V3{1, 1, 1}, V3{2.5, 1.2, 1.4}, V3{3.6, 2.6, 0.9}, V3{1.6, 2.2, 1.5}}};

TEST(ProjectQuad, WarpedQuadMinimisesDistance) {
  check_warped(kWarped, 21, 0.35, {1e-6, 1e-8, 1e-9});
}

TEST(ProjectQuad, SkewedWarpedQuadMinimisesDistance) {
  check_warped(kSkewed, 22, 0.12, {1e-6, 1e-6, 1e-9});
}

TEST(ProjectQuad, SkewedWarpedQuadFarPointsAreApproximate) {
  // Farther from a strongly warped segment the Gauss-Newton iteration (no curvature term)
  // converges linearly, at a rate of about distance x curvature, and stops after 8 iterations
  // without reaching its 1e-12 criterion: at a fifth of the segment size the point is off by
  // up to ~1e-3 in parametric measure (the distance only to second order). Pinned here as the
  // accuracy the contact pass gets today.
  check_warped(kSkewed, 23, 0.35, {2e-3, 2e-3, 1e-6});
}

TEST(ProjectQuad, SignFollowsNodeOrder) {
  const Quad q{{V3{0, 0, 0}, V3{1, 0, 0}, V3{1, 1, 0}, V3{0, 1, 0}}};
  const V3 above{0.3, 0.6, 0.2}, below{0.3, 0.6, -0.2};
  EXPECT_NEAR(q.project(above).distance, 0.2, 1e-14);
  EXPECT_NEAR(q.project(below).distance, -0.2, 1e-14);
  EXPECT_NEAR(q.reversed().project(above).distance, -0.2, 1e-14);
  EXPECT_NEAR(q.reversed().project(above).normal[2], -1.0, 1e-14);
}

TEST(ProjectQuad, StartingPointDoesNotChangeTheAnswer) {
  const Quad& q = kWarped;
  const V3 p = add(q.at(0.4, -0.3), V3{0.02, -0.01, 0.15});
  const SegmentPoint a = q.project(p);
  for (const auto& [x0, e0] : {std::pair{0.5, -0.5}, std::pair{-0.9, 0.9}, std::pair{0.4, -0.3}}) {
    const SegmentPoint b = q.project(p, x0, e0);
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(a.x[k], b.x[k], 1e-10);
  }
}

TEST(ProjectQuad, DegenerateQuad) {
  const V3 c{1, 2, 3};
  const Quad q{{c, c, c, c}};
  EXPECT_TRUE(q.project(V3{0, 0, 0}).degenerate);
}

// Barycentric coordinates of the plane projection from signed sub-triangle areas.
TEST(ProjectTriangle, MatchesBarycentricClosedForm) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 300; ++trial) {
    const V3 c[3] = {V3{u(rng), u(rng), u(rng)}, V3{u(rng), u(rng), u(rng)},
                     V3{u(rng), u(rng), u(rng)}};
    const V3 area2 = cross(sub(c[1], c[0]), sub(c[2], c[0]));
    if (norm(area2) < 0.3)
      continue;  // nearly degenerate: poorly conditioned either way
    const V3 n = unit(area2);
    const V3 p{u(rng), u(rng), u(rng)};
    const double d = dot(sub(p, c[0]), n);
    const V3 q = sub(p, scale(d, n));
    const double total = dot(area2, n);
    const double lam[3] = {dot(cross(sub(c[1], q), sub(c[2], q)), n) / total,
                           dot(cross(sub(c[2], q), sub(c[0], q)), n) / total,
                           dot(cross(sub(c[0], q), sub(c[1], q)), n) / total};
    const SegmentPoint s = project_triangle(p.data(), c[0].data(), c[1].data(), c[2].data());
    check_consistency(s, p, 3, c);
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(s.shape[j], lam[j], 1e-9);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_NEAR(s.x[k], q[k], 1e-9);
      EXPECT_NEAR(s.normal[k], n[k], 1e-12);
    }
    EXPECT_NEAR(s.distance, d, 1e-9);
    const double most_negative = std::min({lam[0], lam[1], lam[2]});
    if (most_negative >= 1e-9) {
      EXPECT_EQ(s.outside, 0.0);
    }
    EXPECT_NEAR(s.outside, 2.0 * std::max(0.0, -most_negative), 1e-9);
    // The opposite orientation flips the sign.
    const SegmentPoint t = project_triangle(p.data(), c[0].data(), c[2].data(), c[1].data());
    EXPECT_NEAR(t.distance, -d, 1e-9);
  }
}

TEST(ProjectTriangle, InsideAndOutside) {
  const V3 c0{0, 0, 0}, c1{1, 0, 0}, c2{0, 1, 0};
  const auto proj = [&](const V3& p) {
    return project_triangle(p.data(), c0.data(), c1.data(), c2.data());
  };
  const SegmentPoint in = proj(V3{0.25, 0.25, 0.1});
  EXPECT_EQ(in.outside, 0.0);
  EXPECT_NEAR(in.distance, 0.1, 1e-15);
  EXPECT_NEAR(in.shape[0], 0.5, 1e-15);
  EXPECT_NEAR(proj(V3{0.25, 0.25, -0.1}).distance, -0.1, 1e-15);
  // Beyond the hypotenuse: lambda_0 = 1 - x - y = -0.2.
  EXPECT_NEAR(proj(V3{0.6, 0.6, 0.0}).outside, 0.4, 1e-14);
  // Beyond a leg: lambda_2 = y = -0.1.
  EXPECT_NEAR(proj(V3{0.5, -0.1, 0.2}).outside, 0.2, 1e-14);
  const V3 same{1, 1, 1};
  EXPECT_TRUE(project_triangle(same.data(), c0.data(), c1.data(), V3{2, 0, 0}.data()).degenerate);
}

}  // namespace
