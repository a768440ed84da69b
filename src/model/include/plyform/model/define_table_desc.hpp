#pragma once

#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *DEFINE_TABLE as written: values (temperatures, strain rates), each with the curve of the
/// table at that value. As in LS-DYNA the curves are the *DEFINE_CURVE keywords that follow the
/// table, one per value in order: `first_curve` is the index in ModelDesc::curves of the first
/// curve read after the table (see table_curve_ids). The LCID column is what the deck wrote
/// (LS-DYNA does not use it).
struct DefineTableDesc {
  int id = 0;                               ///< TBID
  std::string title;                        ///< from the _TITLE option; empty otherwise
  double sfa = 1.0;                         ///< scale factor of the values as written (0 means 1)
  double offa = 0.0;                        ///< offset of the values, applied before SFA
  std::vector<double> values;               ///< VALUE as written, strictly increasing
  std::vector<int> lcid_written;            ///< LCID as written (0 when blank)
  std::vector<SourceLocation> value_where;  ///< the line of each value card
  std::size_t first_curve = 0;  ///< index into ModelDesc::curves of the table's first curve
  SourceLocation where;         ///< the keyword line
};

/// The values LS-DYNA uses: SFA (value + OFFA), a zero SFA read as 1.
std::vector<double> effective_values(const DefineTableDesc& table);

}  // namespace plyform::model
