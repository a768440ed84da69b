// `plyform run`: deck -> validation -> runtime model -> explicit engine -> results in OUTDIR.

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <array>
#include <cmath>
#include <csignal>
#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <ostream>

#include "plyform/app/commands.hpp"
#include "plyform/app/stop_signals.hpp"
#include "plyform/comm/communicator.hpp"
#include "plyform/core/stopwatch.hpp"
#include "plyform/domain/decomposition.hpp"
#include "plyform/domain/resplit.hpp"
#include "plyform/engine/checkpoint_file.hpp"
#include "plyform/engine/solver.hpp"
#include "plyform/keyword/read_deck.hpp"
#include "plyform/output/progress_line.hpp"
#include "plyform/output/summary_json.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/validate.hpp"
#include "result_writer.hpp"
#include "timing_report.hpp"

namespace plyform::app {
namespace {

// Set by the first SIGINT or SIGTERM of a run (stop_signals.hpp).
volatile std::sig_atomic_t stop_requested = 0;

// The sink of the ranks after the first over MPI: every rank holds the whole state, and the first
// writes the files (rank_exchange.hpp).
class NoOutputs final : public engine::OutputSink {
 public:
  void state(const engine::Snapshot& /*s*/) override {}
  void glstat(const engine::Energies& /*e*/) override {}
  void nodout(const engine::Snapshot& /*s*/) override {}
};

// Where the ranks after the first write what the first writes too: nowhere.
class NullBuffer final : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

// Over several ranks: every rank's loop seconds and its timing table's seconds by group, for
// summary.json's rank_timing (a collective: every rank calls it after its run).
std::vector<output::RunSummary::RankTiming> rank_timing(const comm::Communicator& world,
                                                        const engine::PassTiming& timing) {
  static constexpr const char* kGroups[] = {"nodes",   "elements", "ranks", "contact",
                                            "thermal", "outputs",  "other"};
  constexpr std::size_t k = std::size(kGroups) + 1;
  std::vector<double> mine(k, 0.0);
  mine[0] = timing.loop_seconds;
  for (const engine::PassTime& p : timing.passes) {
    for (std::size_t g = 0; g < std::size(kGroups); ++g)
      if (p.group == kGroups[g])
        mine[g + 1] += p.seconds;
  }
  const auto ranks = static_cast<std::size_t>(world.size());
  std::vector<double> all(k * ranks);
  world.all_gather(mine, all, std::vector<std::size_t>(ranks, k));
  std::vector<output::RunSummary::RankTiming> out(ranks);
  for (std::size_t r = 0; r < ranks; ++r) {
    out[r].rank = static_cast<int>(r);
    out[r].loop_seconds = all[k * r];
    for (std::size_t g = 0; g < std::size(kGroups); ++g)
      out[r].groups.emplace_back(kGroups[g], all[k * r + g + 1]);
  }
  return out;
}

// Over several ranks: the nodes each rank moved, rank by rank (a collective); empty where every
// rank moved every node.
std::vector<long> moved_nodes(const comm::Communicator& world, std::size_t mine) {
  const auto ranks = static_cast<std::size_t>(world.size());
  std::vector<double> all(ranks);
  const std::array<double, 1> one{static_cast<double>(mine)};
  world.all_gather(one, all, std::vector<std::size_t>(ranks, 1));
  std::vector<long> out;
  if (mine == 0)
    return out;  // the same on every rank: every rank or none moves its own nodes
  for (const double x : all)
    out.push_back(static_cast<long>(x));
  return out;
}

constexpr const char* untrusted_status = "completed, results not to be trusted";

bool report(const std::vector<keyword::Diagnostic>& errors, std::ostream& err) {
  for (const auto& d : errors)
    fmt::print(err, "error: {}\n", d.to_string());
  return !errors.empty();
}

}  // namespace

int run_deck(const RunOptions& given, std::ostream& terminal_out, std::ostream& terminal_err) {
  // Over MPI (mpirun -np N) every rank reads, checks and builds the same model and runs it
  // (docs/parallel.md); the first speaks for all of them.
  const comm::Communicator& world = comm::Communicator::world();
  NullBuffer nowhere;
  std::ostream quiet(&nowhere);
  std::ostream& out = world.rank() == 0 ? terminal_out : quiet;
  std::ostream& err = world.rank() == 0 ? terminal_err : quiet;
  const keyword::ReadResult read = keyword::read_deck(given.deck);
  const RunOptions options = with_deck_threads(given, read.model);  // --threads, else NCPU
  for (const auto& w : read.warnings)
    fmt::print(err, "warning: {}\n", w.to_string());
  if (report(read.errors, err) || report(setup::validate(read.model), err))
    return 1;
  setup::BuildResult built = setup::build(read.model);
  for (const auto& w : built.warnings)
    fmt::print(err, "warning: {}\n", w.to_string());
  if (report(built.errors, err))
    return 1;
  const core::Model& model = *built.model;

  const std::filesystem::path outdir =
      options.output ? *options.output
                     : std::filesystem::current_path() / (options.deck.stem().string() + "_out");
  const std::filesystem::path checkpoint = outdir / engine::checkpoint_file_name;
  std::optional<core::StateArchive::Records> resume;
  if (options.restart) {
    try {
      resume = engine::read_checkpoint(checkpoint, read.model.source_fingerprint);
      // A run cannot go back: the end time must not lie before the checkpoint's time.
      const double end_time = options.end_time ? *options.end_time : model.controls.end_time;
      const double t = engine::checkpoint_time(*resume);
      if (end_time > 0.0 && t > end_time * (1.0 + 1e-9)) {
        fmt::print(err,
                   "error: cannot restart: the checkpoint {} is at t = {:.6g}, after the end "
                   "time {:.6g}{}\n",
                   checkpoint.string(), t, end_time,
                   options.end_time ? " (--end-time)" : " (ENDTIM; --end-time runs further)");
        return 1;
      }
    } catch (const engine::CheckpointError& e) {
      fmt::print(err, "error: cannot restart: {}\n", e.what());
      return 1;
    } catch (const core::StateError& e) {
      fmt::print(err, "error: cannot restart: {}\n", e.what());
      return 1;
    }
  }
  engine::SolverOptions so;
  so.ranks = &world;
  if (world.size() == 1 && options.rebalance_every != 0) {
    fmt::print(err,
               "warning: --rebalance has nothing to do on one rank: it re-splits a run over "
               "several MPI ranks (mpirun -np N plyform run ...)\n");
  }
  if (world.size() > 1) {
    core::Stopwatch split_clock;
    const domain::DecomposeResult split = domain::decompose(model, world.size());
    if (!split.error.empty()) {
      fmt::print(err, "error: cannot run {} over {} ranks: {}\n", options.deck.string(),
                 world.size(), split.error);
      return 1;
    }
    so.node_owner = split.decomposition.node_owner;
    // Re-balancing (docs/parallel.md): the element graph kept for the splits to come; the first
    // split's costs and time (the price of a split until one is measured; the largest over the
    // ranks, so that every rank decides alike).
    so.rebalance_every = options.rebalance_every;
    if (options.rebalance_every >= 0) {
      // The graph is built at the first re-split (most runs never need one).
      auto splitter = std::make_shared<std::unique_ptr<domain::Resplitter>>();
      so.resplit = [splitter, &model](std::span<const double> shares) {
        if (!*splitter)
          *splitter = std::make_unique<domain::Resplitter>(model);
        return (*splitter)->split(shares);
      };
      for (const domain::DomainSummary& d : split.decomposition.summary)
        so.rank_cost.push_back(d.cost);
      so.split_seconds =
          static_cast<double>(world.max(std::lround(1e6 * split_clock.lap()))) * 1e-6;
    }
  }
  output::RunSummary summary;
  summary.deck = options.deck.string();
  summary.version = "0.1.0";
  summary.end_time = options.end_time ? *options.end_time : model.controls.end_time;
  summary.nodes = static_cast<long>(model.node_count());
  summary.elements = static_cast<long>(model.solid_count() + model.shell_count());
  summary.deformable_elements = static_cast<long>(model.deformable_element_count());
  summary.threads = options.threads;
  summary.ranks = world.size();
  engine::RunResult result;
  try {
    std::filesystem::create_directories(outdir);
    std::optional<ResultWriter> files;
    NoOutputs no_outputs;
    if (world.rank() == 0) {
      files.emplace(model, outdir, std::cout, options.progress && output::stdout_is_terminal(),
                    resume ? &*resume : nullptr);
    }
    engine::OutputSink& writer = files ? static_cast<engine::OutputSink&>(*files) : no_outputs;
    so.threads = options.threads;
    so.end_time = options.end_time;
    so.checkpoint = checkpoint;
    so.checkpoint_cycles = model.output.d3dump_cycles;
    so.fingerprint = read.model.source_fingerprint;
    so.stop = &stop_requested;
    const StopOnSignals signals(&stop_requested);
    engine::Simulation simulation(model, writer, so);
    if (resume) {
      simulation.restore(*resume);
      resume.reset();  // the records are in the state now
    }
    result = simulation.run();
    if (world.size() > 1) {
      summary.rank_timing = rank_timing(world, result.timing);
      summary.rebalancing = {result.resplits, result.rank_shares, result.first_imbalance,
                             result.last_imbalance};
      summary.moved_nodes = moved_nodes(world, result.moved_nodes);
    }
    if (files)
      files->finish();
  } catch (const core::StateError& e) {
    fmt::print(err, "error: cannot restart: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    if (world.size() > 1) {
      // One rank alone cannot go on while the others wait in the next exchange: it stops them.
      fmt::print(terminal_err, "error (rank {} of {}): {}\n", world.rank(), world.size(), e.what());
      world.abort(2);
    }
    fmt::print(err, "error: {}\n", e.what());
    summary.status = std::string("error: ") + e.what();
    output::write_summary_json(outdir / "summary.json", summary);
    return 2;
  }
  summary.status = !result.ok       ? "error: " + result.error
                   : result.stopped ? fmt::format("stopped by a signal at t = {:.6g}", result.time)
                   : !result.distrust.empty() ? std::string(untrusted_status)
                                              : "normal termination";
  for (const engine::Distrust& d : result.distrust)
    summary.distrust.push_back({d.reason, d.time});
  if (result.restarted)
    summary.restarted_at = result.restart_time;
  summary.checkpoint = result.checkpoint;
  summary.cycles = result.cycles;
  summary.final_time = result.time;
  summary.wall_seconds = result.wall_seconds;
  summary.element_cycles_per_second = result.element_cycles_per_second;
  summary.energy_ratio = result.last.ratio;
  summary.dt_initial = result.dt_first;
  summary.dt_final = result.dt_last;
  summary.added_mass = result.added_mass;
  summary.added_mass_ratio =
      result.physical_mass > 0.0 ? result.added_mass / result.physical_mass : 0.0;
  summary.thermal_steps = result.thermal_steps;
  summary.thermal_iterations = result.thermal_iterations;
  summary.heat_stored = result.heat.stored;
  summary.heat_entered = result.heat.entered();
  summary.warnings = result.warnings;
  summary.loop_seconds = result.timing.loop_seconds;
  for (const engine::PassTime& p : result.timing.passes)
    summary.timing.push_back({p.group, p.name, p.seconds});
  if (world.rank() == 0)
    output::write_summary_json(outdir / "summary.json", summary);

  for (const auto& w : result.warnings)
    fmt::print(err, "warning: {}\n", w);
  fmt::print(out,
             "{}: {} cycles to t = {:.6g} in {:.3g} s wall ({:.3g} M element-cycles/s, "
             "{} thread{}{})\n",
             summary.status, result.cycles, result.time, result.wall_seconds,
             result.element_cycles_per_second * 1e-6, options.threads,
             options.threads == 1 ? "" : "s",
             world.size() > 1 ? fmt::format(" on each of {} ranks", world.size()) : "");
  fmt::print(out,
             "energies at the end: kinetic {:.6g}, internal {:.6g}, hourglass {:.6g}, external "
             "work {:.6g}, ratio {:.6f}\n",
             result.last.kinetic, result.last.internal, result.last.hourglass,
             result.last.external_work, result.last.ratio);
  if (result.thread_reductions > 0) {
    fmt::print(out,
               "threads: the cores were shared with other work; 1 thread instead of {} for "
               "{:.3g} of the {:.3g} s ({} time{})\n",
               options.threads, result.reduced_thread_seconds, result.wall_seconds,
               result.thread_reductions, result.thread_reductions == 1 ? "" : "s");
  }
  if (!model.contacts.empty()) {
    std::size_t slaves = 0;
    for (const core::ContactInterface& c : model.contacts)
      for (const core::ContactPass& p : c.passes)
        slaves += p.slave_count();
    fmt::print(out,
               "contact: {} interface{}, {} slave nodes, energy {:.6g}, {} bucket sorts, {:.1f} % "
               "of the slave node-cycles at rest clear of the master\n",
               model.contacts.size(), model.contacts.size() == 1 ? "" : "s", slaves,
               result.last.contact, result.contact_searches, 100.0 * result.contact_rested_share);
  }
  if (model.thermal.enabled) {
    const thermal::HeatLedger& h = result.heat;
    fmt::print(out,
               "heat: {} thermal steps{}; stored {:.6g}, entered {:.6g} (convection {:.6g}, "
               "radiation {:.6g}, flux {:.6g}, prescribed {:.6g}, generation {:.6g}, contact "
               "{:.6g}, friction {:.6g}, plastic {:.6g})\n",
               result.thermal_steps,
               result.thermal_iterations > 0
                   ? fmt::format(" ({} conjugate-gradient iterations)", result.thermal_iterations)
                   : std::string(),
               h.stored, h.entered(), h.convection, h.radiation, h.flux, h.prescribed, h.generation,
               h.contact, h.friction, h.plastic);
  }
  if (result.added_mass > 0.0) {
    fmt::print(out, "mass scaling added {:.6g} ({:.3g} % of {:.6g})\n", result.added_mass,
               100.0 * summary.added_mass_ratio, result.physical_mass);
  }
  if (result.restarted) {
    fmt::print(out, "restarted from the checkpoint of t = {:.6g} (cycle {})\n", result.restart_time,
               result.restart_cycle);
  }
  if (result.checkpoints > 0) {
    fmt::print(out, "checkpoint{}: {} written, the last in {}\n",
               result.checkpoints == 1 ? "" : "s", result.checkpoints, result.checkpoint);
  }
  print_timing(out, result.timing);
  if (!summary.rank_timing.empty()) {
    // The ranks' loops and exchanges side by side: the slower rank sets the pace, the others wait
    // at the exchanges.
    std::string loops, exchanges;
    for (const output::RunSummary::RankTiming& r : summary.rank_timing) {
      loops += fmt::format("{}{:.3g}", loops.empty() ? "" : " / ", r.loop_seconds);
      for (const auto& [group, seconds] : r.groups)
        if (group == "ranks")
          exchanges += fmt::format("{}{:.3g}", exchanges.empty() ? "" : " / ", seconds);
    }
    fmt::print(out, "ranks: loop seconds {} (rank 0 first), of which exchanges {}\n", loops,
               exchanges);
    if (!summary.moved_nodes.empty()) {
      std::string moved;
      for (const long m : summary.moved_nodes)
        moved += fmt::format("{}{}", moved.empty() ? "" : " / ", m);
      fmt::print(out,
                 "ranks: each rank moved its own nodes and its neighbours' around them: {} of {} "
                 "nodes (rank 0 first)\n",
                 moved, summary.nodes);
    } else if (!result.every_node_moved_because.empty()) {
      fmt::print(out, "ranks: every rank moved every node ({})\n", result.every_node_moved_because);
    }
    const output::RunSummary::Rebalancing& b = summary.rebalancing;
    if (b.splits > 0) {
      std::string shares;
      for (const double x : b.shares)
        shares += fmt::format("{}{:.3f}", shares.empty() ? "" : " / ", x);
      fmt::print(out,
                 "ranks: split again {} time{} while running (each rank's share of the estimated "
                 "cost now {}; the ranks' seconds' imbalance {:.3f} at the first look, {:.3f} at "
                 "the last)\n",
                 b.splits, b.splits == 1 ? "" : "s", shares, b.first_imbalance, b.last_imbalance);
    } else if (b.last_imbalance > 0.0) {
      fmt::print(out,
                 "ranks: the split held (the ranks' seconds' imbalance {:.3f} at the last look)\n",
                 b.last_imbalance);
    }
  }
  fmt::print(out, "results in {}\n", outdir.string());
  if (!result.ok) {
    fmt::print(err, "error: {}\n", result.error);
    return 3;
  }
  if (!result.distrust.empty() && !result.stopped) {
    fmt::print(err, "{}: its books broke ({}):\n", untrusted_status, outdir.string());
    for (const engine::Distrust& d : result.distrust)
      fmt::print(err, "  from t = {:.6g}: {}\n", d.time, d.reason);
    return 5;
  }
  if (result.stopped) {
    fmt::print(err,
               "stopped by a signal at t = {:.6g} (cycle {}); checkpoint {}; continue with: "
               "plyform run {} -o {} --restart\n",
               result.time, result.cycles, result.checkpoint, options.deck.string(),
               outdir.string());
    return 4;
  }
  return 0;
}

}  // namespace plyform::app
