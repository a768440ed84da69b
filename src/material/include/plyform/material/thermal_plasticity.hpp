#pragma once
// *MAT_ELASTIC_PLASTIC_THERMAL (004): J2 plasticity whose elastic and hardening constants follow
// the temperature of each point. Point by point: the constants at the point's temperature
// (linear between the table's points), the elastic Jaumann trial with E(T), nu(T), the radial
// return (solids) or the exact plane-stress return (shells) on sigma_y = SIGY(T) + E_p(T) eps_p.
// The thermal strain is not applied here: the element kernels subtract alpha(T) dT from the
// strain increments of every law (core::SolidBlock::expansion).

#include <cstddef>

#include "plyform/core/material.hpp"
#include "plyform/material/constitutive.hpp"
#include "plyform/material/shell.hpp"

namespace plyform::material {

/// The law's constants at one temperature.
struct ThermalPlasticConstants {
  double young = 0.0;
  double poisson = 0.0;
  double sigy = 0.0;
  double hardening = 0.0;  ///< E_p = E ETAN / (E - ETAN)
};

/// Linear interpolation in the table at temperature t (the end values outside it: the engine
/// stops a run whose temperatures leave the table before a law sees them).
[[nodiscard]] ThermalPlasticConstants constants_at(const core::ElasticPlasticThermal& m, double t);

/// 3D update of n points at the temperatures `temperature` (one per point, at t_{n+1}).
void solid_update(const core::ElasticPlasticThermal& m, std::size_t n, ConstSymView d,
                  const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                  const double* temperature, SymView sigma, double* eps_p);

/// Plane-stress update of n shell points at pts.temperature (one per point).
void shell_update(const core::ElasticPlasticThermal& m, std::size_t n, const ShellPoints& pts);

}  // namespace plyform::material
