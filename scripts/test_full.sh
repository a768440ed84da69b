#!/usr/bin/env bash
# What scripts/test.sh leaves out (CI runs both, .ci/run): the `long` tier in the Release build
# (the examples and mesh studies that run for minutes), then a second build with
# AddressSanitizer + UndefinedBehaviorSanitizer (-O1 -g1, without the benchmarks, the examples,
# the regression tier and MPI) running the unit and verification tests under them (the regression
# tier drives the same code through the command line, decks and files; the runs over MPI ranks
# are its `mpi` tests).
# PLYFORM_SKIP_SANITIZE=1 skips the sanitizer pass. Tiers and timings: docs/testing.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=$(nproc)
start=$SECONDS

bash scripts/install_deps.sh
bash scripts/build.sh "$root/build"
echo "== tests (Release; the long tier) =="
ctest --test-dir "$root/build" --output-on-failure --parallel "$jobs" --label-regex long

if [[ "${PLYFORM_SKIP_SANITIZE:-0}" != 1 ]]; then
  # -O1 -g1: what the sanitizers' authors advise (fast enough, stack traces with lines); it
  # compiles two to three times faster than -O2 -g under the instrumentation.
  bash scripts/build.sh "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DPLYFORM_SANITIZE=ON \
    -DPLYFORM_BUILD_BENCHMARKS=OFF -DPLYFORM_BUILD_EXAMPLES=OFF \
    -DPLYFORM_BUILD_REGRESSION_TESTS=OFF -DPLYFORM_MPI=OFF
  # ctest starts the longest tests first when it knows their durations: a fresh tree has none,
  # so it takes the Release tree's (the same tests, each slower by a similar factor). Started
  # last, the minute-long multilayer tests left one core idle for minutes.
  costs=Testing/Temporary/CTestCostData.txt
  if [[ -f "$root/build/$costs" && ! -f "$root/build-sanitize/$costs" ]]; then
    mkdir -p "$root/build-sanitize/Testing/Temporary"
    cp "$root/build/$costs" "$root/build-sanitize/$costs"
  fi
  echo "== tests (AddressSanitizer + UndefinedBehaviorSanitizer) =="
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir "$root/build-sanitize" --output-on-failure --parallel "$jobs" \
    --label-regex 'unit|verification' --label-exclude long
fi
echo "== test_full.sh: passed in $((SECONDS - start)) s"
