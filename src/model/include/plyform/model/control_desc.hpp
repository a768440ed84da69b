#pragma once

#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *CONTROL_TERMINATION.
struct ControlTerminationDesc {
  double end_time = 0.0;  ///< ENDTIM, time units
  int end_cycle = 0;      ///< ENDCYC (0: no limit)
  double dtmin = 0.0;     ///< DTMIN: stop when dt falls below DTMIN x initial dt
  double endeng = 0.0;    ///< ENDENG: energy change limit, as written
  double endmas = 0.0;    ///< ENDMAS: mass change limit (mass scaling), as written
  int nosol = 0;          ///< NOSOL: 1 = read and check only
  SourceLocation where;   ///< the card line
};

/// *CONTROL_TIMESTEP.
struct ControlTimestepDesc {
  double dtinit = 0.0;   ///< DTINIT: initial step (0: the solver chooses), time units
  double tssfac = 0.9;   ///< TSSFAC: scale factor of the stable step (a written 0 is 0.9)
  int isdo = 0;          ///< ISDO: shell characteristic length option, as written
  double tslimt = 0.0;   ///< TSLIMT: shell minimum step, as written
  double dt2ms = 0.0;    ///< DT2MS: mass scaling target step (negative: only added mass)
  int lctm = 0;          ///< LCTM: curve of the largest step against time (0: none)
  int erode = 0;         ///< ERODE, as written
  int ms1st = 0;         ///< MS1ST, as written
  SourceLocation where;  ///< the card line
};

/// *CONTROL_ENERGY: which energies are computed (1 no, 2 yes, as LS-DYNA).
struct ControlEnergyDesc {
  int hgen = 1;    ///< HGEN: hourglass energy
  int rwen = 2;    ///< RWEN: rigid wall energy
  int slnten = 1;  ///< SLNTEN: sliding interface energy
  int rylen = 1;   ///< RYLEN: Rayleigh damping energy
  int irgen = 2;   ///< IRGEN: initial reference geometry energy
  SourceLocation where;
};

/// *CONTROL_ACCURACY: what it asks of the stress update and the shells' frame. plyform's
/// stress update is always objective (OSU is met whatever it says); INN is kept for
/// `plyform check`, which says what it means for plyform's shells.
struct ControlAccuracyDesc {
  int osu = 0;       ///< OSU: second-order objective stress update (0 off, 1 on)
  int inn = 1;       ///< INN: invariant node numbering (1 off, 2 shells, 3 solids, 4 both)
  int pidosu = 0;    ///< PIDOSU: part set of OSU
  int iacc = 0;      ///< IACC: implicit accuracy options
  double exacc = 0;  ///< EXACC: explicit accuracy parameter (0 only)
  SourceLocation where;
};

/// *CONTROL_BULK_VISCOSITY: the bulk viscosity of the parts without *HOURGLASS.
struct ControlBulkViscosityDesc {
  double q1 = 1.5;   ///< Q1: quadratic coefficient
  double q2 = 0.06;  ///< Q2: linear coefficient
  int type = 1;      ///< TYPE: 1 solids; -1, -2 solids and shells
  int btype = 0;     ///< BTYPE: beams (none in plyform), as written
  int tstype = 0;    ///< TSTYPE: thick shells (none in plyform), as written
  SourceLocation where;
};

/// *CONTROL_HOURGLASS: the default hourglass control.
struct ControlHourglassDesc {
  int ihq = 1;      ///< IHQ: default hourglass type
  double qh = 0.1;  ///< QH: default hourglass coefficient
  SourceLocation where;
};

/// *CONTROL_SHELL: the shell controls plyform implements (the others must keep their
/// defaults; the reader rejects anything else).
struct ControlShellDesc {
  int istupd = 0;  ///< ISTUPD: thickness update (plyform always updates; 0 is warned about)
  int theory = 2;  ///< THEORY: default shell formulation (2, Belytschko-Tsay)
  int intgrd = 0;  ///< INTGRD: through-thickness rule, 0 Gauss, 1 Lobatto
  int thshel = 0;  ///< THSHEL: 1 = thick thermal shells (a temperature profile through them)
  int esort = 0;   ///< ESORT: 1-2 sort triangles into a C0 triangle formulation (none here)
  SourceLocation where;
};

/// *CONTROL_PARALLEL: LS-DYNA's shared-memory run settings. `plyform run` takes |NCPU| as its
/// thread count when --threads is not given. A negative NCPU (and CONST 1) ask LS-DYNA for
/// results that do not depend on the thread count: plyform's never do, whatever the card says.
struct ControlParallelDesc {
  int ncpu = 1;          ///< NCPU: threads (negative: with consistency); 0 reads as LS-DYNA's 1
  int numrhs = 0;        ///< NUMRHS: 0 a right-hand side per CPU, 1 one, as written
  int consistency = 2;   ///< CONST: 1 consistent summation on, 2 off (LS-DYNA's default)
  int para = 0;          ///< PARA: parallel force assembly with CONST 1 (0 off, 1-2 on)
  SourceLocation where;  ///< the card line

  /// The thread count the card asks for: |NCPU|, at least 1.
  int threads() const { return ncpu == 0 ? 1 : (ncpu < 0 ? -ncpu : ncpu); }
};

/// *CONTROL_UNITS: names of the deck's units, kept as text (no conversion).
struct ControlUnitsDesc {
  std::string length;  ///< LENGTH ("m", "mm", ...)
  std::string time;    ///< TIME
  std::string mass;    ///< MASS
  std::string temp;    ///< TEMP
  SourceLocation where;
};

}  // namespace plyform::model
