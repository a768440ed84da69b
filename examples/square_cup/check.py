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

import json
import math
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from forming_books import check_books  # noqa: E402
from histories import rows  # noqa: E402


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
