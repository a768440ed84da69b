#pragma once

#include <array>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One point of *INITIAL_STRESS_SHELL: its through-thickness coordinate, the stress in global
/// axes and the effective plastic strain.
struct InitialStressPoint {
  double t = 0.0;                 ///< T: through-thickness coordinate in [-1, 1]
  std::array<double, 6> sigma{};  ///< SIGXX SIGYY SIGZZ SIGXY SIGYZ SIGZX, global, stress
  double eps = 0.0;               ///< EPS: effective plastic strain
  SourceLocation where;           ///< the (first) card line of the point
};

/// *INITIAL_STRESS_SHELL: one shell's stress at t = 0. The points come as the cards give them:
/// NTHICK groups of NPLANE in-plane points (the thickness point outer, the in-plane point
/// inner, as LS-DYNA's manual orders them).
struct InitialStressShellDesc {
  int element_id = 0;  ///< EID
  int nplane = 1;      ///< NPLANE: in-plane points (1 or 4)
  int nthick = 0;      ///< NTHICK: through-thickness points
  int nhisv = 0;       ///< NHISV: history values per point (read, not applied: warned about)
  bool large = false;  ///< LARGE: 20-character fields, two cards per point
  std::vector<InitialStressPoint> points;  ///< nthick * nplane
  SourceLocation where;                    ///< the header card (EID NPLANE NTHICK ...)
};

/// One point of *INITIAL_STRAIN_SHELL: the strain tensor in global axes (tensor shears) and the
/// point's through-thickness coordinate.
struct InitialStrainPoint {
  std::array<double, 6> eps{};  ///< EPSXX EPSYY EPSZZ EPSXY EPSYZ EPSZX
  double t = 0.0;               ///< T in [-1, 1]
};

/// *INITIAL_STRAIN_SHELL: one shell's strains (LS-DYNA's dynain gives its inner and outer
/// surfaces). Read and checked; plyform's strain outputs are computed from the geometry, so the
/// values are not applied (setup warns once, naming the keyword).
struct InitialStrainShellDesc {
  int element_id = 0;  ///< EID
  int nplane = 1;      ///< NPLANE
  int nthick = 2;      ///< NTHICK
  bool large = false;  ///< LARGE
  std::vector<InitialStrainPoint> points;
  SourceLocation where;
};

/// *INTERFACE_SPRINGBACK_LSDYNA: write the dynain file (docs/outputs.md) at the end of the run.
struct InterfaceSpringbackDesc {
  int psid = 0;     ///< PSID: part set of the shells written (0: every deformable shell part)
  int nshv = 0;     ///< NSHV: history values per point written (plyform writes none)
  int ftype = 0;    ///< FTYPE: 0 or 1, LS-DYNA's keyword file (other formats are refused)
  int ftensr = 0;   ///< FTENSR: tensor history written (0 only)
  int nthhsv = 0;   ///< NTHHSV: thermal history values written (0 only)
  int rflag = 0;    ///< RFLAG: reference geometry written (0 only)
  int intstrn = 0;  ///< INTSTRN: strains written (the strain cards are written whatever it says)
  SourceLocation where;
};

}  // namespace plyform::model
