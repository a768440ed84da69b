#pragma once

#include <array>
#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *SECTION_SHELL: the formulation, through-thickness integration and thickness of shells.
struct SectionShellDesc {
  int id = 0;         ///< SECID
  std::string title;  ///< from the _TITLE option; empty otherwise
  /// ELFORM as LS-DYNA uses it: 2 Belytschko-Tsay (one point, hourglass control), 16 fully
  /// integrated. A written 0 (or blank) is stored as 2, LS-DYNA's default. The reader accepts
  /// 2 and 16; the build step decides which it can run.
  int elform = 2;
  /// SHRF: transverse shear correction factor. Blank or 0 is stored as 1.0, LS-DYNA's default
  /// (LS-DYNA recommends 5/6; the deck decides).
  double shear_factor = 1.0;
  int nip = 2;         ///< NIP: integration points through the thickness, 1..10 (0 is stored as 2)
  double propt = 1.0;  ///< PROPT: printout option, as written
  /// QR/IRID: through-thickness quadrature, 0 = Gauss (the only rule read for now; LS-DYNA
  /// selects Lobatto with INTGRD of *CONTROL_SHELL, not here).
  int quadrature = 0;
  int icomp = 0;  ///< ICOMP: 1 = a material angle per integration point (angles below)
  int setyp = 1;  ///< SETYP: 2D solid type (ELFORM 13-15 only), as written
  /// T1..T4: thickness at the element's N1..N4, length. A 0 in T2..T4 is stored as T1 (LS-DYNA
  /// uses T1 for all nodes when only T1 is given).
  std::array<double, 4> thickness{};
  double nloc = 0.0;   ///< NLOC: reference surface offset; must be 0 (mid-surface)
  double marea = 0.0;  ///< MAREA: non-structural mass per area; must be 0 (not supported yet)
  double idof = 0.0;   ///< IDOF: thickness field option; must be 0 (not supported yet)
  int edgset = 0;      ///< EDGSET: edge node set of shell seatbelts; must be 0
  /// B1..B_NIP: material angle at each integration point, degrees (ICOMP = 1 only; empty
  /// otherwise), bottom to top.
  std::vector<double> angles;
  SourceLocation where;  ///< the line of card 1 (SECID ELFORM ...)
};

}  // namespace plyform::model
