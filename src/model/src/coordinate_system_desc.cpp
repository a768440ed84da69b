#include "plyform/model/coordinate_system_desc.hpp"

#include <algorithm>
#include <cmath>

namespace plyform::model {
namespace {

using Vec = std::array<double, 3>;

Vec minus(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}
Vec scaled(const Vec& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}

}  // namespace

std::optional<std::array<std::array<double, 3>, 3>> coordinate_axes(
    const CoordinateSystemDesc& system) {
  const Vec x = minus(system.on_x, system.origin);
  const Vec v = minus(system.in_xy, system.origin);
  const double lx = norm(x), lv = norm(v);
  // Both vectors need a length, and the x-y vector must leave the x axis by more than
  // round-off: |x cross v| is lx lv sin(angle), tested against a relative 1e-10.
  if (!(lx > 0.0) || !(lv > 0.0))
    return std::nullopt;
  const Vec z = cross(x, v);
  const double lz = norm(z);
  if (!(lz > 1e-10 * lx * lv))
    return std::nullopt;
  const Vec ex = scaled(x, 1.0 / lx);
  const Vec ez = scaled(z, 1.0 / lz);
  return std::array<std::array<double, 3>, 3>{ex, cross(ez, ex), ez};
}

}  // namespace plyform::model
