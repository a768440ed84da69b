#!/usr/bin/env bash
# `plyform fit` end to end with the installed command: the probe example's law (eta 3e-3) is
# driven by `plyform law` at two rates; its output files are fitted as they are (columns
# time, gap, pressure) from constants 30-50 % off. CN, SMAX and ETA must come back within 1 %,
# FIT.k must pass `plyform check`, FIT_curves.csv (and the PNG when /usr/bin/python3 has
# matplotlib) must be written; a curve cut before its peak must be refused with the reason.
#
#   fit_command.sh PLYFORM WORKDIR
set -euo pipefail
plyform="$1"
work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "${here}/../.." && pwd)"

rm -rf "${work}"
mkdir -p "${work}"
python3 "${repo}/examples/probe/generate.py" "${work}" >/dev/null
for rate in 3e-03 3e-02; do
  "${plyform}" law "${work}/eta_3e-03.k" --path "${work}/path_v${rate}.csv" -o "${work}/v${rate}.csv"
done
cat >"${work}/start.k" <<'DECK'
*KEYWORD
*USER_INTERFACE_FRICTION
         1        19         0
         1      42.0      0.18      0.18      20.0      20.0    1.5E-3       0.0
       0.0       1.0    1.0E-6         0
                         0.001
*END
DECK
"${plyform}" fit "${work}/v3e-03.csv" "${work}/v3e-02.csv" --deck "${work}/start.k" \
  -o "${work}/fit/probe_fit.k" | tee "${work}/fit.out"

fail() {
  echo "fit_command.sh: FAIL: $*" >&2
  exit 1
}
for pair in CN:30 SMAX:0.3 ETA:0.003; do
  name="${pair%%:*}"
  truth="${pair##*:}"
  value=$(awk -v n="${name}" '$1 == n && NF >= 4 { print $3; exit }' "${work}/fit.out")
  [[ -n "${value}" ]] || fail "no fitted ${name} in the report"
  awk -v v="${value}" -v t="${truth}" 'BEGIN { e = (v - t) / t; if (e < 0) e = -e; exit !(e < 0.01) }' ||
    fail "${name} = ${value}, expected ${truth} within 1 %"
  echo "fit_command.sh: ${name} = ${value} (true ${truth})"
done
"${plyform}" check "${work}/fit/probe_fit.k" >/dev/null || fail "plyform check refuses FIT.k"
[[ -s "${work}/fit/probe_fit_curves.csv" ]] || fail "probe_fit_curves.csv was not written"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  png="${work}/fit/probe_fit_curves.png"
  [[ -f "${png}" ]] || fail "${png} was not written"
  [[ "$(head -c 8 "${png}" | od -An -tx1 | tr -d ' \n')" == "89504e470d0a1a0a" ]] ||
    fail "${png} is not a PNG"
fi

# Cut before the peak (the first 20 points): refused, exit 1, the reason named.
head -n 21 "${work}/v3e-03.csv" >"${work}/cut.csv"
if "${plyform}" fit "${work}/cut.csv" --deck "${work}/start.k" --no-plot \
  -o "${work}/cut_fit.k" >/dev/null 2>"${work}/cut.err"; then
  fail "a curve without a peak was fitted"
fi
grep -q "curve cut.csv: no peak" "${work}/cut.err" || {
  cat "${work}/cut.err" >&2
  fail "the refusal does not say 'no peak'"
}
echo "fit_command.sh: ok"
