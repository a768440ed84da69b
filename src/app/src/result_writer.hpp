#pragma once
// The engine's OutputSink for `plyform run`: ParaView states (results.pvd + results_NNNN.vtu),
// glstat.csv, nodout.csv, rbdout.csv (rigid bodies), bndout.csv, spcforc.csv, matsum.csv,
// elout.csv (history elements), rcforc.csv, interface_energy.csv and sleout.csv (contacts),
// cohesive.csv (history nodes of cohesive interfaces), heat.csv and tprint.csv (computed
// temperatures), dynain (*INTERFACE_SPRINGBACK_LSDYNA) and the progress line, in OUTDIR.

#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <vector>

#include "plyform/engine/solver.hpp"
#include "plyform/output/csv_history.hpp"
#include "plyform/output/progress_line.hpp"
#include "plyform/output/vtu_series.hpp"
#include "shell_formability.hpp"

namespace plyform::app {

class ResultWriter : public engine::OutputSink {
 public:
  /// `resume`: a checkpoint's records (a restart): the files go on from where they were when
  /// it was written (what came after is cut off) instead of starting afresh.
  ResultWriter(const core::Model& model, const std::filesystem::path& outdir,
               std::ostream& terminal, bool show_progress,
               const core::StateArchive::Records* resume = nullptr);

  void state(const engine::Snapshot& s) override;
  void glstat(const engine::Energies& e) override;
  void nodout(const engine::Snapshot& s) override;
  void progress(double time, double end_time, long cycle, double dt, double wall) override;
  void rigid_bodies(double time, const rigid::RigidBodies& bodies) override;
  void rigid_walls(double time, const rigid::RigidWalls& walls) override;
  void boundary_forces(const engine::Snapshot& s) override;
  void constraint_forces(const engine::Snapshot& s) override;
  void interface_energies(double time,
                          const std::vector<contact::InterfaceReport>& interfaces) override;
  void part_energies(double time, const std::vector<engine::PartEnergies>& parts) override;
  void element_histories(const engine::Snapshot& s) override;
  void contact_forces(double time,
                      const std::vector<contact::InterfaceReport>& interfaces) override;
  void heat(double time, const thermal::HeatLedger& ledger) override;
  void temperatures(const engine::Snapshot& s) override;
  void save_state(core::StateArchive& archive) override;
  /// *INTERFACE_SPRINGBACK_LSDYNA: OUTDIR/dynain (dynain_writer.hpp).
  void end_of_run(const engine::Snapshot& s) override;
  void finish();

  [[nodiscard]] std::size_t states_written() const { return series_.states_written(); }

 private:
  const core::Model& model_;
  std::filesystem::path outdir_;
  output::VtuSeries series_;
  std::optional<output::GlstatFile> glstat_;
  std::optional<output::NodoutFile> nodout_;
  std::optional<output::CsvHistory> rbdout_;
  std::optional<output::CsvHistory> rwforc_;
  std::optional<output::RcforcFile> rcforc_;
  std::optional<output::CsvHistory> bndout_;
  std::vector<core::Index> bndout_nodes_;  // prescribed-motion nodes, in index order
  std::optional<output::CsvHistory> spcforc_;
  std::vector<core::Index> spcforc_nodes_;  // nodes with a translation held, in index order
  std::optional<output::CsvHistory> sleout_;
  std::optional<output::CsvHistory> matsum_;
  std::optional<output::CsvHistory> elout_;
  std::vector<std::vector<double>> shell_zeta_;  // per shell block: its points' zeta in [-1, 1]
  std::optional<output::CsvHistory> interface_energy_;
  std::optional<output::CohesiveFile> cohesive_;
  std::optional<output::CsvHistory> heat_;    // heat.csv (temperatures computed)
  std::optional<output::CsvHistory> tprint_;  // tprint.csv (*DATABASE_TPRINT)
  bool cohesive_model_ =
      false;  // a cohesive or tiebreak interface: its arrays go into the VTU states
  std::vector<contact::SlaveNodeResult> slave_results_;
  output::ProgressLine progress_;
  // The parts of every state that do not change: cells and ids.
  std::vector<std::int64_t> connectivity_, offsets_, node_ids_, element_ids_, part_ids_;
  std::vector<std::uint8_t> cell_types_;
  // Per-state buffers, reused.
  std::vector<double> displacement_, velocity_, temperature_, stress_, stress_top_, stress_bottom_,
      plastic_strain_, thickness_, strain_, beta_, contact_pressure_, gap_, contact_state_;
  // Woven plies (*MAT_REINFORCED_THERMOPLASTIC): each family's fibre direction (global, unit)
  // and the shear angle between families 1 and 2 (degrees); NaN in other cells.
  int fibre_families_ = 0;  // the most families of any ply block (0: no ply, no arrays)
  std::vector<double> fibre_[3], shear_angle_;
  // Deformable shells: their surfaces' principal strains and thinning (docs/outputs.md).
  std::optional<ShellFormability> formability_;
  std::vector<output::NodoutRow> rows_;
  std::vector<output::RcforcRow> rcforc_rows_;
  std::vector<output::CohesiveRow> cohesive_rows_;
};

}  // namespace plyform::app
