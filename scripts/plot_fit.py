#!/usr/bin/env python3
"""Plot of `plyform fit`: measured and fitted traction of every curve, and the residuals.

    /usr/bin/python3 plot_fit.py FIT_curves.csv FIT_curves.png

Reads the curves file that `plyform fit` writes (columns curve,file,point,time,gap,
temperature,stress_data,stress_fit,residual,area). Curves that open monotonically are drawn
against the opening, paths that hold or close (a healing test) against time. With a probe area
the tractions are shown as forces. Exits 3 with a message when matplotlib is missing (the fit
itself does not need the plot).
"""

import csv
import sys
from collections import OrderedDict


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        print(f"plot_fit.py: matplotlib is not available ({e}); install python3-matplotlib",
              file=sys.stderr)
        return 3

    curves = OrderedDict()
    with open(sys.argv[1], newline="") as f:
        for row in csv.DictReader(f):
            c = curves.setdefault(row["curve"], {"file": row["file"], "rows": []})
            c["rows"].append({k: float(v) for k, v in row.items() if k not in ("curve", "file")})

    monotone = all(
        all(b["gap"] >= a["gap"] for a, b in zip(c["rows"], c["rows"][1:])) for c in curves.values()
    )
    xkey, xlabel = ("gap", "opening (gap)") if monotone else ("time", "time")
    force = all(c["rows"][0]["area"] > 0 for c in curves.values())
    ylabel = "force (tension positive)" if force else "normal traction (tension positive)"

    fig, (ax, axr) = plt.subplots(2, 1, figsize=(8, 7), sharex=True,
                                  gridspec_kw={"height_ratios": [3, 1]})
    for i, (name, c) in enumerate(curves.items()):
        colour = f"C{i % 10}"
        rows = c["rows"]
        scale = rows[0]["area"] if force else 1.0
        x = [r[xkey] for r in rows]
        ax.plot(x, [r["stress_data"] * scale for r in rows], ".", ms=3, color=colour, alpha=0.5,
                label=f"{c['file']} (data)")
        ax.plot(x, [r["stress_fit"] * scale for r in rows], "-", lw=1.5, color=colour,
                label=f"{c['file']} (fit)")
        axr.plot(x, [r["residual"] * scale for r in rows], ".", ms=2, color=colour)
    if monotone:
        # The law's tail (g_c / g)^3 is long: show the openings where some curve still holds
        # more than 1 % of its peak.
        x_end = max(
            max((r["gap"] for r in c["rows"]
                 if abs(r["stress_data"]) > 0.01 * max(q["stress_data"] for q in c["rows"])),
                default=c["rows"][-1]["gap"])
            for c in curves.values())
        ax.set_xlim(min(r["gap"] for c in curves.values() for r in c["rows"]), 1.3 * x_end)
    ax.set_ylabel(ylabel)
    ax.set_title("plyform fit: measured and fitted curves")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    axr.axhline(0.0, color="k", lw=0.8)
    axr.set_xlabel(xlabel)
    axr.set_ylabel("fit - data")
    axr.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
