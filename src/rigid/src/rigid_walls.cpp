#include "plyform/rigid/rigid_walls.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace plyform::rigid {

RigidWalls::RigidWalls(const core::Model& model) {
  walls_.reserve(model.rigid_walls.size());
  for (const core::RigidWall& w : model.rigid_walls) {
    Wall wall;
    wall.desc = &w;
    wall.velocity = w.velocity0;
    walls_.push_back(wall);
  }
}

const std::vector<WallCorrection>& RigidWalls::apply(double t, double dt_next, double dt_avg,
                                                     const WallArrays& a) {
  corrected_.clear();
  for (Wall& wall : walls_) {
    const core::RigidWall& w = *wall.desc;
    const std::array<double, 3>& n = w.normal;
    const double p[3] = {w.origin[0] + wall.displacement * n[0],
                         w.origin[1] + wall.displacement * n[1],
                         w.origin[2] + wall.displacement * n[2]};
    wall.force = {0.0, 0.0, 0.0};
    wall.normal_force = wall.tangential_force = 0.0;
    wall.held = 0;
    const bool active = t >= w.birth && t <= w.death;
    double v_new = wall.velocity;
    if (active && dt_next > 0.0) {
      // A node is behind the wall when further than this below it (the round-off of a node
      // that landed on it is far smaller).
      const double tolerance =
          1e-9 * std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2]), 1.0});
      candidates_.clear();
      for (const core::Index ni : w.nodes) {
        const auto i = static_cast<std::size_t>(ni);
        const double r[3] = {a.x0[i] + a.ux[i] - p[0], a.y0[i] + a.uy[i] - p[1],
                             a.z0[i] + a.uz[i] - p[2]};
        const double gap = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
        if (gap < -tolerance)
          continue;
        const double s = a.vx[i] * n[0] + a.vy[i] * n[1] + a.vz[i] * n[2] + gap / dt_next;
        if (!(s < wall.velocity))
          continue;
        if (w.finite) {
          const double l = r[0] * w.edge_l[0] + r[1] * w.edge_l[1] + r[2] * w.edge_l[2];
          const double m = r[0] * w.edge_m[0] + r[1] * w.edge_m[1] + r[2] * w.edge_m[2];
          if (l < 0.0 || l > w.length_l || m < 0.0 || m > w.length_m)
            continue;
        }
        candidates_.push_back({ni, s, gap});
      }
      std::size_t caught = candidates_.size();
      if (w.mass > 0.0 && caught > 0) {
        // The common velocity of the wall and the nodes it stops: the nodes in order of s
        // join while their s lies below the common velocity of those before them.
        std::sort(candidates_.begin(), candidates_.end(),
                  [](const Candidate& x, const Candidate& y) {
                    return x.s < y.s || (x.s == y.s && x.node < y.node);
                  });
        double momentum = w.mass * wall.velocity, mass = w.mass;
        caught = 0;
        for (const Candidate& c : candidates_) {
          const double m = a.mass[static_cast<std::size_t>(c.node)];
          if (!(c.s < (momentum + m * c.s) / (mass + m)))
            break;
          momentum += m * c.s;
          mass += m;
          ++caught;
        }
        v_new = momentum / mass;
        // Node order for the corrections (the engine's sums and the reports do not depend on
        // the sort).
        std::sort(candidates_.begin(), candidates_.begin() + static_cast<long>(caught),
                  [](const Candidate& x, const Candidate& y) { return x.node < y.node; });
      }
      for (std::size_t k = 0; k < caught; ++k) {
        const Candidate& c = candidates_[k];
        const auto i = static_cast<std::size_t>(c.node);
        const double before[3] = {a.vx[i], a.vy[i], a.vz[i]};
        const double dn = v_new - c.s;  // the normal velocity's rise
        if (!(dn > 0.0))
          continue;
        double v[3] = {before[0] + dn * n[0], before[1] + dn * n[1], before[2] + dn * n[2]};
        if (w.friction > 0.0) {
          const double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
          const double vt[3] = {v[0] - vn * n[0], v[1] - vn * n[1], v[2] - vn * n[2]};
          const double slide = std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
          const double limit = w.friction >= 1.0 ? slide : w.friction * dn;
          const double keep = slide > limit ? 1.0 - limit / slide : 0.0;
          for (std::size_t d = 0; d < 3; ++d)
            v[d] = vn * n[d] + keep * vt[d];
        }
        a.vx[i] = v[0];
        a.vy[i] = v[1];
        a.vz[i] = v[2];
        corrected_.push_back({c.node, {before[0], before[1], before[2]}});
        const double mi = a.mass[i];
        double j[3];
        for (std::size_t d = 0; d < 3; ++d) {
          j[d] = mi * (v[d] - before[d]);
          wall.force[d] -= j[d] / dt_avg;
        }
        const double jn = j[0] * n[0] + j[1] * n[1] + j[2] * n[2];
        wall.impulse += jn;
        ++wall.held;
      }
      const double fn = -(wall.force[0] * n[0] + wall.force[1] * n[1] + wall.force[2] * n[2]);
      double ft[3];
      for (std::size_t d = 0; d < 3; ++d)
        ft[d] = -wall.force[d] - fn * n[d];
      wall.normal_force = fn;
      wall.tangential_force = std::sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]);
    }
    wall.displacement_now = wall.displacement;
    if (w.mass > 0.0) {
      wall.velocity = v_new;
      wall.displacement += v_new * dt_next;
      for (const core::Index ni : w.display_nodes) {
        const auto i = static_cast<std::size_t>(ni);
        a.vx[i] = v_new * n[0];
        a.vy[i] = v_new * n[1];
        a.vz[i] = v_new * n[2];
      }
    }
  }
  return corrected_;
}

RigidWalls::Report RigidWalls::report(std::size_t k) const {
  const Wall& w = walls_[k];
  Report r;
  r.id = w.desc->id;
  r.normal_force = w.normal_force;
  r.tangential_force = w.tangential_force;
  r.force = w.force;
  r.impulse = w.impulse;
  r.held = w.held;
  r.displacement = w.displacement_now;
  r.velocity = w.velocity;
  r.kinetic = 0.5 * w.desc->mass * w.velocity * w.velocity;
  return r;
}

void RigidWalls::visit_state(core::StateArchive& archive) {
  for (Wall& w : walls_) {
    const auto scope = archive.scope("wall/" + std::to_string(w.desc->id));
    archive.value("displacement", w.displacement);
    archive.value("displacement_now", w.displacement_now);
    archive.value("velocity", w.velocity);
    archive.value("impulse", w.impulse);
    archive.value("force", w.force);
    archive.value("normal_force", w.normal_force);
    archive.value("tangential_force", w.tangential_force);
    double held = static_cast<double>(w.held);
    archive.value("held", held);
    w.held = static_cast<std::size_t>(held);
  }
}

}  // namespace plyform::rigid
