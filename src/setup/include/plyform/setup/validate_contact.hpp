#pragma once
// Validation of the contacts, segment sets, user interface laws and temperatures against the
// rest of the deck. Every error names the file, line, keyword and field; all are reported.
//
// *CONTACT_..._SURFACE_TO_SURFACE: CID unique when not 0 (across the four contact keywords);
// SSID and MSID not 0 (plyform has no "every part" side) and defined as what SSTYP/MSTYP say:
// 0 a *SET_SEGMENT, 2 a *SET_PART_LIST, 3 a *PART, 4 a *SET_NODE_LIST (slave side only).
// *SET_SEGMENT: SID unique; N1..N4 defined nodes; N1, N2, N3 distinct and N4 distinct from them
// or N4 = N3 (a triangle).
// *USER_INTERFACE_FRICTION: NOSID names the CID of a contact. A deck with neither *NODE nor
// *CONTACT_ (the law alone, for `plyform law`) is exempt.
// *INITIAL_TEMPERATURE_NODE/_SET, *BOUNDARY_TEMPERATURE_NODE/_SET: the node or node set is
// defined; a non-zero LCID names a *DEFINE_CURVE; a node takes at most one
// *BOUNDARY_TEMPERATURE entry (directly or through a set).

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

[[nodiscard]] std::vector<keyword::Diagnostic> validate_contact(const model::ModelDesc& model);

}  // namespace plyform::setup
