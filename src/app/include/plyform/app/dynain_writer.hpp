#pragma once
// LS-DYNA's springback file, written at the end of a run with *INTERFACE_SPRINGBACK_LSDYNA
// (docs/outputs.md, "dynain"): the formed shells as a keyword deck that LS-DYNA, OpenRadioss
// and plyform read, so that the next operation (springback, a second draw, a flanging, a
// trimming run) starts from the formed part.
//
//   *KEYWORD
//   *NODE                     the written shells' nodes at their current positions
//   *ELEMENT_SHELL_THICKNESS  the shells, each node's thickness = the element's current one
//   *INITIAL_STRESS_SHELL     per shell: every point's stress (global axes) and plastic strain
//   *INITIAL_STRAIN_SHELL     per shell: the inner and outer surfaces' strain tensors
//   *END
//
// Fixed fields as LS-DYNA's manual lays them out: *NODE I8 + 3 x 16, the element cards 8 x 8
// and 16-character thicknesses, the initial-state headers 8 x 10, their point cards in the
// LARGE format (20-character fields, 14 significant digits) so that the state reads back to
// 1e-13 of itself.

#include <filesystem>

#include "plyform/core/model.hpp"
#include "plyform/engine/solver.hpp"

namespace plyform::app {

/// Writes `file` from the end state `s` (positions up to date: OutputSink::end_of_run) for the
/// shell blocks of model.output.dynain. Written to `file`.tmp and renamed. Throws
/// std::runtime_error when the file cannot be written.
void write_dynain(const std::filesystem::path& file, const core::Model& model,
                  const engine::Snapshot& s);

}  // namespace plyform::app
