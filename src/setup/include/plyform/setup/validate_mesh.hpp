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

#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

[[nodiscard]] std::vector<keyword::Diagnostic> validate_mesh(const model::ModelDesc& model);

}  // namespace plyform::setup
