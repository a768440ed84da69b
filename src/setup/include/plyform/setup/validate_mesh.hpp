#pragma once
// Validation of the mesh and of what refers to it: unique ids, references that resolve,
// element node lists, element-section compatibility. Every error names the file, line, keyword
// and field of the offending item; all errors are reported.
//
// Repeated nodes in *ELEMENT_SOLID: LS-DYNA writes degenerate solids as 8-node elements with
// repeated nodes. These patterns are accepted (a, b, c, ... distinct node ids):
//   hexahedron   a b c d e f g h
//   pentahedron  a b c d e e f f   (LS-DYNA's form)   and  a b c c d e f f  (collapsed face)
//   pyramid      a b c d e e e e
//   tetrahedron  a b c d d d d d   (LS-DYNA's form)   and  a b c c d d d d  (collapsed hex)
// Any other repeat is an error naming the field (N1..N8) that repeats an earlier node.
//
// *ELEMENT_SHELL: N1, N2, N3 distinct; N4 distinct from them, or N4 = N3 (a triangle). Any
// other repeat is an error naming the field. A shell element's part must have a
// *SECTION_SHELL (and a solid element's a *SECTION_SOLID), and the element a thickness: the
// section's T1 > 0 or THIC1..THIC4 (THIC1..THIC3 for a triangle) > 0 on its _THICKNESS card.
// Element ids of solids and shells are separate ranges, as in LS-DYNA; section ids are shared
// by all *SECTION_ keywords, material ids by all *MAT_ keywords.
//
// Rigid bodies: *BOUNDARY_PRESCRIBED_MOTION_RIGID and *LOAD_RIGID_BODY must name a part whose
// material is *MAT_RIGID. *MAT_PIECEWISE_LINEAR_PLASTICITY's LCSS must name a *DEFINE_CURVE.

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

[[nodiscard]] std::vector<keyword::Diagnostic> validate_mesh(const model::ModelDesc& model);

}  // namespace plyform::setup
