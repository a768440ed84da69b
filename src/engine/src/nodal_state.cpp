#include "plyform/engine/nodal_state.hpp"

namespace plyform::engine {

void NodalState::resize(std::size_t n) {
  for_each_state_field([n](const char*, std::vector<double>& v) { v.assign(n, 0.0); });
  mass.assign(n, 0.0);
  inertia.assign(n, 0.0);
}

}  // namespace plyform::engine
