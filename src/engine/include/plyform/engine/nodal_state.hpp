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
  /// Thick thermal shells (THSHEL 1): their bottom and top faces' temperatures at the last
  /// thermal step (a node without faces: its temperature); empty without thick shells.
  std::vector<double> temperature_bottom, temperature_top;
  /// Thick thermal shells: the temperature the contact law reads at each node, a _THERMAL
  /// contact's slave node's face toward its segment (else the node's temperature).
  std::vector<double> temperature_interface;

  /// f(name, array) for every field that changes during a run (the checkpoint's records);
  /// mass and inertia are set up once from the elements. A new nodal field: a member above and
  /// a line here.
  template <class F>
  void for_each_state_field(F&& f) {
    f("x", x), f("y", y), f("z", z), f("ux", ux), f("uy", uy), f("uz", uz);
    f("vx", vx), f("vy", vy), f("vz", vz), f("vnx", vnx), f("vny", vny), f("vnz", vnz);
    f("fx", fx), f("fy", fy), f("fz", fz), f("ex", ex), f("ey", ey), f("ez", ez);
    f("rx", rx), f("ry", ry), f("rz", rz);
    f("wx", wx), f("wy", wy), f("wz", wz), f("wnx", wnx), f("wny", wny), f("wnz", wnz);
    f("mx", mx), f("my", my), f("mz", mz);
    f("temperature", temperature);
    f("temperature_bottom", temperature_bottom), f("temperature_top", temperature_top);
    f("temperature_interface", temperature_interface);
  }

  /// Every array to n zeros.
  void resize(std::size_t n);
  [[nodiscard]] std::size_t size() const { return x.size(); }
};

}  // namespace plyform::engine
