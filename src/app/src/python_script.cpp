#include "plyform/app/python_script.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

extern char** environ;

#ifndef PLYFORM_SCRIPTS_DIR
#define PLYFORM_SCRIPTS_DIR ""
#endif

namespace plyform::app {

ScriptRun run_python_script(const std::string& script_name, const std::vector<std::string>& args) {
  ScriptRun run;
  const char* dir_env = std::getenv("PLYFORM_SCRIPTS_DIR");
  const std::filesystem::path dir =
      dir_env != nullptr && *dir_env != '\0' ? dir_env : PLYFORM_SCRIPTS_DIR;
  const char* python_env = std::getenv("PLYFORM_PYTHON");
  // Debian's interpreter, not the first python3 on PATH, which may be a build without
  // matplotlib.
  const std::string python =
      python_env != nullptr && *python_env != '\0' ? python_env : "/usr/bin/python3";
  const std::filesystem::path script = dir / script_name;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(script, ec)) {
    run.problem = fmt::format("script '{}' not found (set PLYFORM_SCRIPTS_DIR)", script.string());
    return run;
  }
  if (!std::filesystem::is_regular_file(python, ec)) {
    run.problem = fmt::format(
        "Python interpreter '{}' not found (install python3-matplotlib with "
        "scripts/install_deps.sh, or set PLYFORM_PYTHON)",
        python);
    return run;
  }
  std::vector<std::string> words{python, script.string()};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words)
    argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (const int e = posix_spawn(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ);
      e != 0) {
    run.problem = fmt::format("cannot run '{}': {}", python, std::strerror(e));
    return run;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      run.problem = fmt::format("waiting for '{}': {}", python, std::strerror(errno));
      return run;
    }
  }
  if (WIFEXITED(status)) {
    run.ran = true;
    run.status = WEXITSTATUS(status);
    if (run.status != 0)
      run.problem = fmt::format("{} exited with status {}", script_name, run.status);
  } else {
    run.problem = fmt::format("{} was killed by signal {}", script_name,
                              WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  }
  return run;
}

}  // namespace plyform::app
