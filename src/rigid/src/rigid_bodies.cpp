#include "plyform/rigid/rigid_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

namespace plyform::rigid {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;  // row-major
using Quat = std::array<double, 4>;  // w, x, y, z

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 mul(const Mat3& m, const Vec3& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

/// Rotation matrix of a unit quaternion.
Mat3 rotation(const Quat& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

/// exp(phi) as a quaternion: a rotation by |phi| about phi / |phi|.
Quat exp_quat(const Vec3& phi) {
  const double a = std::sqrt(dot(phi, phi));
  const double h = 0.5 * a;
  // sin(h) / a, with its series for small angles.
  const double s = a > 1e-4 ? std::sin(h) / a : 0.5 - a * a / 48.0 + a * a * a * a / 3840.0;
  return {std::cos(h), s * phi[0], s * phi[1], s * phi[2]};
}

/// Hamilton product a b (apply b, then a).
Quat product(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

Quat normalised(const Quat& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

/// R J R^T.
Mat3 rotate_tensor(const Mat3& r, const Mat3& j) {
  Mat3 rj{}, out{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int m = 0; m < 3; ++m)
        rj[3 * i + k] += r[3 * i + m] * j[3 * m + k];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int m = 0; m < 3; ++m)
        out[3 * i + k] += rj[3 * i + m] * r[3 * k + m];
  return out;
}

double determinant(const Mat3& a) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
         a[2] * (a[3] * a[7] - a[4] * a[6]);
}

/// Solves A x = b by the adjugate; false when A is singular.
bool solve(const Mat3& a, const Vec3& b, Vec3& x) {
  const double det = determinant(a);
  if (!(std::abs(det) > 0.0))
    return false;
  const Mat3 adj = {
      a[4] * a[8] - a[5] * a[7], a[2] * a[7] - a[1] * a[8], a[1] * a[5] - a[2] * a[4],
      a[5] * a[6] - a[3] * a[8], a[0] * a[8] - a[2] * a[6], a[2] * a[3] - a[0] * a[5],
      a[3] * a[7] - a[4] * a[6], a[1] * a[6] - a[0] * a[7], a[0] * a[4] - a[1] * a[3]};
  const Vec3 y = mul(adj, b);
  x = {y[0] / det, y[1] / det, y[2] / det};
  return true;
}

/// Mean of a curve over [a, b] (b > a), summed segment by segment: no difference of two large
/// integrals, so no cancellation late in a run.
double curve_mean(const core::LoadCurve& c, double a, double b) {
  if (c.x.empty())
    return 0.0;
  if (!(b > a))
    return c(a);
  double sum = 0.0, lo = a;
  if (lo < c.x.front()) {
    const double hi = std::min(b, c.x.front());
    sum += c.y.front() * (hi - lo);
    lo = hi;
  }
  auto i = static_cast<std::size_t>(std::upper_bound(c.x.begin(), c.x.end(), lo) - c.x.begin());
  while (lo < b && i < c.x.size()) {
    const double hi = std::min(b, c.x[i]);
    sum += 0.5 * (c(lo) + c(hi)) * (hi - lo);
    lo = hi;
    ++i;
  }
  if (lo < b)
    sum += c.y.back() * (b - lo);
  return sum / (b - a);
}

std::string part_name(const core::Model& model, core::Index part) {
  const core::Part& p = model.parts[static_cast<std::size_t>(part)];
  std::string s = "rigid part " + std::to_string(p.id);
  if (!p.title.empty())
    s += " (" + p.title + ")";
  return s;
}

/// CON1/CON2 code (0-7) to the three directions it fixes.
std::array<bool, 3> constraint_code(int code) {
  switch (code) {
    case 0:
      return {false, false, false};
    case 1:
      return {true, false, false};
    case 2:
      return {false, true, false};
    case 3:
      return {false, false, true};
    case 4:
      return {true, true, false};
    case 5:
      return {false, true, true};
    case 6:
      return {true, false, true};
    default:
      return {true, true, true};
  }
}

}  // namespace

RigidBodies::RigidBodies(const core::Model& model)
    : curves_(model.curves), is_rigid_(model.node_count(), 0) {
  std::vector<int> body_of_part(model.parts.size(), -1);
  std::vector<int> body_of_node(model.node_count(), -1);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto mi = static_cast<std::size_t>(model.parts[p].material);
    if (mi >= model.materials.size())
      continue;
    const auto* rm = std::get_if<core::RigidMaterial>(&model.materials[mi]);
    if (rm == nullptr)
      continue;
    const auto part = static_cast<core::Index>(p);
    const std::string name = part_name(model, part);
    Body b;
    b.part = part;
    b.part_id = model.parts[p].id;
    if (rm->cmo < -0.5) {
      throw std::invalid_argument(name +
                                  ": CMO = -1 (constraints in a local system) is not supported");
    }
    if (rm->cmo > 0.5) {
      if (rm->con1 < 0 || rm->con1 > 7 || rm->con2 < 0 || rm->con2 > 7) {
        throw std::invalid_argument(name + ": CON1 = " + std::to_string(rm->con1) +
                                    ", CON2 = " + std::to_string(rm->con2) +
                                    ": with CMO = 1 each must be a code 0 to 7");
      }
      const auto t = constraint_code(rm->con1);
      const auto r = constraint_code(rm->con2);
      b.fixed = {t[0], t[1], t[2], r[0], r[1], r[2]};
    }
    b.props = part_mass_properties(model, part, rm->density);
    if (b.props.nodes.empty())
      throw std::invalid_argument(name + " has no element");
    if (!(b.props.mass > 0.0)) {
      throw std::invalid_argument(name + " has no mass (density " + std::to_string(rm->density) +
                                  ")");
    }
    const auto bi = static_cast<int>(bodies_.size());
    const std::size_t nn = b.props.nodes.size();
    b.X.resize(nn);
    b.Y.resize(nn);
    b.Z.resize(nn);
    b.rx.resize(nn);
    b.ry.resize(nn);
    b.rz.resize(nn);
    const Vec3& c = b.props.centre;
    for (std::size_t k = 0; k < nn; ++k) {
      const auto i = static_cast<std::size_t>(b.props.nodes[k]);
      if (body_of_node[i] >= 0) {
        throw std::invalid_argument(
            name + " shares node " + std::to_string(model.node_id[i]) + " with " +
            part_name(model, bodies_[static_cast<std::size_t>(body_of_node[i])].part) +
            " (merging rigid bodies is not supported)");
      }
      body_of_node[i] = bi;
      is_rigid_[i] = 1;
      b.X[k] = model.x0[i];
      b.Y[k] = model.y0[i];
      b.Z[k] = model.z0[i];
      b.rx[k] = b.X[k] - c[0];
      b.ry[k] = b.Y[k] - c[1];
      b.rz[k] = b.Z[k] - c[2];
    }
    b.xc = c;
    b.xc_t = c;
    // Initial velocities: a rigid fit to the nodal ones.
    if (model.v0x.size() == model.node_count() && model.v0y.size() == model.node_count() &&
        model.v0z.size() == model.node_count()) {
      Vec3 p_lin{}, l_lumped{};
      Mat3 j_lumped{};
      for (std::size_t k = 0; k < nn; ++k) {
        const auto i = static_cast<std::size_t>(b.props.nodes[k]);
        const double m = b.props.nodal_mass[k];
        const Vec3 v = {model.v0x[i], model.v0y[i], model.v0z[i]};
        const Vec3 r = {b.rx[k], b.ry[k], b.rz[k]};
        const Vec3 h = cross(r, v);
        const double rr = dot(r, r);
        for (int d = 0; d < 3; ++d) {
          const auto du = static_cast<std::size_t>(d);
          p_lin[du] += m * v[du];
          l_lumped[du] += m * h[du];
          for (int e = 0; e < 3; ++e) {
            const auto eu = static_cast<std::size_t>(e);
            j_lumped[3 * du + eu] += m * ((d == e ? rr : 0.0) - r[du] * r[eu]);
          }
        }
      }
      for (std::size_t d = 0; d < 3; ++d)
        b.v[d] = p_lin[d] / b.props.mass;
      Vec3 w{};
      if (solve(j_lumped, l_lumped, w))
        b.w = w;
      b.l = mul(b.props.inertia, b.w);
    }
    b.v_old = b.v;
    b.w_old = b.w;
    b.l_old = b.l;
    body_of_part[p] = bi;
    bodies_.push_back(std::move(b));
  }
  for (std::size_t i = 0; i < model.node_count(); ++i) {
    if (is_rigid_[i])
      rigid_nodes_.push_back(static_cast<core::Index>(i));
  }
  const auto body_for = [&](core::Index part, const char* what) -> Body& {
    if (part < 0 || static_cast<std::size_t>(part) >= model.parts.size() ||
        body_of_part[static_cast<std::size_t>(part)] < 0) {
      const std::string pid = part >= 0 && static_cast<std::size_t>(part) < model.parts.size()
                                  ? std::to_string(model.parts[static_cast<std::size_t>(part)].id)
                                  : "index " + std::to_string(part);
      throw std::invalid_argument(std::string(what) + " on part " + pid +
                                  ", which is not a rigid part");
    }
    return bodies_[static_cast<std::size_t>(body_of_part[static_cast<std::size_t>(part)])];
  };
  const auto check = [&](int dof, core::Index curve, const Body& b, const char* what) {
    if (dof < 0 || dof > 5)
      throw std::invalid_argument(std::string(what) + " on " + part_name(model, b.part) + ": dof " +
                                  std::to_string(dof) + " is not 0 to 5");
    if (curve < 0 || static_cast<std::size_t>(curve) >= curves_.size())
      throw std::invalid_argument(std::string(what) + " on " + part_name(model, b.part) +
                                  ": no curve at index " + std::to_string(curve));
  };
  for (const core::RigidMotion& m : model.rigid_motions) {
    Body& b = body_for(m.part, "*BOUNDARY_PRESCRIBED_MOTION_RIGID");
    check(m.dof, m.curve, b, "*BOUNDARY_PRESCRIBED_MOTION_RIGID");
    b.motions.push_back(
        Motion{m.dof, m.kind, static_cast<std::size_t>(m.curve), m.scale, m.birth, m.death});
  }
  for (const core::RigidLoad& l : model.rigid_loads) {
    Body& b = body_for(l.part, "*LOAD_RIGID_BODY");
    check(l.dof, l.curve, b, "*LOAD_RIGID_BODY");
    b.loads.push_back(Load{l.dof, static_cast<std::size_t>(l.curve), l.scale});
  }
}

void RigidBodies::advance(const StepTimes& step, const NodalArrays& nodes) {
  w_interp_ = step.dt_avg > 0.0 ? step.dt_prev / (2.0 * step.dt_avg) : 0.0;
  for (Body& b : bodies_)
    advance_body(b, step, nodes);
}

void RigidBodies::advance_body(Body& b, const StepTimes& step, const NodalArrays& a) const {
  const double t = step.t, dt = step.dt_next, dt_avg = step.dt_avg;
  const double mass = b.props.mass;
  const std::size_t nn = b.props.nodes.size();
  const Mat3 r_now = rotation(b.q);

  // Resultants of the nodal forces about the centre.
  Vec3 f{}, m{};
  for (std::size_t k = 0; k < nn; ++k) {
    const auto i = static_cast<std::size_t>(b.props.nodes[k]);
    const Vec3 g = {a.ex[i] - a.fx[i], a.ey[i] - a.fy[i], a.ez[i] - a.fz[i]};
    const Vec3 r = mul(r_now, Vec3{b.rx[k], b.ry[k], b.rz[k]});
    const Vec3 h = cross(r, g);
    for (std::size_t d = 0; d < 3; ++d) {
      f[d] += g[d];
      m[d] += h[d];
    }
  }
  Vec3 fl{}, ml{};
  for (const Load& l : b.loads) {
    const double val = l.scale * curves_[l.curve](t);
    if (l.dof < 3)
      fl[static_cast<std::size_t>(l.dof)] += val;
    else
      ml[static_cast<std::size_t>(l.dof - 3)] += val;
  }
  b.force = f;
  b.moment = m;
  b.load_force = fl;
  b.load_moment = ml;
  b.v_old = b.v;
  b.l_old = b.l;
  b.w_old = b.w;
  b.xc_t = b.xc;

  // Translation.
  Vec3 v{};
  for (std::size_t d = 0; d < 3; ++d) {
    v[d] = b.v[d] + (f[d] + fl[d]) / mass * dt_avg;
    if (b.fixed[d])
      v[d] = 0.0;
  }
  // Rotation: the components given by constraints and motions.
  std::array<bool, 3> given = {b.fixed[3], b.fixed[4], b.fixed[5]};
  Vec3 w_given{};
  const double t_mid = t + 0.5 * dt;
  for (const Motion& mo : b.motions) {
    if (t_mid < mo.birth || t_mid > mo.death)
      continue;
    const core::LoadCurve& c = curves_[mo.curve];
    const bool rot = mo.dof >= 3;
    const auto d = static_cast<std::size_t>(rot ? mo.dof - 3 : mo.dof);
    double value = 0.0;
    switch (mo.kind) {
      case core::MotionKind::velocity:
        value = step.hold ? (rot ? b.w[d] : b.v[d]) : mo.scale * curve_mean(c, t, t + dt);
        break;
      case core::MotionKind::acceleration:
        value = (rot ? b.w[d] : b.v[d]) + mo.scale * c(t) * dt_avg;
        break;
      case core::MotionKind::displacement:
        // At the end of the run the body keeps the last step's velocity rather than one read
        // from the curve beyond the end.
        if (step.hold)
          value = rot ? b.w[d] : b.v[d];
        else
          value = rot ? (mo.scale * c(t + dt) - b.angle[d]) / dt
                      : (b.props.centre[d] + mo.scale * c(t + dt) - b.xc[d]) / dt;
        break;
    }
    if (rot) {
      given[d] = true;
      w_given[d] = value;
    } else {
      v[d] = value;
    }
  }
  for (std::size_t d = 0; d < 3; ++d)
    b.reaction[d] = dt_avg > 0.0 ? mass * (v[d] - b.v[d]) / dt_avg - (f[d] + fl[d]) : 0.0;

  // Angular momentum, then Omega from J(R_h) Omega = L* on the free components.
  Vec3 l_star{};
  for (std::size_t d = 0; d < 3; ++d)
    l_star[d] = b.l[d] + (m[d] + ml[d]) * dt_avg;
  Vec3 w = b.w;
  for (std::size_t d = 0; d < 3; ++d) {
    if (given[d])
      w[d] = w_given[d];
  }
  const bool all_given = given[0] && given[1] && given[2];
  Mat3 jh{};
  for (int it = 0; it < 50; ++it) {
    const Vec3 half = {0.5 * dt * w[0], 0.5 * dt * w[1], 0.5 * dt * w[2]};
    jh = rotate_tensor(rotation(normalised(product(exp_quat(half), b.q))), b.props.inertia);
    if (all_given)
      break;
    Mat3 sys = jh;
    Vec3 rhs = l_star;
    for (std::size_t d = 0; d < 3; ++d) {
      if (given[d]) {
        for (std::size_t e = 0; e < 3; ++e)
          sys[3 * d + e] = d == e ? 1.0 : 0.0;
        rhs[d] = w_given[d];
      }
    }
    Vec3 w_new{};
    if (!solve(sys, rhs, w_new))
      break;  // cannot happen for a positive-definite inertia
    const Vec3 diff = {w_new[0] - w[0], w_new[1] - w[1], w_new[2] - w[2]};
    w = w_new;
    if (dot(diff, diff) <= 1e-30 * dot(w, w))
      break;
  }
  const Vec3 jw = mul(jh, w);
  Vec3 l{};
  for (std::size_t d = 0; d < 3; ++d) {
    l[d] = given[d] ? jw[d] : l_star[d];
    b.reaction_moment[d] = dt_avg > 0.0 ? (l[d] - b.l[d]) / dt_avg - (m[d] + ml[d]) : 0.0;
  }

  // New state: centre and orientation at t + dt.
  b.v = v;
  b.w = w;
  b.l = l;
  for (std::size_t d = 0; d < 3; ++d) {
    b.xc[d] += v[d] * dt;
    b.angle[d] += w[d] * dt;
  }
  b.q = normalised(product(exp_quat(Vec3{w[0] * dt, w[1] * dt, w[2] * dt}), b.q));
  const Mat3 r_new = rotation(b.q);

  // Nodal velocities: the secant field onto the rigid image of the reference configuration.
  const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  for (std::size_t k = 0; k < nn; ++k) {
    const auto i = static_cast<std::size_t>(b.props.nodes[k]);
    const Vec3 r = mul(r_new, Vec3{b.rx[k], b.ry[k], b.rz[k]});
    if (dt > 0.0) {
      a.vx[i] = (b.xc[0] + r[0] - (b.X[k] + a.ux[i])) * inv_dt;
      a.vy[i] = (b.xc[1] + r[1] - (b.Y[k] + a.uy[i])) * inv_dt;
      a.vz[i] = (b.xc[2] + r[2] - (b.Z[k] + a.uz[i])) * inv_dt;
    } else {
      const Vec3 wr = cross(w, r);
      a.vx[i] = v[0] + wr[0];
      a.vy[i] = v[1] + wr[1];
      a.vz[i] = v[2] + wr[2];
    }
    if (a.wx != nullptr) {
      a.wx[i] = w[0];
      a.wy[i] = w[1];
      a.wz[i] = w[2];
    }
  }
}

RigidBodies::BodyReport RigidBodies::report(std::size_t k) const {
  const Body& b = bodies_[k];
  const double s = w_interp_;
  BodyReport r;
  r.part_id = b.part_id;
  r.mass = b.props.mass;
  r.force = b.force;
  r.moment = b.moment;
  r.load_force = b.load_force;
  r.load_moment = b.load_moment;
  r.reaction = b.reaction;
  r.reaction_moment = b.reaction_moment;
  r.centre = b.xc_t;
  for (std::size_t d = 0; d < 3; ++d) {
    r.velocity[d] = b.v_old[d] + (b.v[d] - b.v_old[d]) * s;
    r.omega[d] = b.w_old[d] + (b.w[d] - b.w_old[d]) * s;
    r.angular_momentum[d] = b.l_old[d] + (b.l[d] - b.l_old[d]) * s;
    r.velocity_half[d] = b.v[d];
    r.omega_half[d] = b.w[d];
    r.velocity_before[d] = b.v_old[d];
    r.omega_before[d] = b.w_old[d];
  }
  return r;
}

std::vector<RigidBodies::BodyReport> RigidBodies::report() const {
  std::vector<BodyReport> out;
  out.reserve(bodies_.size());
  for (std::size_t k = 0; k < bodies_.size(); ++k)
    out.push_back(report(k));
  return out;
}

double RigidBodies::kinetic_energy() const {
  const double s = w_interp_;
  double e = 0.0;
  for (const Body& b : bodies_) {
    Vec3 v{}, w{}, l{};
    for (std::size_t d = 0; d < 3; ++d) {
      v[d] = b.v_old[d] + (b.v[d] - b.v_old[d]) * s;
      w[d] = b.w_old[d] + (b.w[d] - b.w_old[d]) * s;
      l[d] = b.l_old[d] + (b.l[d] - b.l_old[d]) * s;
    }
    e += 0.5 * b.props.mass * dot(v, v) + 0.5 * dot(w, l);
  }
  return e;
}

void RigidBodies::visit_state(core::StateArchive& archive) {
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const auto scope = archive.scope("body/" + std::to_string(bodies_[k].part_id));
    Body& b = bodies_[k];
    archive.value("centre", b.xc);
    archive.value("orientation", b.q);
    archive.value("velocity", b.v);
    archive.value("angular_momentum", b.l);
    archive.value("omega", b.w);
    archive.value("velocity_old", b.v_old);
    archive.value("angular_momentum_old", b.l_old);
    archive.value("omega_old", b.w_old);
    archive.value("centre_at_t", b.xc_t);
    archive.value("angle", b.angle);
    archive.value("force", b.force);
    archive.value("moment", b.moment);
    archive.value("load_force", b.load_force);
    archive.value("load_moment", b.load_moment);
    archive.value("reaction", b.reaction);
    archive.value("reaction_moment", b.reaction_moment);
  }
  archive.value("w_interp", w_interp_);
}

}  // namespace plyform::rigid
