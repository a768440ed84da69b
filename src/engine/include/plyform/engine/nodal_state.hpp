#pragma once
// Nodal state of the explicit integrator, one array per component.

#include <cstddef>
#include <vector>

namespace plyform::engine {

struct NodalState {
  std::vector<double> x, y, z;        ///< current coordinates, t_n
  std::vector<double> ux, uy, uz;     ///< displacements, t_n
  std::vector<double> vx, vy, vz;     ///< velocities at t_{n+1/2} (integrator's own)
  std::vector<double> vnx, vny, vnz;  ///< velocities at t_n (for output and kinetic energy)
  std::vector<double> fx, fy, fz;     ///< internal forces at t_n
  std::vector<double> ex, ey, ez;     ///< external forces at t_n
  std::vector<double> rx, ry, rz;     ///< reaction forces at constrained dofs, t_n
  std::vector<double> mass;           ///< lumped mass (with mass scaling)
  // Rotational freedoms (nodes of shells; zero inertia elsewhere).
  std::vector<double> wx, wy, wz;     ///< angular velocities at t_{n+1/2}
  std::vector<double> wnx, wny, wnz;  ///< angular velocities at t_n (output, kinetic energy)
  std::vector<double> mx, my, mz;     ///< internal moments at t_n
  std::vector<double> inertia;        ///< lumped rotary inertia (isotropic)
  std::vector<double> temperature;    ///< nodal temperature at t_n (the contact law reads it)

  void resize(std::size_t n);
  [[nodiscard]] std::size_t size() const { return x.size(); }
};

}  // namespace plyform::engine
