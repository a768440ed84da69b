#include "tied_nodes.hpp"

namespace plyform::engine {

namespace {

// The offset d = x_s - sum w_j x_j at the current positions.
void offset(const core::Model& m, const NodalState& s, core::Index slave, const core::Index* node,
            const double* w, double* d) {
  const auto i = static_cast<std::size_t>(slave);
  d[0] = m.x0[i] + s.ux[i];
  d[1] = m.y0[i] + s.uy[i];
  d[2] = m.z0[i] + s.uz[i];
  for (int a = 0; a < 4; ++a) {
    const auto j = static_cast<std::size_t>(node[a]);
    d[0] -= w[a] * (m.x0[j] + s.ux[j]);
    d[1] -= w[a] * (m.y0[j] + s.uy[j]);
    d[2] -= w[a] * (m.z0[j] + s.uz[j]);
  }
}

}  // namespace

TiedNodes::TiedNodes(const core::Model& model)
    : model_(model), reaction_(model.tied.size(), std::array<double, 3>{0.0, 0.0, 0.0}) {
  for (std::size_t ti = 0; ti < model.tied.size(); ++ti) {
    const core::TiedInterface& t = model.tied[ti];
    for (std::size_t k = 0; k < t.slaves.size(); ++k) {
      Link l;
      l.slave = t.slaves[k];
      l.rotations = t.rotations;
      // A triangle repeats N3 as N4 with weight 0: keep the four as they are.
      for (std::size_t a = 0; a < 4; ++a) {
        l.node[a] = t.segment[k][a];
        l.w[a] = t.weight[k][a];
      }
      slave_.push_back(l);
      interface_of_.push_back(ti);
    }
  }
  net_.assign(3 * slave_.size(), 0.0);
}

void TiedNodes::lump(const std::vector<double>& mass, const std::vector<double>& inertia,
                     std::vector<double>& inv_mass, std::vector<double>& inv_inertia) const {
  std::vector<double> m = mass, in = inertia;
  for (const Link& l : slave_) {
    const auto s = static_cast<std::size_t>(l.slave);
    double d2 = 0.0;
    if (l.rotations) {
      double d[3];
      const core::Model& md = model_;
      d[0] = md.x0[s];
      d[1] = md.y0[s];
      d[2] = md.z0[s];
      for (int a = 0; a < 4; ++a) {
        const auto j = static_cast<std::size_t>(l.node[a]);
        d[0] -= l.w[a] * md.x0[j];
        d[1] -= l.w[a] * md.y0[j];
        d[2] -= l.w[a] * md.z0[j];
      }
      d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    }
    for (int a = 0; a < 4; ++a) {
      const auto j = static_cast<std::size_t>(l.node[a]);
      m[j] += l.w[a] * mass[s];
      if (l.rotations)
        in[j] += l.w[a] * (inertia[s] + mass[s] * d2);
    }
  }
  for (const Link& l : slave_) {
    for (int a = 0; a < 4; ++a) {
      const auto j = static_cast<std::size_t>(l.node[a]);
      if (m[j] > 0.0)
        inv_mass[j] = 1.0 / m[j];
      if (l.rotations && in[j] > 0.0)
        inv_inertia[j] = 1.0 / in[j];
    }
  }
  for (const Link& l : slave_) {
    const auto s = static_cast<std::size_t>(l.slave);
    inv_mass[s] = 0.0;
    if (l.rotations)
      inv_inertia[s] = 0.0;
  }
}

void TiedNodes::gather(NodalState& s) {
  for (std::size_t k = 0; k < slave_.size(); ++k) {
    const Link& l = slave_[k];
    const auto i = static_cast<std::size_t>(l.slave);
    // The net force on the slave, in the internal arrays' sense (subtracted by the update).
    const double f[3] = {s.fx[i] - s.ex[i], s.fy[i] - s.ey[i], s.fz[i] - s.ez[i]};
    net_[3 * k] = f[0], net_[3 * k + 1] = f[1], net_[3 * k + 2] = f[2];
    for (int a = 0; a < 4; ++a) {
      const auto j = static_cast<std::size_t>(l.node[a]);
      s.fx[j] += l.w[a] * f[0];
      s.fy[j] += l.w[a] * f[1];
      s.fz[j] += l.w[a] * f[2];
    }
    s.fx[i] = s.fy[i] = s.fz[i] = 0.0;
    if (!l.rotations)
      continue;
    double d[3];
    offset(model_, s, l.slave, l.node, l.w, d);
    // The moment about the surface point, in the same sense: m_s + d x f.
    const double mm[3] = {s.mx[i] + d[1] * f[2] - d[2] * f[1], s.my[i] + d[2] * f[0] - d[0] * f[2],
                          s.mz[i] + d[0] * f[1] - d[1] * f[0]};
    for (int a = 0; a < 4; ++a) {
      const auto j = static_cast<std::size_t>(l.node[a]);
      s.mx[j] += l.w[a] * mm[0];
      s.my[j] += l.w[a] * mm[1];
      s.mz[j] += l.w[a] * mm[2];
    }
    s.mx[i] = s.my[i] = s.mz[i] = 0.0;
  }
}

double TiedNodes::follow(NodalState& s, double dt_avg) {
  double work = 0.0;
  for (auto& r : reaction_)
    r = {0.0, 0.0, 0.0};
  const double inv_dt = dt_avg > 0.0 ? 1.0 / dt_avg : 0.0;
  for (std::size_t k = 0; k < slave_.size(); ++k) {
    const Link& l = slave_[k];
    const auto i = static_cast<std::size_t>(l.slave);
    double v[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < 4; ++a) {
      const auto j = static_cast<std::size_t>(l.node[a]);
      v[0] += l.w[a] * s.vx[j];
      v[1] += l.w[a] * s.vy[j];
      v[2] += l.w[a] * s.vz[j];
    }
    if (l.rotations) {
      double w[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < 4; ++a) {
        const auto j = static_cast<std::size_t>(l.node[a]);
        w[0] += l.w[a] * s.wx[j];
        w[1] += l.w[a] * s.wy[j];
        w[2] += l.w[a] * s.wz[j];
      }
      double d[3];
      offset(model_, s, l.slave, l.node, l.w, d);
      v[0] += w[1] * d[2] - w[2] * d[1];
      v[1] += w[2] * d[0] - w[0] * d[2];
      v[2] += w[0] * d[1] - w[1] * d[0];
      s.wx[i] = w[0];
      s.wy[i] = w[1];
      s.wz[i] = w[2];
    }
    work += (v[0] - s.vx[i]) * s.ex[i] + (v[1] - s.vy[i]) * s.ey[i] + (v[2] - s.vz[i]) * s.ez[i];
    // The slave kept its velocity of the last half step through the update (no mass of its
    // own there): v - s.v is its whole change, m_s (v - s.v) / dt_avg the force it took.
    std::array<double, 3>& r = reaction_[interface_of_[k]];
    const double m = s.mass[i] * inv_dt;
    r[0] += m * (v[0] - s.vx[i]) + net_[3 * k];
    r[1] += m * (v[1] - s.vy[i]) + net_[3 * k + 1];
    r[2] += m * (v[2] - s.vz[i]) + net_[3 * k + 2];
    s.vx[i] = v[0];
    s.vy[i] = v[1];
    s.vz[i] = v[2];
  }
  return work;
}

}  // namespace plyform::engine
