#pragma once
// The interlayer contact law (RCCM cohesion with damage and re-healing, Coulomb or film
// friction): a pure function of (parameters, history, increment) to (tractions, new history),
// with no knowledge of meshes. See docs/contact-law.md.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "plyform/law/detail/step.hpp"
#include "plyform/law/node_state.hpp"
#include "plyform/law/parameters.hpp"
#include "plyform/law/user_constants.hpp"

namespace plyform::law {

/// Thrown by the Law constructor when the parameters are invalid; carries every error.
class InvalidParameters : public std::invalid_argument {
 public:
  explicit InvalidParameters(std::vector<ConstantError> errors);
  [[nodiscard]] const std::vector<ConstantError>& errors() const { return errors_; }

 private:
  std::vector<ConstantError> errors_;
};

/// Inputs of a batched update, one entry per node (structure of arrays, host-owned).
/// `mass` may be null (no normal damping). Everything else is required.
struct BatchInput {
  std::size_t count = 0;
  const double* gap = nullptr;
  const double* slip_x = nullptr;  ///< tangential slip increment, first master-plane axis
  const double* slip_y = nullptr;
  const double* temperature = nullptr;
  const double* k_normal = nullptr;
  const double* k_tangent = nullptr;
  const double* area = nullptr;
  const double* mass = nullptr;
  double dt = 0.0;
};

/// History arrays of a batch (the fields of NodeHistory, one array each), updated in place.
struct BatchHistory {
  std::int32_t* state = nullptr;  ///< NodeState as its integer value
  double* beta = nullptr;
  double* gap = nullptr;
  double* slip_x = nullptr;
  double* slip_y = nullptr;
  double* opening_x = nullptr;
  double* opening_y = nullptr;
  double* e_damage = nullptr;
  double* e_viscous = nullptr;
  double* e_friction = nullptr;
  double* e_damping = nullptr;
  double* e_healing = nullptr;
  double* damping = nullptr;  ///< NodeHistory::damping
};

/// Outputs of a batch. `stored` may be null.
struct BatchOutput {
  double* pressure = nullptr;
  double* tau_x = nullptr;
  double* tau_y = nullptr;
  double* stored = nullptr;
};

/// An owning structure-of-arrays history, for hosts that do not keep their own.
class HistoryStore {
 public:
  HistoryStore() = default;
  explicit HistoryStore(std::size_t count);
  [[nodiscard]] std::size_t size() const { return state_.size(); }
  [[nodiscard]] BatchHistory view();
  [[nodiscard]] NodeHistory get(std::size_t i) const;
  void set(std::size_t i, const NodeHistory& h);

 private:
  std::vector<std::int32_t> state_;
  std::vector<double> beta_, gap_, slip_x_, slip_y_, opening_x_, opening_y_;
  std::vector<double> e_damage_, e_viscous_, e_friction_, e_damping_, e_healing_, damping_;
};

class Law {
 public:
  /// Validates `p`; throws InvalidParameters with every error.
  explicit Law(Parameters p);

  [[nodiscard]] const Parameters& parameters() const { return p_; }

  /// History at t = 0 for a node at `gap`: bonded (CONTACT or SEPARATING, beta = BETA0) when
  /// BOND_TOL > 0 and |gap| <= BOND_TOL, else APPROACHING with beta = BETA0 (the intensity the
  /// node takes at first contact).
  [[nodiscard]] NodeHistory initial_history(double gap) const;

  /// One node, one cycle (dt > 0).
  Response update(const Increment& in, NodeHistory& h) const;

  /// Many nodes, one cycle: the same arithmetic as `update`, over host-owned arrays.
  void update_batch(const BatchInput& in, const BatchHistory& h, const BatchOutput& out) const;

  /// Fills `h` for `count` nodes at their initial gaps.
  void initialize_batch(std::size_t count, const double* gap, const BatchHistory& h) const;

 private:
  Parameters p_;
  detail::Prepared q_;
};

/// Reads and writes entry `i` of batch history arrays.
[[nodiscard]] NodeHistory load_history(const BatchHistory& h, std::size_t i);
void store_history(const BatchHistory& h, std::size_t i, const NodeHistory& v);

}  // namespace plyform::law
