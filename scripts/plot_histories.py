#!/usr/bin/python3
"""PNG plots of the histories of a `plyform run` (what `plyform plot OUTDIR` runs).

    /usr/bin/python3 plot_histories.py OUTDIR

Needs Debian's python3-matplotlib and python3-numpy (hence /usr/bin/python3). Reads from OUTDIR
and writes next to them:
  glstat.csv   -> energies.png  energies against time (kinetic, internal, hourglass, contact,
                                external work, total) and the energy ratio
  nodout.csv   -> nodout.png    per history node: displacement and velocity components
  rcforc.csv   -> rcforc.png    per contact interface: resultant force components
  cohesive.csv -> cohesive.png  gap, pressure, shear and beta of the cohesive history nodes
  interface_energy.csv -> interface_energy.png  per interface: the contact work and the law's
                  energy books (stored, damage, viscous, friction, damping; healing)
  heat.csv     -> heat.png      the heat ledger: heat stored against the heat that entered by
                                each path, and their difference (the balance)
  tprint.csv   -> tprint.png    temperatures of the history nodes against time (thick
                                 thermal shells: their top and bottom faces dashed, dotted)
glstat.csv is required; the others are plotted when present. Exit status 0 on success, 1 when
OUTDIR or glstat.csv is missing or a file cannot be read, 2 on a usage error.
"""

import csv
import json
import os
import sys

MAX_NODE_ROWS = 8  # nodout.png: at most this many history nodes, one row each
MAX_CURVES = 12  # cohesive.png: at most this many (interface, node) curves


def fail(message, status=1):
    print(f"plyform plot: error: {message}", file=sys.stderr)
    sys.exit(status)


try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as e:  # a Python without Debian's packages
    fail(f"{sys.executable} cannot import {e.name}: install python3-matplotlib and "
         "python3-numpy (scripts/install_deps.sh), and run with /usr/bin/python3")


def read_table(path, required):
    """Columns of a CSV history file as lists of strings, keyed by header name."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.reader(f)
            header = next(reader, None)
            rows = [r for r in reader if r]
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror}")
    if header is None:
        fail(f"{path} is empty (no header line)")
    header = [h.strip() for h in header]
    missing = [c for c in required if c not in header]
    if missing:
        fail(f"{path}: missing column(s) {', '.join(missing)} (header: {','.join(header)})")
    cols = {h: [] for h in header}
    for k, r in enumerate(rows, start=2):
        if len(r) != len(header):
            fail(f"{path}:{k}: {len(r)} fields, expected {len(header)}")
        for h, v in zip(header, r):
            cols[h].append(v.strip())
    return cols


def floats(values, path, name):
    try:
        return np.array([float(v) for v in values], dtype=float)
    except ValueError as e:
        fail(f"{path}: column {name}: {e}")


def style(ax, xlabel=None, ylabel=None, title=None):
    if xlabel:
        ax.set_xlabel(xlabel)
    if ylabel:
        ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title, fontsize=10)
    ax.grid(True, color="0.9")


def plot_energies(outdir, title):
    path = os.path.join(outdir, "glstat.csv")
    names = ["time", "kinetic", "internal", "hourglass", "contact", "external_work", "total",
             "energy_ratio"]
    cols = read_table(path, names)
    d = {n: floats(cols[n], path, n) for n in names}
    t = d["time"]
    if len(t) == 0:
        fail(f"{path} has no rows")
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8.0, 6.4), sharex=True, layout="constrained",
                                 height_ratios=[2.2, 1.0])
    ax.plot(t, d["external_work"], color="0.6", lw=4.0, alpha=0.6, label="external work")
    ax.plot(t, d["total"], "k--", lw=1.2, label="total")
    ax.plot(t, d["internal"], color="C0", lw=1.5, label="internal")
    ax.plot(t, d["kinetic"], color="C3", lw=1.5, label="kinetic")
    for name, color in (("hourglass", "C2"), ("contact", "C4")):
        if np.any(d[name] != 0.0):
            ax.plot(t, d[name], color=color, lw=1.2, label=name)
    style(ax, ylabel="energy", title=title)
    ax.legend(fontsize=9, frameon=False, loc="best")
    ratio = d["energy_ratio"]
    bx.plot(t, ratio, color="k", lw=1.2)
    finite = ratio[np.isfinite(ratio)]
    if finite.size:
        lo, hi = float(finite.min()), float(finite.max())
        pad = max(0.02, 0.1 * (hi - lo))
        bx.set_ylim(max(lo - pad, 0.5), min(hi + pad, 1.5))
    bx.axhline(1.0, color="0.6", lw=0.8, ls=":")
    bx.set_xlim(float(t[0]), float(t[-1]) if t[-1] > t[0] else float(t[0]) + 1.0)
    style(bx, xlabel="time", ylabel="energy ratio")
    target = os.path.join(outdir, "energies.png")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    return target


def group(cols, key_names, path):
    """Row indices grouped by the tuple of key columns, in order of first appearance."""
    keys = list(zip(*(cols[k] for k in key_names)))
    groups = {}
    for i, k in enumerate(keys):
        groups.setdefault(k, []).append(i)
    return groups


def plot_nodout(outdir, title):
    path = os.path.join(outdir, "nodout.csv")
    comps = ["ux", "uy", "uz", "vx", "vy", "vz"]
    cols = read_table(path, ["time", "node"] + comps)
    d = {n: floats(cols[n], path, n) for n in ["time"] + comps}
    groups = group(cols, ["node"], path)
    if not groups:
        fail(f"{path} has no rows")
    nodes = list(groups)[:MAX_NODE_ROWS]
    n = len(nodes)
    fig, axes = plt.subplots(n, 2, figsize=(10.0, 1.2 + 2.1 * n), sharex=True,
                             layout="constrained", squeeze=False)
    styles = {"x": ("C0", "-"), "y": ("C1", "--"), "z": ("C2", "-.")}
    for row, key in enumerate(nodes):
        idx = np.array(groups[key])
        t = d["time"][idx]
        for col, (kind, unit) in enumerate((("u", "displacement"), ("v", "velocity"))):
            ax = axes[row][col]
            for c, (color, ls) in styles.items():
                ax.plot(t, d[kind + c][idx], color=color, ls=ls, lw=1.3, label=f"{kind}{c}")
            style(ax, ylabel=f"node {key[0]}\n{unit}")
            if row == 0:
                ax.set_title(f"{unit}", fontsize=10)
                ax.legend(fontsize=8, frameon=False, ncol=3, loc="best")
    for ax in axes[-1]:
        ax.set_xlabel("time")
    more = len(groups) - n
    fig.suptitle(title + (f"  (first {n} of {len(groups)} history nodes)" if more > 0 else ""),
                 fontsize=10)
    target = os.path.join(outdir, "nodout.png")
    fig.savefig(target, dpi=110)
    plt.close(fig)
    return target


def plot_rcforc(outdir, title):
    path = os.path.join(outdir, "rcforc.csv")
    names = ["fx", "fy", "fz"]
    cols = read_table(path, ["time", "interface"] + names)
    d = {n: floats(cols[n], path, n) for n in ["time"] + names}
    groups = group(cols, ["interface"], path)
    if not groups:
        fail(f"{path} has no rows")
    n = len(groups)
    fig, axes = plt.subplots(n, 1, figsize=(8.0, 1.2 + 2.4 * n), sharex=True,
                             layout="constrained", squeeze=False)
    for ax, (key, idx) in zip(axes[:, 0], groups.items()):
        idx = np.array(idx)
        for c, color in zip(names, ("C0", "C1", "C2")):
            ax.plot(d["time"][idx], d[c][idx], color=color, lw=1.3, label=c)
        style(ax, ylabel=f"interface {key[0]}\nforce")
        ax.legend(fontsize=8, frameon=False, ncol=3, loc="best")
    axes[-1][0].set_xlabel("time")
    fig.suptitle(title + "  resultant force on the slave side", fontsize=10)
    target = os.path.join(outdir, "rcforc.png")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    return target


def plot_cohesive(outdir, title):
    path = os.path.join(outdir, "cohesive.csv")
    names = ["gap", "pressure", "tau", "beta"]
    cols = read_table(path, ["time", "interface", "node"] + names)
    d = {n: floats(cols[n], path, n) for n in ["time"] + names}
    groups = group(cols, ["interface", "node"], path)
    if not groups:
        fail(f"{path} has no rows")
    keys = list(groups)[:MAX_CURVES]
    fig, axes = plt.subplots(2, 2, figsize=(10.0, 6.4), sharex=True, layout="constrained")
    for ax, name in zip(axes.flat, names):
        for k in keys:
            idx = np.array(groups[k])
            ax.plot(d["time"][idx], d[name][idx], lw=1.2, label=f"if {k[0]} node {k[1]}")
        style(ax, ylabel=name)
    axes[0][0].legend(fontsize=8, frameon=False, loc="best")
    for ax in axes[-1]:
        ax.set_xlabel("time")
    more = len(groups) - len(keys)
    fig.suptitle(title + "  cohesive history nodes" +
                 (f" (first {len(keys)} of {len(groups)})" if more > 0 else ""), fontsize=10)
    target = os.path.join(outdir, "cohesive.png")
    fig.savefig(target, dpi=110)
    plt.close(fig)
    return target


def plot_interface_energy(outdir, title):
    """Each interface's work next to the law's books: work = stored + damage + viscous +
    friction + damping (docs/contact.md); healing restored adhesion without work."""
    path = os.path.join(outdir, "interface_energy.csv")
    books = ["stored", "damage", "viscous", "friction", "damping"]
    names = ["work"] + books + ["healing"]
    cols = read_table(path, ["time", "interface"] + names)
    d = {n: floats(cols[n], path, n) for n in ["time"] + names}
    groups = group(cols, ["interface"], path)
    if not groups:
        fail(f"{path} has no rows")
    n = len(groups)
    fig, axes = plt.subplots(n, 1, figsize=(8.0, 1.2 + 2.6 * n), sharex=True,
                             layout="constrained", squeeze=False)
    for ax, (key, idx) in zip(axes[:, 0], groups.items()):
        idx = np.array(idx)
        t = d["time"][idx]
        ax.stackplot(t, *[d[b][idx] for b in books], labels=books, alpha=0.6)
        ax.plot(t, d["work"][idx], color="k", lw=1.4, label="work of the contact forces")
        ax.plot(t, d["healing"][idx], color="k", lw=1.0, ls="--", label="healing")
        style(ax, ylabel=f"interface {key[0]}\nenergy")
        ax.legend(fontsize=7, frameon=False, ncol=2, loc="upper left")
    axes[-1][0].set_xlabel("time")
    fig.suptitle(title + "  interface energy: work and the law's books", fontsize=10)
    target = os.path.join(outdir, "interface_energy.png")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    return target


def plot_heat(outdir, title):
    """The heat ledger: stored = the sum of the paths (docs/thermal.md)."""
    path = os.path.join(outdir, "heat.csv")
    paths = ["contact", "friction", "plastic", "convection", "radiation", "flux", "prescribed",
             "generation"]
    cols = read_table(path, ["time", "stored"] + paths)
    d = {n: floats(cols[n], path, n) for n in ["time", "stored"] + paths}
    if len(d["time"]) == 0:
        fail(f"{path} has no rows")
    t = d["time"]
    entered = sum(d[p] for p in paths)
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8.0, 6.0), sharex=True, layout="constrained",
                                 gridspec_kw={"height_ratios": [3, 1]})
    for p in paths:
        if np.any(d[p] != 0.0):
            ax.plot(t, d[p], lw=1.2, label=p)
    ax.plot(t, d["stored"], color="k", lw=1.8, label="stored")
    ax.plot(t, entered, color="k", lw=1.0, ls="--", label="sum of the paths")
    style(ax, ylabel="heat (cumulative)")
    ax.legend(fontsize=8, frameon=False, ncol=2, loc="best")
    bx.plot(t, d["stored"] - entered, color="C3", lw=1.2)
    style(bx, xlabel="time", ylabel="stored - entered")
    fig.suptitle(title + "  heat ledger", fontsize=10)
    target = os.path.join(outdir, "heat.png")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    return target


def plot_tprint(outdir, title):
    path = os.path.join(outdir, "tprint.csv")
    cols = read_table(path, ["time", "node", "temperature"])
    d = {n: floats(cols[n], path, n) for n in ["time", "temperature"]}
    groups = group(cols, ["node"], path)
    if not groups:
        fail(f"{path} has no rows")
    fig, ax = plt.subplots(figsize=(8.0, 4.5), layout="constrained")
    faces = "temperature_top" in cols  # thick thermal shells: the faces too
    if faces:
        for n in ["temperature_top", "temperature_bottom"]:
            d[n] = floats(cols[n], path, n)
    for key in list(groups)[:MAX_CURVES]:
        idx = np.array(groups[key])
        line = ax.plot(d["time"][idx], d["temperature"][idx], lw=1.3, label=f"node {key[0]}")[0]
        if faces:
            for n, dash in [("temperature_top", "--"), ("temperature_bottom", ":")]:
                ax.plot(d["time"][idx], d[n][idx], dash, lw=1.0, color=line.get_color())
    if faces:
        ax.plot([], [], "k--", lw=1.0, label="top face")
        ax.plot([], [], "k:", lw=1.0, label="bottom face")
    style(ax, xlabel="time", ylabel="temperature")
    ax.legend(fontsize=8, frameon=False, loc="best")
    fig.suptitle(title + "  temperatures of the history nodes", fontsize=10)
    target = os.path.join(outdir, "tprint.png")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    return target


def main(argv):
    if len(argv) != 1 or argv[0] in ("-h", "--help"):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    outdir = argv[0]
    if not os.path.isdir(outdir):
        fail(f"results folder '{outdir}' does not exist or is not a folder")
    glstat = os.path.join(outdir, "glstat.csv")
    if not os.path.isfile(glstat):
        fail(f"'{glstat}' not found: is '{outdir}' the output folder of `plyform run`, with "
             "*DATABASE_GLSTAT in the deck?")
    title = os.path.basename(os.path.normpath(os.path.abspath(outdir)))
    try:  # name the deck when the run's summary is there
        with open(os.path.join(outdir, "summary.json"), encoding="utf-8") as f:
            deck = json.load(f).get("deck")
        if deck:
            title = f"{os.path.basename(deck)}  ({title})"
    except (OSError, ValueError, AttributeError):
        pass
    plt.rcParams.update({"font.size": 9})
    written = [plot_energies(outdir, title)]
    for name, plot in (("nodout.csv", plot_nodout), ("rcforc.csv", plot_rcforc),
                       ("cohesive.csv", plot_cohesive),
                       ("interface_energy.csv", plot_interface_energy),
                       ("heat.csv", plot_heat), ("tprint.csv", plot_tprint)):
        if os.path.isfile(os.path.join(outdir, name)):
            written.append(plot(outdir, title))
        elif name == "nodout.csv":
            print(f"plyform plot: note: no {os.path.join(outdir, name)} (no *DATABASE_NODOUT "
                  "with *DATABASE_HISTORY_NODE in the deck): nodout.png not written",
                  file=sys.stderr)
    for w in written:
        print(f"wrote {w}")


if __name__ == "__main__":
    main(sys.argv[1:])
