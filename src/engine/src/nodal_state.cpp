#include "plyform/engine/nodal_state.hpp"

namespace plyform::engine {

void NodalState::resize(std::size_t n) {
  for (auto* v : {&x,   &y,  &z,  &ux,  &uy,  &uz,  &vx, &vy, &vz, &vnx,     &vny,
                  &vnz, &fx, &fy, &fz,  &ex,  &ey,  &ez, &rx, &ry, &rz,      &mass,
                  &wx,  &wy, &wz, &wnx, &wny, &wnz, &mx, &my, &mz, &inertia, &temperature}) {
    v->assign(n, 0.0);
  }
}

}  // namespace plyform::engine
