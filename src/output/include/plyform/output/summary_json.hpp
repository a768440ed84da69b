#pragma once
// OUTDIR/summary.json: the outcome of a run in one small JSON object, written atomically.

#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace plyform::output {

/// What a run reports at its end. Doubles that are not finite are written as null.
struct RunSummary {
  /// "normal termination", "completed, results not to be trusted" (the run reached its end
  /// with books that broke: `distrust`), "stopped by a signal at t = ..." or "error: <message>"
  std::string status = "normal termination";
  std::string deck;                        ///< deck path as given on the command line
  std::string version;                     ///< plyform version
  long cycles = 0;                         ///< time steps taken
  double final_time = 0.0;                 ///< simulated time reached (model time unit)
  double end_time = 0.0;                   ///< termination time of the deck (model time unit)
  double wall_seconds = 0.0;               ///< wall-clock time of the time loop (s)
  double element_cycles_per_second = 0.0;  ///< elements x cycles / wall_seconds (1/s)
  double energy_ratio = 0.0;               ///< total / (initial total + external work) at the end
  double dt_initial = 0.0;                 ///< first time step (model time unit)
  double dt_final = 0.0;                   ///< last time step (model time unit)
  double added_mass = 0.0;        ///< mass added by mass scaling at the end (model mass unit)
  double added_mass_ratio = 0.0;  ///< added_mass / physical mass (dimensionless)
  long nodes = 0;
  long elements = 0;             ///< solids and shells, rigid parts' included
  long deformable_elements = 0;  ///< what element_cycles_per_second counts
  int threads = 1;
  int ranks = 1;  ///< MPI ranks (docs/parallel.md)
  /// Over several ranks, the re-balancing (docs/parallel.md): how often the model was split
  /// again while running, each rank's share of the estimated cost in the last split (empty:
  /// the first split), and the imbalance of the ranks' seconds at the first and the last look
  /// (0: none). Written as `"rebalancing": {"splits": ..., "shares": [...], "first_imbalance":
  /// ..., "last_imbalance": ...}`.
  struct Rebalancing {
    int splits = 0;
    std::vector<double> shares;
    double first_imbalance = 0.0, last_imbalance = 0.0;
  };
  Rebalancing rebalancing;
  /// Over several ranks, the nodes each rank moved (its own and a ring of its neighbours'),
  /// rank by rank; empty where every rank moved every node. Written as `"moved_nodes": [...]`.
  std::vector<long> moved_nodes;
  /// A restart: the time it continued from (NaN, written null: the run started at t = 0). The
  /// other fields cover the whole run, its parts before the restart included.
  double restarted_at = std::numeric_limits<double>::quiet_NaN();
  std::string checkpoint;  ///< the last checkpoint written (empty: none)
  /// Computed temperatures (SOLN 1, 2): thermal steps, conjugate-gradient iterations, and the
  /// heat ledger's stored heat and the sum of its paths at the end (heat.csv).
  long thermal_steps = 0;
  long thermal_iterations = 0;
  double heat_stored = 0.0;
  double heat_entered = 0.0;
  std::vector<std::string> warnings;
  /// The books that broke, each with the time it first held (written as
  /// `"distrust": [{"reason": ..., "time": ...}]`).
  struct Distrust {
    std::string reason;
    double time = 0.0;
  };
  std::vector<Distrust> distrust;
  /// Where the time loop's wall time went (written as `"timing": {"loop_seconds": ...,
  /// "passes": [{"group": ..., "pass": ..., "seconds": ..., "share": ...}]}`, share the fraction
  /// of loop_seconds): the element kernels by formulation and law, each contact interface by
  /// stage, the thermal step, the nodal passes and the outputs, in the cycle's order.
  struct PassTime {
    std::string group;
    std::string pass;
    double seconds = 0.0;
  };
  double loop_seconds = 0.0;
  std::vector<PassTime> timing;
  /// Over several MPI ranks, each rank's loop and its seconds by group (the groups of `timing`:
  /// nodes, elements, ranks (the exchanges), contact, thermal, outputs, other), written as
  /// `"rank_timing": [{"rank": ..., "loop_seconds": ..., "groups": {...}}]`; empty on one rank.
  struct RankTiming {
    int rank = 0;
    double loop_seconds = 0.0;
    std::vector<std::pair<std::string, double>> groups;
  };
  std::vector<RankTiming> rank_timing;
};

/// The JSON text of a summary (an object, two-space indentation, ending with a newline).
/// Strings are escaped per RFC 8259; invalid UTF-8 bytes become U+FFFD.
[[nodiscard]] std::string summary_json_text(const RunSummary& summary);

/// Writes `summary_json_text(summary)` to `file` (temporary file, then rename); throws
/// std::runtime_error naming the file on failure.
void write_summary_json(const std::filesystem::path& file, const RunSummary& summary);

/// `text` as a JSON string literal, quotes included.
[[nodiscard]] std::string json_string(std::string_view text);

}  // namespace plyform::output
