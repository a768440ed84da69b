#pragma once

#include <array>
#include <string>
#include <vector>

#include "plyform/core/types.hpp"

namespace plyform::core {

/// A planar rigid wall (*RIGIDWALL_PLANAR): its slave nodes cannot cross the plane through
/// `origin` from the side `normal` points to (docs/boundary-conditions.md, "Rigid walls").
struct RigidWall {
  GlobalId id = 0;      ///< the deck's id (_ID), else its place among the walls (1, 2, ...)
  std::string heading;  ///< its title, for messages
  /// The slave nodes, in index order: the deck's nodes less those left out (NSIDEX, OFFSET,
  /// held by a constraint or a rigid body, of no element, behind the wall at t = 0).
  std::vector<Index> nodes;
  std::vector<Index> display_nodes;  ///< N1..N4 of _FORCES: moved with the wall
  std::array<double, 3> origin{};    ///< a point of the wall at t = 0 (the tail)
  std::array<double, 3> normal{};    ///< unit normal, towards the slave nodes
  bool finite = false;               ///< _FINITE: the rectangle origin + a l + b m, a, b >= 0
  std::array<double, 3> edge_l{};    ///< unit edge l (in the plane)
  std::array<double, 3> edge_m{};    ///< unit edge m = n x l
  double length_l = 0.0, length_m = 0.0;
  double friction = 0.0;   ///< 0 frictionless, 1 no sliding, between: Coulomb coefficient
  double mass = 0.0;       ///< > 0: a moving wall of this mass; 0: the wall does not move
  double velocity0 = 0.0;  ///< initial velocity along the normal (moving walls)
  double birth = 0.0, death = 1e20;
};

}  // namespace plyform::core
