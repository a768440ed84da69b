#!/usr/bin/python3
"""The forming-limit diagram and the formability map of a `plyform run` state (what
`plyform plot OUTDIR --fld ...` runs).

    /usr/bin/python3 plot_fld.py OUTDIR (--flc FILE | --keeler-n N --keeler-t T)
                                 [--state K] [--margin M] [--low-strain S]

Needs Debian's python3-matplotlib, python3-numpy and python3-vtk9 (hence /usr/bin/python3).
Reads the state results_K.vtu of OUTDIR (default: the last one results.pvd lists) and its shell
cells' formability arrays (major_strain_top, minor_strain_top, major_strain_bottom,
minor_strain_bottom, major_strain_middle, minor_strain_middle, thinning; docs/outputs.md,
"Formability"), and writes into OUTDIR:
  fld.png          every shell's (minor, major) true strain at its top and bottom surfaces
                   against the forming-limit curve (FLC), its safety margin and the strain
                   paths of uniaxial tension, plane strain, equibiaxial tension, pure shear and
                   uniaxial compression
  formability.png  the deformed part seen along its two thinnest extents, each shell coloured
                   by its category: cracks, risk of cracks, safe, low strain, thickening,
                   wrinkling tendency
  fld.csv          per shell: element, part, the six strains, thinning, the worse surface's
                   major strain less the FLC's at its minor strain (flc_distance), category
The FLC: --flc FILE, two columns (minor, major true strain; comma- or space-separated; lines
starting with #, $ or a word are skipped; minor strains increasing), or Keeler-Brazier's from
the strain-hardening exponent n and the thickness t in mm (--keeler-n, --keeler-t). The
categories and margins: docs/outputs.md. Exit status 0 on success, 1 on bad input (no state,
no shells, an unreadable curve), 2 on a usage error.
"""

import argparse
import csv
import math
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

# The categories in order of precedence, with their colours on the map and the diagram.
CATEGORIES = [
    ("cracks", "#d62728"),
    ("risk of cracks", "#ffb000"),
    ("wrinkling tendency", "#8c564b"),
    ("thickening", "#1f77b4"),
    ("low strain", "#a0a0a0"),
    ("safe", "#2ca02c"),
]
KEELER_RIGHT_SLOPE = 0.6  # de1/de2 of the FLC's right side, engineering strains (docs/outputs.md)


def fail(message, status=1):
    print(f"plyform plot: error: {message}", file=sys.stderr)
    sys.exit(status)


try:
    import numpy as np
except ImportError as e:  # a Python without Debian's packages
    fail(f"{sys.executable} cannot import {e.name}: install python3-numpy "
         "(scripts/install_deps.sh), and run with /usr/bin/python3")


def pyplot():
    """matplotlib's pyplot, imported once the inputs are read (a bad call fails fast)."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail(f"{sys.executable} cannot import {e.name}: install python3-matplotlib "
             "(scripts/install_deps.sh), and run with /usr/bin/python3")
    return plt


class Flc:
    """A forming-limit curve: major true strain as a function of the minor true strain."""

    def __init__(self, label, minor=None, major=None, keeler=None):
        self.label = label
        self.minor, self.major = minor, major
        self.keeler = keeler  # (FLD0 in engineering strain, its true strain)

    def __call__(self, e2):
        e2 = np.asarray(e2, dtype=float)
        if self.keeler is not None:
            fld0_eng, fld0 = self.keeler
            # Left: slope -1 in true strains (constant thickness strain, Hill's necking line).
            left = fld0 - e2
            # Right: e1 = FLD0 + 0.6 e2 in engineering strains, back to true strains.
            eng2 = np.expm1(np.maximum(e2, 0.0))
            right = np.log1p(fld0_eng + KEELER_RIGHT_SLOPE * eng2)
            return np.where(e2 <= 0.0, left, right)
        # A measured curve: linear between its points, its end segments extended.
        x, y = self.minor, self.major
        inside = np.interp(e2, x, y)
        lo = y[0] + (e2 - x[0]) * (y[1] - y[0]) / (x[1] - x[0])
        hi = y[-1] + (e2 - x[-1]) * (y[-1] - y[-2]) / (x[-1] - x[-2])
        return np.where(e2 < x[0], lo, np.where(e2 > x[-1], hi, inside))


def keeler_flc(n, t):
    if not (n > 0.0 and math.isfinite(n)):
        fail(f"--keeler-n {n}: the strain-hardening exponent must be positive", 2)
    if not (t > 0.0 and math.isfinite(t)):
        fail(f"--keeler-t {t}: the sheet thickness (mm) must be positive", 2)
    fld0_eng = (23.3 + 14.13 * t) * n / 0.21 / 100.0  # Keeler-Brazier, percent -> fraction
    return Flc(f"Keeler-Brazier n = {n:g}, t = {t:g} mm: FLD0 = {100 * fld0_eng:.1f} % "
               f"(true {math.log1p(fld0_eng):.3f})", keeler=(fld0_eng, math.log1p(fld0_eng)))


def read_flc(path):
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.readlines()
    except (OSError, UnicodeDecodeError) as e:
        fail(f"cannot read the FLC curve '{path}': {getattr(e, 'strerror', None) or e}")
    points = []
    for k, line in enumerate(lines, start=1):
        text = line.strip()
        if not text or text[0] in "#$*" or re.match(r"[A-Za-z_]", text):
            continue  # comments, keyword lines, a header
        fields = [f for f in re.split(r"[,\s;]+", text) if f]
        try:
            values = [float(f) for f in fields]
        except ValueError:
            fail(f"{path}:{k}: '{text}' is not two numbers (minor, major true strain)")
        if len(values) != 2 or not all(math.isfinite(v) for v in values):
            fail(f"{path}:{k}: '{text}' is not two numbers (minor, major true strain)")
        points.append(values)
    if len(points) < 2:
        fail(f"the FLC curve '{path}' has {len(points)} point(s); it needs two or more "
             "(minor, major true strain per line)")
    minor = np.array([p[0] for p in points])
    major = np.array([p[1] for p in points])
    if np.any(np.diff(minor) <= 0.0):
        k = int(np.argmax(np.diff(minor) <= 0.0))
        fail(f"the FLC curve '{path}': its minor strains must increase "
             f"({minor[k]:g} then {minor[k + 1]:g})")
    return Flc(f"FLC {os.path.basename(path)}", minor=minor, major=major)


def pick_state(outdir, state):
    """The state file and its time: results_<state>.vtu, else the last one the series has."""
    files, times = [], {}
    pvd = os.path.join(outdir, "results.pvd")
    if os.path.isfile(pvd):
        try:
            for d in ElementTree.parse(pvd).getroot().iter("DataSet"):
                name = d.get("file")
                files.append(name)
                times[name] = float(d.get("timestep", "nan"))
        except (ElementTree.ParseError, ValueError) as e:
            fail(f"cannot read {pvd}: {e}")
    if not files:
        files = sorted(f for f in os.listdir(outdir) if re.fullmatch(r"results_\d+\.vtu", f))
    if not files:
        fail(f"no state in '{outdir}' (no results.pvd or results_NNNN.vtu): is it the output "
             "folder of `plyform run`, with *DATABASE_BINARY_D3PLOT in the deck?")
    if state is None:
        name = files[-1]
    else:
        numbered = [(f, re.fullmatch(r"results_(\d+)\.vtu", os.path.basename(f))) for f in files]
        wanted = [f for f, m in numbered if m and int(m.group(1)) == state]
        if not wanted:
            fail(f"--state {state}: no results_{state:04d}.vtu among the {len(files)} states of "
                 f"'{outdir}' (0 .. {len(files) - 1})")
        name = wanted[0]
    path = os.path.join(outdir, name)
    if not os.path.isfile(path):
        fail(f"state '{path}' listed in results.pvd does not exist")
    return path, times.get(name, float("nan"))


FIELDS = ["major_strain_top", "minor_strain_top", "major_strain_bottom", "minor_strain_bottom",
          "major_strain_middle", "minor_strain_middle", "thinning"]


def read_state(path):
    try:  # the reader alone: the whole vtk package takes three times as long to import
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    except ImportError:
        fail(f"{sys.executable} cannot import vtk: install python3-vtk9 (scripts/install_deps.sh)")
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid is None or grid.GetNumberOfCells() == 0:
        fail(f"cannot read the state '{path}' (no cells)")
    cd = grid.GetCellData()
    arrays = {cd.GetArrayName(k): vtk_to_numpy(cd.GetArray(k))
              for k in range(cd.GetNumberOfArrays())}
    missing = [f for f in FIELDS if f not in arrays]
    if missing:
        fail(f"'{path}' has no shell formability arrays ({', '.join(missing)}): the model has no "
             "deformable shells, or the run was made by a plyform without them")
    points = vtk_to_numpy(grid.GetPoints().GetData())
    offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
    connectivity = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    cells = [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]
    return points, cells, arrays


def classify(s, flc, margin, low):
    """Categories and the FLC distance of every shell (docs/outputs.md, "Formability")."""
    d_top = s["major_strain_top"] - flc(s["minor_strain_top"])
    d_bottom = s["major_strain_bottom"] - flc(s["minor_strain_bottom"])
    distance = np.fmax(d_top, d_bottom)
    e1, e2 = s["major_strain_middle"], s["minor_strain_middle"]
    names = np.empty(len(e1), dtype=object)
    names[:] = "safe"
    small = np.maximum(np.abs(e1), np.abs(e2)) < low
    # Lowest precedence first: each rule overwrites the ones before it.
    names[e1 + e2 < 0.0] = "thickening"
    names[e1 < -0.5 * e2] = "wrinkling tendency"
    names[small] = "low strain"
    names[distance >= -margin] = "risk of cracks"
    names[distance >= 0.0] = "cracks"
    return names, distance


def plot_diagram(path, s, names, flc, margin, title):
    plt = pyplot()
    from matplotlib.patches import Patch

    fig, ax = plt.subplots(figsize=(10.0, 6.4), layout="constrained")
    minor = np.concatenate([s["minor_strain_top"], s["minor_strain_bottom"]])
    major = np.concatenate([s["major_strain_top"], s["major_strain_bottom"]])
    lo = min(-0.3, 1.15 * float(np.min(minor)))
    hi = max(0.3, 1.15 * float(np.max(minor)))
    x = np.linspace(lo, hi, 400)
    curve = flc(x)
    top = max(float(np.max(curve[(x > -0.5) & (x < 0.5)])) * 1.3,
              1.1 * float(np.max(major)), 0.2)
    bottom = min(-0.1, 1.1 * float(np.min(major)))
    # Below the diagonal the minor strain would exceed the major: no point can lie there.
    ax.fill_between([min(lo, bottom), max(hi, top)], [min(lo, bottom), max(hi, top)], bottom,
                    color="0.95", lw=0)
    # The strain paths from the origin, minor = beta major: uniaxial tension (beta = -1/2),
    # plane strain (0), equibiaxial tension (1), pure shear (-1), uniaxial compression (-2).
    m = np.array([0.0, top])
    for beta, label in ((-0.5, "uniaxial"), (0.0, "plane strain"), (1.0, "equibiaxial"),
                        (-1.0, "pure shear"), (-2.0, "uniaxial compression")):
        ax.plot(beta * m, m, color="0.75", lw=0.8, ls="--")
        end = 0.93 * top
        if beta < 0.0:
            end = min(end, 0.97 * lo / beta)
        elif beta > 0.0:
            end = min(end, 0.97 * hi / beta)
        ax.annotate(label, (beta * end, end), fontsize=7, color="0.45", va="bottom",
                    ha="left" if beta < 0.0 else "right" if beta > 0.0 else "center")
    ax.plot(x, curve, color="k", lw=2.0, label=flc.label)
    ax.plot(x, curve - margin, color="k", lw=1.0, ls=":",
            label=f"safety margin {margin:g} below the FLC")
    colours = dict(CATEGORIES)
    size = float(np.clip(4000.0 / len(names), 6.0, 40.0))  # a few shells: large points
    for surface, marker in (("top", "o"), ("bottom", "^")):
        for name, colour in CATEGORIES:
            pick = names == name
            if np.any(pick):
                ax.scatter(s[f"minor_strain_{surface}"][pick], s[f"major_strain_{surface}"][pick],
                           s=size, marker=marker, color=colours[name], alpha=0.8, linewidths=0)
    handles, labels = ax.get_legend_handles_labels()
    handles += [plt.Line2D([], [], ls="", marker="o", color="0.3", markersize=4),
                plt.Line2D([], [], ls="", marker="^", color="0.3", markersize=4)]
    labels += ["top surface", "bottom surface"]
    present = [(n, c) for n, c in CATEGORIES if np.any(names == n)]
    handles += [Patch(color=c) for _, c in present]
    labels += [f"{n} ({int(np.sum(names == n))})" for n, _ in present]
    ax.legend(handles, labels, fontsize=7.5, frameon=False, loc="upper left",
              bbox_to_anchor=(1.02, 1.0))
    ax.set_xlim(lo, hi)
    ax.set_ylim(bottom, top)
    ax.set_xlabel("minor true strain")
    ax.set_ylabel("major true strain")
    ax.set_title(title, fontsize=9)
    ax.grid(True, color="0.92")
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_map(path, points, shells, names, title):
    plt = pyplot()
    from matplotlib.collections import PolyCollection
    from matplotlib.patches import Patch

    extent = np.ptp(points[np.concatenate(shells)], axis=0)
    order = np.argsort(extent)  # the thinnest extent first: look along it, then the next
    # A part with depth (over 5 % of its largest extent) is also seen from the side.
    views = order[:2] if extent[order[0]] > 0.05 * extent[order[2]] else order[:1]
    colours = dict(CATEGORIES)
    fig, axes = plt.subplots(1, len(views), figsize=(6.5 * len(views), 5.6),
                             layout="constrained", squeeze=False)
    axes = axes[0]
    axis_names = "xyz"
    for ax, view in zip(axes, views):
        u, v = [a for a in (0, 1, 2) if a != view]
        # Painter's order: the shells nearest the viewer (largest coordinate along the view
        # axis) drawn last.
        depth = np.array([points[c, view].mean() for c in shells])
        sequence = np.argsort(depth)
        polygons = [points[shells[k]][:, [u, v]] for k in sequence]
        faces = [colours[names[k]] for k in sequence]
        ax.add_collection(PolyCollection(polygons, facecolors=faces, edgecolors="0.25",
                                         linewidths=0.15))
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_xlabel(axis_names[u])
        ax.set_ylabel(axis_names[v])
        ax.set_title(f"seen from +{axis_names[view]}", fontsize=9)
    present = [(n, c) for n, c in CATEGORIES if np.any(names == n)]
    axes[-1].legend([Patch(color=c) for _, c in present],
                   [f"{n} ({int(np.sum(names == n))})" for n, _ in present], loc="upper left",
                   bbox_to_anchor=(1.02, 1.0), fontsize=8, frameon=False)
    fig.suptitle(title, fontsize=9)
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv):
    p = argparse.ArgumentParser(prog="plot_fld.py", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("outdir")
    p.add_argument("--flc")
    p.add_argument("--keeler-n", type=float)
    p.add_argument("--keeler-t", type=float)
    p.add_argument("--state", type=int)
    p.add_argument("--margin", type=float, default=0.1)
    p.add_argument("--low-strain", type=float, default=0.02)
    a = p.parse_args(argv)
    if not os.path.isdir(a.outdir):
        fail(f"results folder '{a.outdir}' does not exist or is not a folder")
    keeler = a.keeler_n is not None or a.keeler_t is not None
    if a.flc is not None and keeler:
        fail("give the FLC either as --flc FILE or by --keeler-n and --keeler-t, not both", 2)
    if a.flc is None and not keeler:
        fail("no forming-limit curve: give --flc FILE or --keeler-n N --keeler-t T", 2)
    if keeler and (a.keeler_n is None or a.keeler_t is None):
        fail("Keeler's FLC needs both --keeler-n and --keeler-t", 2)
    if not (a.margin >= 0.0 and math.isfinite(a.margin)):
        fail(f"--margin {a.margin}: the safety margin must be >= 0", 2)
    if not (a.low_strain >= 0.0 and math.isfinite(a.low_strain)):
        fail(f"--low-strain {a.low_strain}: must be >= 0", 2)
    flc = read_flc(a.flc) if a.flc is not None else keeler_flc(a.keeler_n, a.keeler_t)
    state, time = pick_state(a.outdir, a.state)
    points, cells, arrays = read_state(state)
    # Shell cells with strains: the solids and the rigid parts' shells hold NaN.
    shell = np.isfinite(arrays["major_strain_middle"])
    if not np.any(shell):
        fail(f"'{state}' has no deformable shell with strains (solids and rigid parts have none)")
    index = np.flatnonzero(shell)
    s = {f: arrays[f][index] for f in FIELDS}
    names, distance = classify(s, flc, a.margin, a.low_strain)
    title = (f"{os.path.basename(os.path.normpath(os.path.abspath(a.outdir)))}: "
             f"{os.path.basename(state)}" + (f", t = {time:g}" if math.isfinite(time) else "")
             + f"; margin {a.margin:g}, low strain {a.low_strain:g}")
    written = []
    target = os.path.join(a.outdir, "fld.png")
    plot_diagram(target, s, names, flc, a.margin, title)
    written.append(target)
    target = os.path.join(a.outdir, "formability.png")
    plot_map(target, points, [cells[k] for k in index], names, f"{title}\n{flc.label}")
    written.append(target)
    target = os.path.join(a.outdir, "fld.csv")
    ids = arrays.get("element_id", np.full(len(shell), -1))[index]
    parts = arrays.get("part", np.full(len(shell), -1))[index]
    with open(target, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["element", "part"] + FIELDS + ["flc_distance", "category"])
        for k in range(len(index)):
            w.writerow([int(ids[k]), int(parts[k])] + [repr(float(s[n][k])) for n in FIELDS]
                       + [repr(float(distance[k])), names[k]])
    written.append(target)
    for name, _ in CATEGORIES:
        print(f"{name}: {int(np.sum(names == name))}")
    for w in written:
        print(f"wrote {w}")


if __name__ == "__main__":
    main(sys.argv[1:])
