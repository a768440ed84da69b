#include "plyform/law/point_driver.hpp"

#include <stdexcept>
#include <string>

namespace plyform::law {

std::vector<PathSample> drive(const Law& law, std::span<const PathPoint> path,
                              const DriverSettings& settings) {
  std::vector<PathSample> out;
  if (path.empty())
    return out;
  out.reserve(path.size());
  NodeHistory h = law.initial_history(path[0].gap);
  out.push_back(PathSample{path[0], Response{}, h});
  Increment in;
  in.k_normal = settings.k_normal;
  in.k_tangent = settings.k_tangent > 0.0 ? settings.k_tangent : settings.k_normal;
  in.area = settings.area;
  in.mass = settings.mass;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const PathPoint& a = path[i - 1];
    const PathPoint& b = path[i];
    in.dt = b.time - a.time;
    if (!(in.dt > 0.0)) {
      throw std::invalid_argument("path row " + std::to_string(i + 1) +
                                  ": time must increase (dt = " + std::to_string(in.dt) + ")");
    }
    in.gap = b.gap;
    in.slip[0] = b.slip[0] - a.slip[0];
    in.slip[1] = b.slip[1] - a.slip[1];
    in.temperature = b.temperature;
    const Response r = law.update(in, h);
    out.push_back(PathSample{b, r, h});
  }
  return out;
}

double interface_work(std::span<const PathSample> s) {
  double w = 0.0;
  for (std::size_t i = 1; i < s.size(); ++i) {
    const Response& a = s[i - 1].response;
    const Response& b = s[i].response;
    const double dg = s[i].at.gap - s[i - 1].at.gap;
    const double ds0 = s[i].at.slip[0] - s[i - 1].at.slip[0];
    const double ds1 = s[i].at.slip[1] - s[i - 1].at.slip[1];
    w += -0.5 * (a.pressure + b.pressure) * dg - 0.5 * (a.tau[0] + b.tau[0]) * ds0 -
         0.5 * (a.tau[1] + b.tau[1]) * ds1;
  }
  return w;
}

}  // namespace plyform::law
