#!/usr/bin/env python3
"""Checks a run of the LS-PrePost-style deep-drawing deck. Standard library only.

    python3 check.py OUTDIR PARAMS.json

Criteria (each printed with its measured value; exit 1 when one fails):
- conservation of energy: |kinetic + internal + hourglass + contact - external work| at every
  output within 1 % of the final external work;
- every CSV written once per output time (the end's row not repeated);
- internal energy never negative; hourglass energy below 5 % of the internal energy at the end;
- matsum.csv: the parts' internal, kinetic and hourglass energies add up to glstat's (1e-6);
  the sheet carries all the internal energy (the tools are rigid);
- sleout.csv lists every contact, and their energies add up to glstat's contact energy (1e-6);
- spcforc.csv: the symmetry planes' reactions are written at every output;
- elout.csv: every history shell at every thickness point (5), its plastic strain never
  decreasing; the shell at the die's shoulder yields;
- the sheet is drawn in: the edge midpoints move inwards, and the punch pushes down on the
  sheet (rcforc.csv: contact 1's force on the sheet points down at the end).
"""

import json
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from histories import rows  # noqa: E402


def main(argv):
    outdir, params = argv[0], json.load(open(argv[1]))
    ok = True

    def report(name, good, text):
        nonlocal ok
        print(f"check.py: {'ok  ' if good else 'FAIL'} {name}: {text}")
        ok = ok and good

    g = rows(os.path.join(outdir, "glstat.csv"))
    ext = g[-1]["external_work"]
    worst = max(abs(r["kinetic"] + r["internal"] + r["hourglass"] + r["contact"] -
                    r["external_work"]) for r in g)
    report("energy balance", worst <= 0.01 * ext,
           f"largest imbalance {worst:.4g} = {100 * worst / ext:.3f} % of the external work "
           f"{ext:.6g}; final ratio {g[-1]['energy_ratio']:.5f}")
    report("internal energy", min(r["internal"] for r in g) >= 0.0,
           f"never negative (final {g[-1]['internal']:.6g})")
    once = True
    for name, key in (("glstat.csv", None), ("matsum.csv", "part"), ("sleout.csv", "interface"),
                      ("rcforc.csv", "interface"), ("spcforc.csv", "node"),
                      ("nodout.csv", "node")):
        seen = set()
        for r in rows(os.path.join(outdir, name)):
            k = (r["time"], r[key] if key else 0)
            once = once and k not in seen
            seen.add(k)
    report("one row per output", once, "no (time, entity) row written twice in any CSV")
    hg = g[-1]["hourglass"] / g[-1]["internal"]
    report("hourglass", hg < 0.05, f"{100 * hg:.2f} % of the internal energy at the end")

    m = rows(os.path.join(outdir, "matsum.csv"))
    by_time = defaultdict(lambda: [0.0, 0.0, 0.0])
    sheet_internal = {}
    for r in m:
        s = by_time[r["time"]]
        s[0] += r["internal"]
        s[1] += r["kinetic"]
        s[2] += r["hourglass"]
        if int(r["part"]) == params["sheet_part"]:
            sheet_internal[r["time"]] = r["internal"]
    worst = 0.0
    for r in g:
        if r["time"] in by_time:
            s = by_time[r["time"]]
            scale = max(ext, 1e-30)
            worst = max(worst, abs(s[0] - r["internal"]) / scale, abs(s[1] - r["kinetic"]) / scale,
                        abs(s[2] - r["hourglass"]) / scale)
    report("matsum", len(by_time) > 10 and worst < 1e-6,
           f"{len(by_time)} outputs; the parts add up to glstat within {worst:.2g} of the "
           f"external work; the sheet holds {sheet_internal[max(sheet_internal)]:.6g}")

    sl = rows(os.path.join(outdir, "sleout.csv"))
    interfaces = sorted({int(r["interface"]) for r in sl})
    last_t = max(r["time"] for r in sl)
    total = sum(r["energy"] for r in sl if r["time"] == last_t)
    contact = [r for r in g if r["time"] == last_t]
    gap = abs(total - contact[0]["contact"]) / ext if contact else 1.0
    report("sleout", interfaces == params["tool_contacts"] + [params["self_contact"]] and gap < 1e-6,
           f"interfaces {interfaces}; their energies add up to glstat's contact energy within "
           f"{gap:.2g} of the external work")

    sp = rows(os.path.join(outdir, "spcforc.csv"))
    times = {r["time"] for r in sp}
    report("spcforc", len(times) > 10, f"{len(times)} outputs of the symmetry planes' reactions")

    el = rows(os.path.join(outdir, "elout.csv"))
    per = defaultdict(list)
    for r in el:
        per[(int(r["element"]), int(r["point"]))].append((r["time"], r["plastic_strain"]))
    complete = set(e for e, _ in per) == set(params["history_shells"]) and \
        all(len({p for e2, p in per if e2 == e}) == 5 for e in params["history_shells"])
    monotone = all(all(b[1] >= a[1] - 1e-12 for a, b in zip(v, v[1:])) for v in per.values())
    shoulder = params["history_shells"][1]
    eps = max(v[-1][1] for (e, _), v in per.items() if e == shoulder)
    report("elout", complete and monotone and eps > 0.0,
           f"{len(per)} (shell, point) histories, plastic strain never decreasing; the shoulder's "
           f"shell reaches {eps:.4f}")

    nd = rows(os.path.join(outdir, "nodout.csv"))
    last = {int(r["node"]): r for r in nd if r["time"] == nd[-1]["time"]}
    dx = last[params["edge_x"]]["ux"]
    dy = last[params["edge_y"]]["uy"]
    rc = rows(os.path.join(outdir, "rcforc.csv"))
    punch = [r for r in rc if int(r["interface"]) == 1][-1]
    report("draw", dx < 0.0 and dy < 0.0 and punch["fz"] < 0.0,
           f"draw-in {-dx:.3f} mm (x edge), {-dy:.3f} mm (y edge); the punch contact's force on "
           f"the sheet {punch['fz']:.6g} N (quarter model)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
