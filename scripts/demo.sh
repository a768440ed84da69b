#!/usr/bin/env bash
# Installs what is missing (apt-get), builds plyform, and runs the main job on a shipped
# example: the probe tack test (examples/probe), results and plots in ./probe_out/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-"$PWD/probe_out"}

bash "$root/scripts/install_deps.sh"
bash "$root/scripts/build.sh" "$root/build"
bash "$root/examples/probe/run.sh" "$root/build/plyform" "$out"
