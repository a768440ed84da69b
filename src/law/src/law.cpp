#include "plyform/law/law.hpp"

#include <sstream>
#include <utility>

#include "plyform/law/detail/step.hpp"

namespace plyform::law {
namespace {

std::string join(const std::vector<ConstantError>& errors) {
  std::ostringstream os;
  os << "invalid contact-law parameters:";
  for (const ConstantError& e : errors)
    os << "\n  " << e.message;
  return os.str();
}

}  // namespace

InvalidParameters::InvalidParameters(std::vector<ConstantError> errors)
    : std::invalid_argument(join(errors)), errors_(std::move(errors)) {}

Law::Law(Parameters p) : p_(std::move(p)) {
  if (auto errors = validate(p_); !errors.empty())
    throw InvalidParameters(std::move(errors));
}

NodeHistory Law::initial_history(double gap) const {
  NodeHistory h;
  h.gap = gap;
  h.beta = p_.beta0;
  const bool bonded = p_.bond_tol > 0.0 && std::abs(gap) <= p_.bond_tol;
  if (bonded) {
    if (gap <= 0.0) {
      h.state = NodeState::contact;
    } else {
      h.state = p_.beta0 > 0.0 ? NodeState::separating : NodeState::detached;
    }
  }
  return h;
}

Response Law::update(const Increment& in, NodeHistory& h) const {
  return detail::step(p_, in, h);
}

NodeHistory load_history(const BatchHistory& h, std::size_t i) {
  NodeHistory v;
  v.state = static_cast<NodeState>(h.state[i]);
  v.beta = h.beta[i];
  v.gap = h.gap[i];
  v.slip[0] = h.slip_x[i];
  v.slip[1] = h.slip_y[i];
  v.opening_t[0] = h.opening_x[i];
  v.opening_t[1] = h.opening_y[i];
  v.e_damage = h.e_damage[i];
  v.e_viscous = h.e_viscous[i];
  v.e_friction = h.e_friction[i];
  v.e_damping = h.e_damping[i];
  v.e_healing = h.e_healing[i];
  return v;
}

void store_history(const BatchHistory& h, std::size_t i, const NodeHistory& v) {
  h.state[i] = static_cast<std::int32_t>(v.state);
  h.beta[i] = v.beta;
  h.gap[i] = v.gap;
  h.slip_x[i] = v.slip[0];
  h.slip_y[i] = v.slip[1];
  h.opening_x[i] = v.opening_t[0];
  h.opening_y[i] = v.opening_t[1];
  h.e_damage[i] = v.e_damage;
  h.e_viscous[i] = v.e_viscous;
  h.e_friction[i] = v.e_friction;
  h.e_damping[i] = v.e_damping;
  h.e_healing[i] = v.e_healing;
}

void Law::update_batch(const BatchInput& in, const BatchHistory& h, const BatchOutput& out) const {
  const Parameters& p = p_;
  for (std::size_t i = 0; i < in.count; ++i) {
    Increment inc;
    inc.gap = in.gap[i];
    inc.slip[0] = in.slip_x[i];
    inc.slip[1] = in.slip_y[i];
    inc.dt = in.dt;
    inc.temperature = in.temperature[i];
    inc.k_normal = in.k_normal[i];
    inc.k_tangent = in.k_tangent[i];
    inc.area = in.area[i];
    inc.mass = in.mass != nullptr ? in.mass[i] : 0.0;
    NodeHistory v = load_history(h, i);
    const Response r = detail::step(p, inc, v);
    store_history(h, i, v);
    out.pressure[i] = r.pressure;
    out.tau_x[i] = r.tau[0];
    out.tau_y[i] = r.tau[1];
    if (out.stored != nullptr)
      out.stored[i] = r.stored;
  }
}

void Law::initialize_batch(std::size_t count, const double* gap, const BatchHistory& h) const {
  for (std::size_t i = 0; i < count; ++i)
    store_history(h, i, initial_history(gap[i]));
}

HistoryStore::HistoryStore(std::size_t count)
    : state_(count, 0),
      beta_(count, 1.0),
      gap_(count, 0.0),
      slip_x_(count, 0.0),
      slip_y_(count, 0.0),
      opening_x_(count, 0.0),
      opening_y_(count, 0.0),
      e_damage_(count, 0.0),
      e_viscous_(count, 0.0),
      e_friction_(count, 0.0),
      e_damping_(count, 0.0),
      e_healing_(count, 0.0) {}

BatchHistory HistoryStore::view() {
  return BatchHistory{state_.data(),     beta_.data(),       gap_.data(),       slip_x_.data(),
                      slip_y_.data(),    opening_x_.data(),  opening_y_.data(), e_damage_.data(),
                      e_viscous_.data(), e_friction_.data(), e_damping_.data(), e_healing_.data()};
}

NodeHistory HistoryStore::get(std::size_t i) const {
  NodeHistory v;
  v.state = static_cast<NodeState>(state_[i]);
  v.beta = beta_[i];
  v.gap = gap_[i];
  v.slip[0] = slip_x_[i];
  v.slip[1] = slip_y_[i];
  v.opening_t[0] = opening_x_[i];
  v.opening_t[1] = opening_y_[i];
  v.e_damage = e_damage_[i];
  v.e_viscous = e_viscous_[i];
  v.e_friction = e_friction_[i];
  v.e_damping = e_damping_[i];
  v.e_healing = e_healing_[i];
  return v;
}

void HistoryStore::set(std::size_t i, const NodeHistory& h) {
  store_history(view(), i, h);
}

}  // namespace plyform::law
