#!/usr/bin/env bash
# Installs what is missing (apt-get), builds plyform and runs the whole test suite with ctest;
# then builds it again with AddressSanitizer + UndefinedBehaviorSanitizer and runs the suite
# under them. PLYFORM_SKIP_SANITIZE=1 skips the second pass.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=$(nproc)

bash scripts/install_deps.sh
bash scripts/build.sh "$root/build"
echo "== tests (Release) =="
ctest --test-dir "$root/build" --output-on-failure --parallel "$jobs"

if [[ "${PLYFORM_SKIP_SANITIZE:-0}" != 1 ]]; then
  bash scripts/build.sh "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DPLYFORM_SANITIZE=ON -DPLYFORM_BUILD_BENCHMARKS=OFF
  echo "== tests (AddressSanitizer + UndefinedBehaviorSanitizer) =="
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir "$root/build-sanitize" --output-on-failure --parallel "$jobs"
fi
