#pragma once
// The thermal keywords as read: the solution type, the thermal solver and its time step,
// thermal materials and the heat boundaries on segment sets. The meaning of each field is
// LS-DYNA's; the reader rejects by name the values plyform does not implement.

#include <array>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *CONTROL_SOLUTION.
struct ControlSolutionDesc {
  int soln = 0;     ///< SOLN: 0 structural only, 1 thermal only, 2 coupled
  int nlq = 0;      ///< NLQ: vector length, as written (no meaning here)
  int isnan = 0;    ///< ISNAN: plyform always checks for non-finite forces
  int lcint = 100;  ///< LCINT: curve rediscretization points (plyform evaluates curves exactly)
  SourceLocation where;
};

/// *CONTROL_THERMAL_SOLVER (cards 1-3).
struct ControlThermalSolverDesc {
  int atype = 0;          ///< ATYPE: 0 steady state, 1 transient
  int ptype = 0;          ///< PTYPE: 0 linear
  int solver = 11;        ///< SOLVER: 11 direct (LDL^T), 12 diagonally scaled conjugate gradients
  int gpt = 8;            ///< GPT: Gauss points of the solids, 8 or 1
  double eqheat = 1.0;    ///< EQHEAT: mechanical equivalent of heat
  double fwork = 1.0;     ///< FWORK: fraction of the mechanical work turned into heat
  double sbc = 0.0;       ///< SBC: Stefan-Boltzmann constant (enclosure radiation only)
  int msglvl = 0;         ///< MSGLVL, as written
  int maxitr = 500;       ///< MAXITR: conjugate-gradient iterations (blank or 0: 500)
  double abstol = 1e-10;  ///< ABSTOL: absolute tolerance (blank or 0: 1e-10)
  double reltol = 1e-6;   ///< RELTOL: relative tolerance (blank or 0: 1e-6)
  double omega = 0.0;     ///< OMEGA: relaxation of solvers 14 and 16; must be 0
  double tsf = 1.0;       ///< TSF: thermal speed-up factor (< 0: -TSF is a curve against time)
  int mxdmp = 0;          ///< MXDMP: matrix dumps; must be 0
  double dtvf = 0.0;      ///< DTVF: view factor updates (no enclosure radiation); as written
  int varden = 0;         ///< VARDEN: must be 0 (the thermal density stays TRO)
  int ncycl = 1;          ///< NCYCL: thermal steps between matrix reassemblies (blank or 0: 1)
  SourceLocation where;
};

/// *CONTROL_THERMAL_TIMESTEP.
struct ControlThermalTimestepDesc {
  int ts = 0;          ///< TS: 0 fixed step, 1 variable step
  double tip = 0.5;    ///< TIP: time integration parameter theta, 0.5 to 1 (blank or 0: 0.5)
  double its = 0.0;    ///< ITS: initial thermal step, time units
  double tmin = 0.0;   ///< TMIN: smallest step (0: the mechanical step)
  double tmax = 0.0;   ///< TMAX: largest step (0: 100 mechanical steps)
  double dtemp = 1.0;  ///< DTEMP: temperature change per step that the variable step aims at
  double tscp = 0.5;   ///< TSCP: factor by which the variable step is cut (0 < TSCP < 1)
  int lcts = 0;        ///< LCTS: curve of step breakpoints; must be 0
  SourceLocation where;
};

/// *MAT_THERMAL_ISOTROPIC (orthotropic = false) and *MAT_THERMAL_ORTHOTROPIC.
struct MatThermalDesc {
  int id = 0;                  ///< TMID
  bool orthotropic = false;    ///< the _ORTHOTROPIC keyword
  double density = 0.0;        ///< TRO: thermal density (0: the structural density)
  int tgrlc = 0;               ///< TGRLC: curve of the heat generation rate (> 0 time, < 0 T)
  double tgmult = 0.0;         ///< TGMULT: heat generation rate per volume (multiplier)
  double tlat = 0.0;           ///< TLAT: phase change temperature; as written
  double hlat = 0.0;           ///< HLAT: latent heat; must be 0
  double heat_capacity = 0.0;  ///< HC: specific heat
  /// TC (isotropic: all three) or K1 K2 K3 along the material axes a, b, c.
  std::array<double, 3> conductivity{};
  int aopt = 0;               ///< AOPT (orthotropic): 0 element nodes 1-2-4, 2 vectors A and D
  std::array<double, 3> p{};  ///< XP YP ZP (AOPT 1), as written
  std::array<double, 3> a{};  ///< A1 A2 A3
  std::array<double, 3> d{};  ///< D1 D2 D3
  SourceLocation where;       ///< the line of card 1
};

/// Which heat boundary a *BOUNDARY_..._SET card is.
enum class HeatBoundaryKind { kConvection, kFlux, kRadiation };

/// One *BOUNDARY_CONVECTION_SET, *BOUNDARY_FLUX_SET or *BOUNDARY_RADIATION_SET: on the
/// segments of a segment set.
///  - convection: q = h (T_inf - T), h = HMULT x curve HLCID(t) (0: HMULT), T_inf = TMULT x
///    curve TLCID(t) (0: TMULT);
///  - flux: q = MLCi x curve LCID(t) at node i of each segment (0: MLCi), positive into the
///    body;
///  - radiation (TYPE 1, to the environment): q = f (T_inf^4 - T^4), f = RFMULT x curve
///    RFLCID(t) (0: RFMULT), T_inf = TIMULT x curve TILCID(t) (0: TIMULT); T in absolute units.
/// A negative curve id (a function of temperature) is not supported.
struct HeatBoundaryDesc {
  HeatBoundaryKind kind = HeatBoundaryKind::kConvection;
  int segment_set_id = 0;                               ///< SSID
  int pserod = 0;                                       ///< PSEROD: must be 0 (no erosion)
  int type = 1;                                         ///< TYPE (radiation): must be 1
  int curve_id = 0;                                     ///< HLCID, LCID or RFLCID
  double mult = 1.0;                                    ///< HMULT or RFMULT
  std::array<double, 4> node_mult{1.0, 1.0, 1.0, 1.0};  ///< MLC1..MLC4 (flux)
  int ambient_curve_id = 0;                             ///< TLCID or TILCID
  double ambient_mult = 1.0;                            ///< TMULT or TIMULT
  int loc = 0;           ///< LOC: thick thermal shells' face: -1 bottom, 0 middle, 1 top
  int nhisv = 0;         ///< NHISV (flux): must be 0
  SourceLocation where;  ///< the line of card 2 (or 1)
};

/// *DATABASE_TPRINT: thermal histories (tprint.csv, heat.csv).
struct DatabaseTprintDesc {
  double dt = 0.0;  ///< DT: interval
  int binary = 0;   ///< BINARY, as written (plyform writes CSV)
  int lcur = 0;     ///< LCUR: must be 0
  int ioopt = 1;    ///< IOOPT, as written
  SourceLocation where;
};

}  // namespace plyform::model
