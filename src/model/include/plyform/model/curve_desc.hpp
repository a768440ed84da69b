#pragma once

#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One point of a curve after scale factors and offsets are applied.
struct CurvePoint {
  double x = 0.0;
  double y = 0.0;
};

/// *DEFINE_CURVE as written in the deck. Values are raw: scale factors and offsets are not
/// applied to the points; use effective_points() for the curve LS-DYNA evaluates.
struct CurveDesc {
  int id = 0;         ///< LCID
  std::string title;  ///< from the _TITLE option; empty otherwise
  int sidr = 0;       ///< 0: transient analysis only, 1: stress initialisation only, 2: both
  double sfa = 1.0;   ///< abscissa scale factor as written (0 means 1, see effective_points)
  double sfo = 1.0;   ///< ordinate scale factor as written (0 means 1)
  double offa = 0.0;  ///< abscissa offset, in abscissa units
  double offo = 0.0;  ///< ordinate offset, in ordinate units
  int dattyp = 0;     ///< data type flag (0: general curve)
  int lcint = 0;      ///< number of discretisation points (0: the solver default)
  std::vector<double> abscissa;  ///< A1..An as written (strictly increasing)
  std::vector<double> ordinate;  ///< O1..On as written
  SourceLocation where;          ///< the keyword line
};

/// The scale factor LS-DYNA uses for a written one: a scale factor of 0 means 1.
double effective_scale_factor(double written);

/// Points of the curve as LS-DYNA evaluates it: the offsets are applied first, then the scale
/// factors, x = SFA * (a + OFFA), y = SFO * (o + OFFO), with a zero SFA/SFO taken as 1.
std::vector<CurvePoint> effective_points(const CurveDesc& curve);

}  // namespace plyform::model
