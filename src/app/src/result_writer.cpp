#include "result_writer.hpp"

#include <algorithm>
#include <limits>
#include <numbers>
#include <variant>

#include "plyform/app/dynain_writer.hpp"
#include "plyform/element/shell_kernels.hpp"
#include "plyform/material/woven_ply.hpp"
#include "shell_stress_global.hpp"
#include "state_strain.hpp"

namespace plyform::app {

namespace {

// The file names of save_state's records.
constexpr const char* kGlstat = "glstat.csv";
constexpr const char* kNodout = "nodout.csv";
constexpr const char* kRbdout = "rbdout.csv";
constexpr const char* kRwforc = "rwforc.csv";
constexpr const char* kBndout = "bndout.csv";
constexpr const char* kSpcforc = "spcforc.csv";
constexpr const char* kSleout = "sleout.csv";
constexpr const char* kMatsum = "matsum.csv";
constexpr const char* kElout = "elout.csv";
constexpr const char* kRcforc = "rcforc.csv";
constexpr const char* kInterfaceEnergy = "interface_energy.csv";
constexpr const char* kCohesive = "cohesive.csv";
constexpr const char* kHeat = "heat.csv";
constexpr const char* kTprint = "tprint.csv";

/// The number of shell cells (the last cells of every state).
std::size_t shell_cells(const core::Model& model) {
  std::size_t n = 0;
  for (const core::ShellBlock& b : model.shell_blocks)
    n += b.size();
  return n;
}

}  // namespace

ResultWriter::ResultWriter(const core::Model& model, const std::filesystem::path& outdir,
                           std::ostream& terminal, bool show_progress,
                           const core::StateArchive::Records* resume)
    : model_(model), outdir_(outdir), series_(outdir), progress_(terminal, show_progress) {
  std::optional<core::StateArchive> archive;
  if (resume != nullptr)
    archive.emplace(core::StateArchive::for_loading(*resume));
  std::optional<core::StateArchive::Scope> scope;
  if (archive)
    scope.emplace(*archive, "outputs");
  // How far the file had been written at the checkpoint (none: a new file).
  const auto at = [&](const char* file) -> std::optional<std::uint64_t> {
    if (!archive)
      return std::nullopt;
    std::uint64_t bytes = 0;
    archive->value(file, bytes);
    return bytes;
  };
  if (archive) {
    std::vector<double> times;
    archive->array("states", times);
    series_.resume(times);
  }
  if (model.output.glstat_dt > 0.0)
    glstat_.emplace(outdir / output::glstat_file_name, at(kGlstat));
  if (model.output.nodout_dt > 0.0 && !model.output.history_nodes.empty()) {
    nodout_.emplace(outdir / output::nodout_file_name, at(kNodout));
  }
  bool rigid = false;
  for (const auto& m : model.materials)
    rigid = rigid || std::holds_alternative<core::RigidMaterial>(m);
  if (rigid && model.output.glstat_dt > 0.0) {
    rbdout_.emplace(outdir / kRbdout,
                    std::vector<std::string>{"time", "part", "fx", "fy", "fz", "mx", "my", "mz",
                                             "x", "y", "z", "vx", "vy", "vz"},
                    at(kRbdout));
  }
  if (model.output.rwforc_dt > 0.0 && !model.rigid_walls.empty()) {
    rwforc_.emplace(
        outdir / kRwforc,
        std::vector<std::string>{"time", "wall", "normal", "tangential", "fx", "fy", "fz",
                                 "impulse", "nodes", "displacement", "velocity", "kinetic"},
        at(kRwforc));
  }
  if (model.output.bndout_dt > 0.0 && !model.motions.empty()) {
    for (const core::PrescribedMotion& p : model.motions)
      bndout_nodes_.push_back(p.node);
    std::sort(bndout_nodes_.begin(), bndout_nodes_.end());
    bndout_nodes_.erase(std::unique(bndout_nodes_.begin(), bndout_nodes_.end()),
                        bndout_nodes_.end());
    bndout_.emplace(outdir / kBndout, std::vector<std::string>{"time", "node", "fx", "fy", "fz"},
                    at(kBndout));
  }
  if (model.output.spcforc_dt > 0.0) {
    for (const core::FixedDofs& f : model.fixed) {
      if ((f.dofs & (core::dof_x | core::dof_y | core::dof_z)) != 0)
        spcforc_nodes_.push_back(f.node);
    }
    std::sort(spcforc_nodes_.begin(), spcforc_nodes_.end());
    spcforc_nodes_.erase(std::unique(spcforc_nodes_.begin(), spcforc_nodes_.end()),
                         spcforc_nodes_.end());
    if (!spcforc_nodes_.empty()) {
      spcforc_.emplace(outdir / kSpcforc,
                       std::vector<std::string>{"time", "node", "fx", "fy", "fz"}, at(kSpcforc));
    }
  }
  if (!model.contacts.empty() && model.output.sleout_dt > 0.0) {
    sleout_.emplace(outdir / kSleout,
                    std::vector<std::string>{"time", "interface", "energy", "friction"},
                    at(kSleout));
  }
  if (model.output.matsum_dt > 0.0) {
    matsum_.emplace(outdir / kMatsum,
                    std::vector<std::string>{"time", "part", "rigid", "internal", "kinetic",
                                             "hourglass", "momentum_x", "momentum_y", "momentum_z"},
                    at(kMatsum));
  }
  if (model.output.elout_dt > 0.0 &&
      (!model.output.history_shells.empty() || !model.output.history_solids.empty())) {
    elout_.emplace(
        outdir / kElout,
        std::vector<std::string>{"time", "element", "part", "type", "point", "points", "zeta",
                                 "sxx", "syy", "szz", "sxy", "syz", "szx", "plastic_strain"},
        at(kElout));
    for (const core::ShellBlock& b : model.shell_blocks) {
      std::vector<double> zeta(static_cast<std::size_t>(b.nip)), weight(zeta.size());
      element::thickness_rule(b.rule, b.nip, zeta.data(), weight.data());
      shell_zeta_.push_back(std::move(zeta));
    }
  }
  if ((!model.contacts.empty() || !model.tied.empty()) && model.output.rcforc_dt > 0.0)
    rcforc_.emplace(outdir / output::rcforc_file_name, at(kRcforc));
  if (!model.contacts.empty() && model.output.rcforc_dt > 0.0) {
    interface_energy_.emplace(
        outdir / kInterfaceEnergy,
        std::vector<std::string>{"time", "interface", "work", "stored", "damage", "viscous",
                                 "friction", "damping", "healing", "in_contact", "bonded",
                                 "surface"},
        at(kInterfaceEnergy));
  }
  for (const core::ContactInterface& c : model.contacts)
    cohesive_model_ = cohesive_model_ || c.cohesive || c.tiebreak.option > 0;
  if (cohesive_model_ && model.output.nodout_dt > 0.0 && !model.output.history_nodes.empty())
    cohesive_.emplace(outdir / output::cohesive_file_name, at(kCohesive));
  if (model.thermal.enabled) {
    heat_.emplace(
        outdir / kHeat,
        std::vector<std::string>{"time", "stored", "contact", "friction", "plastic", "convection",
                                 "radiation", "flux", "prescribed", "generation"},
        at(kHeat));
    if (model.output.tprint_dt > 0.0 && !model.output.history_nodes.empty()) {
      std::vector<std::string> columns{"time", "node", "temperature"};
      if (model.thermal.thick_shells) {
        columns.emplace_back("temperature_top");
        columns.emplace_back("temperature_bottom");
      }
      tprint_.emplace(outdir / kTprint, columns, at(kTprint));
    }
  }
  node_ids_.assign(model.node_id.begin(), model.node_id.end());
  for (const core::SolidBlock& b : model.solid_blocks) {
    for (std::size_t e = 0; e < b.size(); ++e) {
      // LS-DYNA's hexahedron order is VTK's; degenerate hexes stay hexahedra with repeated nodes.
      for (int i = 0; i < 8; ++i) {
        connectivity_.push_back(b.connectivity[8 * e + static_cast<std::size_t>(i)]);
      }
      offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
      cell_types_.push_back(output::vtk_cell::hexahedron);
      element_ids_.push_back(b.element_id[e]);
      part_ids_.push_back(model.parts[static_cast<std::size_t>(b.part)].id);
    }
  }
  for (const core::ShellBlock& b : model.shell_blocks) {
    for (std::size_t e = 0; e < b.size(); ++e) {
      const core::Index* c = &b.connectivity[4 * e];
      const bool triangle = c[2] == c[3];
      for (int i = 0; i < (triangle ? 3 : 4); ++i)
        connectivity_.push_back(c[i]);
      offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
      cell_types_.push_back(triangle ? output::vtk_cell::triangle : output::vtk_cell::quad);
      element_ids_.push_back(b.element_id[e]);
      part_ids_.push_back(model.parts[static_cast<std::size_t>(b.part)].id);
    }
  }
  const std::size_t n = model.node_count(), cells = element_ids_.size();
  displacement_.resize(3 * n);
  velocity_.resize(3 * n);
  // Without temperatures in the deck, NaN says "not defined" rather than a made-up value.
  temperature_.assign(n, std::numeric_limits<double>::quiet_NaN());
  stress_.resize(6 * cells);
  stress_top_.resize(6 * cells);
  stress_bottom_.resize(6 * cells);
  plastic_strain_.assign(cells, 0.0);
  thickness_.assign(cells, std::numeric_limits<double>::quiet_NaN());  // solids: none
  if (model.output.state_fields.strain)
    strain_.resize(6 * cells);
  for (const core::ShellBlock& b : model.shell_blocks) {
    const auto* ply = std::get_if<core::ReinforcedThermoplastic>(
        &model.materials[static_cast<std::size_t>(b.material)]);
    if (ply != nullptr)
      fibre_families_ = std::max(fibre_families_, ply->families);
  }
  bool deformable_shells = false;
  for (const core::ShellBlock& b : model.shell_blocks) {
    deformable_shells =
        deformable_shells ||
        (b.size() > 0 && !std::holds_alternative<core::RigidMaterial>(
                             model.materials[static_cast<std::size_t>(b.material)]));
  }
  if (deformable_shells)
    formability_.emplace(model, cells);
  if (fibre_families_ > 0) {
    for (int i = 0; i < fibre_families_; ++i)
      fibre_[i].assign(3 * cells, std::numeric_limits<double>::quiet_NaN());
    shear_angle_.assign(cells, std::numeric_limits<double>::quiet_NaN());
  }
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
  // Solids: the mean over the integration points (top and bottom are the same).
  std::size_t cell = 0;
  for (const element::SolidBlockState& st : *s.solids) {
    const auto points = static_cast<std::size_t>(st.points);
    const std::size_t elements = st.volume.size();
    for (std::size_t e = 0; e < elements; ++e, ++cell) {
      double eps = 0.0;
      for (std::size_t q = 0; q < points; ++q)
        eps += st.eps_p[e * points + q];
      plastic_strain_[cell] = eps / static_cast<double>(points);
      for (int c = 0; c < 6; ++c) {
        double sum = 0.0;
        for (std::size_t q = 0; q < points; ++q)
          sum += st.s[c][e * points + q];
        const auto k = 6 * cell + static_cast<std::size_t>(c);
        stress_[k] = stress_top_[k] = stress_bottom_[k] = sum / static_cast<double>(points);
      }
    }
  }
  // Shells: the co-rotational stresses turned to global axes at the bottom, middle and top
  // points; plastic strain the largest through the thickness.
  for (std::size_t b = 0; b < s.shells->size(); ++b) {
    const element::ShellBlockState& st = (*s.shells)[b];
    const core::ShellBlock& blk = model_.shell_blocks[b];
    const auto nip = static_cast<std::size_t>(st.nip);
    const std::size_t ppe = st.points_per_element();
    const auto inplane = static_cast<std::size_t>(st.inplane);
    for (std::size_t e = 0; e < blk.size(); ++e, ++cell) {
      double e1[3], e2[3], e3[3];
      current_shell_frame(blk, ns, e, e1, e2, e3);
      const double* axes[3] = {e1, e2, e3};
      // Thickness point k's stress component c: ELFORM 16's mean over its in-plane points
      // (LS-DYNA's output of the fully integrated shell), the one point's for ELFORM 2.
      const auto mean_point = [&](int c, std::size_t k) {
        double sum = 0.0;
        for (std::size_t g = 0; g < inplane; ++g)
          sum += st.s[c][e * ppe + g * nip + k];
        return sum / static_cast<double>(inplane);
      };
      const auto global = [&](double w_lo, std::size_t lo, std::size_t hi, double* out) {
        // Local tensor (szz = 0) at the weighted point, then to global axes.
        const auto at = [&](int c) {
          return w_lo * mean_point(c, lo) + (1.0 - w_lo) * mean_point(c, hi);
        };
        const double l[3][3] = {{at(0), at(2), at(4)}, {at(2), at(1), at(3)}, {at(4), at(3), 0.0}};
        shell_stress_to_global(axes, l, out);
      };
      const std::size_t mid_hi = nip / 2, mid_lo = (nip - 1) / 2;
      global(0.5, mid_lo, mid_hi, &stress_[6 * cell]);
      global(1.0, nip - 1, nip - 1, &stress_top_[6 * cell]);
      global(1.0, 0, 0, &stress_bottom_[6 * cell]);
      double eps = 0.0;
      for (std::size_t q = 0; q < ppe; ++q)
        eps = std::max(eps, st.eps_p[e * ppe + q]);
      plastic_strain_[cell] = eps;
      thickness_[cell] = st.thickness[e];
      if (const auto* ply = std::get_if<core::ReinforcedThermoplastic>(
              &model_.materials[static_cast<std::size_t>(blk.material)])) {
        // The fibres at the middle point (nip / 2; ELFORM 16: of its first Gauss point),
        // turned from the frame to global axes.
        const std::size_t q = e * ppe + nip / 2;
        const material::WovenPlyState w = material::woven_ply_state(
            *ply, st.history.empty() ? nullptr : &st.history[material::WovenPlyHistory::count * q]);
        if (w.initialised) {
          for (int i = 0; i < ply->families; ++i) {
            for (int d = 0; d < 3; ++d)
              fibre_[i][3 * cell + static_cast<std::size_t>(d)] =
                  w.direction[i][0] * e1[d] + w.direction[i][1] * e2[d];
          }
          shear_angle_[cell] = w.shear_angle[0] * 180.0 / std::numbers::pi;
        }
      }
    }
  }
  if (!model_.temperature0.empty() || model_.thermal.enabled)
    std::copy(ns.temperature.begin(), ns.temperature.end(), temperature_.begin());
  const bool faces = !ns.temperature_top.empty();
  if (cohesive_model_ && s.contact != nullptr) {
    // Nodes that are no slave node of a cohesive interface: NaN (nothing defined there).
    const double nan = std::numeric_limits<double>::quiet_NaN();
    beta_.assign(n, nan);
    contact_pressure_.assign(n, nan);
    gap_.assign(n, nan);
    contact_state_.assign(n, nan);
    s.contact->cohesive_results(slave_results_);
    for (const contact::SlaveNodeResult& r : slave_results_) {
      const auto i = static_cast<std::size_t>(r.node);
      beta_[i] = r.beta;
      contact_pressure_[i] = r.pressure;
      gap_[i] = r.gap;
      contact_state_[i] = static_cast<double>(r.state);
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
  if (faces) {  // thick thermal shells
    piece.point_data.push_back({"temperature_top", 1, ns.temperature_top});
    piece.point_data.push_back({"temperature_bottom", 1, ns.temperature_bottom});
  }
  if (cohesive_model_ && s.contact != nullptr) {
    piece.point_data.push_back({"beta", 1, beta_});
    piece.point_data.push_back({"contact_pressure", 1, contact_pressure_});
    piece.point_data.push_back({"gap", 1, gap_});
    piece.point_data.push_back({"contact_state", 1, contact_state_});
  }
  // *DATABASE_EXTENT_BINARY: an array left out for shells but kept for solids (flag 3) is NaN
  // in the shell cells.
  const core::OutputRequests::StateFields& fields = model_.output.state_fields;
  const std::size_t solid_cells = cell - shell_cells(model_);
  const auto drop_shells = [&](std::vector<double>& a, std::size_t width) {
    std::fill(a.begin() + static_cast<std::ptrdiff_t>(width * solid_cells), a.end(),
              std::numeric_limits<double>::quiet_NaN());
  };
  const bool stress = fields.solid_stress || fields.shell_stress;
  if (stress && !fields.shell_stress) {
    for (auto* a : {&stress_, &stress_top_, &stress_bottom_})
      drop_shells(*a, 6);
  }
  if (fields.solid_plastic_strain && !fields.shell_plastic_strain)
    drop_shells(plastic_strain_, 1);
  piece.cell_data.clear();
  if (stress) {
    piece.cell_data.push_back({"stress", 6, stress_});
    piece.cell_data.push_back({"stress_top", 6, stress_top_});
    piece.cell_data.push_back({"stress_bottom", 6, stress_bottom_});
  }
  if (fields.solid_plastic_strain || fields.shell_plastic_strain)
    piece.cell_data.push_back({"plastic_strain", 1, plastic_strain_});
  if (fields.thickness)
    piece.cell_data.push_back({"thickness", 1, thickness_});
  if (fields.strain) {
    element_log_strains(model_, ns, *s.shells, strain_);
    piece.cell_data.push_back({"strain", 6, strain_});
  }
  if (formability_) {
    formability_->compute(ns, *s.shells);
    static constexpr const char* kMajor[3] = {"major_strain_bottom", "major_strain_middle",
                                              "major_strain_top"};
    static constexpr const char* kMinor[3] = {"minor_strain_bottom", "minor_strain_middle",
                                              "minor_strain_top"};
    for (int k : {2, 0, 1}) {
      piece.cell_data.push_back({kMajor[k], 1, formability_->major[k]});
      piece.cell_data.push_back({kMinor[k], 1, formability_->minor[k]});
    }
    piece.cell_data.push_back({"thinning", 1, formability_->thinning});
  }
  static constexpr const char* kFibre[3] = {"fibre_1", "fibre_2", "fibre_3"};
  for (int i = 0; i < fibre_families_; ++i)
    piece.cell_data.push_back({kFibre[i], 3, fibre_[i]});
  if (fibre_families_ > 1)
    piece.cell_data.push_back({"shear_angle", 1, shear_angle_});
  piece.point_ids = {{"node_id", node_ids_}};
  piece.cell_ids = {{"element_id", element_ids_}, {"part", part_ids_}};
  series_.write_state(s.time, piece);
}

void ResultWriter::rigid_bodies(double time, const rigid::RigidBodies& bodies) {
  if (!rbdout_)
    return;
  for (const auto& b : bodies.report()) {
    rbdout_->row({time, static_cast<double>(b.part_id), b.force[0], b.force[1], b.force[2],
                  b.moment[0], b.moment[1], b.moment[2], b.centre[0], b.centre[1], b.centre[2],
                  b.velocity[0], b.velocity[1], b.velocity[2]});
  }
}

void ResultWriter::rigid_walls(double time, const rigid::RigidWalls& walls) {
  if (!rwforc_)
    return;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const rigid::RigidWalls::Report r = walls.report(k);
    rwforc_->row({time, static_cast<double>(r.id), r.normal_force, r.tangential_force, r.force[0],
                  r.force[1], r.force[2], r.impulse, static_cast<double>(r.held), r.displacement,
                  r.velocity, r.kinetic});
  }
}

void ResultWriter::boundary_forces(const engine::Snapshot& s) {
  if (!bndout_)
    return;
  const engine::NodalState& ns = *s.nodes;
  for (core::Index n : bndout_nodes_) {
    const auto i = static_cast<std::size_t>(n);
    bndout_->row_mixed(
        {s.time, static_cast<std::int64_t>(node_ids_[i]), ns.rx[i], ns.ry[i], ns.rz[i]});
  }
}

void ResultWriter::constraint_forces(const engine::Snapshot& s) {
  if (!spcforc_)
    return;
  const engine::NodalState& ns = *s.nodes;
  for (core::Index n : spcforc_nodes_) {
    const auto i = static_cast<std::size_t>(n);
    spcforc_->row_mixed(
        {s.time, static_cast<std::int64_t>(node_ids_[i]), ns.rx[i], ns.ry[i], ns.rz[i]});
  }
}

void ResultWriter::interface_energies(double time,
                                      const std::vector<contact::InterfaceReport>& interfaces) {
  if (!sleout_)
    return;
  for (const contact::InterfaceReport& r : interfaces)
    sleout_->row_mixed({time, static_cast<std::int64_t>(r.id), r.work, r.friction});
}

void ResultWriter::part_energies(double time, const std::vector<engine::PartEnergies>& parts) {
  if (!matsum_)
    return;
  for (const engine::PartEnergies& p : parts) {
    matsum_->row_mixed({time, static_cast<std::int64_t>(p.part),
                        static_cast<std::int64_t>(p.rigid ? 1 : 0), p.internal, p.kinetic,
                        p.hourglass, p.momentum[0], p.momentum[1], p.momentum[2]});
  }
}

void ResultWriter::element_histories(const engine::Snapshot& s) {
  if (!elout_)
    return;
  // Solids first, then shells (LS-DYNA's elout order), each in the order the deck names them.
  for (const core::BlockElement& h : model_.output.history_solids) {
    const core::SolidBlock& blk = model_.solid_blocks[static_cast<std::size_t>(h.block)];
    const element::SolidBlockState& st = (*s.solids)[static_cast<std::size_t>(h.block)];
    const auto e = static_cast<std::size_t>(h.element);
    // ELFORM 1: its one point; ELFORM 2: the mean of its eight (LS-DYNA's elout default).
    const auto points = static_cast<std::size_t>(st.points);
    double mean[7] = {};
    for (std::size_t q = e * points; q < (e + 1) * points; ++q) {
      for (int c = 0; c < 6; ++c)
        mean[c] += st.s[c][q];
      mean[6] += st.eps_p[q];
    }
    for (double& v : mean)
      v /= static_cast<double>(points);
    elout_->row_mixed(
        {s.time, static_cast<std::int64_t>(blk.element_id[e]),
         static_cast<std::int64_t>(model_.parts[static_cast<std::size_t>(blk.part)].id),
         std::string_view("solid"), std::int64_t{1}, std::int64_t{1}, std::string_view(), mean[0],
         mean[1], mean[2], mean[3], mean[4], mean[5], mean[6]});
  }
  for (const core::BlockElement& h : model_.output.history_shells) {
    const auto b = static_cast<std::size_t>(h.block);
    const core::ShellBlock& blk = model_.shell_blocks[b];
    const element::ShellBlockState& st = (*s.shells)[b];
    const auto e = static_cast<std::size_t>(h.element);
    const auto nip = static_cast<std::size_t>(st.nip);
    const std::size_t ppe = st.points_per_element();
    const auto inplane = static_cast<std::size_t>(st.inplane);
    double e1[3], e2[3], e3[3];
    current_shell_frame(blk, *s.nodes, e, e1, e2, e3);
    const double* axes[3] = {e1, e2, e3};
    const auto element = static_cast<std::int64_t>(blk.element_id[e]);
    const auto part =
        static_cast<std::int64_t>(model_.parts[static_cast<std::size_t>(blk.part)].id);
    for (std::size_t k = 0; k < nip; ++k) {
      // ELFORM 16: the mean of thickness point k over the four in-plane points (LS-DYNA's
      // elout of the fully integrated shell).
      double m[6] = {};
      for (std::size_t gp = 0; gp < inplane; ++gp) {
        const std::size_t q = e * ppe + gp * nip + k;
        for (int c = 0; c < 5; ++c)
          m[c] += st.s[c][q];
        m[5] += st.eps_p[q];
      }
      for (double& v : m)
        v /= static_cast<double>(inplane);
      const double l[3][3] = {{m[0], m[2], m[4]}, {m[2], m[1], m[3]}, {m[4], m[3], 0.0}};
      double g[6];
      shell_stress_to_global(axes, l, g);
      elout_->row_mixed({s.time, element, part, std::string_view("shell"),
                         static_cast<std::int64_t>(k + 1), static_cast<std::int64_t>(nip),
                         shell_zeta_[b][k], g[0], g[1], g[2], g[3], g[4], g[5], m[5]});
    }
  }
}

void ResultWriter::contact_forces(double time,
                                  const std::vector<contact::InterfaceReport>& interfaces) {
  if (!rcforc_)
    return;
  rcforc_rows_.clear();
  for (const contact::InterfaceReport& r : interfaces) {
    rcforc_rows_.push_back({time, r.id, r.force[0], r.force[1], r.force[2]});
    if (r.tied || !interface_energy_)
      continue;  // a constraint: no books
    interface_energy_->row_mixed({time, static_cast<std::int64_t>(r.id), r.work, r.stored, r.damage,
                                  r.viscous, r.friction, r.damping, r.healing,
                                  static_cast<std::int64_t>(r.in_contact),
                                  static_cast<std::int64_t>(r.bonded), r.surface});
  }
  rcforc_->write(rcforc_rows_);
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
  if (!cohesive_ || s.contact == nullptr)
    return;
  // History nodes that are slave nodes of a cohesive interface.
  s.contact->cohesive_results(slave_results_);
  std::vector<char> wanted(model_.node_count(), 0);
  for (core::Index idx : model_.output.history_nodes)
    wanted[static_cast<std::size_t>(idx)] = 1;
  cohesive_rows_.clear();
  for (const contact::SlaveNodeResult& r : slave_results_) {
    if (!wanted[static_cast<std::size_t>(r.node)])
      continue;
    cohesive_rows_.push_back({s.time, r.interface, model_.node_id[static_cast<std::size_t>(r.node)],
                              law::to_string(r.state), r.gap, r.pressure, r.tau, r.beta});
  }
  cohesive_->write(cohesive_rows_);
}

void ResultWriter::heat(double time, const thermal::HeatLedger& h) {
  if (heat_)
    heat_->row({time, h.stored, h.contact, h.friction, h.plastic, h.convection, h.radiation, h.flux,
                h.prescribed, h.generation});
}

void ResultWriter::temperatures(const engine::Snapshot& s) {
  if (!tprint_)
    return;
  for (core::Index i : model_.output.history_nodes) {
    const auto node = static_cast<std::size_t>(i);
    if (model_.thermal.thick_shells) {
      const bool faces = !s.nodes->temperature_top.empty();
      const double t = s.nodes->temperature[node];
      tprint_->row_mixed({s.time, static_cast<std::int64_t>(model_.node_id[node]), t,
                          faces ? s.nodes->temperature_top[node] : t,
                          faces ? s.nodes->temperature_bottom[node] : t});
    } else {
      tprint_->row_mixed(
          {s.time, static_cast<std::int64_t>(model_.node_id[node]), s.nodes->temperature[node]});
    }
  }
}

void ResultWriter::progress(double time, double end_time, long cycle, double dt, double wall) {
  progress_.update(time, end_time, cycle, dt, wall);
}

void ResultWriter::save_state(core::StateArchive& archive) {
  std::vector<double> times = series_.times();
  archive.array("states", times);
  const auto put = [&](const char* file, const output::CsvHistory& csv) {
    std::uint64_t bytes = csv.bytes_written();
    archive.value(file, bytes);
  };
  if (glstat_)
    put(kGlstat, glstat_->csv());
  if (nodout_)
    put(kNodout, nodout_->csv());
  if (rbdout_)
    put(kRbdout, *rbdout_);
  if (rwforc_)
    put(kRwforc, *rwforc_);
  if (bndout_)
    put(kBndout, *bndout_);
  if (spcforc_)
    put(kSpcforc, *spcforc_);
  if (sleout_)
    put(kSleout, *sleout_);
  if (matsum_)
    put(kMatsum, *matsum_);
  if (elout_)
    put(kElout, *elout_);
  if (rcforc_)
    put(kRcforc, rcforc_->csv());
  if (interface_energy_)
    put(kInterfaceEnergy, *interface_energy_);
  if (cohesive_)
    put(kCohesive, cohesive_->csv());
  if (heat_)
    put(kHeat, *heat_);
  if (tprint_)
    put(kTprint, *tprint_);
}

void ResultWriter::end_of_run(const engine::Snapshot& s) {
  if (model_.output.dynain.write)
    write_dynain(outdir_ / "dynain", model_, s);
}

void ResultWriter::finish() {
  progress_.finish();
}

}  // namespace plyform::app
