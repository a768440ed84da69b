#pragma once

#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One range of a _GENERATE set: every id from `first` to `last` that the deck defines.
struct IdRange {
  int first = 0;  ///< BnBEG
  int last = 0;   ///< BnEND (>= first)
  SourceLocation where;
};

/// *SET_NODE_LIST or *SET_PART_LIST: a list of node or part ids (ModelDesc keeps the two
/// kinds apart: node_sets, part_sets); or *SET_NODE_GENERATE / *SET_PART_GENERATE, whose
/// ranges the reader turns into `ids` once the whole deck is read.
struct SetListDesc {
  int id = 0;         ///< SID
  std::string title;  ///< from the _TITLE option; empty otherwise
  double da1 = 0.0;   ///< DA1..DA4: attributes, as written
  double da2 = 0.0;
  double da3 = 0.0;
  double da4 = 0.0;
  std::string solver;                     ///< SOLVER ("MECH" when blank)
  std::vector<int> ids;                   ///< the node or part ids, in deck order
  std::vector<SourceLocation> ids_where;  ///< the card line of each id
  std::vector<IdRange> ranges;            ///< _GENERATE: the ranges as written
  std::string keyword;                    ///< as written, "*SET_NODE_GENERATE", for messages
  SourceLocation where;                   ///< the line of card 1 (SID ...)
};

}  // namespace plyform::model
