#!/usr/bin/env bash
# The README's test command. Installs what is missing (apt-get), builds plyform (Release,
# through ccache when it is installed) and runs every unit, verification and regression test
# and the examples that take less than about a minute: everything but the `long` tier
# (`ctest -LE long`). The long tier (the minutes-long examples and mesh studies) and the pass
# under AddressSanitizer + UndefinedBehaviorSanitizer are scripts/test_full.sh; CI runs both
# (.ci/run). Tiers and timings: docs/testing.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=$(nproc)
start=$SECONDS

bash scripts/install_deps.sh
bash scripts/build.sh "$root/build"
echo "== tests (Release; every tier but long) =="
ctest --test-dir "$root/build" --output-on-failure --parallel "$jobs" --label-exclude long
echo "== test.sh: passed in $((SECONDS - start)) s. The long tier and the sanitizer pass:" \
  "bash scripts/test_full.sh (or one tier: ctest --test-dir build -L long|unit|verification|regression|example)"
