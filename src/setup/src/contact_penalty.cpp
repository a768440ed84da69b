#include "plyform/setup/contact_penalty.hpp"

#include <array>
#include <cmath>

namespace plyform::setup {
namespace {

// Area of a segment at t = 0 from its diagonals (a triangle repeats its third node, so the
// second diagonal is then an edge and the formula still gives the triangle's area).
double segment_area0(const core::Model& m, const core::ContactPass& p, std::size_t s) {
  const auto at = [&](std::size_t j) {
    const auto n = static_cast<std::size_t>(p.segments[4 * s + j]);
    return std::array<double, 3>{m.x0[n], m.y0[n], m.z0[n]};
  };
  const auto a = at(0), b = at(1), c = at(2), d = at(3);
  const double d1[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double d2[3] = {d[0] - b[0], d[1] - b[1], d[2] - b[2]};
  const double x = d1[1] * d2[2] - d1[2] * d2[1], y = d1[2] * d2[0] - d1[0] * d2[2],
               z = d1[0] * d2[1] - d1[1] * d2[0];
  return 0.5 * std::sqrt(x * x + y * y + z * z);
}

}  // namespace

std::vector<double> slave_penalty_per_area(const core::ContactPass& p) {
  std::vector<double> k(p.slave_count());
  for (std::size_t i = 0; i < k.size(); ++i)
    k[i] = p.slave_stiffness[i] / p.slave_area[i];
  return k;
}

std::vector<double> master_penalty_per_area(const core::Model& m, const core::ContactPass& p) {
  std::vector<double> k;
  for (std::size_t s = 0; s < p.segment_count(); ++s) {
    const double area = segment_area0(m, p, s);
    if (area > 0.0 && p.segment_stiffness[s] > 0.0)
      k.push_back(p.segment_stiffness[s] / area);
  }
  return k;
}

SidePenalty side_penalty(const core::Model& m, const core::ContactPass& p) {
  double ks = 0.0, as = 0.0, km = 0.0, am = 0.0;
  for (std::size_t i = 0; i < p.slave_count(); ++i) {
    ks += p.slave_stiffness[i];
    as += p.slave_area[i];
  }
  for (std::size_t s = 0; s < p.segment_count(); ++s) {
    km += p.segment_stiffness[s];
    am += segment_area0(m, p, s);
  }
  return {as > 0.0 ? ks / as : 0.0, am > 0.0 ? km / am : 0.0};
}

}  // namespace plyform::setup
