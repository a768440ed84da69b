#pragma once
// The runtime description of heat transfer: thermal materials, heat boundaries on faces and
// the thermal solver's controls, built by setup::build from the thermal keywords. Quantities
// with time in the denominator are as the deck gives them; the thermal speed-up factor scales
// them in the solver.

#include <array>
#include <vector>

#include "plyform/core/types.hpp"

namespace plyform::core {

/// *MAT_THERMAL_ISOTROPIC / _ORTHOTROPIC of one part.
struct ThermalMaterial {
  GlobalId id = 0;             ///< TMID
  double density = 0.0;        ///< TRO, or the structural density when TRO = 0
  double heat_capacity = 0.0;  ///< HC: specific heat
  /// Conductivity along the material axes a, b, c (isotropic: three equal values).
  std::array<double, 3> conductivity{};
  bool orthotropic = false;
  int aopt = 0;                 ///< 0: axes from element nodes 1-2-4; 2: the vectors a and d
  std::array<double, 3> a{};    ///< AOPT 2: a
  std::array<double, 3> d{};    ///< AOPT 2: d (b = c x a, c = a x d)
  Index generation_curve = -1;  ///< TGRLC: heat generation rate per volume against time
  double generation = 0.0;      ///< TGMULT
};

enum class HeatBoundaryKind : int { convection = 0, flux = 1, radiation = 2 };

/// One *BOUNDARY_CONVECTION/_FLUX/_RADIATION_SET on the faces of a segment set.
struct HeatBoundary {
  HeatBoundaryKind kind = HeatBoundaryKind::convection;
  GlobalId set_id = 0;       ///< SSID, for messages
  std::vector<Index> faces;  ///< 4 node indices per face (a triangle repeats N3)
  Index curve = -1;          ///< h, flux or radiation factor against time (-1: constant)
  double mult = 1.0;         ///< HMULT, RFMULT (flux: 1)
  std::array<double, 4> node_mult{1.0, 1.0, 1.0, 1.0};  ///< flux MLC1..MLC4
  Index ambient_curve = -1;                             ///< T_inf against time (-1: constant)
  double ambient_mult = 1.0;                            ///< TMULT, TIMULT
  int loc = 0;  ///< LOC: on thick thermal shells the bottom (-1), middle (0) or top (1) face
};

/// *CONTROL_SOLUTION, *CONTROL_THERMAL_SOLVER and *CONTROL_THERMAL_TIMESTEP.
struct ThermalControls {
  bool enabled = false;        ///< SOLN 1 or 2: temperatures are computed
  bool thermal_only = false;   ///< SOLN 1: no mechanics
  bool steady = false;         ///< ATYPE 0: each thermal step solves the steady state
  int solver = 11;             ///< 11 direct LDL^T, 12 diagonally scaled conjugate gradients
  bool one_point = false;      ///< GPT 1: solids integrate at their centre
  double theta = 0.5;          ///< TIP
  double dt_initial = 0.0;     ///< ITS
  bool variable_step = false;  ///< TS 1
  double dt_min = 0.0;         ///< TMIN (0: the mechanical step; thermal only: none)
  double dt_max = 0.0;         ///< TMAX (0: 100 mechanical steps; thermal only: none)
  double dtemp = 1.0;          ///< DTEMP
  double tscp = 0.5;           ///< TSCP
  double tsf = 1.0;            ///< TSF (when tsf_curve < 0)
  Index tsf_curve = -1;        ///< -TSF: the speed-up factor against time
  int max_iterations = 500;    ///< MAXITR
  double abs_tol = 1e-10;      ///< ABSTOL
  double rel_tol = 1e-6;       ///< RELTOL
  int reassemble_every = 1;    ///< NCYCL
  double fwork = 1.0;          ///< FWORK
  double eqheat = 1.0;         ///< EQHEAT
  /// *CONTROL_SHELL THSHEL 1: conducting shells carry a temperature profile through their
  /// thickness (thick thermal shells: bottom, middle and top temperatures per node).
  bool thick_shells = false;
};

}  // namespace plyform::core
