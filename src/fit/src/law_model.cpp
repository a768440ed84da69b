#include "plyform/fit/law_model.hpp"

namespace plyform::fit {

std::vector<double> model_stress(const law::Law& law, const MeasuredCurve& curve,
                                 const ModelSettings& settings) {
  law::DriverSettings driver;
  driver.k_normal = settings.penalty > 0.0 ? settings.penalty : law.parameters().cn;
  const int n = settings.substeps > 1 ? settings.substeps : 1;
  std::vector<double> out;
  out.reserve(curve.path.size());
  if (n == 1) {
    for (const law::PathSample& s : law::drive(law, curve.path, driver))
      out.push_back(-s.response.pressure);
    return out;
  }
  std::vector<law::PathPoint> fine;
  fine.reserve((curve.path.size() - 1) * static_cast<std::size_t>(n) + 1);
  fine.push_back(curve.path.front());
  for (std::size_t i = 1; i < curve.path.size(); ++i) {
    const law::PathPoint& a = curve.path[i - 1];
    const law::PathPoint& b = curve.path[i];
    for (int k = 1; k <= n; ++k) {
      const double w = static_cast<double>(k) / n;
      law::PathPoint p;
      p.time = a.time + w * (b.time - a.time);
      p.gap = a.gap + w * (b.gap - a.gap);
      p.slip[0] = a.slip[0] + w * (b.slip[0] - a.slip[0]);
      p.slip[1] = a.slip[1] + w * (b.slip[1] - a.slip[1]);
      p.temperature = a.temperature + w * (b.temperature - a.temperature);
      fine.push_back(k == n ? b : p);
    }
  }
  const std::vector<law::PathSample> samples = law::drive(law, fine, driver);
  for (std::size_t i = 0; i < samples.size(); i += static_cast<std::size_t>(n))
    out.push_back(-samples[i].response.pressure);
  return out;
}

}  // namespace plyform::fit
