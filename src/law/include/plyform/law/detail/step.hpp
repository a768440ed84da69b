#pragma once
// The one-node update of the law. Both entry points (one node, batched arrays) call this
// function, so they give bit-identical results. Header-only so the batched loop inlines it.

#include <cmath>

#include "plyform/law/node_state.hpp"
#include "plyform/law/parameters.hpp"

namespace plyform::law::detail {

inline Response step(const Parameters& p, const Increment& in, NodeHistory& h) {
  Response r;
  const double g = in.gap;
  const double g_old = h.gap;
  h.gap = g;

  // Gap-driven transitions; damage and healing may change the state again below.
  NodeState s = h.state;
  if (g <= 0.0) {
    s = NodeState::contact;
  } else if (s == NodeState::contact) {
    s = h.beta > 0.0 ? NodeState::separating : NodeState::detached;
  }
  if (s == NodeState::approaching || s == NodeState::detached) {
    // No force of any kind, damping included (the paper's reason for its own damping).
    h.state = s;
    h.slip[0] = h.slip[1] = 0.0;
    h.opening_t[0] = h.opening_t[1] = 0.0;
    return r;
  }

  const double temperature = in.temperature;
  const double area = in.area;
  const double smax = evaluate(p.sigma_max, p, temperature);
  const double omega = smax * smax / p.cn;
  double beta = h.beta;

  // Damage: backward Euler of eta beta_dot = -(Y beta - omega) while Y beta > omega.
  if (beta > 0.0) {
    if (p.ct > 0.0) {
      h.opening_t[0] += in.slip[0];
      h.opening_t[1] += in.slip[1];
    }
    const double g_open = g > 0.0 ? g : 0.0;
    const double y = p.cn * g_open * g_open +
                     p.ct * (h.opening_t[0] * h.opening_t[0] + h.opening_t[1] * h.opening_t[1]);
    bool damaged = false;
    if (y * beta > omega) {
      const double a = in.dt / p.eta;
      const double b_new = (beta + a * omega) / (1.0 + a * y);
      if (b_new < beta) {
        // Backward Euler makes (Y b_new - omega) = eta (beta - b_new) / dt >= 0: the viscous
        // part of the driving force; omega (beta - b_new) is the adhesion energy released.
        const double db = beta - b_new;
        h.e_damage += omega * db * area;
        h.e_viscous += (y * b_new - omega) * db * area;
        beta = b_new;
        damaged = true;
      }
    }
    const bool released = s == NodeState::separating && g > p.release_gap;
    if ((damaged && beta < p.beta_min) || released) {
      // Cut-off: the rest of the adhesion and the elastic energy it held are released.
      h.e_damage += (omega * beta + 0.5 * y * beta * beta) * area;
      beta = 0.0;
    }
  }
  if (beta <= 0.0) {
    beta = 0.0;
    h.opening_t[0] = h.opening_t[1] = 0.0;
    if (s == NodeState::separating) {
      h.state = NodeState::detached;
      h.beta = 0.0;
      h.slip[0] = h.slip[1] = 0.0;
      return r;
    }
  }

  // Normal traction: penalty in contact, RCCM cohesion C_N g beta^2 in separation.
  double p_elastic;
  double k_node;
  if (s == NodeState::contact) {
    p_elastic = in.k_normal * (-g);
    k_node = in.k_normal;
  } else {
    k_node = p.cn * beta * beta;
    p_elastic = -k_node * g;
  }
  double pressure = p_elastic;
  if (p.vdc > 0.0 && in.mass > 0.0 && in.dt > 0.0) {
    // c = (VDC/100) 2 sqrt(k m_eff) with k = k_node * area, as a traction per gap rate.
    const double g_rate = (g - g_old) / in.dt;
    const double c = 0.02 * p.vdc * std::sqrt(k_node * in.mass / area);
    pressure -= c * g_rate;
    h.e_damping += c * g_rate * g_rate * in.dt * area;
  }

  // Re-healing under compression, also from beta = 0 (re-sticking).
  if (s == NodeState::contact && p_elastic > 0.0 && beta < 1.0) {
    double db = evaluate(p.zeta, p, temperature) * p_elastic * in.dt;
    if (beta + db > 1.0)
      db = 1.0 - beta;
    if (db > 0.0) {
      beta += db;
      h.e_healing += omega * db * area;
    }
  }

  // Tangential traction.
  double tau0 = 0.0;
  double tau1 = 0.0;
  double stored_t = 0.0;
  if (p.friction == FrictionModel::coulomb) {
    if (s == NodeState::contact && p_elastic > 0.0 && in.k_tangent > 0.0) {
      double mu = evaluate(p.mu, p, temperature);
      if (p.decay_dc > 0.0 && in.dt > 0.0) {
        const double v = std::sqrt(in.slip[0] * in.slip[0] + in.slip[1] * in.slip[1]) / in.dt;
        mu *= p.dynamic_ratio + (1.0 - p.dynamic_ratio) * std::exp(-p.decay_dc * v);
      }
      if (p.coupling == FrictionCoupling::rccm)
        mu *= 1.0 - beta;
      const double trial0 = h.slip[0] + in.slip[0];
      const double trial1 = h.slip[1] + in.slip[1];
      tau0 = -in.k_tangent * trial0;
      tau1 = -in.k_tangent * trial1;
      const double tau_norm = std::sqrt(tau0 * tau0 + tau1 * tau1);
      const double limit = mu * p_elastic;
      if (tau_norm > limit) {
        // Return to the Coulomb cone; the inelastic slip dissipates limit * |slip_p|.
        const double scale = limit / tau_norm;
        tau0 *= scale;
        tau1 *= scale;
        h.slip[0] = -tau0 / in.k_tangent;
        h.slip[1] = -tau1 / in.k_tangent;
        const double sp0 = trial0 - h.slip[0];
        const double sp1 = trial1 - h.slip[1];
        h.e_friction += limit * std::sqrt(sp0 * sp0 + sp1 * sp1) * area;
      } else {
        h.slip[0] = trial0;
        h.slip[1] = trial1;
      }
      stored_t = 0.5 * in.k_tangent * (h.slip[0] * h.slip[0] + h.slip[1] * h.slip[1]);
    } else {
      h.slip[0] = h.slip[1] = 0.0;
    }
  } else if (in.dt > 0.0) {
    // Newtonian film: in contact and, while bonded, in the cohesive zone.
    const double f = evaluate(p.film_viscosity, p, temperature) / (p.film_thickness * in.dt);
    tau0 = -f * in.slip[0];
    tau1 = -f * in.slip[1];
    h.e_friction += f * (in.slip[0] * in.slip[0] + in.slip[1] * in.slip[1]) * area;
  }
  if (p.ct > 0.0 && beta > 0.0) {
    const double kt = p.ct * beta * beta;
    tau0 -= kt * h.opening_t[0];
    tau1 -= kt * h.opening_t[1];
    stored_t += 0.5 * kt * (h.opening_t[0] * h.opening_t[0] + h.opening_t[1] * h.opening_t[1]);
  }

  h.state = s;
  h.beta = beta;
  r.pressure = pressure;
  r.tau[0] = tau0;
  r.tau[1] = tau1;
  r.stored = (0.5 * k_node * g * g + stored_t) * area;
  return r;
}

}  // namespace plyform::law::detail
