#pragma once

#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *DATABASE_BINARY_D3PLOT: the interval of full states (results_NNNN.vtu).
struct DatabaseBinaryD3plotDesc {
  double dt = 0.0;      ///< DT: interval, time units
  int lcdt = 0;         ///< LCDT: must be 0 (an interval curve is not supported yet)
  int beam = 0;         ///< BEAM, as written
  int npltc = 0;        ///< NPLTC: if > 0, DT = ENDTIM / NPLTC
  int part_set_id = 0;  ///< PSETID: part set written (0: all)
  SourceLocation where;
};

/// *DATABASE_BINARY_D3DUMP: checkpoints (OUTDIR/d3dump) every CYCL cycles and at the end.
struct DatabaseBinaryD3dumpDesc {
  int cycles = 0;  ///< CYCL: cycles between checkpoints (> 0)
  SourceLocation where;
};

/// *DATABASE_GLSTAT / *DATABASE_NODOUT: an ASCII history file's interval.
struct DatabaseAsciiDesc {
  std::string name;  ///< "GLSTAT", "NODOUT" or "RCFORC"
  double dt = 0.0;   ///< DT: interval, time units
  int binary = 0;    ///< BINARY: 0/1 ASCII, 2 binout, 3 both; plyform writes CSV always
  int lcur = 0;      ///< LCUR: must be 0 (an interval curve is not supported yet)
  int ioopt = 1;     ///< IOOPT, as written
  SourceLocation where;
};

/// *DATABASE_ELOUT: the interval of elout.csv (stresses and plastic strain of the
/// *DATABASE_HISTORY_SHELL / _SOLID elements at their integration points).
struct DatabaseEloutDesc {
  double dt = 0.0;  ///< DT: interval, time units
  int binary = 0;   ///< BINARY: 0/1 ASCII, 2 binout, 3 both; plyform writes CSV always
  int lcur = 0;     ///< LCUR: must be 0 (an interval curve is not supported yet)
  int ioopt = 1;    ///< IOOPT, as written
  /// OPTION1..OPTION4: extra history variables per integration point of solids, shells, thick
  /// shells and beams (LS-DYNA's); plyform writes none of them, a non-zero value is warned.
  int option1 = 0;
  int option2 = 0;
  int option3 = 0;
  int option4 = 0;
  SourceLocation where;
};

/// *DATABASE_EXTENT_BINARY: which fields the states (results_NNNN.vtu) hold. The values as
/// written (0 where blank); LS-DYNA's meaning of each is in docs/keywords.md. plyform honours
/// SIGFLG, EPSFLG, ENGFLG (thickness) and STRFLG's strain digit; requests for data it does not
/// write are warned about when read.
struct DatabaseExtentBinaryDesc {
  int neiph = 0, neips = 0, maxint = 0, strflg = 0, sigflg = 0, epsflg = 0, rltflg = 0, engflg = 0;
  int cmpflg = 0, ieverp = 0, beamip = 0, dcomp = 0, shge = 0, stssz = 0, n3thdt = 0, ialemat = 0;
  int nintsld = 0, pkp_sen = 0, hydro = 0, msscl = 0, therm = 0;
  double sclp = 0.0;
  std::string intout, nodout;
  int dtdt = 0, resplt = 0;
  SourceLocation where;
};

/// *DATABASE_HISTORY_SHELL / *DATABASE_HISTORY_SOLID (_ID): elements written to elout.csv.
struct DatabaseHistoryElementDesc {
  bool shell = true;                      ///< _SHELL (else _SOLID)
  std::vector<int> element_ids;           ///< in deck order
  std::vector<std::string> headings;      ///< _ID: the HEADING of each element; empty otherwise
  std::vector<SourceLocation> ids_where;  ///< the card line of each element id
  SourceLocation where;                   ///< the keyword line
};

/// *DATABASE_HISTORY_NODE (_ID): nodes written to nodout.csv.
struct DatabaseHistoryNodeDesc {
  std::vector<int> node_ids;               ///< in deck order
  std::vector<std::string> headings;       ///< _ID: the HEADING of each node; empty otherwise
  std::vector<SourceLocation> ids_where;   ///< the card line of each node id
  std::vector<int> set_ids;                ///< _SET: node set ids, in deck order
  std::vector<SourceLocation> sets_where;  ///< the card line of each set id
  SourceLocation where;                    ///< the keyword line
};

}  // namespace plyform::model
