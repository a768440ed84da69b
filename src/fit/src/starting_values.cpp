#include "plyform/fit/starting_values.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "plyform/law/user_constants.hpp"

namespace plyform::fit {
namespace {

// Lambda = eta v / (omega g_c) of the starting eta at the fastest rate: the rate effect is
// then visible but moderate (peak about 2 % above sigma_max), a start from which the fit
// moves either way.
constexpr double kStartLambda = 0.3;

struct Features {
  double smax = 0.0;           ///< lowest peak tension of the curves
  double g_peak = 0.0;         ///< opening at that peak
  double fastest = 0.0;        ///< largest opening rate
  double pressure_time = 0.0;  ///< largest integral of the measured pressure over a curve's contact
  bool opens_first = false;    ///< a curve starts by opening (an initially bonded test)
  double first_gap = 0.0;      ///< largest |first gap| of those curves
};

Features features(std::span<const MeasuredCurve> curves) {
  Features f;
  f.smax = INFINITY;
  for (const MeasuredCurve& c : curves) {
    const auto it = std::max_element(c.stress.begin(), c.stress.end());
    const auto i = static_cast<std::size_t>(it - c.stress.begin());
    if (*it > 0.0 && *it < f.smax) {
      f.smax = *it;
      f.g_peak = c.path[i].gap;
    }
    double pt = 0.0;
    for (std::size_t k = 1; k < c.path.size(); ++k) {
      const double dt = c.path[k].time - c.path[k - 1].time;
      const double dg = c.path[k].gap - c.path[k - 1].gap;
      if (dg > 0.0)
        f.fastest = std::max(f.fastest, dg / dt);
      if (c.path[k].gap <= 0.0 && c.stress[k] < 0.0)
        pt += -c.stress[k] * dt;
    }
    f.pressure_time = std::max(f.pressure_time, pt);
    for (std::size_t k = 1; k < c.path.size(); ++k) {
      if (c.path[k].gap != c.path[0].gap) {
        if (c.path[k].gap > c.path[0].gap) {
          f.opens_first = true;
          f.first_gap = std::max(f.first_gap, std::abs(c.path[0].gap));
        }
        break;
      }
    }
  }
  return f;
}

}  // namespace

std::vector<std::optional<double>> default_start(std::span<const MeasuredCurve> curves,
                                                 std::vector<std::string>& notes) {
  const Features f = features(curves);
  const double smax = std::isfinite(f.smax) ? f.smax : 1.0;
  const double cn = f.g_peak > 0.0 ? smax / f.g_peak : smax;
  const double gc = smax / cn;
  const double omega = smax * smax / cn;
  const double eta = f.fastest > 0.0 ? kStartLambda * omega * gc / f.fastest : 1e-6 * omega;
  const auto table = law::user_constant_table();
  std::vector<std::optional<double>> uc(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (!table[i].required)
      uc[i] = table[i].default_from > 0 ? std::optional<double>() : table[i].default_value;
  }
  const auto set = [&](std::string_view name, double v) {
    for (const law::ConstantSpec& s : table) {
      if (name == s.name)
        uc[static_cast<std::size_t>(s.index - 1)] = v;
    }
  };
  set("CN", cn);
  set("SMAX_LO", smax);
  set("SMAX_HI", smax);
  set("ETA", eta);
  notes.push_back(fmt::format(
      "no --deck: starting constants from the curves: SMAX = {:.4g} (lowest peak tension), "
      "CN = {:.4g} (SMAX over the opening {:.4g} at that peak), ETA = {:.4g} (Lambda = eta v / "
      "(omega g_c) = {} at the fastest opening rate {:.4g})",
      smax, cn, f.g_peak, eta, kStartLambda, f.fastest));
  if (f.opens_first) {
    const double tol = f.first_gap + 1e-3 * gc;
    set("BETA0", 1.0);
    set("BOND_TOL", tol);
    notes.push_back(fmt::format(
        "the curves start by opening: the point starts bonded and intact (BETA0 = 1, BOND_TOL "
        "= {:.4g})",
        tol));
  } else {
    set("BETA0", 0.0);
    set("BOND_TOL", 0.0);
    notes.push_back(
        "the curves start by pressing: the point starts unbonded (BETA0 = 0, BOND_TOL = 0) and "
        "bonds only by healing under pressure (ZETA)");
  }
  return uc;
}

void complete_start(std::span<const FreeConstant> free, std::span<const MeasuredCurve> curves,
                    std::vector<std::optional<double>>& uc, std::vector<std::string>& notes) {
  const Features f = features(curves);
  for (const FreeConstant& c : free) {
    if (c.transform != Transform::log || value_of(c, uc) != 0.0)
      continue;
    if ((c.name == "ZETA" || c.name == "ZETA_LO" || c.name == "ZETA_HI") && f.pressure_time > 0.0) {
      // Half healing over the longest measured hold: beta_h = zeta * integral of P dt.
      const double zeta = 0.5 / f.pressure_time;
      set_value(c, zeta, uc);
      notes.push_back(fmt::format(
          "{} starts at 0 (no healing); the fit starts it at {:.4g}, which heals half over "
          "the longest measured hold (integral of the pressure {:.4g})",
          c.name, zeta, f.pressure_time));
    }
  }
}

}  // namespace plyform::fit
