#!/usr/bin/env bash
# `plyform plot OUTDIR` end to end: a tiny solid block run (examples/solid_block, 2^3 hex8),
# then `plyform plot`; energies.png and nodout.png must exist and hold a real figure, and a
# folder without glstat.csv must fail with a message naming the file.
#
#   plot_command.sh PLYFORM WORKDIR
set -euo pipefail
plyform="$1"
work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"

rm -rf "${work}"
mkdir -p "${work}"
python3 "${repo}/examples/solid_block/generate.py" "${work}" --elements 2 >/dev/null
# Eight one-point hexahedra compressed at once ring their hourglass modes (18 % of the largest
# internal energy): the run completes with its results not to be trusted (exit 5), and its
# files are what `plyform plot` draws all the same.
status=0
"${plyform}" run "${work}/solid_block.k" -o "${work}/out" </dev/null >/dev/null 2>&1 || status=$?
if [[ ${status} != 0 && ${status} != 5 ]]; then
  echo "plot_command.sh: FAIL: plyform run exited ${status}" >&2
  exit 1
fi
"${plyform}" plot "${work}/out"

for png in energies.png nodout.png; do
  file="${work}/out/${png}"
  if [[ ! -f "${file}" ]]; then
    echo "plot_command.sh: FAIL: ${file} was not written" >&2
    exit 1
  fi
  size=$(stat -c %s "${file}")
  if ((size < 20000)); then
    echo "plot_command.sh: FAIL: ${file} has only ${size} bytes" >&2
    exit 1
  fi
  if [[ "$(head -c 8 "${file}" | od -An -tx1 | tr -d ' \n')" != "89504e470d0a1a0a" ]]; then
    echo "plot_command.sh: FAIL: ${file} is not a PNG" >&2
    exit 1
  fi
  echo "plot_command.sh: ${png}: ${size} bytes"
done

# A folder without glstat.csv: non-zero exit, and the message names the missing file.
mkdir -p "${work}/empty"
if "${plyform}" plot "${work}/empty" 2>"${work}/empty.err"; then
  echo "plot_command.sh: FAIL: plyform plot succeeded on a folder without glstat.csv" >&2
  exit 1
fi
if ! grep -q "empty/glstat.csv" "${work}/empty.err"; then
  echo "plot_command.sh: FAIL: the message does not name glstat.csv:" >&2
  cat "${work}/empty.err" >&2
  exit 1
fi
echo "plot_command.sh: ok"
