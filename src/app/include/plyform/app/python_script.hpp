#pragma once
// Runs one of the plotting scripts of scripts/ with Debian's /usr/bin/python3 (which has
// python3-matplotlib); $PLYFORM_SCRIPTS_DIR and $PLYFORM_PYTHON override the two.

#include <string>
#include <vector>

namespace plyform::app {

struct ScriptRun {
  bool ran = false;     ///< the interpreter started and ended by itself
  int status = 0;       ///< its exit status when it ran
  std::string problem;  ///< why it did not run or failed, in words; empty on success
};

/// Runs `python script_name args...` (no shell) and waits for it. Never throws: a missing
/// interpreter or script comes back as `problem`.
[[nodiscard]] ScriptRun run_python_script(const std::string& script_name,
                                          const std::vector<std::string>& args);

}  // namespace plyform::app
