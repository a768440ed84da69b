#include "plyform/law/law.hpp"

#include <sstream>
#include <utility>

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
  q_ = detail::prepare(p_);
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
  return detail::step(p_, q_, detail::IncrementAccess{in}, detail::NodeHistoryAccess{h});
}

namespace {

// Accessors over entry i of the host's arrays: the kernel reads and writes them in place.
struct BatchHistoryAccess {
  const BatchHistory& b;
  std::size_t i;
  NodeState state() const { return static_cast<NodeState>(b.state[i]); }
  void set_state(NodeState s) const { b.state[i] = static_cast<std::int32_t>(s); }
  double& beta() const { return b.beta[i]; }
  double& gap() const { return b.gap[i]; }
  double& slip(int k) const { return (k == 0 ? b.slip_x : b.slip_y)[i]; }
  double& opening(int k) const { return (k == 0 ? b.opening_x : b.opening_y)[i]; }
  double& e_damage() const { return b.e_damage[i]; }
  double& e_viscous() const { return b.e_viscous[i]; }
  double& e_friction() const { return b.e_friction[i]; }
  double& e_damping() const { return b.e_damping[i]; }
  double& e_healing() const { return b.e_healing[i]; }
  double& damping() const { return b.damping[i]; }
};

struct BatchInputAccess {
  const BatchInput& in;
  std::size_t i;
  double gap() const { return in.gap[i]; }
  double slip(int k) const { return (k == 0 ? in.slip_x : in.slip_y)[i]; }
  double dt() const { return in.dt; }
  double temperature() const { return in.temperature[i]; }
  double k_normal() const { return in.k_normal[i]; }
  double k_tangent() const { return in.k_tangent[i]; }
  double area() const { return in.area[i]; }
  double mass() const { return in.mass != nullptr ? in.mass[i] : 0.0; }
};

}  // namespace

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
  v.damping = h.damping[i];
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
  h.damping[i] = v.damping;
}

void Law::update_batch(const BatchInput& in, const BatchHistory& h, const BatchOutput& out) const {
  for (std::size_t i = 0; i < in.count; ++i) {
    const Response r = detail::step(p_, q_, BatchInputAccess{in, i}, BatchHistoryAccess{h, i});
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
      e_healing_(count, 0.0),
      damping_(count, 0.0) {}

BatchHistory HistoryStore::view() {
  return BatchHistory{state_.data(),     beta_.data(),       gap_.data(),       slip_x_.data(),
                      slip_y_.data(),    opening_x_.data(),  opening_y_.data(), e_damage_.data(),
                      e_viscous_.data(), e_friction_.data(), e_damping_.data(), e_healing_.data(),
                      damping_.data()};
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
  v.damping = damping_[i];
  return v;
}

void HistoryStore::set(std::size_t i, const NodeHistory& h) {
  store_history(view(), i, h);
}

}  // namespace plyform::law
