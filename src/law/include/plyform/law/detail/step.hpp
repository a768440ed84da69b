#pragma once
// The one-node update of the law. Both entry points (one node, batched arrays) instantiate
// this one function template, so they give bit-identical results. The history and the
// increment are reached through small accessor types: for the batched form they read and
// write the host's arrays in place, so each branch touches only the arrays it needs (an
// approaching node reads its gap and writes three numbers).

#include <cmath>

#include "plyform/law/node_state.hpp"
#include "plyform/law/parameters.hpp"

namespace plyform::law::detail {

/// Constants derived once from the parameters, so the kernel divides as little as possible.
struct Prepared {
  double inv_cn = 0.0;
  double inv_eta = 0.0;
  double inv_dt_range = 0.0;  ///< 1 / (T_hi - T_lo), 0 when equal
  double damping = 0.0;       ///< 2 VDC / 100
  double inv_film = 0.0;      ///< 1 / h_f
};

inline Prepared prepare(const Parameters& p) {
  Prepared q;
  q.inv_cn = 1.0 / p.cn;
  q.inv_eta = 1.0 / p.eta;
  q.inv_dt_range = p.t_hi > p.t_lo ? 1.0 / (p.t_hi - p.t_lo) : 0.0;
  q.damping = 0.02 * p.vdc;
  q.inv_film = p.film_thickness > 0.0 ? 1.0 / p.film_thickness : 0.0;
  return q;
}

/// `evaluate()` with the prepared reciprocal.
inline double at_temperature(const TemperatureDependent& t, const Parameters& p, const Prepared& q,
                             double temperature) {
  if (t.curve >= 0)
    return p.curves[static_cast<std::size_t>(t.curve)](temperature);
  if (temperature <= p.t_lo)
    return t.lo;
  if (temperature >= p.t_hi)
    return t.hi;
  return t.lo + (t.hi - t.lo) * cubic_transition((temperature - p.t_lo) * q.inv_dt_range);
}

/// Accessors over one NodeHistory / Increment (the single-node entry point).
struct NodeHistoryAccess {
  NodeHistory& h;
  NodeState state() const { return h.state; }
  void set_state(NodeState s) const { h.state = s; }
  double& beta() const { return h.beta; }
  double& gap() const { return h.gap; }
  double& slip(int k) const { return h.slip[k]; }
  double& opening(int k) const { return h.opening_t[k]; }
  double& e_damage() const { return h.e_damage; }
  double& e_viscous() const { return h.e_viscous; }
  double& e_friction() const { return h.e_friction; }
  double& e_damping() const { return h.e_damping; }
  double& e_healing() const { return h.e_healing; }
  double& damping() const { return h.damping; }
};

struct IncrementAccess {
  const Increment& in;
  double gap() const { return in.gap; }
  double slip(int k) const { return in.slip[k]; }
  double dt() const { return in.dt; }
  double temperature() const { return in.temperature; }
  double k_normal() const { return in.k_normal; }
  double k_tangent() const { return in.k_tangent; }
  double area() const { return in.area; }
  double mass() const { return in.mass; }
};

/// Zeroes a stored value only when it is not zero already: a detached node then writes
/// nothing to its slip arrays, which keeps memory traffic down in the batched loop.
inline void clear(double& x) {
  if (x != 0.0)
    x = 0.0;
}

/// A node leaving compressive contact lets go of its stick spring: the traction falls to zero
/// over the step, so the spring's energy, less the trapezoid's work on the step's slip, is
/// dissipated, kt e_old . (e_old + slip) (the trapezoid rule of the Coulomb return with
/// e_new = 0).
template <class H, class In>
inline void release_stick_spring(const In& in, const H& h) {
  const double e0 = h.slip(0);
  const double e1 = h.slip(1);
  if (e0 == 0.0 && e1 == 0.0)
    return;
  const double kt = in.k_tangent();
  h.e_friction() += 0.5 * kt * (e0 * (e0 + in.slip(0)) + e1 * (e1 + in.slip(1))) * in.area();
  h.slip(0) = 0.0;
  h.slip(1) = 0.0;
}

template <class H, class In>
inline Response step(const Parameters& p, const Prepared& q, const In& in, const H& h) {
  Response r;
  const double g = in.gap();
  const double g_old = h.gap();
  h.gap() = g;
  // The damper's work is booked as the host books the contact's work, each traction on half
  // the step before and half the step after its time: here the second half of the last
  // update's, below the first half of this one's. Booked as c g_rate^2 dt, it took zeta omega dt
  // more than its force did, and under a ringing of a few steps' period (the rate changing sign
  // each step, where the force does almost no work) many times more.
  if (h.damping() != 0.0) {
    h.e_damping() += 0.5 * h.damping() * (g - g_old) * in.area();
    h.damping() = 0.0;
  }

  // Gap-driven transitions; damage may detach the node again below.
  const NodeState s_old = h.state();
  NodeState s = s_old;
  if (g <= 0.0) {
    s = NodeState::contact;
  } else if (s == NodeState::contact) {
    s = h.beta() > 0.0 ? NodeState::separating : NodeState::detached;
  }
  if (s == NodeState::approaching || s == NodeState::detached) {
    // No force of any kind, damping included (the paper's reason for its own damping).
    if (s != s_old) {
      h.set_state(s);
      release_stick_spring(in, h);
      clear(h.opening(0));
      clear(h.opening(1));
    }
    return r;
  }

  const double temperature = in.temperature();
  const double area = in.area();
  const double dt = in.dt();
  const double smax = at_temperature(p.sigma_max, p, q, temperature);
  const double omega = smax * smax * q.inv_cn;
  double beta = h.beta();
  const double beta_in = beta;

  // Damage: backward Euler of eta beta_dot = -(Y beta - omega) while Y beta > omega.
  if (beta > 0.0) {
    double y = 0.0;
    if (g > 0.0)
      y = p.cn * g * g;
    if (p.ct > 0.0) {
      const double o0 = h.opening(0) += in.slip(0);
      const double o1 = h.opening(1) += in.slip(1);
      y += p.ct * (o0 * o0 + o1 * o1);
    }
    bool damaged = false;
    if (y * beta > omega) {
      const double a = dt * q.inv_eta;
      const double b_new = (beta + a * omega) / (1.0 + a * y);
      if (b_new < beta) {
        // Backward Euler makes (Y b_new - omega) = eta (beta - b_new) / dt >= 0: the viscous
        // part of the driving force; omega (beta - b_new) is the adhesion energy released.
        const double db = beta - b_new;
        h.e_damage() += omega * db * area;
        h.e_viscous() += (y * b_new - omega) * db * area;
        beta = b_new;
        damaged = true;
      }
    }
    const bool released = s == NodeState::separating && g > p.release_gap;
    if ((damaged && beta < p.beta_min) || released) {
      // Cut-off: the rest of the adhesion and the elastic energy it held are released.
      h.e_damage() += (omega * beta + 0.5 * y * beta * beta) * area;
      beta = 0.0;
    }
  }
  if (beta <= 0.0) {
    beta = 0.0;
    if (p.ct > 0.0) {
      clear(h.opening(0));
      clear(h.opening(1));
    }
    if (s == NodeState::separating) {
      h.set_state(NodeState::detached);
      if (beta_in != 0.0)
        h.beta() = 0.0;
      release_stick_spring(in, h);
      return r;
    }
  }

  // Normal traction: penalty in contact, RCCM cohesion C_N g beta^2 in separation. A bonded
  // node in compression is at least as stiff as its adhesive layer, C_N beta^2: the intact
  // interface is then the same elastic layer in compression and in tension (a soft penalty
  // would let bonded layers sink into each other where a bent laminate presses them).
  double p_elastic;
  double k_node;
  if (s == NodeState::contact) {
    k_node = in.k_normal();
    if (beta > 0.0 && p.cn * beta * beta > k_node)
      k_node = p.cn * beta * beta;
    p_elastic = -k_node * g;
  } else {
    k_node = p.cn * beta * beta;
    p_elastic = -k_node * g;
  }
  double pressure = p_elastic;
  if (q.damping > 0.0) {
    const double mass = in.mass();
    if (mass > 0.0) {
      // c = (VDC/100) 2 sqrt(k m_eff) with k = k_node * area, as a traction per gap rate.
      const double g_rate = (g - g_old) / dt;
      const double c = q.damping * std::sqrt(k_node * mass / area);
      pressure -= c * g_rate;
      h.damping() = c * g_rate;
      h.e_damping() += 0.5 * h.damping() * (g - g_old) * area;
    }
  }

  // Re-healing under compression, also from beta = 0 (re-sticking).
  if (s == NodeState::contact && p_elastic > 0.0 && beta < 1.0) {
    double db = at_temperature(p.zeta, p, q, temperature) * p_elastic * dt;
    if (beta + db > 1.0)
      db = 1.0 - beta;
    if (db > 0.0) {
      // New bonds form where the layers are now, free of strain: the adhesive shear spring
      // C_T beta^2 keeps the elastic energy it held (its opening scales by beta_old /
      // beta_new), or healing would create stored energy that no work paid for.
      if (p.ct > 0.0 && beta > 0.0) {
        const double keep = beta / (beta + db);
        h.opening(0) *= keep;
        h.opening(1) *= keep;
      }
      beta += db;
      h.e_healing() += omega * db * area;
    }
  }

  // Tangential traction.
  double tau0 = 0.0;
  double tau1 = 0.0;
  double stored_t = 0.0;
  if (p.friction == FrictionModel::coulomb) {
    const double kt = in.k_tangent();
    if (s == NodeState::contact && p_elastic > 0.0 && kt > 0.0) {
      const double ds0 = in.slip(0);
      const double ds1 = in.slip(1);
      double mu = at_temperature(p.mu, p, q, temperature);
      if (p.decay_dc > 0.0) {
        const double v = std::sqrt(ds0 * ds0 + ds1 * ds1) / dt;
        mu *= p.dynamic_ratio + (1.0 - p.dynamic_ratio) * std::exp(-p.decay_dc * v);
      }
      if (p.coupling == FrictionCoupling::rccm)
        mu *= 1.0 - beta;
      double& s0 = h.slip(0);
      double& s1 = h.slip(1);
      const double e0 = s0;  // the elastic slip at the step's start
      const double e1 = s1;
      const double trial0 = s0 + ds0;
      const double trial1 = s1 + ds1;
      tau0 = -kt * trial0;
      tau1 = -kt * trial1;
      const double tau_sq = tau0 * tau0 + tau1 * tau1;
      double limit = mu * p_elastic;
      if (p.friction_limit > 0.0 && limit > p.friction_limit)
        limit = p.friction_limit;
      if (tau_sq > limit * limit) {
        // Return to the Coulomb cone. The inelastic slip dissipates the step's mean traction
        // along it, kt (e_old + e_new) / 2 . slip_p: what the contact's work (the trapezoid
        // of the forces, docs/contact.md) takes less what the stick spring keeps, to
        // round-off. Sliding on the cone at a steady pressure that is limit |slip_p|; where the
        // pressure rises from zero within a step (a node that touches down while sliding) it
        // is half of it, and a node that lifts off hands its spring's energy to friction here
        // too (below).
        const double scale = limit / std::sqrt(tau_sq);
        tau0 *= scale;
        tau1 *= scale;
        s0 = -tau0 / kt;
        s1 = -tau1 / kt;
        const double sp0 = trial0 - s0;
        const double sp1 = trial1 - s1;
        h.e_friction() += 0.5 * kt * ((e0 + s0) * sp0 + (e1 + s1) * sp1) * area;
      } else {
        s0 = trial0;
        s1 = trial1;
      }
      stored_t = 0.5 * kt * (s0 * s0 + s1 * s1);
    } else {
      release_stick_spring(in, h);
    }
  } else {
    // Newtonian film: in contact and, while bonded, in the cohesive zone.
    const double ds0 = in.slip(0);
    const double ds1 = in.slip(1);
    const double f = at_temperature(p.film_viscosity, p, q, temperature) * q.inv_film / dt;
    tau0 = -f * ds0;
    tau1 = -f * ds1;
    h.e_friction() += f * (ds0 * ds0 + ds1 * ds1) * area;
  }
  if (p.ct > 0.0 && beta > 0.0) {
    const double kt = p.ct * beta * beta;
    const double o0 = h.opening(0);
    const double o1 = h.opening(1);
    tau0 -= kt * o0;
    tau1 -= kt * o1;
    stored_t += 0.5 * kt * (o0 * o0 + o1 * o1);
  }

  if (s != s_old)
    h.set_state(s);
  if (beta != beta_in)
    h.beta() = beta;
  r.pressure = pressure;
  r.tau[0] = tau0;
  r.tau[1] = tau1;
  r.stored = (0.5 * k_node * g * g + stored_t) * area;
  return r;
}

}  // namespace plyform::law::detail
