#pragma once
// The penalty stiffness of a slave node against a segment (PENOPT, SOFT, the layers' and the
// tools' stability caps, the ties' share) and the masses it is scaled by.

#include <cmath>
#include <vector>

#include "pass_runtime.hpp"

namespace plyform::contact {

// Effective mass m_s m_m / (m_s + m_m) of a slave node against a point of a segment; rigid
// nodes count as infinitely heavy.
inline double effective_mass(double ms, double mm) {
  if (!std::isfinite(ms))
    return std::isfinite(mm) ? mm : 0.0;
  if (!std::isfinite(mm))
    return ms;
  return ms + mm > 0.0 ? ms * mm / (ms + mm) : 0.0;
}

// A node's mass; a rigid body's nodes count as infinitely heavy.
inline double node_mass(const std::vector<double>& mass, const unsigned char* rigid,
                        core::Index n) {
  const auto i = static_cast<std::size_t>(n);
  return rigid != nullptr && rigid[i] ? kInf : mass[i];
}

// A guard pass acts beyond this share of the two offsets' depth (core::ContactPass::guard):
// deep enough that the interface's own penalty carries every pressure of a healthy run alone
// (two stiff springs taking turns at one place chatter, and the friction's return mapping then
// books more than the friction force's work), shallow enough to stop a node well before its
// mid-surface reaches the other layer's.
constexpr double kGuardDepth = 0.1;

// A layer interface's penalty is held below kLayerPenaltyScale m* / dt0^2.
constexpr double kLayerPenaltyScale = 0.25;

// The stick spring of friction acts in the sheet's plane, where its elements' highest mode is
// already at the step's limit (at TSSFAC 0.9, 81 % of it in frequency squared); a spring of the
// normal penalty there (a 7 mm aluminium skin on a rigid die) outran what was left and the
// nodes chattered along the die. Held at sqrt(k / m*) dt0 = 1/2, as a layer's penalty.
constexpr double kStickScale = 0.25;

// A tool's (or any non-layer) material penalty is held below kToolPenaltyScale m* / dt0^2
// (sqrt(k / m*) dt0 = 1). A skin's edge node pressed by a rigid holder (7.5 mm elements of a
// 0.25 mm aluminium skin: sqrt(k / m*) dt0 = 1.22 at SFS 1) carries, beside that spring, its
// elements' transverse mode and the layer interface below it; together they passed the
// central difference's limit, the node flipped its velocity every cycle between the two
// springs and the contact gave energy (the restart tests' square cup at n 10 without backup
// contacts: -1.5 mJ, 1.7 % of the entered energy). The step vote cannot see it: it takes each
// spring alone.
constexpr double kToolPenaltyScale = 1.0;

/// The penalty stiffness [force/length] of slave k against segment s (PENOPT, SOFT).
double penalty(const PassRuntime& pr, std::size_t k, core::Index s, double m_eff);

}  // namespace plyform::contact
