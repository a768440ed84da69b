#!/usr/bin/env python3
"""Checks a hot deep-drawing run against conservation and the example's stability criteria,
reports its results and writes them to OUTDIR/results.json (plot.py and study.py read it).

    /usr/bin/python3 check.py OUTDIR PARAMS.json

Needs numpy and VTK (python3-vtk9) to read the VTU states. Criteria (each printed with its
measured value; exit 1 when one fails):
- the run ended normally (no inverted element, no instability: plyform stops on those);
- energy: |kinetic + internal + hourglass + contact - external work| within 2 % of the final
  external work at every output (the energy ratio within 1 +- 0.02);
- internal energy positive at the end; at no output below -0.1 % of the external work (while
  the blank cools on the tools, thermal contraction against the bonded layers and the tools
  does negative stress work: the stress work counts the total strain);
- hourglass energy below 5 % of the internal energy;
- no contact gives the model energy: every contact's work above -0.1 % of the external work;
- each interface's books (stored + damage + viscous + friction + damping) within 2 % of the
  external work of its own work (README: what the books leave out where the core thickens);
- the heat ledger closes: stored = the sum of the paths within 2 % of the largest path;
- the layers stay in order: no node of a layer beyond a neighbouring layer's mid-surface in any
  state, and none beyond the blank holder's face (a skin that slipped out from under the
  others rises through it unless the holder's contact takes it);
- beta in [0, 1] on every skin node in every state;
- beta = 1 in every state on the upper skin's nodes that start under the middle of the punch
  face (within a quarter of the punch's width of the centre): the punch presses them onto
  the core and the bottom hardly stretches, so there the layers neither open nor slide by
  more than hundredths of a millimetre, below the law's g_c (0.05 mm in the melt with the
  example's constants), and must stay bonded. (The lower skin there is free on its underside
  and stretches plastically over the core's inextensible fibres: it slides, README.)
"""

import json
import math
import os
import sys
from collections import defaultdict

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import layer_order  # noqa: E402
from forming_books import check_books  # noqa: E402
from histories import rows, states  # noqa: E402

PUNCH_HALF = 35.0
DIE_EDGE = 37.235 + 8.0  # the die opening's half-width plus its shoulder radius
HOLDER_PART = 13  # the blank holder (examples/common/square_cup_tools.py: node ids 1300001...)


def read_state(path, cells=False):
    x, point, cell, conn = layer_order.read_state(path)
    return (x, point, cell, conn) if cells else (x, point, cell)


part_of_node = layer_order.part_of_node


def choose_points(history, x0, p):
    """The three interface points of the paper's fig. 12, chosen from the upper skin's history
    nodes by what their beta did (the rule is printed with the choice):
    - re-heals: the largest rise of beta after its lowest value, among nodes that fell below 0.5;
    - stays bonded: the node farthest from the centre whose beta stayed 1 throughout;
    - flange: the node on the x axis that ends nearest the middle of the flange."""
    chosen = {}
    best = (0.0, None)
    for node, h in history.items():
        b = [r["beta"] for r in h]
        k = int(np.argmin(b))
        if b[k] < 0.5 and max(b[k:]) - b[k] > best[0]:
            best = (max(b[k:]) - b[k], node)
    chosen["re-heals"] = best[1]
    stay = [n for n, h in history.items() if min(r["beta"] for r in h) >= 1.0]
    if stay:
        chosen["stays bonded"] = max(stay, key=lambda n: math.hypot(*x0[n][:2]))
    flange_mid = 0.5 * (DIE_EDGE + p["blank_half"] - 15.0)
    axis = [n for n in p["axis"] if n in history and n in x0]
    if axis:
        chosen["flange"] = min(axis, key=lambda n: abs(x0[n][0] + history[n][-1].get("dx", 0.0)
                                                       - flange_mid))
    return chosen


def main(outdir, params_path):
    p = json.load(open(params_path))
    summary = json.load(open(os.path.join(outdir, "summary.json")))
    failures = []
    results = {"interface": p["interface"], "n": p["n"], "core_n": p["core_n"],
               "full": p["full"]}

    def report(name, ok, text):
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {text}")
        if not ok:
            failures.append(name)

    report("run", summary["status"] == "normal termination",
           f"{summary['status']} at t = {summary['final_time']:.6g} s, {summary['cycles']} "
           f"cycles, {summary['wall_seconds']:.0f} s wall on {summary['threads']} thread(s)")
    # The square cup's energy criteria with this example's tolerances (module docstring).
    _, books = check_books(outdir, p["interfaces"], report, balance=0.02,
                                     internal_floor=1e-3, books_tol=0.02, damping_tol=None)
    results["interface_books"] = {
        iface: {k: books[iface][-1][k] for k in ("work", "stored", "damage", "viscous",
                                                  "friction", "damping", "healing", "bonded")}
        for iface in p["interfaces"]}

    heat = rows(os.path.join(outdir, "heat.csv"))
    paths = [k for k in heat[0] if k not in ("time", "stored")]
    moved = max(max(abs(r[k]) for k in paths) for r in heat) or 1.0
    gap = max(abs(r["stored"] - sum(r[k] for k in paths)) for r in heat)
    hl = heat[-1]
    report("heat ledger", gap <= 0.02 * moved,
           f"|stored - sum of the paths| at most {gap:.4g} mJ = {100 * gap / moved:.2e} % of the "
           f"largest path; at the end stored {hl['stored']:.5g} mJ = tools {hl['contact']:.5g} "
           f"+ friction {hl['friction']:.5g} + plastic work {hl['plastic']:.5g} mJ")
    results["heat"] = {k: hl[k] for k in hl}

    # The VTU states: beta in [0, 1]; bonded in the middle of the punch face; the fields.
    seq = states(outdir)
    x_first, pd0, _ = read_state(seq[0][1])
    ids = pd0["node_id"].astype(np.int64)
    x0 = {int(n): x_first[i] for i, n in enumerate(ids)}
    skins = np.isin(part_of_node(ids), p["skins"])
    middle = (part_of_node(ids) == max(p["skins"])) & (
        np.hypot(x_first[:, 0], x_first[:, 1]) < 0.5 * PUNCH_HALF)
    cohesive = "beta" in pd0  # the tiebreak variant has no adhesion intensity
    if cohesive:
        bad_range, middle_low = 0, 1.0
        for t, path in seq:
            _, pd, _ = read_state(path)
            beta = pd["beta"][skins]
            beta = beta[np.isfinite(beta)]
            bad_range += int(np.sum((beta < 0.0) | (beta > 1.0)))
            bm = pd["beta"][middle]
            if np.any(np.isfinite(bm)):
                middle_low = min(middle_low, float(np.nanmin(bm)))
        report("beta range", bad_range == 0,
               f"{bad_range} values outside [0, 1] on the skins' nodes in {len(seq)} states")
        report("bonded under the punch", middle_low >= 1.0,
               f"lowest beta {middle_low:.6g} on the {int(np.sum(middle))} upper skin nodes that "
               f"start within {0.5 * PUNCH_HALF:.1f} mm of the centre, over {len(seq)} states")
    else:
        print("     (tiebreak interfaces: no adhesion intensity beta to check)")
    worst_cross, worst_holder, holder_side = (0, 0.0), (0, 0.0), None
    reach = 0.5 * p["blank_half"] / p["n"]
    for t, path in seq:
        x, pd, cd, conn = read_state(path, cells=True)
        ids, cell_part = pd["node_id"].astype(np.int64), cd["part"].astype(np.int64)
        c = layer_order.crossings(x, ids, conn, cell_part, min(p["skins"]), p["core"],
                                  max(p["skins"]), reach)
        if c > worst_cross[0]:
            worst_cross = (c, t)
        h, holder_side = layer_order.tool_crossings(x, ids, conn, cell_part,
                                                    (*p["skins"], p["core"]), HOLDER_PART,
                                                    holder_side)
        if h > worst_holder[0]:
            worst_holder = (h, t)
    report("layers in order", worst_cross[0] == 0,
           f"at most {worst_cross[0]} nodes beyond a neighbouring layer's mid-surface (at t = "
           f"{worst_cross[1]:.4g} s) over {len(seq)} states")
    report("layers under the holder", worst_holder[0] == 0,
           f"at most {worst_holder[0]} nodes of the blank beyond the holder's face (at t = "
           f"{worst_holder[1]:.4g} s) over {len(seq)} states")
    results["core_nodes_through_skins"] = worst_cross[0]
    _, pe, ce = read_state(seq[-1][1])
    node_part = part_of_node(pe["node_id"].astype(np.int64))
    temp = pe["temperature"]
    results["temperature_end"] = {str(pid): [float(np.nanmin(temp[node_part == pid])),
                                             float(np.nanmax(temp[node_part == pid]))]
                                  for pid in (1, 2, 3)}
    cell_part = ce["part"].astype(np.int64)
    plastic = ce["plastic_strain"]
    results["plastic_strain_max"] = {str(pid): float(np.nanmax(plastic[cell_part == pid]))
                                     for pid in p["skins"]}
    if cohesive:
        bonded = pe["beta"][np.isin(node_part, p["skins"])]
        results["bonded_share_end"] = float(np.mean(bonded[np.isfinite(bonded)] > 0.5))
    if "shear_angle" in ce:
        results["shear_angle_max"] = float(np.nanmax(np.abs(ce["shear_angle"][cell_part == 2])))
    th = ce["thickness"][cell_part == 2]
    results["core_thickness"] = [float(np.nanmin(th)), float(np.nanmax(th))]
    print(f"     temperatures at the end (C): " + ", ".join(
        f"part {k} {v[0]:.1f}-{v[1]:.1f}" for k, v in results["temperature_end"].items()))
    print(f"     skins' largest plastic strain: " + ", ".join(
        f"part {k} {v:.3f}" for k, v in results["plastic_strain_max"].items()) +
        f"; core thickness {th.min():.3f}-{th.max():.3f} mm, largest shear angle "
        f"{results.get('shear_angle_max', float('nan')):.1f} degrees" +
        (f"; {100 * results['bonded_share_end']:.1f} % of the skin nodes bonded (beta > 0.5)"
         if cohesive else ""))

    # Histories: punch force against stroke, draw-in and the layers' slip at the blank's edge.
    nodes = defaultdict(list)
    for r in rows(os.path.join(outdir, "nodout.csv")):
        nodes[int(r["node"])].append(r)
    punch = [r for r in rows(os.path.join(outdir, "rcforc.csv")) if int(r["interface"]) == 1]
    body = [r for r in rows(os.path.join(outdir, "rbdout.csv")) if int(r["part"]) == 11]
    z0 = body[0]["z"]
    scale = 1.0 / p["model_fraction"]
    ztime = [r["time"] for r in body]
    zval = [z0 - r["z"] for r in body]
    results["punch"] = [[float(np.interp(r["time"], ztime, zval)), -scale * r["fz"]] for r in punch]
    peak = max(f for _, f in results["punch"])
    half = p["blank_half"]
    draw = []
    for layer, (ex, ey, c) in enumerate(zip(p["edge_x"], p["edge_y"], p["corner"])):
        ax, ay = nodes[ex][-1], nodes[ey][-1]
        draw.append([half - ax["x"], half - ay["y"]])
    results["draw_in"] = draw
    ex = p["edge_x"]
    results["slip_edge"] = [[r0["time"], r2["x"] - r1["x"], r0["x"] - r1["x"]]
                            for r0, r1, r2 in zip(nodes[ex[0]], nodes[ex[1]], nodes[ex[2]])]
    s_end = results["slip_edge"][-1]
    print(f"     draw-in along x (lower skin, core, upper skin): "
          + ", ".join(f"{d[0]:.2f}" for d in draw) + " mm; at the edge the core's end lies "
          f"{s_end[1]:.2f} mm inside the upper skin's and {s_end[2]:.2f} mm inside the lower's")
    print(f"     punch force (whole part) at most {peak / 1000:.2f} kN; stroke "
          f"{zval[-1]:.2f} mm")

    history = defaultdict(list)
    cohesive_csv = os.path.join(outdir, "cohesive.csv")
    for r in (rows(cohesive_csv) if os.path.exists(cohesive_csv) else []):
        if int(r["interface"]) == p["interfaces"][0]:
            history[int(r["node"])].append(r)
    if history:
        for n in history:
            if n in nodes:
                for r in history[n]:
                    r["dx"] = nodes[n][-1]["x"] - x0[n][0]
        chosen = choose_points(history, x0, p)
        results["points"] = {}
        for what, n in chosen.items():
            if n is None:
                print(f"     {what}: no history node qualifies")
                continue
            b = [r["beta"] for r in history[n]]
            results["points"][what] = {"node": n, "x0": [float(v) for v in x0[n][:2]],
                                       "time": [r["time"] for r in history[n]], "beta": b}
            print(f"     point '{what}': node {n} starting at ({x0[n][0]:.1f}, {x0[n][1]:.1f}) "
                  f"mm: beta lowest {min(b):.3f}, at the end {b[-1]:.3f}")
    with open(os.path.join(outdir, "results.json"), "w") as f:
        json.dump(results, f)
    if failures:
        print(f"{len(failures)} check(s) failed: {', '.join(failures)}")
        return 1
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
