// The C ABI over plyform::law. No exception crosses it: each entry point catches and returns
// a status.

#include <cmath>
#include <cstring>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "plyform/law/law.hpp"
#include "plyform/law/plyform_law.h"

struct plyform_law {
  plyform::law::Law law;
};

namespace {

using plyform::law::NodeHistory;
using plyform::law::NodeState;

void write_message(char* buffer, std::size_t size, const std::string& text) {
  if (buffer == nullptr || size == 0)
    return;
  const std::size_t n = text.size() < size - 1 ? text.size() : size - 1;
  std::memcpy(buffer, text.data(), n);
  buffer[n] = '\0';
}

NodeHistory from_c(const plyform_law_history& c) {
  NodeHistory h;
  h.state = static_cast<NodeState>(c.state);
  h.beta = c.beta;
  h.gap = c.gap;
  h.slip[0] = c.slip[0];
  h.slip[1] = c.slip[1];
  h.opening_t[0] = c.opening[0];
  h.opening_t[1] = c.opening[1];
  h.e_damage = c.e_damage;
  h.e_viscous = c.e_viscous;
  h.e_friction = c.e_friction;
  h.e_damping = c.e_damping;
  h.e_healing = c.e_healing;
  h.damping = c.damping;
  return h;
}

plyform_law_history to_c(const NodeHistory& h) {
  plyform_law_history c{};
  c.state = static_cast<int32_t>(h.state);
  c.beta = h.beta;
  c.gap = h.gap;
  c.slip[0] = h.slip[0];
  c.slip[1] = h.slip[1];
  c.opening[0] = h.opening_t[0];
  c.opening[1] = h.opening_t[1];
  c.e_damage = h.e_damage;
  c.e_viscous = h.e_viscous;
  c.e_friction = h.e_friction;
  c.e_damping = h.e_damping;
  c.e_healing = h.e_healing;
  c.damping = h.damping;
  return c;
}

bool valid_state(int32_t s) {
  return s >= 0 && s <= 3;
}

}  // namespace

extern "C" {

plyform_law_status plyform_law_create(const double* constants, int32_t n_constants,
                                      const plyform_law_curve* curves, int32_t n_curves,
                                      plyform_law** law, char* message, size_t message_size) {
  if (law == nullptr || n_constants < 0 || n_curves < 0 || (n_constants > 0 && !constants) ||
      (n_curves > 0 && !curves)) {
    write_message(message, message_size, "plyform_law_create: invalid argument");
    return PLYFORM_LAW_INVALID_ARGUMENT;
  }
  *law = nullptr;
  try {
    std::vector<std::optional<double>> uc(static_cast<std::size_t>(n_constants));
    for (std::size_t i = 0; i < uc.size(); ++i) {
      if (!std::isnan(constants[i]))
        uc[i] = constants[i];
    }
    std::vector<plyform::law::Curve> tables;
    for (int32_t c = 0; c < n_curves; ++c) {
      const plyform_law_curve& src = curves[c];
      if (src.n_points < 0 || (src.n_points > 0 && (!src.x || !src.y))) {
        write_message(message, message_size, "plyform_law_create: invalid curve");
        return PLYFORM_LAW_INVALID_ARGUMENT;
      }
      const auto n = static_cast<std::size_t>(src.n_points);
      tables.emplace_back(src.id, std::vector<double>(src.x, src.x + n),
                          std::vector<double>(src.y, src.y + n));
    }
    auto result = plyform::law::from_user_constants(uc, tables);
    if (!result.ok()) {
      std::string text;
      for (const auto& e : result.errors)
        text += e.message + "\n";
      write_message(message, message_size, text);
      return PLYFORM_LAW_INVALID_PARAMETER;
    }
    *law = new plyform_law{plyform::law::Law(std::move(result.parameters))};
    write_message(message, message_size, "");
    return PLYFORM_LAW_OK;
  } catch (const plyform::law::InvalidParameters& e) {
    write_message(message, message_size, e.what());
    return PLYFORM_LAW_INVALID_PARAMETER;
  } catch (const std::bad_alloc&) {
    return PLYFORM_LAW_OUT_OF_MEMORY;
  } catch (...) {
    return PLYFORM_LAW_INTERNAL_ERROR;
  }
}

void plyform_law_destroy(plyform_law* law) {
  delete law;
}

plyform_law_status plyform_law_initial_history(const plyform_law* law, double gap,
                                               plyform_law_history* history) {
  if (law == nullptr || history == nullptr || !std::isfinite(gap)) {
    return PLYFORM_LAW_INVALID_ARGUMENT;
  }
  *history = to_c(law->law.initial_history(gap));
  return PLYFORM_LAW_OK;
}

plyform_law_status plyform_law_update_node(const plyform_law* law,
                                           const plyform_law_increment* increment,
                                           plyform_law_history* history,
                                           plyform_law_response* response) {
  if (law == nullptr || increment == nullptr || history == nullptr || response == nullptr ||
      !(increment->dt > 0.0) || !valid_state(history->state)) {
    return PLYFORM_LAW_INVALID_ARGUMENT;
  }
  plyform::law::Increment in;
  in.gap = increment->gap;
  in.slip[0] = increment->slip[0];
  in.slip[1] = increment->slip[1];
  in.dt = increment->dt;
  in.temperature = increment->temperature;
  in.k_normal = increment->k_normal;
  in.k_tangent = increment->k_tangent;
  in.area = increment->area;
  in.mass = increment->mass;
  NodeHistory h = from_c(*history);
  const plyform::law::Response r = law->law.update(in, h);
  *history = to_c(h);
  response->pressure = r.pressure;
  response->tau[0] = r.tau[0];
  response->tau[1] = r.tau[1];
  response->stored = r.stored;
  return PLYFORM_LAW_OK;
}

plyform_law_status plyform_law_update_batch(const plyform_law* law, const plyform_law_batch* b) {
  if (law == nullptr || b == nullptr || b->n < 0 || !(b->dt > 0.0)) {
    return PLYFORM_LAW_INVALID_ARGUMENT;
  }
  if (b->n == 0)
    return PLYFORM_LAW_OK;
  const void* required[] = {
      b->gap,       b->slip_x,    b->slip_y,   b->temperature, b->k_normal,    b->k_tangent,
      b->area,      b->state,     b->beta,     b->hist_gap,    b->hist_slip_x, b->hist_slip_y,
      b->opening_x, b->opening_y, b->e_damage, b->e_viscous,   b->e_friction,  b->e_damping,
      b->e_healing, b->pressure,  b->tau_x,    b->tau_y,       b->damping};
  for (const void* ptr : required) {
    if (ptr == nullptr)
      return PLYFORM_LAW_INVALID_ARGUMENT;
  }
  for (int64_t i = 0; i < b->n; ++i) {
    if (!valid_state(b->state[i]))
      return PLYFORM_LAW_INVALID_ARGUMENT;
  }
  const plyform::law::BatchInput in{static_cast<std::size_t>(b->n),
                                    b->gap,
                                    b->slip_x,
                                    b->slip_y,
                                    b->temperature,
                                    b->k_normal,
                                    b->k_tangent,
                                    b->area,
                                    b->mass,
                                    b->dt};
  const plyform::law::BatchHistory h{b->state,       b->beta,       b->hist_gap,  b->hist_slip_x,
                                     b->hist_slip_y, b->opening_x,  b->opening_y, b->e_damage,
                                     b->e_viscous,   b->e_friction, b->e_damping, b->e_healing,
                                     b->damping};
  const plyform::law::BatchOutput out{b->pressure, b->tau_x, b->tau_y, b->stored};
  law->law.update_batch(in, h, out);
  return PLYFORM_LAW_OK;
}

plyform_law_status plyform_law_update_mode1(const plyform_law* law, double gap, double dt,
                                            double temperature, double k_normal, double hist[3],
                                            double* pressure) {
  if (law == nullptr || hist == nullptr || pressure == nullptr || !(dt > 0.0)) {
    return PLYFORM_LAW_INVALID_ARGUMENT;
  }
  const auto state = static_cast<int32_t>(hist[0]);
  if (!valid_state(state) || static_cast<double>(state) != hist[0]) {
    return PLYFORM_LAW_INVALID_ARGUMENT;
  }
  NodeHistory h;
  h.state = static_cast<NodeState>(state);
  h.beta = hist[1];
  h.gap = hist[2];
  plyform::law::Increment in;
  in.gap = gap;
  in.dt = dt;
  in.temperature = temperature;
  in.k_normal = k_normal;
  const plyform::law::Response r = law->law.update(in, h);
  hist[0] = static_cast<double>(static_cast<int32_t>(h.state));
  hist[1] = h.beta;
  hist[2] = h.gap;
  *pressure = r.pressure;
  return PLYFORM_LAW_OK;
}

const char* plyform_law_state_name(int32_t state) {
  if (!valid_state(state))
    return "UNKNOWN";
  // string_view literals of to_string are NUL-terminated.
  return plyform::law::to_string(static_cast<NodeState>(state)).data();
}

}  // extern "C"
