// plyform: explicit FE for thermoforming of multi-layer sheets. This file only parses the
// command line and hands over to the subcommands of plyform/app/commands.hpp.

#include <CLI/CLI.hpp>
#include <iostream>

#include "plyform/app/commands.hpp"
#include "plyform/app/stop_signals.hpp"
#include "plyform/comm/communicator.hpp"

int main(int argc, char** argv) {
  // Before MPI and OpenMP start threads: the stop signals taken by a thread of their own.
  plyform::app::watch_stop_signals();
  // Under mpirun: MPI for the whole command (docs/parallel.md); otherwise nothing.
  const plyform::comm::Session mpi(&argc, &argv);
  CLI::App app{"plyform: explicit finite elements for the thermoforming of multi-layer sheets"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "plyform 0.1.0");

  plyform::app::RunOptions run;
  std::filesystem::path run_output;
  CLI::App* run_cmd = app.add_subcommand("run", "Run a deck with the explicit solver");
  run_cmd->add_option("DECK", run.deck, "keyword deck (.k)")->required();
  auto* run_out =
      run_cmd->add_option("-o,--output", run_output, "results folder (default: <deck stem>_out)");
  run_cmd
      ->add_option("--threads", run.threads,
                   "OpenMP threads (default: the deck's *CONTROL_PARALLEL NCPU, else 1)")
      ->check(CLI::Range(1, 1024));
  std::string rebalance = "auto";
  run_cmd
      ->add_option("--rebalance", rebalance,
                   "over several MPI ranks: split the model again while running when the ranks "
                   "wait for each other long enough to pay for it (auto, the default), never "
                   "(off), or every N cycles or so (N, for studies)")
      ->check([](const std::string& v) -> std::string {
        if (v == "auto" || v == "off")
          return {};
        try {
          std::size_t used = 0;
          const long n = std::stol(v, &used);
          if (used == v.size() && n > 0)
            return {};
        } catch (const std::exception&) {
        }
        return "expected auto, off or a positive number of cycles, got '" + v + "'";
      });
  run_cmd->add_flag("--restart", run.restart,
                    "continue from the checkpoint in OUTDIR (OUTDIR/d3dump: "
                    "*DATABASE_BINARY_D3DUMP, or written when a run was stopped by a signal)");
  double end_time = 0.0;
  auto* end_opt = run_cmd
                      ->add_option("--end-time", end_time,
                                   "termination time in place of the deck's ENDTIM (a restart "
                                   "may go on past it)")
                      ->check(CLI::PositiveNumber);

  std::filesystem::path check_deck;
  CLI::App* check = app.add_subcommand("check", "Read and validate a deck; print a summary");
  check->add_option("DECK", check_deck, "keyword deck (.k)")->required();
  int check_ranks = 1;
  check
      ->add_option("--ranks", check_ranks,
                   "also print the split of the model over this many MPI ranks (METIS): each "
                   "domain's elements, nodes, shared nodes, contact slave nodes, ghost segments")
      ->check(CLI::Range(1, 1 << 20));

  std::filesystem::path plot_dir;
  CLI::App* plot = app.add_subcommand(
      "plot",
      "PNG plots of the histories of a run (glstat, nodout, rcforc, cohesive); with --fld the "
      "forming-limit diagram and formability map of a state");
  plot->add_option("OUTDIR", plot_dir, "results folder of `plyform run`")->required();
  plyform::app::FldOptions fld;
  std::filesystem::path fld_curve;
  double keeler_n = 0.0, keeler_t = 0.0;
  int fld_state = 0;
  bool plot_fld = false;
  auto* fld_flag = plot->add_flag(
      "--fld", plot_fld,
      "draw the forming-limit diagram (fld.png), the formability map of the deformed "
      "part (formability.png) and fld.csv from a state's shell strains, instead of the "
      "histories; needs --flc or --keeler-n with --keeler-t");
  auto* flc_opt = plot->add_option("--flc", fld_curve,
                                   "forming-limit curve: a file of minor, major true strains, "
                                   "one point per line, minor increasing (with --fld)");
  auto* kn_opt = plot->add_option("--keeler-n", keeler_n,
                                  "Keeler-Brazier FLC: strain-hardening exponent n (with --fld "
                                  "and --keeler-t)");
  auto* kt_opt = plot->add_option("--keeler-t", keeler_t,
                                  "Keeler-Brazier FLC: sheet thickness in mm (with --fld and "
                                  "--keeler-n)");
  auto* state_opt = plot->add_option(
      "--state", fld_state, "the state results_K.vtu to judge (default: the last; with --fld)");
  auto* margin_opt = plot->add_option("--margin", fld.margin,
                                      "safety margin below the FLC, in major true strain: risk "
                                      "of cracks above FLC - margin (with --fld)")
                         ->capture_default_str();
  auto* low_opt = plot->add_option("--low-strain", fld.low_strain,
                                   "low strain (insufficient stretch): both mid-surface "
                                   "principal strains within +-S (with --fld)")
                      ->capture_default_str();
  for (auto* o : {flc_opt, kn_opt, kt_opt, state_opt, margin_opt, low_opt})
    o->needs(fld_flag);

  plyform::app::LawOptions law;
  std::filesystem::path law_output;
  double penalty = 0.0;
  int interface_id = 0;
  CLI::App* law_cmd = app.add_subcommand(
      "law", "Drive one contact point with the deck's *USER_INTERFACE_FRICTION law");
  law_cmd->add_option("DECK", law.deck, "keyword deck with a *USER_INTERFACE_FRICTION")->required();
  law_cmd->add_option("--path", law.path_csv, "CSV: time,gap,slip_x,slip_y,temperature")
      ->required();
  auto* out_opt =
      law_cmd->add_option("-o,--output", law_output, "CSV to write (default: standard output)");
  auto* pen_opt =
      law_cmd->add_option("--penalty", penalty, "normal penalty stiffness per area (default: C_N)");
  auto* id_opt = law_cmd->add_option("--interface", interface_id,
                                     "NOSID of the law to drive when the deck has several");

  plyform::app::FitOptions fit;
  std::filesystem::path fit_output, fit_deck;
  double fit_temperature = 0.0, fit_penalty = 0.0;
  int fit_interface = 0;
  bool fit_no_plot = false;
  CLI::App* fit_cmd = app.add_subcommand(
      "fit", "Fit the law's constants to measured traction-opening curves (least squares)");
  fit_cmd
      ->add_option("PROBE", fit.curves,
                   "CSV curves with a header: time, gap (or opening), and stress (tension "
                   "positive), pressure (compression positive) or force (with --area)")
      ->required()
      ->check(CLI::ExistingFile);
  auto* fit_out = fit_cmd->add_option(
      "-o,--output", fit_output,
      "fitted deck (default: <first curve stem>_fit.k); also writes <stem>_curves.csv, .png");
  auto* fit_deck_opt = fit_cmd->add_option(
      "--deck", fit_deck, "deck whose *USER_INTERFACE_FRICTION gives the starting constants");
  auto* fit_id_opt = fit_cmd->add_option("--interface", fit_interface,
                                         "NOSID of that card when the deck has several");
  fit_cmd->add_option("--free", fit.free, "constants to fit, by the law's names")
      ->capture_default_str();
  fit_cmd
      ->add_option("--rate", fit.rates,
                   "opening rate, one for all curves or one per curve (files without a time "
                   "or a gap column)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  fit_cmd->add_option("--area", fit.areas, "probe area for force columns, one or one per curve")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  auto* fit_t_opt = fit_cmd->add_option(
      "--temperature", fit_temperature,
      "temperature of curves without a temperature column (default: T_LO of the start)");
  auto* fit_pen_opt =
      fit_cmd->add_option("--penalty", fit_penalty, "normal penalty per area (default: C_N)")
          ->check(CLI::PositiveNumber);
  fit_cmd->add_option("--substeps", fit.substeps, "law updates per data interval")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  fit_cmd->add_flag("--no-plot", fit_no_plot, "do not draw <stem>_curves.png");

  CLI11_PARSE(app, argc, argv);
  // Only `run` works over several ranks; the other commands are the first rank's alone.
  const plyform::comm::Communicator& world = plyform::comm::Communicator::world();
  if (!run_cmd->parsed() && world.rank() != 0)
    return 0;

  if (run_cmd->parsed()) {
    if (*run_out)
      run.output = run_output;
    if (*end_opt)
      run.end_time = end_time;
    run.rebalance_every = rebalance == "auto" ? 0 : rebalance == "off" ? -1 : std::stol(rebalance);
    return plyform::app::run_deck(run, std::cout, std::cerr);
  }
  if (check->parsed())
    return plyform::app::run_check(check_deck, std::cout, std::cerr, check_ranks);
  if (plot->parsed() && plot_fld) {
    fld.outdir = plot_dir;
    if (*flc_opt)
      fld.flc = fld_curve;
    if (*kn_opt)
      fld.keeler_n = keeler_n;
    if (*kt_opt)
      fld.keeler_t = keeler_t;
    if (*state_opt)
      fld.state = fld_state;
    return plyform::app::run_fld_plot(fld, std::cout, std::cerr);
  }
  if (plot->parsed())
    return plyform::app::run_plot(plot_dir, std::cout, std::cerr);
  if (law_cmd->parsed()) {
    if (*out_opt)
      law.output = law_output;
    if (*pen_opt)
      law.penalty = penalty;
    if (*id_opt)
      law.interface_id = interface_id;
    return plyform::app::run_law(law, std::cout, std::cerr);
  }
  if (fit_cmd->parsed()) {
    if (*fit_out)
      fit.output = fit_output;
    if (*fit_deck_opt)
      fit.deck = fit_deck;
    if (*fit_id_opt)
      fit.interface_id = fit_interface;
    if (*fit_t_opt)
      fit.temperature = fit_temperature;
    if (*fit_pen_opt)
      fit.penalty = fit_penalty;
    fit.plot = !fit_no_plot;
    return plyform::app::run_fit(fit, std::cout, std::cerr);
  }
  return 2;
}
