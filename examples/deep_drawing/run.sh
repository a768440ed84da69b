#!/usr/bin/env bash
# Hot deep drawing of the three-layer sandwich (steel 0.25 / woven carbon-PA6 1.00 / steel
# 0.25 mm, cohesive interfaces, computed temperatures): generates the deck, runs it with
# `plyform run` (2 threads), checks the energy books, the heat ledger and the interface
# (check.py; README.md says what and why) and draws the plots and pictures of the part.
#
#   run.sh [PLYFORM] [OUTDIR] [generate.py options, e.g. --n 20 --full --interface tiebreak]
#
# The checks and plots need /usr/bin/python3 with numpy, matplotlib and VTK (python3-vtk9,
# installed by scripts/install_deps.sh).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"
plyform="${1:-${repo}/build/plyform}"
outdir="${2:-deep_drawing_out}"
shift $(($# < 2 ? $# : 2))
if [[ ! -x "${plyform}" ]]; then
  echo "run.sh: error: plyform binary '${plyform}' not found or not executable" >&2
  echo "run.sh: usage: run.sh [PLYFORM] [OUTDIR] [generate.py options]" >&2
  exit 2
fi
sys_py=/usr/bin/python3
if ! "${sys_py}" -c "import numpy, vtk, matplotlib" 2>/dev/null; then
  echo "run.sh: error: ${sys_py} needs numpy, vtk and matplotlib (bash scripts/install_deps.sh)" >&2
  exit 2
fi
mkdir -p "${outdir}"
outdir="$(cd "${outdir}" && pwd)"
name=deep_drawing
"${sys_py}" "${here}/generate.py" "${outdir}" --name "${name}" "$@"
echo "run.sh: plyform run ${name}.k --threads 2"
"${plyform}" run "${outdir}/${name}.k" -o "${outdir}/${name}" --threads 2 </dev/null | tail -n 5
status=0
"${sys_py}" "${here}/check.py" "${outdir}/${name}" "${outdir}/${name}.json" || status=1
"${sys_py}" "${here}/plot.py" curves "${outdir}/deep_drawing.png" "this run=${outdir}/${name}" || status=1
"${sys_py}" "${here}/plot.py" parts "${outdir}/deep_drawing_parts.png" "${outdir}/${name}" || status=1
echo "run.sh: plots in ${outdir}/deep_drawing.png and ${outdir}/deep_drawing_parts.png;" \
  "ParaView: ${outdir}/${name}/results.pvd"
exit "${status}"
