#!/usr/bin/env bash
# Deformable test model of the paper (figs. 8-10): a soft Mooney-Rivlin block bonded to a rigid
# plate by the cohesive interface, a rigid cylinder slid across its top. Generates the deck,
# runs it with `plyform run` (1 thread), checks it and draws the figures (check.py; README.md).
#
#   run.sh [PLYFORM] [OUTDIR] [GENERATOR OPTIONS...]
#     PLYFORM  the plyform binary (default: build/plyform relative to the repository root)
#     OUTDIR   where everything is written (default: deformable_out in the current directory)
#     options  passed to generate.py: the ctest runs the coarse mesh `--dx 2 --dz0 1` (about a
#              minute); the default mesh (dx 1, dz0 0.5) takes about 3-4 minutes on one core
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"
plyform="${1:-${repo}/build/plyform}"
outdir="${2:-deformable_out}"
shift $(($# > 2 ? 2 : $#))
if [[ ! -x "${plyform}" ]]; then
  echo "run.sh: error: plyform binary '${plyform}' not found or not executable" >&2
  echo "run.sh: usage: run.sh [PLYFORM] [OUTDIR] [GENERATOR OPTIONS...]" >&2
  exit 2
fi
mkdir -p "${outdir}"
outdir="$(cd "${outdir}" && pwd)"
# Debian's interpreter has matplotlib, numpy and VTK (check.py); generate.py needs only the
# standard library.
check_python=/usr/bin/python3
gen_python="$(command -v python3 || echo "${check_python}")"

"${gen_python}" "${here}/generate.py" "${outdir}" "$@"
"${plyform}" check "${outdir}/deformable.k" >"${outdir}/check.txt"
echo "run.sh: plyform run deformable.k --threads 1"
start=$(date +%s)
OMP_NUM_THREADS=1 "${plyform}" run "${outdir}/deformable.k" -o "${outdir}" --threads 1 \
  </dev/null | tail -n 5
echo "run.sh: run took $(($(date +%s) - start)) s wall"
"${check_python}" "${here}/check.py" "${outdir}" --plots "${outdir}"
echo "run.sh: done; results in ${outdir} (results.pvd for ParaView: pvpython" \
  "${here}/paraview_state.py ${outdir})"
