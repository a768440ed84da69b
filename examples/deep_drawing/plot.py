#!/usr/bin/env python3
"""Plots and pictures of hot deep-drawing runs (examples/deep_drawing), with matplotlib.

    /usr/bin/python3 plot.py curves PNG LABEL=OUTDIR [LABEL=OUTDIR ...]
    /usr/bin/python3 plot.py parts PNG OUTDIR [TIME]
    /usr/bin/python3 plot.py maps PNG LABEL=OUTDIR [LABEL=OUTDIR ...]

curves: punch force against stroke of every run given (the first one's interface points,
energies, heat ledger and layer slip next to it); each OUTDIR must hold results.json
(check.py). parts: the deformed blank of one run at TIME (default: the last state), the
quarter mirrored to the whole part, four views: the upper and the lower skin coloured by the
adhesive intensity beta (the paper's fig. 13), the temperature, and the skins' plastic strain
(the paper's fig. 12). maps: the upper skin of each run seen from above, coloured by beta,
side by side (study.py). Drawn with matplotlib's 3-D polygons (no display, no OpenGL needed);
the VTU states are read with VTK.
"""

import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import check  # noqa: E402  (the VTU and CSV readers)


def csv_rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items() if k != "state"} for r in csv.DictReader(f)]


def curves(png, runs):
    fig, ax = plt.subplots(2, 3, figsize=(16, 9))
    (a_force, a_beta, a_energy), (a_heat, a_slip, a_temp) = ax
    first = None
    for label, outdir in runs:
        res = json.load(open(os.path.join(outdir, "results.json")))
        s, f = np.array(res["punch"]).T
        a_force.plot(s, f / 1000.0, label=label)
        first = first or (label, outdir, res)
    a_force.set(xlabel="punch stroke (mm)", ylabel="punch force, whole part (kN)",
                title="punch force against stroke")
    a_force.legend()
    label, outdir, res = first
    for what, pt in res.get("points", {}).items():
        a_beta.plot(np.array(pt["time"]) * 1e3, pt["beta"],
                    label=f"{what}: node {pt['node']} from ({pt['x0'][0]:.0f}, {pt['x0'][1]:.0f})")
    a_beta.set(xlabel="time (ms)", ylabel="adhesive intensity beta", ylim=(-0.05, 1.05),
               title=f"beta at three points of the upper interface ({label})")
    a_beta.legend(fontsize=8)
    g = csv_rows(os.path.join(outdir, "glstat.csv"))
    t = np.array([r["time"] for r in g]) * 1e3
    for key in ("external_work", "internal", "contact", "kinetic", "hourglass"):
        a_energy.plot(t, [r[key] / 1000.0 for r in g], label=key.replace("_", " "))
    a_energy.plot(t, [(r["kinetic"] + r["internal"] + r["hourglass"] + r["contact"]) / 1000.0
                      for r in g], "k:", label="kinetic + internal + hourglass + contact")
    a_energy.set(xlabel="time (ms)", ylabel="energy (J)", title=f"energy books ({label})")
    a_energy.legend(fontsize=8)
    h = csv_rows(os.path.join(outdir, "heat.csv"))
    th = np.array([r["time"] for r in h]) * 1e3
    for key, name in (("stored", "stored in the blank"), ("contact", "through the tools"),
                      ("friction", "friction"), ("plastic", "plastic work")):
        a_heat.plot(th, [r[key] / 1000.0 for r in h], label=name)
    a_heat.set(xlabel="time (ms)", ylabel="heat since t = 0 (J)",
               title=f"heat ledger ({label}; stored = sum of the paths)")
    a_heat.legend(fontsize=8)
    slip = np.array(res["slip_edge"])
    a_slip.plot(slip[:, 0] * 1e3, slip[:, 1], label="upper skin's edge minus the core's")
    a_slip.plot(slip[:, 0] * 1e3, slip[:, 2], label="lower skin's edge minus the core's")
    a_slip.set(xlabel="time (ms)", ylabel="x of the skin's edge minus the core's (mm)",
               title=f"layer slip at the blank's edge, x axis ({label})")
    a_slip.legend(fontsize=8)
    tp = csv_rows(os.path.join(outdir, "tprint.csv"))
    by_node = {}
    for r in tp:
        by_node.setdefault(int(r["node"]), []).append((r["time"], r["temperature"]))
    for what, pt in res.get("points", {}).items():
        if pt["node"] in by_node:
            tt, tv = np.array(by_node[pt["node"]]).T
            a_temp.plot(tt * 1e3, tv, label=f"{what}: node {pt['node']}")
    a_temp.set(xlabel="time (ms)", ylabel="temperature (C)",
               title="temperature at the three points (upper skin)")
    a_temp.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=100)


def mirrored(points, cells, full):
    """The quarter's polygons and their copies mirrored about x = 0 and y = 0."""
    polys = [points[c] for c in cells]
    if full:
        return polys, 1
    out = []
    for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1)):
        out += [q * np.array([sx, sy, 1.0]) for q in polys]
    return out, 4


def parts(png, outdir, time=None):
    seq = check.states(outdir)
    t, path = seq[-1] if time is None else min(seq, key=lambda s: abs(s[0] - time))
    pts, pd, cd, conn = read_cells(path)
    part = cd["part"].astype(int)
    full = bool(np.any(pts[:, 0] < -1.0))
    views = [(3, "beta", "upper skin: adhesive intensity beta", (0.0, 1.0), 35),
             (1, "beta", "lower skin (seen from below): beta", (0.0, 1.0), -35),
             (3, "temperature", "upper skin: temperature (C)", None, 35),
             (1, "plastic_strain", "lower skin (seen from below): plastic strain", None, -35)]
    fig = plt.figure(figsize=(14, 11))
    for k, (pid, field, title, lim, elev) in enumerate(views):
        ax = fig.add_subplot(2, 2, k + 1, projection="3d")
        cells = conn[part == pid]
        if field in pd:
            vals = np.nanmean(pd[field][cells], axis=1)
        elif field in cd:
            vals = cd[field][part == pid]
        else:
            ax.set_title(f"{title}: not in this run")
            continue
        polys, copies = mirrored(pts, cells, full)
        vals = np.tile(vals, copies)
        lo, hi = lim or (np.nanmin(vals), np.nanmax(vals))
        cmap = plt.get_cmap("viridis" if field != "temperature" else "inferno")
        colors = cmap(np.clip((np.nan_to_num(vals, nan=lo) - lo) / max(hi - lo, 1e-12), 0, 1))
        ax.add_collection3d(Poly3DCollection(polys, facecolors=colors, edgecolors="none"))
        ext = np.abs(pts[np.isin(np.arange(len(pts)), cells.ravel())]).max(axis=0)
        ax.set(xlim=(-ext[0], ext[0]), ylim=(-ext[1], ext[1]), zlim=(-ext[0], 0.6 * ext[0]))
        ax.view_init(elev=elev, azim=-60)
        ax.set_box_aspect((1, 1, 0.8))
        ax.set_axis_off()
        sm = plt.cm.ScalarMappable(cmap=cmap, norm=plt.Normalize(lo, hi))
        fig.colorbar(sm, ax=ax, shrink=0.6)
        ax.set_title(title)
    fig.suptitle(f"{os.path.basename(os.path.normpath(outdir))} at t = {t * 1e3:.2f} ms"
                 + ("" if full else " (the quarter model mirrored)"))
    fig.tight_layout()
    fig.savefig(png, dpi=90)


def maps(png, runs):
    """The upper skin of each run seen from above, coloured by beta, side by side."""
    from matplotlib.collections import PolyCollection

    fig, axes = plt.subplots(1, len(runs), figsize=(5.2 * len(runs), 5), squeeze=False)
    for ax, (label, outdir) in zip(axes[0], runs):
        _, path = check.states(outdir)[-1]
        pts, pd, cd, conn = read_cells(path)
        cells = conn[cd["part"].astype(int) == 3]
        if "beta" not in pd:
            vals = np.full(len(cells), np.nan)
        else:
            vals = np.nanmean(pd["beta"][cells], axis=1)
        polys, copies = mirrored(pts, cells, bool(np.any(pts[:, 0] < -1.0)))
        coll = PolyCollection([q[:, :2] for q in polys], array=np.tile(vals, copies),
                              cmap="viridis", clim=(0.0, 1.0), edgecolors="none")
        coll.cmap.set_bad("lightgrey")
        ax.add_collection(coll)
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_title(label if "beta" in pd else f"{label} (no beta: tiebreak)")
        ax.set_xlabel("x (mm)")
    fig.colorbar(coll, ax=axes[0].tolist(), shrink=0.8, label="beta, upper interface")
    fig.savefig(png, dpi=90)


def read_cells(path):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    pts = vtk_to_numpy(g.GetPoints().GetData())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray()).reshape(-1, 4)
    pd = {g.GetPointData().GetArrayName(k): vtk_to_numpy(g.GetPointData().GetArray(k))
          for k in range(g.GetPointData().GetNumberOfArrays())}
    cd = {g.GetCellData().GetArrayName(k): vtk_to_numpy(g.GetCellData().GetArray(k))
          for k in range(g.GetCellData().GetNumberOfArrays())}
    return pts, pd, cd, conn


def main(argv):
    if len(argv) >= 3 and argv[0] == "curves":
        curves(argv[1], [a.split("=", 1) for a in argv[2:]])
    elif len(argv) >= 3 and argv[0] == "maps":
        maps(argv[1], [a.split("=", 1) for a in argv[2:]])
    elif len(argv) in (3, 4) and argv[0] == "parts":
        parts(argv[1], argv[2], float(argv[3]) if len(argv) == 4 else None)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
