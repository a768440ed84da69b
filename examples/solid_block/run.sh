#!/usr/bin/env bash
# Solid block demo: generate the deck, run it with `plyform run`, plot the histories and check
# them against the closed form of uniaxial stress.
#
#   run.sh [PLYFORM] [OUTDIR] [ELEMENTS]
#     PLYFORM   the plyform binary (default: build/plyform relative to the repository root)
#     OUTDIR    where everything is written (default: solid_block_out in the current directory)
#     ELEMENTS  hexahedra along each edge of the cube, even (default 10)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"

plyform="${1:-${repo}/build/plyform}"
outdir="${2:-solid_block_out}"
elements="${3:-10}"

if [[ ! -x "${plyform}" ]]; then
  echo "run.sh: error: plyform binary '${plyform}' not found or not executable" >&2
  echo "run.sh: usage: run.sh [PLYFORM] [OUTDIR] [ELEMENTS]" >&2
  exit 2
fi
mkdir -p "${outdir}"
outdir="$(cd "${outdir}" && pwd)"

# Debian's interpreter has python3-matplotlib and python3-numpy; the first python3 on PATH
# may be a separate build without them. generate.py needs only the standard library.
plot_python=/usr/bin/python3
gen_python="$(command -v python3 || echo "${plot_python}")"

echo "run.sh: generating the deck in ${outdir}"
"${gen_python}" "${here}/generate.py" "${outdir}" --elements "${elements}"

echo "run.sh: plyform run ${outdir}/solid_block.k"
"${plyform}" run "${outdir}/solid_block.k" -o "${outdir}" </dev/null

echo "run.sh: plotting with ${plot_python}"
"${plot_python}" "${here}/plot.py" "${outdir}"

echo "run.sh: done; results in ${outdir} (results.pvd for ParaView, glstat.csv, nodout.csv," \
  "summary.json, solid_block_energies.png, solid_block_response.png)"
