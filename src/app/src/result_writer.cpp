#include "result_writer.hpp"

#include <limits>

namespace plyform::app {

ResultWriter::ResultWriter(const core::Model& model, const std::filesystem::path& outdir,
                           std::ostream& terminal, bool show_progress)
    : model_(model), series_(outdir), progress_(terminal, show_progress) {
  if (model.output.glstat_dt > 0.0)
    glstat_.emplace(outdir / output::glstat_file_name);
  if (model.output.nodout_dt > 0.0 && !model.output.history_nodes.empty()) {
    nodout_.emplace(outdir / output::nodout_file_name);
  }
  node_ids_.assign(model.node_id.begin(), model.node_id.end());
  for (const core::SolidBlock& b : model.solid_blocks) {
    for (std::size_t e = 0; e < b.size(); ++e) {
      // LS-DYNA's hexahedron order is VTK's; degenerate hexes stay hexahedra with repeated nodes.
      for (int i = 0; i < 8; ++i)
        connectivity_.push_back(b.connectivity[8 * e + static_cast<std::size_t>(i)]);
      offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
      cell_types_.push_back(output::vtk_cell::hexahedron);
      element_ids_.push_back(b.element_id[e]);
      part_ids_.push_back(model.parts[static_cast<std::size_t>(b.part)].id);
    }
  }
  const std::size_t n = model.node_count();
  displacement_.resize(3 * n);
  velocity_.resize(3 * n);
  // No thermal field yet: NaN says "not defined" rather than a made-up temperature.
  temperature_.assign(n, std::numeric_limits<double>::quiet_NaN());
  stress_.resize(6 * element_ids_.size());
  plastic_strain_.assign(element_ids_.size(), 0.0);  // the solid laws so far are elastic
}

void ResultWriter::state(const engine::Snapshot& s) {
  const engine::NodalState& ns = *s.nodes;
  const std::size_t n = ns.size();
  for (std::size_t i = 0; i < n; ++i) {
    displacement_[3 * i] = ns.ux[i];
    displacement_[3 * i + 1] = ns.uy[i];
    displacement_[3 * i + 2] = ns.uz[i];
    velocity_[3 * i] = ns.vnx[i];
    velocity_[3 * i + 1] = ns.vny[i];
    velocity_[3 * i + 2] = ns.vnz[i];
  }
  // Cell stress: the mean over the element's integration points.
  std::size_t cell = 0;
  for (const element::SolidBlockState& st : *s.solids) {
    const auto points = static_cast<std::size_t>(st.points);
    const std::size_t elements = st.volume.size();
    for (std::size_t e = 0; e < elements; ++e, ++cell) {
      for (int c = 0; c < 6; ++c) {
        double sum = 0.0;
        for (std::size_t q = 0; q < points; ++q)
          sum += st.s[c][e * points + q];
        stress_[6 * cell + static_cast<std::size_t>(c)] = sum / static_cast<double>(points);
      }
    }
  }
  output::GridPiece piece;
  piece.x = ns.x;
  piece.y = ns.y;
  piece.z = ns.z;
  piece.connectivity = connectivity_;
  piece.offsets = offsets_;
  piece.cell_types = cell_types_;
  piece.point_data = {{"displacement", 3, displacement_},
                      {"velocity", 3, velocity_},
                      {"temperature", 1, temperature_}};
  piece.cell_data = {{"stress", 6, stress_}, {"plastic_strain", 1, plastic_strain_}};
  piece.point_ids = {{"node_id", node_ids_}};
  piece.cell_ids = {{"element_id", element_ids_}, {"part", part_ids_}};
  series_.write_state(s.time, piece);
}

void ResultWriter::glstat(const engine::Energies& e) {
  if (!glstat_)
    return;
  glstat_->write(output::GlstatRow{e.time, e.dt, e.kinetic, e.internal, e.hourglass, e.contact,
                                   e.external_work, e.total, e.ratio});
}

void ResultWriter::nodout(const engine::Snapshot& s) {
  if (!nodout_)
    return;
  const engine::NodalState& ns = *s.nodes;
  rows_.clear();
  for (core::Index idx : model_.output.history_nodes) {
    const auto i = static_cast<std::size_t>(idx);
    rows_.push_back(output::NodoutRow{s.time, model_.node_id[i], ns.x[i], ns.y[i], ns.z[i],
                                      ns.ux[i], ns.uy[i], ns.uz[i], ns.vnx[i], ns.vny[i],
                                      ns.vnz[i]});
  }
  nodout_->write(rows_);
}

void ResultWriter::progress(double time, double end_time, long cycle, double dt, double wall) {
  progress_.update(time, end_time, cycle, dt, wall);
}

void ResultWriter::finish() {
  progress_.finish();
}

}  // namespace plyform::app
