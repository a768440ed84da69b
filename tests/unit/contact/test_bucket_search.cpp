// Bucket search of contact segments (plyform/contact/bucket_search.hpp): the candidate list of
// every query point must be exactly the brute-force list of the segments whose bounding box,
// grown by the segment's radius, contains the point, in increasing segment order.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "plyform/contact/bucket_search.hpp"

namespace {

using plyform::contact::BucketSearch;
using plyform::core::Index;

constexpr std::size_t kStride = 5;  // not 3: the search must honour the stride

struct Scene {
  std::vector<double> coords;  // kStride per node: x y z, then two unused slots
  std::vector<Index> segments;
  std::vector<double> radius;
  std::vector<Index> queries;  // node indices of the query points

  Index add_node(double x, double y, double z) {
    for (const double v : {x, y, z, 1e30, -1e30})
      coords.push_back(v);
    return static_cast<Index>(coords.size() / kStride - 1);
  }
  [[nodiscard]] const double* at(Index n) const {
    return &coords[kStride * static_cast<std::size_t>(n)];
  }
};

// The reference: every segment tested against every point.
std::vector<std::vector<Index>> brute_force(const Scene& s) {
  const std::size_t ns = s.segments.size() / 4;
  std::vector<std::vector<Index>> out(s.queries.size());
  for (std::size_t q = 0; q < s.queries.size(); ++q) {
    const double* p = s.at(s.queries[q]);
    for (std::size_t k = 0; k < ns; ++k) {
      bool inside = true;
      for (int d = 0; d < 3; ++d) {
        double lo = 1e300, hi = -1e300;
        for (int j = 0; j < 4; ++j) {
          const double v = s.at(s.segments[4 * k + static_cast<std::size_t>(j)])[d];
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        inside = inside && p[d] >= lo - s.radius[k] && p[d] <= hi + s.radius[k];
      }
      if (inside)
        out[q].push_back(static_cast<Index>(k));
    }
  }
  return out;
}

// Runs the search on 1 and 2 threads and compares every list with the brute force; returns
// the total number of candidates (so that a test can check it is not trivially empty).
std::size_t check(const Scene& s) {
  BucketSearch grid;
  grid.build(s.segments, s.coords.data(), kStride, s.radius);
  const auto ref = brute_force(s);
  const int threads0 = omp_get_max_threads();
  std::size_t total = 0;
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    omp_set_num_threads(threads);
    std::vector<std::size_t> start;
    std::vector<Index> cand;
    grid.query(s.queries, s.coords.data(), kStride, start, cand);
    EXPECT_EQ(start.size(), s.queries.size() + 1);
    if (start.size() != s.queries.size() + 1)
      break;
    EXPECT_EQ(start.front(), 0u);
    EXPECT_EQ(start.back(), cand.size());
    std::size_t mismatches = 0;
    for (std::size_t q = 0; q < s.queries.size(); ++q) {
      const std::vector<Index> got(cand.begin() + static_cast<std::ptrdiff_t>(start[q]),
                                   cand.begin() + static_cast<std::ptrdiff_t>(start[q + 1]));
      if (got != ref[q] && ++mismatches <= 5) {
        const double* p = s.at(s.queries[q]);
        ADD_FAILURE() << "query " << q << " at (" << p[0] << ", " << p[1] << ", " << p[2]
                      << "): " << got.size() << " candidates, brute force " << ref[q].size();
      }
    }
    EXPECT_EQ(mismatches, 0u);
    total = cand.size();
  }
  omp_set_num_threads(threads0);
  return total;
}

// A wavy sheet of quads, one in five split into a triangle, random radii.
Scene wavy_sheet(unsigned seed) {
  Scene s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> r01(0.0, 1.0);
  const int nx = 40, ny = 25;
  const double h = 0.5;
  const auto id = [&](int i, int j) { return static_cast<Index>(j * (nx + 1) + i); };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = h * i + 0.1 * (r01(rng) - 0.5), y = h * j + 0.1 * (r01(rng) - 0.5);
      s.add_node(x, y, 0.8 * std::sin(0.4 * x) * std::cos(0.3 * y));
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Index q[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      const bool tri = (i + 2 * j) % 5 == 0;
      s.segments.insert(s.segments.end(), {q[0], q[1], q[2], tri ? q[2] : q[3]});
      s.radius.push_back(0.3 * h * r01(rng));
    }
  // Query points: random ones around and beyond the sheet, and the mesh nodes themselves.
  std::uniform_real_distribution<double> x(-2.0, nx * h + 2.0), y(-2.0, ny * h + 2.0), z(-1.5, 1.5);
  for (int k = 0; k < 4000; ++k)
    s.queries.push_back(s.add_node(x(rng), y(rng), z(rng)));
  for (int k = 0; k < (nx + 1) * (ny + 1); k += 3)
    s.queries.push_back(static_cast<Index>(k));
  return s;
}

TEST(BucketSearch, WavySheetMatchesBruteForce) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Scene s = wavy_sheet(seed);
    EXPECT_GT(check(s), 1000u) << "seed " << seed;
  }
}

TEST(BucketSearch, RandomSoupMatchesBruteForce) {
  // Segments of sizes over three decades (a few much larger than the rest), random radii
  // (some zero), points in and around their cloud.
  for (unsigned seed : {7u, 8u, 9u}) {
    Scene s;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> r01(0.0, 1.0), centre(0.0, 10.0);
    for (int k = 0; k < 600; ++k) {
      const double size = 0.01 * std::pow(300.0, r01(rng));
      const double c[3] = {centre(rng), centre(rng), 0.3 * centre(rng)};
      Index q[4];
      for (Index& n : q)
        n = s.add_node(c[0] + size * (r01(rng) - 0.5), c[1] + size * (r01(rng) - 0.5),
                       c[2] + size * (r01(rng) - 0.5));
      if (k % 4 == 0)
        q[3] = q[2];
      s.segments.insert(s.segments.end(), {q[0], q[1], q[2], q[3]});
      s.radius.push_back(k % 7 == 0 ? 0.0 : 0.5 * r01(rng));
    }
    std::uniform_real_distribution<double> around(-1.5, 11.5), az(-1.5, 4.5);
    for (int k = 0; k < 5000; ++k)
      s.queries.push_back(s.add_node(around(rng), around(rng), az(rng)));
    // Segment nodes are queries too (points on box faces and corners).
    for (int k = 0; k < 600; ++k)
      s.queries.push_back(s.segments[4 * static_cast<std::size_t>(k)]);
    EXPECT_GT(check(s), 1000u) << "seed " << seed;
  }
}

TEST(BucketSearch, FlatSheetWithZeroRadius) {
  // Zero thickness of the whole cloud in z and no growth: only points on the plane, inside
  // (or on the edge of) a segment's box, are candidates.
  Scene s;
  const int n = 10;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      s.add_node(i, j, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto id = [&](int a, int b) { return static_cast<Index>(b * (n + 1) + a); };
      s.segments.insert(s.segments.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      s.radius.push_back(0.0);
    }
  s.queries.push_back(s.add_node(3.5, 4.5, 0.0));   // one segment
  s.queries.push_back(s.add_node(3.0, 4.5, 0.0));   // on an edge: two
  s.queries.push_back(s.add_node(3.0, 4.0, 0.0));   // on a corner: four
  s.queries.push_back(s.add_node(3.5, 4.5, 1e-9));  // off the plane: none
  s.queries.push_back(s.add_node(10.0, 10.0, 0.0));
  s.queries.push_back(s.add_node(-1e-12, 5.0, 0.0));
  EXPECT_EQ(check(s), 1u + 2u + 4u + 0u + 1u + 0u);
}

TEST(BucketSearch, NoSegments) {
  Scene s;
  s.queries.push_back(s.add_node(0, 0, 0));
  s.queries.push_back(s.add_node(1, 2, 3));
  EXPECT_EQ(check(s), 0u);
}

TEST(BucketSearch, GridStaysSmall) {
  // The grid is capped at a few cells per segment, even for a cloud with one far outlier.
  Scene s = wavy_sheet(4);
  const Index far = s.add_node(1e4, -1e4, 5e3);
  s.segments.insert(s.segments.end(), {far, far, far, far});
  s.radius.push_back(1.0);
  s.queries.push_back(far);
  check(s);
  BucketSearch grid;
  grid.build(s.segments, s.coords.data(), kStride, s.radius);
  EXPECT_LE(grid.cell_count(), 4 * (s.segments.size() / 4) + 64);
}

}  // namespace
