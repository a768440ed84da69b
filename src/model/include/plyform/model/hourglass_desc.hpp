#pragma once

#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *HOURGLASS: hourglass control referenced by a part's HGID. Blank fields hold LS-DYNA's
/// defaults as documented in docs/keywords.md.
struct HourglassDesc {
  int id = 0;            ///< HGID
  std::string title;     ///< from the _TITLE option; empty otherwise
  int ihq = 0;           ///< IHQ: hourglass control type (0: *CONTROL_HOURGLASS's)
  double qm = 0.1;       ///< QM: hourglass coefficient
  int ibq = 0;           ///< IBQ: not used by LS-DYNA's explicit solver, as written
  double q1 = 1.5;       ///< Q1: quadratic bulk viscosity coefficient
  double q2 = 0.06;      ///< Q2: linear bulk viscosity coefficient
  double qb = 0.1;       ///< QB (VDC for IHQ 10): bending hourglass coefficient; blank = QM
  double qw = 0.1;       ///< QW: warping hourglass coefficient; blank = QM
  SourceLocation where;  ///< the line of the card holding HGID
};

}  // namespace plyform::model
