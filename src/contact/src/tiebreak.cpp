#include "plyform/contact/tiebreak.hpp"

#include <cmath>

namespace plyform::contact {

void tie_node(const law::BatchHistory& h, const TieArrays& tie, std::size_t k, double gap) {
  tie.state[k] = static_cast<std::int8_t>(TieState::tied);
  tie.gap0[k] = gap;
  h.state[k] =
      static_cast<std::int32_t>(gap <= 0.0 ? law::NodeState::contact : law::NodeState::separating);
  h.beta[k] = 1.0;
  h.gap[k] = gap;
  h.damping[k] = 0.0;
  h.slip_x[k] = h.slip_y[k] = 0.0;
  h.opening_x[k] = h.opening_y[k] = 0.0;
}

namespace {

law::Increment increment(const law::BatchInput& in, std::size_t i) {
  law::Increment inc;
  inc.gap = in.gap[i];
  inc.slip[0] = in.slip_x[i];
  inc.slip[1] = in.slip_y[i];
  inc.dt = in.dt;
  inc.temperature = in.temperature[i];
  inc.k_normal = in.k_normal[i];
  inc.k_tangent = in.k_tangent[i];
  inc.area = in.area[i];
  inc.mass = in.mass != nullptr ? in.mass[i] : 0.0;
  return inc;
}

// The law's update of node i; returns the energy it holds now.
double law_update(const law::Law& law, const law::BatchInput& in, const law::BatchHistory& h,
                  const law::BatchOutput& out, std::size_t i) {
  law::NodeHistory nh = law::load_history(h, i);
  const law::Response r = law.update(increment(in, i), nh);
  law::store_history(h, i, nh);
  out.pressure[i] = r.pressure;
  out.tau_x[i] = r.tau[0];
  out.tau_y[i] = r.tau[1];
  if (out.stored != nullptr)
    out.stored[i] = r.stored;
  return r.stored;
}

// The friction limit of a tied OPTION 4 node: SFLS (PARAM = 1), else the law's Coulomb limit
// mu(T) p (with its static-to-dynamic decay and VC cap), nothing in tension.
double sliding_limit(const core::Tiebreak& tb, const law::Parameters& p, double pressure,
                     double temperature, double slip_rate) {
  if (tb.sfls_is_friction_limit)
    return tb.sfls;
  if (pressure <= 0.0)
    return 0.0;
  double mu = law::evaluate(p.mu, p, temperature);
  if (p.decay_dc > 0.0)
    mu *= p.dynamic_ratio + (1.0 - p.dynamic_ratio) * std::exp(-p.decay_dc * slip_rate);
  double limit = mu * pressure;
  if (p.friction_limit > 0.0 && limit > p.friction_limit)
    limit = p.friction_limit;
  return limit;
}

}  // namespace

void tiebreak_update(const core::Tiebreak& tb, const law::Law& law, const law::BatchInput& in,
                     const law::BatchHistory& h, const TieArrays& tie,
                     const law::BatchOutput& out) {
  const law::Parameters& p = law.parameters();
  for (std::size_t i = 0; i < in.count; ++i) {
    const double g = in.gap[i];
    auto st = static_cast<TieState>(tie.state[i]);
    if (st == TieState::free && tb.ties_on_contact() && g <= 0.0) {
      // It touches: it is held at the surface from now on (a rest gap of 0, so that the
      // penetration of its arrival is pushed out as in plain contact).
      tie_node(h, tie, i, 0.0);
      st = TieState::tied;
    }
    if (st != TieState::tied) {
      law_update(law, in, h, out, i);
      continue;
    }
    const double a = in.area[i];
    const double kn = in.k_normal[i];
    const double kt = in.k_tangent[i];
    const double opening = g - tie.gap0[i];
    double pressure = -kn * opening;
    // The contact's normal damping (VDC, percent of critical on the spring and the pair's
    // effective mass, as the law damps a bonded node): a tie is a stiff spring between two
    // layers, and undamped its mode rang through the hot draw's stack at +-0.45 MPa, close to
    // the ties' strength, wherever the press shook the sheet (the middle of the bottom failed
    // at 0.75 ms at a mean pressure of +0.25 MPa and no shear).
    // Its work is booked as the contact's work is, each traction on half the step before and
    // half the step after its time: the last cycle's second half now, this one's first half if
    // the tie holds. Booked as c (dg/dt)^2 dt, the damper took (zeta omega dt) more than its
    // force did (1.5 % at zeta 0.1, omega dt 0.11).
    const double dg = g - h.gap[i];
    h.e_damping[i] += 0.5 * h.damping[i] * dg * a;
    h.damping[i] = 0.0;
    double damping = 0.0;
    if (p.vdc > 0.0 && in.mass != nullptr && in.mass[i] > 0.0 && in.dt > 0.0 && a > 0.0) {
      const double c = 0.02 * p.vdc * std::sqrt(kn * in.mass[i] / a);
      damping = c * dg / in.dt;
      pressure -= damping;
    }
    double s0 = h.slip_x[i] + in.slip_x[i];
    double s1 = h.slip_y[i] + in.slip_y[i];
    double tau0 = -kt * s0;
    double tau1 = -kt * s1;
    double tau_sq = tau0 * tau0 + tau1 * tau1;
    if (!tb.holds_tangential()) {
      const double ds = std::hypot(in.slip_x[i], in.slip_y[i]);
      const double limit = sliding_limit(tb, p, pressure, in.temperature[i], ds / in.dt);
      if (tau_sq > limit * limit) {
        // Return to the friction limit; the inelastic slip dissipates the step's mean
        // traction along it, kt (e_old + e_new) / 2 . slip_p (the law's rule, detail/step.hpp).
        const double scale = limit > 0.0 ? limit / std::sqrt(tau_sq) : 0.0;
        tau0 *= scale;
        tau1 *= scale;
        const double e0 = kt > 0.0 ? -tau0 / kt : 0.0, e1 = kt > 0.0 ? -tau1 / kt : 0.0;
        h.e_friction[i] +=
            0.5 * kt * ((h.slip_x[i] + e0) * (s0 - e0) + (h.slip_y[i] + e1) * (s1 - e1)) * a;
        s0 = e0;
        s1 = e1;
        tau_sq = tau0 * tau0 + tau1 * tau1;
      }
    }
    const double held = 0.5 * (kn * opening * opening + kt * (s0 * s0 + s1 * s1)) * a;
    bool fails = false;
    if (tb.can_fail()) {
      const double tension = pressure < 0.0 ? -pressure / tb.nfls : 0.0;
      double c = tension * tension;
      if (tb.holds_tangential())
        c += tau_sq / (tb.sfls * tb.sfls);
      fails = c >= 1.0;
    }
    if (fails) {
      // The bond breaks: the springs' energy is released, and the node is an ordinary contact
      // node from this cycle on (no tension; friction only under pressure).
      tie.state[i] = static_cast<std::int8_t>(TieState::failed);
      h.state[i] =
          static_cast<std::int32_t>(g <= 0.0 ? law::NodeState::contact : law::NodeState::detached);
      h.beta[i] = 0.0;
      h.slip_x[i] = h.slip_y[i] = 0.0;
      h.opening_x[i] = h.opening_y[i] = 0.0;
      // Released: what the springs held less what the contact's penalty keeps holding (a tie
      // failed in shear under pressure hands its compression on).
      h.e_damage[i] += held - law_update(law, in, h, out, i);
      continue;
    }
    h.e_damping[i] += 0.5 * damping * dg * a;
    h.damping[i] = damping;
    h.slip_x[i] = s0;
    h.slip_y[i] = s1;
    h.gap[i] = g;
    h.state[i] =
        static_cast<std::int32_t>(g <= 0.0 ? law::NodeState::contact : law::NodeState::separating);
    out.pressure[i] = pressure;
    out.tau_x[i] = tau0;
    out.tau_y[i] = tau1;
    if (out.stored != nullptr)
      out.stored[i] = held;
  }
}

}  // namespace plyform::contact
