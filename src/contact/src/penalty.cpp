#include "penalty.hpp"

#include <algorithm>
#include <cmath>

namespace plyform::contact {

namespace {

// The passes that tie a node hold it together, in tension as in compression, all the time: a
// core between two skins tied by two-pass tiebreak contacts is held by four springs, each
// voting a step as if alone. At kToolPenaltyScale each, their sum reached the central
// difference's limit on their own (sqrt(k / m*) dt0 = 2 for the four), the ties failed within
// microseconds at sub-micrometre motions and the interface gave energy (the hot draw with
// tiebreak interfaces, n 10: 6 of 31 history nodes failed in 60 us, contact energy -1.9 % of
// what entered, the kinetic book negative). Each tie's spring gets its share of one tool
// spring's budget: the budget over the most tie passes at any of its nodes. A layer's cohesive
// passes meet the same budget by their scale (four at kLayerPenaltyScale make one).
double tie_share(const PassRuntime& pr, std::size_t k, core::Index s) {
  const core::ContactPass& cp = *pr.pass;
  unsigned most = pr.ties_at[static_cast<std::size_t>(cp.slave_nodes[k])];
  for (int j = 0; j < 4; ++j)
    most = std::max<unsigned>(
        most, pr.ties_at[static_cast<std::size_t>(
                  cp.segments[4 * static_cast<std::size_t>(s) + static_cast<std::size_t>(j)])]);
  return most > 1 ? 1.0 / most : 1.0;
}

}  // namespace

double penalty(const PassRuntime& pr, std::size_t k, core::Index s, double m_eff) {
  const core::ContactInterface& ci = *pr.iface;
  const double ks = pr.pass->slave_stiffness[k];
  const double km = pr.pass->segment_stiffness[static_cast<std::size_t>(s)];
  double kk = ci.penopt == 2 ? km : ci.penopt == 3 ? ks : std::min(ks, km);
  if (ci.penopt == 0) {
    // A layer interface (core::ContactInterface::penopt): the stiffer side's penalty, so that
    // a soft core does not let the press sink stiff skins into it, held where the spring's
    // frequency on the pair's mass would reach half the first step's (sqrt(k / m*) dt0 =
    // 1/2): together with the elements' highest mode at the node, still inside the central
    // difference's limit, and its step vote never binds.
    double hi = std::max(ks, km);
    if (pr.dt0 > 0.0 && m_eff > 0.0)
      hi = std::min(hi, kLayerPenaltyScale * m_eff / (pr.dt0 * pr.dt0));
    kk = std::max(kk, hi);
  }
  if (ci.penalty == core::PenaltyKind::mass && pr.dt0 > 0.0)
    kk = std::max(kk, 0.5 * ci.sofscl * m_eff / (pr.dt0 * pr.dt0));
  else if (ci.penopt != 0 && pr.dt0 > 0.0 && m_eff > 0.0) {
    const double budget = kToolPenaltyScale * (pr.ties_at != nullptr ? tie_share(pr, k, s) : 1.0);
    kk = std::min(kk, budget * m_eff / (pr.dt0 * pr.dt0));
  }
  return kk;
}

}  // namespace plyform::contact
