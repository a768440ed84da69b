#pragma once
// The subcommands of `plyform`, callable in-process. Each returns the exit status and writes
// results to `out`, diagnostics to `err`.

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace plyform::model {
struct ModelDesc;
}

namespace plyform::app {

struct LawOptions {
  std::filesystem::path deck;
  std::filesystem::path path_csv;
  std::optional<std::filesystem::path> output;  ///< none: write to `out`
  std::optional<double> penalty;                ///< normal penalty per area; none: C_N
  std::optional<int> interface_id;              ///< NOSID; needed when the deck has several
};

/// `plyform law DECK.k --path PATH.csv [-o OUT.csv] [--penalty K] [--interface ID]`
int run_law(const LawOptions& options, std::ostream& out, std::ostream& err);

struct FitOptions {
  std::vector<std::filesystem::path> curves;    ///< PROBE.csv files, one measured curve each
  std::optional<std::filesystem::path> output;  ///< FIT.k; none: <first curve stem>_fit.k
  std::optional<std::filesystem::path> deck;    ///< starting constants; none: from the curves
  std::optional<int> interface_id;              ///< NOSID; needed when the deck has several
  std::string free = "CN,SMAX,ETA";             ///< the constants fitted, by the law's names
  std::vector<double> rates;          ///< opening rate: none, one for all curves, or one per curve
  std::vector<double> areas;          ///< probe area for force columns: none, one, or one per curve
  std::optional<double> temperature;  ///< of curves without a temperature column; none: T_LO
  std::optional<double> penalty;      ///< normal penalty per area; none: C_N (as `plyform law`)
  int substeps = 1;                   ///< law updates per data interval
  bool plot = true;                   ///< FIT_curves.png with scripts/plot_fit.py
};

/// `plyform fit PROBE.csv... [-o FIT.k] [--deck base.k] [--free CN,SMAX,ETA] [--rate V...]
/// [--area A...]`: 0 fitted (FIT.k, FIT_curves.csv and FIT_curves.png written), 1 input errors
/// or curves the law cannot represent, 2 output errors, 3 a fit that is not meaningful (a
/// constant at its bound or not identifiable, a curve not represented): FIT_curves.csv and the
/// plot are written for the diagnosis, FIT.k is not. A missing Python or matplotlib only skips
/// the plot, with a note.
int run_fit(const FitOptions& options, std::ostream& out, std::ostream& err);

struct RunOptions {
  std::filesystem::path deck;
  std::optional<std::filesystem::path> output;  ///< none: <deck stem>_out in the current folder
  int threads = 0;       ///< --threads; 0 (not given): the deck's *CONTROL_PARALLEL NCPU, else 1
  bool progress = true;  ///< a progress line when standard output is a terminal
  bool restart = false;  ///< continue from OUTDIR/d3dump
  std::optional<double> end_time;  ///< replaces the deck's ENDTIM
  /// --rebalance over several ranks: 0 (auto) splits again when it pays, -1 (off) never, N > 0
  /// every N cycles or so (engine::SolverOptions::rebalance_every).
  long rebalance_every = 0;
};

/// `plyform run DECK.k [-o OUTDIR] [--threads N] [--restart] [--end-time T] [--rebalance M]`:
/// 0 normal
/// termination, 1 deck errors or a checkpoint refused (--restart), 2 output errors, 3 the run
/// stopped (instability) with the results written so far, 4 stopped by SIGINT or SIGTERM
/// after writing a checkpoint (continue with --restart), 5 completed with books that broke
/// (results not to be trusted: docs/energy.md).
int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err);

/// `options` with the run's thread count: --threads when given, else the magnitude of the
/// deck's *CONTROL_PARALLEL NCPU (a negative one asks LS-DYNA for consistency, which plyform
/// always has), else 1.
RunOptions with_deck_threads(RunOptions options, const model::ModelDesc& deck);

/// `plyform check DECK.k [--ranks N]`: with N > 1 also the split of the model over N MPI ranks
/// (domain/decomposition.hpp): each domain's elements, nodes, shared nodes, contact slave nodes
/// and ghost segments, and the imbalance.
int run_check(const std::filesystem::path& deck, std::ostream& out, std::ostream& err,
              int ranks = 1);

/// `plyform plot OUTDIR`: runs scripts/plot_histories.py with /usr/bin/python3 (overrides:
/// $PLYFORM_SCRIPTS_DIR, $PLYFORM_PYTHON), which writes energies.png from glstat.csv and
/// nodout.png, rcforc.png, cohesive.png from the history files present. Returns the script's
/// exit status (its messages go to the process's standard streams), or 1 with a message on
/// `err` when OUTDIR, the script or the interpreter is missing.
int run_plot(const std::filesystem::path& outdir, std::ostream& out, std::ostream& err);

struct FldOptions {
  std::filesystem::path outdir;              ///< results folder of `plyform run`
  std::optional<std::filesystem::path> flc;  ///< --flc: minor, major true strains per line
  std::optional<double> keeler_n, keeler_t;  ///< --keeler-n, --keeler-t (t in mm)
  std::optional<int> state;                  ///< --state K: results_K.vtu; none: the last
  double margin = 0.1;                       ///< --margin: risk of cracks below the FLC
  double low_strain = 0.02;                  ///< --low-strain: below it, low strain
};

/// `plyform plot OUTDIR --fld (--flc FILE | --keeler-n N --keeler-t T) [--state K]
/// [--margin M] [--low-strain S]`: runs scripts/plot_fld.py (as run_plot runs its script),
/// which writes fld.png (the forming-limit diagram), formability.png (the categories on the
/// deformed part) and fld.csv into OUTDIR (docs/outputs.md, "Formability"). Returns 1 with a
/// message naming the option on `err` when no curve or two are given, the curve file or
/// OUTDIR is missing, else the script's exit status (1: no state, no shells, a bad curve).
int run_fld_plot(const FldOptions& options, std::ostream& out, std::ostream& err);

}  // namespace plyform::app
