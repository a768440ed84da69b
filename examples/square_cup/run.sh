#!/usr/bin/env bash
# Square-cup deep drawing (the NUMISHEET'93 tool set, quarter model), 30 mm deep: a single
# 0.81 mm aluminium sheet and the three-layer bonded sandwich (aluminium 0.25 / soft core 1.00 /
# aluminium 0.25 mm, cohesive interfaces). Generates the decks, runs them with `plyform run`
# (2 threads), and checks each run's energy books and contacts (check.py; README.md says what
# and why). Plots with /usr/bin/python3 and matplotlib when it is there.
#
#   run.sh [PLYFORM] [OUTDIR]
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"
plyform="${1:-${repo}/build/plyform}"
outdir="${2:-square_cup_out}"
if [[ ! -x "${plyform}" ]]; then
  echo "run.sh: error: plyform binary '${plyform}' not found or not executable" >&2
  echo "run.sh: usage: run.sh [PLYFORM] [OUTDIR]" >&2
  exit 2
fi
mkdir -p "${outdir}"
outdir="$(cd "${outdir}" && pwd)"
py="$(command -v python3 || echo /usr/bin/python3)"
status=0
# The single sheet, the sandwich as shipped, the sandwich written plainly: no *HOURGLASS
# (one-point shells with the viscous default), a softer core (E 1000 MPa) drawn at 2 m/s; and
# the sandwich with frictionless interfaces (MU 0), whose skins slide over the kinks of the
# core's surface at the die's shoulder (README.md: it blew up until the shells' resultants took
# the end-of-step thickness, and its interfaces' books failed until the core's offset surface
# met at its nodes and a node changed segment across a ridge once its gaps there parted).
for case in 1 3 plain mu0; do
  name="square_cup_${case}"
  options=(--layers "${case}")
  [[ ${case} == plain ]] && options=(--layers 3 --plain --speed 2000 --set CORE_E=1000 --name "${name}")
  [[ ${case} == mu0 ]] && options=(--layers 3 --set MU=0 --name "${name}")
  "${py}" "${here}/generate.py" "${outdir}" "${options[@]}"
  echo "run.sh: plyform run ${name}.k --threads 2"
  "${plyform}" run "${outdir}/${name}.k" -o "${outdir}/${name}" --threads 2 </dev/null | tail -n 4
  "${py}" "${here}/check.py" "${outdir}/${name}" "${outdir}/${name}.json" || status=1
  if [[ ${case} != 1 ]] && /usr/bin/python3 -c "import vtk, numpy" 2>/dev/null; then
    # Layers in order in every state (an independent reading of the states' geometry), none
    # through the blank holder (part 13).
    /usr/bin/python3 "${here}/../common/layer_order.py" "${outdir}/${name}" --lower 1 --core 2 \
      --upper 3 --reach 1.0 --tools 13 || status=1
  fi
done
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "${here}/plot.py" "${outdir}/square_cup.png" \
    "one sheet=${outdir}/square_cup_1" "three layers=${outdir}/square_cup_3" || status=1
fi
exit "${status}"
