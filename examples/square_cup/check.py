#!/usr/bin/env python3
"""Checks a square-cup run against conservation and the standing energy criteria, and reports
the draw-ins and the punch force. Standard library only.

    python3 check.py OUTDIR PARAMS.json

Criteria (each printed with its measured value; exit 1 when one fails):
- energy balance: |kinetic + internal + hourglass + contact - external work| at every output
  within 1 % of the run's final external work (conservation of energy);
- internal energy (the elements' stress work) never negative;
- hourglass energy below 5 % of the internal energy at the end, and at every output once the
  internal energy has reached 1 % of its final value;
- no contact gives the model energy: every interface's work stays above -0.1 % of the final
  external work at every output;
- cohesive interfaces (three layers): their normal damping below 1 % of the external work, and
  their books (stored + damage + viscous + friction + damping) within 0.5 % of the external work
  of their own work.
"""

import csv
import json
import math
import os
import sys
from collections import defaultdict


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def check_books(outdir, interfaces, report, balance=0.01, internal_floor=0.0, books_tol=0.005,
                damping_tol=0.01):
    """The energy criteria every forming example is held to, each passed to report(name, ok,
    text); the tolerances are fractions of the final external work. Returns (glstat rows,
    interface_energy rows by interface)."""
    glstat = rows(os.path.join(outdir, "glstat.csv"))
    books = defaultdict(list)
    for r in rows(os.path.join(outdir, "interface_energy.csv")):
        books[int(r["interface"])].append(r)
    last = glstat[-1]
    ext = last["external_work"]
    worst = max(abs(r["kinetic"] + r["internal"] + r["hourglass"] + r["contact"] -
                    r["external_work"]) for r in glstat)
    report("energy balance", worst <= balance * ext,
           f"largest |total - external work| {worst:.4g} mJ = {100 * worst / ext:.3f} % of the "
           f"external work {ext:.6g} mJ; energy ratio at the end {last['energy_ratio']:.5f}")
    lowest = min(r["internal"] for r in glstat)
    if internal_floor == 0.0:
        report("internal energy", lowest >= 0.0, f"lowest {lowest:.4g} mJ")
    else:
        report("internal energy", last["internal"] > 0.0 and lowest >= -internal_floor * ext,
               f"{last['internal']:.6g} mJ at the end; lowest {lowest:.4g} mJ "
               f"({100 * lowest / ext:+.4f} % of the external work)")
    final_internal = last["internal"]
    share = [r["hourglass"] / r["internal"] for r in glstat
             if r["internal"] >= 0.01 * final_internal and r["internal"] > 0.0]
    report("hourglass", max(share) < 0.05,
           f"{100 * last['hourglass'] / final_internal:.2f} % of the internal energy at the end, "
           f"at most {100 * max(share):.2f} % once the internal energy passed 1 % of its final "
           f"value")
    for iface, hist in sorted(books.items()):
        low = min(r["work"] for r in hist)
        report(f"contact {iface} work", low >= -1e-3 * ext,
               f"lowest {low:.4g} mJ ({100 * low / ext:+.4f} % of the external work), at the end "
               f"{hist[-1]['work']:.6g} mJ")
    for iface in interfaces:
        h = books[iface][-1]
        booked = h["stored"] + h["damage"] + h["viscous"] + h["friction"] + h["damping"]
        if damping_tol is not None:
            report(f"interface {iface} damping", h["damping"] <= damping_tol * ext,
                   f"{h['damping']:.4g} mJ = {100 * h['damping'] / ext:.3f} % of the external "
                   f"work")
        report(f"interface {iface} books", abs(booked - h["work"]) <= books_tol * ext,
               f"work {h['work']:.5g} mJ, books {booked:.5g} mJ (stored {h['stored']:.4g}, "
               f"damage {h['damage']:.4g}, friction {h['friction']:.4g}, damping "
               f"{h['damping']:.4g}, healing {h['healing']:.4g}); difference "
               f"{100 * abs(booked - h['work']) / ext:.3f} % of the external work")
    return glstat, books


def main(outdir, params_path):
    p = json.load(open(params_path))
    failures = []

    def report(name, ok, text):
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {text}")
        if not ok:
            failures.append(name)

    check_books(outdir, p["interfaces"], report)

    # Results: draw-ins of the blank's edge midpoints and corner, the punch force and stroke.
    nodes = defaultdict(list)
    for r in rows(os.path.join(outdir, "nodout.csv")):
        nodes[int(r["node"])].append(r)
    half = p["blank_half"]
    for layer, (ex, ey, c) in enumerate(zip(p["edge_x"], p["edge_y"], p["corner"])):
        ax, ay, ac = nodes[ex][-1], nodes[ey][-1], nodes[c][-1]
        dd = math.hypot(half, half) - math.hypot(ac["x"], ac["y"])
        print(f"     layer {layer + 1}: draw-in DX {half - ax['x']:.2f} mm, DY {half - ay['y']:.2f} "
              f"mm, DD (corner, along the diagonal) {dd:.2f} mm")
    punch = [r for r in rows(os.path.join(outdir, "rcforc.csv")) if int(r["interface"]) == 1]
    body = [r for r in rows(os.path.join(outdir, "rbdout.csv")) if int(r["part"]) == 11]
    z0 = body[0]["z"]
    peak = max(-r["fz"] for r in punch)
    print(f"     punch force (full cup, 4 x the quarter's) at most {4 * peak / 1000:.2f} kN; "
          f"stroke {z0 - body[-1]['z']:.2f} mm")
    if failures:
        print(f"{len(failures)} check(s) failed: {', '.join(failures)}")
        return 1
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
