#pragma once
// Strain-rate scaling of the yield stress (Cowper-Symonds), shared by the J2 laws that take it:
// *MAT_PLASTIC_KINEMATIC (003, SRC SRP), *MAT_POWER_LAW_PLASTICITY (018, SRC SRP) and
// *MAT_PIECEWISE_LINEAR_PLASTICITY (024, C P with VP = 0). LS-DYNA's measure of the rate is
// the effective strain rate sqrt(D : D) of the total rate of deformation; a shell point's
// D_zz, which the element does not know before the law, is taken as -(D_xx + D_yy) (the
// plastic flow the factor acts on is isochoric), its transverse shear included.

#include <cmath>
#include <cstddef>

#include "plyform/material/constitutive.hpp"
#include "plyform/material/shell.hpp"

namespace plyform::material {

/// The Cowper-Symonds constants of a law: the yield stress is scaled by 1 + (rate / c)^(1 / p).
struct CowperSymonds {
  double c = 0.0;  ///< 1/time
  double p = 0.0;
  /// Rate effects are on when both constants are positive (LS-DYNA: 0 and 0 ignore them).
  [[nodiscard]] bool on() const { return c > 0.0 && p > 0.0; }
  /// The factor at an effective strain rate (1/time); 1 when off or at rest.
  [[nodiscard]] double factor(double rate) const {
    if (!on() || !(rate > 0.0))
      return 1.0;
    return 1.0 + std::pow(rate / c, 1.0 / p);
  }
};

/// sqrt(D : D) of solid point i (D the rate of deformation, tensor shear).
inline double solid_strain_rate(ConstSymView d, std::size_t i) {
  return std::sqrt(d.xx[i] * d.xx[i] + d.yy[i] * d.yy[i] + d.zz[i] * d.zz[i] +
                   2.0 * (d.xy[i] * d.xy[i] + d.yz[i] * d.yz[i] + d.zx[i] * d.zx[i]));
}

/// sqrt(D : D) of shell point i from its increments over the step dt, D_zz = -(D_xx + D_yy); 0
/// when the step is not known (dt <= 0).
inline double shell_strain_rate(const ShellPoints& pts, std::size_t i, double dt) {
  if (!(dt > 0.0))
    return 0.0;
  const double dxx = pts.dxx[i], dyy = pts.dyy[i], dzz = -(dxx + dyy);
  const double dd =
      dxx * dxx + dyy * dyy + dzz * dzz +
      2.0 * (pts.dxy[i] * pts.dxy[i] + pts.dyz[i] * pts.dyz[i] + pts.dzx[i] * pts.dzx[i]);
  return std::sqrt(dd) / dt;
}

}  // namespace plyform::material
