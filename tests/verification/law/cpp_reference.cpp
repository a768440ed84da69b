// The C++ side of the Fortran test: runs the same path through plyform::law::Law directly.
#include <optional>
#include <vector>

#include "plyform/law/law.hpp"

extern "C" int cpp_reference_separation(const double* uc, int n_uc, int n_steps, double dt,
                                        double temperature, double k_normal, const double* gaps,
                                        double* pressure, double* beta) {
  try {
    std::vector<std::optional<double>> constants(uc, uc + n_uc);
    const auto built = plyform::law::from_user_constants(constants, {});
    if (!built.ok())
      return 1;
    const plyform::law::Law law(built.parameters);
    plyform::law::NodeHistory h = law.initial_history(gaps[0]);
    for (int i = 1; i < n_steps; ++i) {
      plyform::law::Increment in;
      in.gap = gaps[i];
      in.dt = dt;
      in.temperature = temperature;
      in.k_normal = k_normal;
      in.k_tangent = k_normal;
      const plyform::law::Response r = law.update(in, h);
      pressure[i] = r.pressure;
      beta[i] = h.beta;
    }
    return 0;
  } catch (...) {
    return 2;
  }
}
