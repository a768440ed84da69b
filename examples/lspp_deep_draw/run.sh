#!/usr/bin/env bash
# The LS-PrePost-style deep-drawing deck (README.md): generates it, `plyform check`s it (every
# keyword read; the requests plyform does not write are warned about), runs it with
# `plyform run`, and checks the run's energy books and outputs (check.py).
#
#   run.sh [PLYFORM] [OUTDIR]
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"
plyform="${1:-${repo}/build/plyform}"
outdir="${2:-lspp_deep_draw_out}"
if [[ ! -x "${plyform}" ]]; then
  echo "run.sh: error: plyform binary '${plyform}' not found or not executable" >&2
  echo "run.sh: usage: run.sh [PLYFORM] [OUTDIR]" >&2
  exit 2
fi
mkdir -p "${outdir}"
outdir="$(cd "${outdir}" && pwd)"
py="$(command -v python3 || echo /usr/bin/python3)"
"${py}" "${here}/generate.py" "${outdir}"
"${plyform}" check "${outdir}/lspp_deep_draw.k" > "${outdir}/check.txt" 2>&1
tail -n 3 "${outdir}/check.txt"
echo "run.sh: plyform run lspp_deep_draw.k"
"${plyform}" run "${outdir}/lspp_deep_draw.k" -o "${outdir}/run" </dev/null 2>&1 | tail -n 4
"${py}" "${here}/check.py" "${outdir}/run" "${outdir}/lspp_deep_draw.json"
