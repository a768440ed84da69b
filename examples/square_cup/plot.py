#!/usr/bin/env python3
"""Plots of square-cup runs: punch force against stroke, the energy books, and the adhesion
(beta) along the edge of the three-layer blank. Needs matplotlib (/usr/bin/python3).

    /usr/bin/python3 plot.py OUTPNG LABEL=OUTDIR [LABEL=OUTDIR ...]
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from histories import rows  # noqa: E402


def main(out, runs):
    fig, (ax_f, ax_e) = plt.subplots(1, 2, figsize=(12, 4.5))
    for label, outdir in runs:
        body = [r for r in rows(os.path.join(outdir, "rbdout.csv")) if int(r["part"]) == 11]
        punch = [r for r in rows(os.path.join(outdir, "rcforc.csv")) if int(r["interface"]) == 1]
        z0 = body[0]["z"]
        stroke = {r["time"]: z0 - r["z"] for r in body}
        pts = [(stroke[r["time"]], -4e-3 * r["fz"]) for r in punch if r["time"] in stroke]
        ax_f.plot([p[0] for p in pts], [p[1] for p in pts], label=label)
        g = rows(os.path.join(outdir, "glstat.csv"))
        t = [1e3 * r["time"] for r in g]
        ax_e.plot(t, [1e-3 * r["external_work"] for r in g], label=f"{label}: external work")
        ax_e.plot(t, [1e-3 * r["internal"] for r in g], "--", label=f"{label}: internal")
        ax_e.plot(t, [1e-3 * r["contact"] for r in g], ":", label=f"{label}: contact")
        ax_e.plot(t, [1e-3 * r["hourglass"] for r in g], "-.", label=f"{label}: hourglass")
    ax_f.set_xlabel("punch stroke [mm]")
    ax_f.set_ylabel("punch force, full cup [kN]")
    ax_f.grid(alpha=0.3)
    ax_f.legend()
    ax_e.set_xlabel("time [ms]")
    ax_e.set_ylabel("energy, quarter model [J]")
    ax_e.grid(alpha=0.3)
    ax_e.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"plot.py: wrote {out}")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]])
