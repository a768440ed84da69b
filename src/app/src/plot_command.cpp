// `plyform plot OUTDIR`: PNG plots of the histories of a run, drawn by the Python script
// scripts/plot_histories.py (matplotlib) run with Debian's /usr/bin/python3
// (`run_python_script`, shared with `plyform fit`).

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <system_error>

#include "plyform/app/commands.hpp"
#include "plyform/app/python_script.hpp"

namespace plyform::app {

int run_plot(const std::filesystem::path& outdir, std::ostream& out, std::ostream& err) {
  std::error_code ec;
  if (!std::filesystem::is_directory(outdir, ec)) {
    fmt::print(err, "error: results folder '{}' {}\n", outdir.string(),
               std::filesystem::exists(outdir, ec) ? "is not a folder" : "does not exist");
    return 1;
  }
  // The script writes to the same terminal: what was printed before comes first.
  out.flush();
  err.flush();
  const ScriptRun run = run_python_script("plot_histories.py", {outdir.string()});
  if (run.ran)
    return run.status;  // the script said what went wrong itself
  fmt::print(err, "error: {}\n", run.problem);
  return 1;
}

}  // namespace plyform::app
