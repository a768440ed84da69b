// `plyform plot OUTDIR --fld ...`: the forming-limit diagram and the formability map of a
// state, drawn by scripts/plot_fld.py with Debian's /usr/bin/python3 (`run_python_script`).
// Here the options are checked against each other and the files they name, so that a wrong
// call is told by option name before Python starts; the script reads the curve and the state.

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "plyform/app/commands.hpp"
#include "plyform/app/python_script.hpp"

namespace plyform::app {
namespace {

/// The shortest text that reads back to the same double (the script parses it).
std::string number(double v) {
  return fmt::format("{}", v);
}

}  // namespace

int run_fld_plot(const FldOptions& o, std::ostream& out, std::ostream& err) {
  std::error_code ec;
  if (!std::filesystem::is_directory(o.outdir, ec)) {
    fmt::print(err, "error: results folder '{}' {}\n", o.outdir.string(),
               std::filesystem::exists(o.outdir, ec) ? "is not a folder" : "does not exist");
    return 1;
  }
  const bool keeler = o.keeler_n.has_value() || o.keeler_t.has_value();
  if (o.flc && keeler) {
    fmt::print(err,
               "error: plot --fld: give the forming-limit curve either as --flc FILE or by "
               "--keeler-n and --keeler-t, not both\n");
    return 1;
  }
  if (!o.flc && !keeler) {
    fmt::print(err,
               "error: plot --fld needs a forming-limit curve: --flc FILE (minor, major true "
               "strain per line) or --keeler-n N --keeler-t T (Keeler-Brazier, t in mm)\n");
    return 1;
  }
  if (keeler && !(o.keeler_n && o.keeler_t)) {
    fmt::print(err,
               "error: plot --fld: Keeler's curve needs both --keeler-n and --keeler-t ({} "
               "is missing)\n",
               o.keeler_n ? "--keeler-t" : "--keeler-n");
    return 1;
  }
  if (keeler && !(*o.keeler_n > 0.0 && *o.keeler_t > 0.0 && std::isfinite(*o.keeler_n) &&
                  std::isfinite(*o.keeler_t))) {
    fmt::print(err, "error: plot --fld: --keeler-n ({}) and --keeler-t ({}) must be positive\n",
               *o.keeler_n, *o.keeler_t);
    return 1;
  }
  if (o.flc && !std::filesystem::is_regular_file(*o.flc, ec)) {
    fmt::print(err, "error: plot --fld: --flc '{}' {}\n", o.flc->string(),
               std::filesystem::exists(*o.flc, ec) ? "is not a file" : "does not exist");
    return 1;
  }
  if (!(o.margin >= 0.0) || !(o.low_strain >= 0.0)) {
    fmt::print(err, "error: plot --fld: --margin ({}) and --low-strain ({}) must be >= 0\n",
               o.margin, o.low_strain);
    return 1;
  }
  if (o.state && *o.state < 0) {
    fmt::print(err, "error: plot --fld: --state {} is negative (0 is the first state)\n", *o.state);
    return 1;
  }
  std::vector<std::string> args{o.outdir.string()};
  if (o.flc) {
    args.insert(args.end(), {"--flc", o.flc->string()});
  } else {
    args.insert(args.end(), {"--keeler-n", number(*o.keeler_n), "--keeler-t", number(*o.keeler_t)});
  }
  if (o.state)
    args.insert(args.end(), {"--state", std::to_string(*o.state)});
  args.insert(args.end(), {"--margin", number(o.margin), "--low-strain", number(o.low_strain)});
  // The script writes to the same terminal: what was printed before comes first.
  out.flush();
  err.flush();
  const ScriptRun run = run_python_script("plot_fld.py", args);
  if (run.ran)
    return run.status;  // the script said what went wrong itself
  fmt::print(err, "error: {}\n", run.problem);
  return 1;
}

}  // namespace plyform::app
