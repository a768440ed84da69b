#!/usr/bin/python3
"""`plyform run` end to end: results read back by VTK, threads, instability diagnosis.

    check_run.py vtk      PLYFORM DECK OUTDIR
    check_run.py threads  PLYFORM DECK OUTDIR
    check_run.py unstable PLYFORM DECK OUTDIR REGEX
    check_run.py bndout   PLYFORM DECK OUTDIR (also spcforc.csv and matsum.csv)
    check_run.py sleout   PLYFORM DECK OUTDIR

vtk       runs DECK; VTK's own reader (python3-vtk9 of Debian) reads every results_NNNN.vtu
          listed in results.pvd; the .pvd lists the states in increasing time, one file per
          state, all present; each state's points are the deck's *NODE coordinates plus the
          displacement; the displacement and velocity of every history node equal nodout.csv's
          at the same time (the deck writes states and nodout on one interval).
threads   runs DECK with --threads 1 and --threads 2: every history (.csv) and state (.vtu, .pvd)
          file byte-identical.
sleout    runs DECK (a plate thrown onto a rigid plate with friction): sleout.csv has one row
          per interface and output; its energy is the interface's work of interface_energy.csv
          and the interfaces' sum is glstat's contact energy at the same time (the same books,
          split: a consistency check); friction is interface_energy's, positive, below the
          energy, and the books close (glstat ratio within 1e-3).
unstable  runs DECK, which goes unstable: exit code non-zero, stderr matches REGEX (names the
          element or node and the time), the .pvd is valid XML whose last state is at the
          failure time, every listed .vtu is readable (by VTK when installed), and summary.json
          reports the error.

Exit status: 0 pass, 1 fail, 77 python3-vtk9 missing (vtk mode only: ctest shows a skip).
Run with Debian's /usr/bin/python3: the first python3 on PATH may lack the Debian packages.
"""

import csv
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
    return condition


def run_plyform(plyform, deck, outdir, *extra):
    shutil.rmtree(outdir, ignore_errors=True)
    p = subprocess.run([plyform, "run", deck, "-o", outdir, *extra], capture_output=True,
                       text=True, check=False)
    return p


def read_deck_nodes(deck):
    """*NODE of a fixed-format deck (8 + 3 x 16 columns): id -> (x, y, z)."""
    nodes, inside = {}, False
    with open(deck, encoding="ascii") as f:
        for line in f:
            if line.startswith("*"):
                inside = line.strip().upper() == "*NODE"
                continue
            if inside and not line.startswith("$") and line.strip():
                nodes[int(line[0:8])] = tuple(float(line[8 + 16 * i:24 + 16 * i]) for i in range(3))
    return nodes


def read_pvd(outdir):
    """[(time, file)] in the order of the collection."""
    root = ET.parse(os.path.join(outdir, "results.pvd")).getroot()
    check(root.tag == "VTKFile" and root.get("type") == "Collection", "pvd: not a VTK collection")
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def read_nodout(outdir):
    """{time: {node: row}} with floats."""
    rows = {}
    with open(os.path.join(outdir, "nodout.csv"), encoding="ascii") as f:
        for r in csv.DictReader(f):
            rows.setdefault(float(r["time"]), {})[int(r["node"])] = {
                k: float(v) for k, v in r.items() if k not in ("time", "node")}
    return rows


def vtk_reader(path):
    import vtk  # noqa: PLC0415 (imported late: the threads mode needs no VTK)
    from vtk.util.numpy_support import vtk_to_numpy  # noqa: PLC0415
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    pd = grid.GetPointData()
    return {
        "points": vtk_to_numpy(grid.GetPoints().GetData()) if grid.GetPoints() else None,
        "cells": grid.GetNumberOfCells(),
        "displacement": pd.GetArray("displacement"),
        "velocity": pd.GetArray("velocity"),
        "node_id": pd.GetArray("node_id"),
        "stress": grid.GetCellData().GetArray("stress"),
    }


def mode_vtk(plyform, deck, outdir):
    try:
        import vtk  # noqa: F401, PLC0415
    except ImportError:
        print("check_run.py: python3-vtk9 is not installed (apt-get install python3-vtk9)")
        return 77
    p = run_plyform(plyform, deck, outdir)
    if not check(p.returncode == 0, f"plyform run exited {p.returncode}: {p.stderr}"):
        return 1
    nodes = read_deck_nodes(deck)
    states = read_pvd(outdir)
    nodout = read_nodout(outdir)
    check(len(states) >= 5, f"only {len(states)} states")
    times = [t for t, _ in states]
    check(all(a < b for a, b in zip(times, times[1:])), f"pvd times not increasing: {times}")
    check(len({f for _, f in states}) == len(states), "pvd lists a file twice")
    vtus = sorted(f for f in os.listdir(outdir) if re.fullmatch(r"results_\d{4}\.vtu", f))
    check(vtus == sorted(f for _, f in states), f"pvd {states} does not list the files {vtus}")
    compared = 0
    for t, name in states:
        g = vtk_reader(os.path.join(outdir, name))
        n = g["points"].shape[0] if g["points"] is not None else 0
        if not check(n == len(nodes) and g["displacement"] is not None and g["node_id"] is not None
                     and g["velocity"] is not None, f"{name}: {n} points or arrays missing"):
            continue
        check(g["cells"] > 0 and g["stress"] is not None and g["stress"].GetNumberOfComponents()
              == 6, f"{name}: cells or 6-component stress missing")
        rows = nodout.get(t)
        check(rows is not None, f"{name}: no nodout rows at t = {t!r}")
        for i in range(n):
            nid = int(g["node_id"].GetTuple1(i))
            u = g["displacement"].GetTuple3(i)
            x0 = nodes[nid]
            for d in range(3):
                # The solver forms x = x0 + u in double precision: the same sum here is exact.
                check(g["points"][i][d] == x0[d] + u[d],
                      f"{name}: node {nid} point[{d}] {g['points'][i][d]!r} != x0 + u "
                      f"{x0[d] + u[d]!r}")
            if rows and nid in rows:
                v = g["velocity"].GetTuple3(i)
                r = rows[nid]
                for d, c in enumerate("xyz"):
                    check(u[d] == r["u" + c], f"{name}: node {nid} u{c} {u[d]!r} != nodout "
                          f"{r['u' + c]!r} at t = {t!r}")
                    check(v[d] == r["v" + c], f"{name}: node {nid} v{c} {v[d]!r} != nodout "
                          f"{r['v' + c]!r} at t = {t!r}")
                    check(g["points"][i][d] == r[c], f"{name}: node {nid} {c} != nodout")
                compared += 1
    history = len(next(iter(nodout.values()))) if nodout else 0
    check(history > 0 and compared == history * len(states),
          f"compared {compared} history-node states, expected {history} x {len(states)}")
    moved = max(abs(r["ux"]) for rows in nodout.values() for r in rows.values())
    check(moved > 1e-3, f"the history nodes hardly move (max |ux| = {moved})")
    print(f"check_run.py vtk: {len(states)} states, {compared} history-node states compared")
    return 0


def mode_threads(plyform, deck, outdir):
    out = {}
    for threads in (1, 2):
        d = os.path.join(outdir, f"threads_{threads}")
        p = run_plyform(plyform, deck, d, "--threads", str(threads))
        if not check(p.returncode == 0, f"--threads {threads} exited {p.returncode}: {p.stderr}"):
            return 1
        out[threads] = d
    # Every history and state file (summary.json holds the wall times).
    names = sorted(n for n in os.listdir(out[1]) if n.endswith((".csv", ".vtu", ".pvd")))
    check("nodout.csv" in names and "glstat.csv" in names, f"no nodout.csv or glstat.csv: {names}")
    for name in names:
        with open(os.path.join(out[1], name), "rb") as a, open(os.path.join(out[2], name),
                                                                "rb") as b:
            da, db = a.read(), b.read()
        if name in ("nodout.csv", "glstat.csv"):
            check(len(da.splitlines()) > 10, f"{name}: too few lines")
        check(da == db, f"{name} differs between 1 and 2 threads")
    print(f"check_run.py threads: {len(names)} files identical with 1 and 2 threads "
          f"({', '.join(n for n in names if n.endswith('.csv'))})")
    return 0


def mode_unstable(plyform, deck, outdir, pattern):
    p = run_plyform(plyform, deck, outdir)
    check(p.returncode != 0, "plyform run exited 0 on an unstable deck")
    m = re.search(pattern, p.stderr)
    check(m is not None, f"stderr does not match {pattern!r}: {p.stderr!r}")
    states = read_pvd(outdir)
    check(len(states) >= 2, f"pvd lists {len(states)} states")
    times = [t for t, _ in states]
    check(all(a < b for a, b in zip(times, times[1:])), f"pvd times not increasing: {times}")
    with open(os.path.join(outdir, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    check(summary["status"].startswith("error"), f"summary status {summary['status']!r}")
    check(abs(times[-1] - summary["final_time"]) <= 1e-12 * summary["final_time"],
          f"last state at {times[-1]}, failure at {summary['final_time']}")
    check(summary["final_time"] < summary["end_time"], "ran to the end")
    if m is not None and "t" in m.groupdict():
        t_msg = float(m.group("t"))
        check(abs(t_msg - summary["final_time"]) <= 1e-5 * summary["final_time"],
              f"message time {t_msg} vs final time {summary['final_time']}")
    try:
        import vtk  # noqa: F401, PLC0415
        have_vtk = True
    except ImportError:
        have_vtk = False
    for _, name in states:
        path = os.path.join(outdir, name)
        if not check(os.path.isfile(path), f"{name} listed but missing"):
            continue
        if have_vtk:
            check(vtk_reader(path)["points"] is not None, f"VTK cannot read {name}")
        else:
            ET.parse(path)  # at least well-formed up to the appended data
    print(f"check_run.py unstable: exit {p.returncode}, {len(states)} states, "
          f"'{p.stderr.strip().splitlines()[-1]}'")
    return 0


def mode_sleout(plyform, deck, outdir):
    p = run_plyform(plyform, deck, outdir)
    if not check(p.returncode == 0, f"plyform run exit {p.returncode}: {p.stderr}"):
        return 1
    rows = {}
    for name in ("sleout.csv", "interface_energy.csv", "glstat.csv"):
        path = os.path.join(outdir, name)
        if not check(os.path.exists(path), f"{name} not written"):
            return 1
        with open(path) as f:
            rows[name] = list(csv.DictReader(f))
    sle = rows["sleout.csv"]
    check(list(sle[0].keys()) == ["time", "interface", "energy", "friction"],
          f"columns {list(sle[0])}")
    books = {(r["time"], r["interface"]): r for r in rows["interface_energy.csv"]}
    glstat = {float(r["time"]): r for r in rows["glstat.csv"]}
    for r in sle:
        b = books.get((r["time"], r["interface"]))
        if not check(b is not None, f"no interface_energy row for {r}"):
            continue
        check(float(r["energy"]) == float(b["work"]), f"energy {r} against work {b['work']}")
        check(float(r["friction"]) == float(b["friction"]), f"friction {r} against {b}")
        g = glstat.get(float(r["time"]))
        if check(g is not None, f"no glstat row at {r['time']}"):
            contact = float(g["contact"])
            check(abs(float(r["energy"]) - contact) <= 1e-12 * max(abs(contact), 1.0),
                  f"sleout energy {r['energy']} against glstat contact {contact}")
    last = sle[-1]
    energy, friction = float(last["energy"]), float(last["friction"])
    check(0.0 < friction < energy, f"friction {friction} against the interface energy {energy}")
    ratio = float(rows["glstat.csv"][-1]["energy_ratio"])
    check(abs(ratio - 1.0) < 1e-3, f"energy ratio {ratio}")
    print(f"check_run.py sleout: {len(sle)} rows; at the end energy {energy:.6g} mJ, of it "
          f"friction {friction:.6g} mJ; energy ratio {ratio:.6f}")
    return 0


def mode_bndout(plyform, deck, outdir):
    """A block of Poisson's ratio 0 (4 mm long, 2 x 2 mm section), x = 0 held, x = 4 pulled by
    0.01 mm over 60 axial periods: the force the prescribed motion applies is the static
    E A u(t) / L within 1 % along the ramp (its start leaves an axial ringing of about 0.4 %)."""
    p = run_plyform(plyform, deck, outdir)
    check(p.returncode == 0, f"plyform run exit {p.returncode}: {p.stderr}")
    path = os.path.join(outdir, "bndout.csv")
    if not check(os.path.exists(path), "bndout.csv not written"):
        return 1
    with open(path) as f:
        rows = list(csv.DictReader(f))
    check(list(rows[0].keys()) == ["time", "node", "fx", "fy", "fz"], f"columns {list(rows[0])}")
    times = sorted({float(r["time"]) for r in rows})
    end = times[-1]
    worst = 0.0
    # Along the ramp u = 0.01 t / end, from a quarter of it on (the last output is left out:
    # there the constraint already turns to the curve's end, where the motion stops).
    along = [x for x in times[1:-1] if x > 0.25 * end]
    for t in along:
        at = [r for r in rows if float(r["time"]) == t]
        check(len(at) == 9, f"{len(at)} prescribed nodes at t = {t}, expected 9")
        force = sum(float(r["fx"]) for r in at)
        expected = 210000.0 * 4.0 * (0.01 * t / end) / 4.0
        worst = max(worst, abs(force / expected - 1.0))
        check(abs(force - expected) <= 0.01 * expected,
              f"pull force {force:.6g} N at t = {t:.4g} against E A u / L = {expected:.6g} N")
        check(all(abs(float(r["fy"])) < 1e-9 * expected and abs(float(r["fz"])) < 1e-9 * expected
                  for r in at), "force on directions that are not prescribed")
    print(f"check_run.py bndout: {len(along)} outputs along the ramp, largest departure "
          f"from E A u / L {100 * worst:.2f} %")
    check("*DATABASE_SECFORC" in p.stderr and "not written" in p.stderr,
          f"no warning for the output request plyform does not write: {p.stderr}")

    # spcforc.csv: the 9 held nodes at x = 0 take the pull back: their x reactions sum to
    # -E A u / L (static equilibrium of the block), and the block is at rest laterally.
    path = os.path.join(outdir, "spcforc.csv")
    if not check(os.path.exists(path), "spcforc.csv not written"):
        return 1
    with open(path) as f:
        spc = list(csv.DictReader(f))
    check(list(spc[0].keys()) == ["time", "node", "fx", "fy", "fz"], f"columns {list(spc[0])}")
    worst_spc = 0.0
    for t in along:
        at = [r for r in spc if float(r["time"]) == t]
        check(len(at) == 9, f"{len(at)} held nodes at t = {t}, expected 9")
        expected = 210000.0 * 4.0 * (0.01 * t / end) / 4.0
        reaction = sum(float(r["fx"]) for r in at)
        worst_spc = max(worst_spc, abs(-reaction / expected - 1.0))
        check(abs(reaction + expected) <= 0.01 * expected,
              f"held end's reaction {reaction:.6g} N at t = {t:.4g}, expected {-expected:.6g} N")

    # matsum.csv: one part, whose books are glstat's (the same numbers: one part takes all the
    # stress work, hourglass energy and nodal mass), and whose stored energy is the static
    # E A u^2 / (2 L) along the ramp within 2 % (the force is within 1 %, the energy goes as
    # its square).
    path = os.path.join(outdir, "matsum.csv")
    if not check(os.path.exists(path), "matsum.csv not written"):
        return 1
    with open(path) as f:
        ms = list(csv.DictReader(f))
    with open(os.path.join(outdir, "glstat.csv")) as f:
        gl = {float(r["time"]): r for r in csv.DictReader(f)}
    check(list(ms[0].keys()) == ["time", "part", "rigid", "internal", "kinetic", "hourglass",
                                 "momentum_x", "momentum_y", "momentum_z"],
          f"columns {list(ms[0])}")
    worst_ms = 0.0
    for r in ms:
        t = float(r["time"])
        check(r["part"] == "1" and r["rigid"] == "0", f"row {r}")
        g = gl.get(t)
        if not check(g is not None, f"no glstat row at t = {t}"):
            continue
        for key in ("internal", "kinetic", "hourglass"):
            a, b = float(r[key]), float(g[key])
            check(abs(a - b) <= 1e-9 * max(abs(b), 1e-12),
                  f"matsum {key} {a:.9g} against glstat {b:.9g} at t = {t}")
        if t in along:
            u = 0.01 * t / end
            expected = 210000.0 * 4.0 * u * u / (2.0 * 4.0)
            worst_ms = max(worst_ms, abs(float(r["internal"]) / expected - 1.0))
            check(abs(float(r["internal"]) - expected) <= 0.02 * expected,
                  f"stored energy {float(r['internal']):.6g} mJ at t = {t:.4g} against "
                  f"E A u^2 / 2L = {expected:.6g} mJ")
    print(f"check_run.py bndout: spcforc reaction within {100 * worst_spc:.2f} % of -E A u / L, "
          f"matsum internal within {100 * worst_ms:.2f} % of E A u^2 / 2L")
    return 0


def main(argv):
    if len(argv) < 4:
        print(__doc__)
        return 2
    mode, plyform, deck, outdir = argv[:4]
    if mode == "vtk":
        status = mode_vtk(plyform, deck, outdir)
    elif mode == "threads":
        status = mode_threads(plyform, deck, outdir)
    elif mode == "bndout":
        status = mode_bndout(plyform, deck, outdir)
    elif mode == "sleout":
        status = mode_sleout(plyform, deck, outdir)
    elif mode == "unstable" and len(argv) == 5:
        status = mode_unstable(plyform, deck, outdir, argv[4])
    else:
        print(__doc__)
        return 2
    for f in FAILURES[:20]:
        print("FAIL:", f)
    if FAILURES:
        print(f"check_run.py {mode}: {len(FAILURES)} failures")
        return 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
