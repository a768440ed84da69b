// `plyform plot OUTDIR`: PNG plots of the histories of a run, drawn by the Python script
// scripts/plot_histories.py (matplotlib) run with Debian's /usr/bin/python3.

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "plyform/app/commands.hpp"

extern char** environ;

#ifndef PLYFORM_SCRIPTS_DIR
#define PLYFORM_SCRIPTS_DIR ""
#endif

namespace plyform::app {
namespace {

constexpr const char* kScriptName = "plot_histories.py";
constexpr const char* kDefaultPython = "/usr/bin/python3";

/// The folder of the plotting scripts: $PLYFORM_SCRIPTS_DIR when set, else the source tree's
/// scripts/ folder baked in at build time.
std::filesystem::path scripts_dir() {
  if (const char* env = std::getenv("PLYFORM_SCRIPTS_DIR"); env != nullptr && *env != '\0')
    return env;
  return PLYFORM_SCRIPTS_DIR;
}

/// The interpreter: $PLYFORM_PYTHON when set, else Debian's /usr/bin/python3 (which has
/// python3-matplotlib; the first python3 on PATH may be a build without it).
std::string python() {
  if (const char* env = std::getenv("PLYFORM_PYTHON"); env != nullptr && *env != '\0')
    return env;
  return kDefaultPython;
}

}  // namespace

int run_plot(const std::filesystem::path& outdir, std::ostream& out, std::ostream& err) {
  std::error_code ec;
  if (!std::filesystem::is_directory(outdir, ec)) {
    fmt::print(err, "error: results folder '{}' {}\n", outdir.string(),
               std::filesystem::exists(outdir, ec) ? "is not a folder" : "does not exist");
    return 1;
  }
  const std::filesystem::path script = scripts_dir() / kScriptName;
  if (!std::filesystem::is_regular_file(script, ec)) {
    fmt::print(err,
               "error: plotting script '{}' not found (set PLYFORM_SCRIPTS_DIR to the folder "
               "holding {})\n",
               script.string(), kScriptName);
    return 1;
  }
  const std::string interpreter = python();
  if (!std::filesystem::is_regular_file(interpreter, ec)) {
    fmt::print(err,
               "error: Python interpreter '{}' not found (install python3-matplotlib with "
               "scripts/install_deps.sh, or set PLYFORM_PYTHON)\n",
               interpreter);
    return 1;
  }

  // posix_spawn with an argument vector: no shell, so no quoting of the paths is needed.
  std::string arg_script = script.string();
  std::string arg_outdir = outdir.string();
  std::string arg_python = interpreter;
  std::vector<char*> argv{arg_python.data(), arg_script.data(), arg_outdir.data(), nullptr};
  out.flush();
  err.flush();
  pid_t pid = 0;
  const int spawn_error =
      posix_spawn(&pid, interpreter.c_str(), nullptr, nullptr, argv.data(), environ);
  if (spawn_error != 0) {
    fmt::print(err, "error: cannot run '{}': {}\n", interpreter, std::strerror(spawn_error));
    return 1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      fmt::print(err, "error: waiting for '{}': {}\n", interpreter, std::strerror(errno));
      return 1;
    }
  }
  if (WIFEXITED(status))
    return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) {
    fmt::print(err, "error: '{} {}' was killed by signal {}\n", interpreter, arg_script,
               WTERMSIG(status));
    return 128 + WTERMSIG(status);
  }
  return 1;
}

}  // namespace plyform::app
