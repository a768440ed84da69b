#!/usr/bin/env bash
# Probe tack test: generate the decks and paths, drive the law for every (eta, rate) case with
# `plyform law`, plot the force-opening curves and print the per-case summary.
#
#   run.sh [PLYFORM] [OUTDIR]
#     PLYFORM  the plyform binary (default: build/plyform relative to the repository root)
#     OUTDIR   where everything is written (default: probe_out in the current directory)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"

plyform="${1:-${repo}/build/plyform}"
outdir="${2:-probe_out}"

if [[ ! -x "${plyform}" ]]; then
  echo "run.sh: error: plyform binary '${plyform}' not found or not executable" >&2
  echo "run.sh: usage: run.sh [PLYFORM] [OUTDIR]" >&2
  exit 2
fi
# Absolute paths: the law runs below happen inside OUTDIR.
plyform="$(cd "$(dirname "${plyform}")" && pwd)/$(basename "${plyform}")"
mkdir -p "${outdir}"
outdir="$(cd "${outdir}" && pwd)"

# Debian's interpreter has python3-matplotlib and python3-numpy; the first python3 on PATH
# may be a separate build without them. generate.py needs only the standard library.
plot_python=/usr/bin/python3
gen_python="$(command -v python3 || echo "${plot_python}")"

echo "run.sh: generating decks and paths in ${outdir}"
"${gen_python}" "${here}/generate.py" "${outdir}"

cd "${outdir}"
n=0
# cases.csv: case,eta,rate,lambda,deck,path,output
while IFS=, read -r name eta rate lambda deck path output; do
  [[ "${name}" == "case" ]] && continue
  echo "run.sh: case ${name}: eta = ${eta} MPa mm s, rate = ${rate} mm/s, Lambda = ${lambda}"
  "${plyform}" law "${deck}" --path "${path}" -o "${output}" </dev/null
  n=$((n + 1))
done < cases.csv
if [[ ${n} -eq 0 ]]; then
  echo "run.sh: error: no cases in ${outdir}/cases.csv" >&2
  exit 1
fi

echo "run.sh: plotting with ${plot_python}"
"${plot_python}" "${here}/plot.py" "${outdir}"

echo "run.sh: ${n} cases done; results in ${outdir} (probe_eta.png, probe_rate.png, summary.csv)"
