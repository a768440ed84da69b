#!/usr/bin/env bash
# Installs what is missing (apt-get), builds plyform, and runs the main job on the shipped
# examples: the fundamental model of the cohesive interface (examples/fundamental: two shell
# plates pressed, pulled apart, re-healed and pulled again with `plyform run`), results and
# plots in ./fundamental_out/; the probe tack test (examples/probe) in ./probe_out/; the solid
# block (examples/solid_block: a rubber cube compressed and released) in ./solid_block_out/.
# Works from any current directory.
#
#   demo.sh [PROBE_OUT] [SOLID_BLOCK_OUT] [FUNDAMENTAL_OUT]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-"$PWD/probe_out"}
solid_out=${2:-"$PWD/solid_block_out"}
fundamental_out=${3:-"$PWD/fundamental_out"}

bash "$root/scripts/install_deps.sh"
bash "$root/scripts/build.sh" "$root/build"
bash "$root/examples/fundamental/run.sh" "$root/build/plyform" "$fundamental_out"
bash "$root/examples/probe/run.sh" "$root/build/plyform" "$out"
bash "$root/examples/solid_block/run.sh" "$root/build/plyform" "$solid_out"
