#!/usr/bin/env bash
# Fundamental model of the cohesive interface: generate the decks, run them with `plyform run`
# (full cycle with 1 and 2 threads, partial damage, the partial cycle at three temperatures),
# plot the paper's figs. 6 and 7 and check them against the closed forms of the law.
#
#   run.sh [PLYFORM] [OUTDIR]
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"
plyform="${1:-${repo}/build/plyform}"
outdir="${2:-fundamental_out}"
if [[ ! -x "${plyform}" ]]; then
  echo "run.sh: error: plyform binary '${plyform}' not found or not executable" >&2
  echo "run.sh: usage: run.sh [PLYFORM] [OUTDIR]" >&2
  exit 2
fi
mkdir -p "${outdir}"
outdir="$(cd "${outdir}" && pwd)"
plot_python=/usr/bin/python3
gen_python="$(command -v python3 || echo "${plot_python}")"

one() {  # one SUBDIR NAME THREADS GENERATOR-OPTIONS...
  local sub=$1 name=$2 threads=$3
  shift 3
  "${gen_python}" "${here}/generate.py" "${outdir}/${sub}" --name "${name}" "$@"
  echo "run.sh: plyform run ${sub}/${name}.k --threads ${threads}"
  "${plyform}" run "${outdir}/${sub}/${name}.k" -o "${outdir}/${sub}" --threads "${threads}" \
    </dev/null | tail -n 3
}
one full fundamental 1 --variant full
one full_2threads fundamental 2 --variant full
one partial fundamental_partial 1 --variant partial
for t in 100 150 200; do
  one "temperature_${t}" "temperature_${t}" 1 --variant partial --temperature "${t}"
done

echo "run.sh: plotting and checking with ${plot_python}"
"${plot_python}" "${here}/plot.py" "${outdir}"
echo "run.sh: done; results in ${outdir} (full/, partial/: results.pvd, rcforc.csv," \
  "cohesive.csv, interface_energy.csv, glstat.csv; fundamental_*.png)"
