#!/usr/bin/env python3
"""Checks a DCB run of generate.py against beam theory (derivation in README.md).

    check.py RUNDIR [--plot PNG]

RUNDIR holds dcb.json, bndout.csv, nodout.csv, glstat.csv, interface_energy.csv and
cohesive.csv of `plyform run`, and check.txt, what `plyform check` printed for the deck (the
contact penalty per area as built: the interface's stiffness in compression, which the beam
reference of the peak needs). Prints each check with its figures; exits 1 when one fails.
Needs numpy and scipy (the beam reference, cohesive_beam.py); the plot needs matplotlib.
"""

import json
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import cohesive_beam  # noqa: E402
from histories import rows  # noqa: E402


def contact_penalty(run):
    """The penalty per area the interface uses in compression, from `plyform check`."""
    path = os.path.join(run, "check.txt")
    try:
        with open(path) as f:
            text = f.read()
    except OSError:
        sys.exit(f"check.py: {path} missing: write it with `plyform check DECK > {path}`")
    m = re.search(r"penalty per area slave ([0-9.e+-]+), master ([0-9.e+-]+), PENOPT (\d)", text)
    if not m:
        sys.exit(f"check.py: {path}: no 'penalty per area' line for the contact")
    slave, master, penopt = float(m.group(1)), float(m.group(2)), int(m.group(3))
    return {1: min(slave, master), 2: master, 3: slave}.get(penopt, min(slave, master))


def plate_modulus(p):
    """The arms' bending modulus: the decks hold y (and the rotations about x and z) at every
    node, so an arm bends in plane strain across its width: E / (1 - nu^2)."""
    return p["E"] / (1.0 - p.get("nu", 0.0) ** 2)


def closed_forms(p):
    e, b, h, a0 = plate_modulus(p), p["width"], p["thickness"], p["a0"]
    ei = e * b * h ** 3 / 12.0  # one arm
    g_ic = p["sigma_max"] ** 2 / p["cn"]  # omega = sigma_max^2 / C_N
    k = 2.0 * p["cn"] * b  # foundation of one arm: half the interface layer, per length
    lam = (k / (4.0 * ei)) ** 0.25
    la = lam * a0
    # Opening of the two tips per load (beam on an elastic foundation, Kanninen 1973).
    compliance = 2.0 * a0 ** 3 / (3.0 * ei) * (1 + 3 / la + 3 / la ** 2 + 1.5 / la ** 3)
    big_k = b * math.sqrt(g_ic * e * h ** 3 / 12.0)  # = sqrt(G_Ic B E I)
    peak = big_k / (a0 + 1.0 / lam)  # LEFM with the root rotation of the foundation
    return {"EI": ei, "G_Ic": g_ic, "lambda": lam, "compliance": compliance, "K": big_k,
            "peak": peak,
            "propagation": lambda d: math.sqrt(2.0 * big_k ** 3 / (3.0 * ei * d))}


def main(argv):
    if not argv:
        sys.exit(__doc__)
    run = argv[0]
    plot = argv[argv.index("--plot") + 1] if "--plot" in argv else None
    with open(os.path.join(run, "dcb.json")) as f:
        p = json.load(f)
    cf = closed_forms(p)
    # The peak: beam theory with the deck's own cohesive law (cohesive_beam.py), converged in
    # its spacing; LEFM with the root rotation is the limit of a vanishing cohesive zone.
    k_pen = contact_penalty(run)
    beam = cohesive_beam.peak_load(p, k_pen, h=0.05)
    beam_fine = cohesive_beam.peak_load(p, k_pen, h=0.025)
    print(f"DCB {run}: the cohesive beam's peak {beam['peak']:.4g} N (spacing 0.05 mm; "
          f"{beam_fine['peak']:.4g} N at 0.025), {100 * (beam['peak'] / cf['peak'] - 1):+.1f} % "
          f"from LEFM with the root rotation ({cf['peak']:.4g} N); penalty in compression "
          f"{k_pen:.4g} per area")
    try:  # the same beam with the interface lumped at the run's node spacing, for comparison
        lumped = cohesive_beam.peak_load(p, k_pen, h=p["dx"])["peak"]
        print(f"       (with the interface lumped {p['dx']} mm apart like the run's nodes: "
              f"{lumped:.4g} N, {100 * (lumped / beam['peak'] - 1):+.1f} %)")
    except RuntimeError:
        pass
    # Tip opening from nodout.
    tips = {}
    for r in rows(os.path.join(run, "nodout.csv")):
        n = int(r["node"])
        if n in (p["tip_upper"], p["tip_lower"]):
            tips.setdefault(r["time"], {})[n] = float(r["uz"])
    # The load: what the prescribed motion applies to the upper tip (bndout.csv).
    upper = set(p["tip_upper_nodes"])
    load = {}
    for r in rows(os.path.join(run, "bndout.csv")):
        if int(r["node"]) in upper:
            load[r["time"]] = load.get(r["time"], 0.0) + float(r["fz"])
    curve = []
    for t, u in tips.items():
        if len(u) == 2 and t in load:
            curve.append((float(t), u[p["tip_upper"]] - u[p["tip_lower"]], load[t]))
    curve.sort()
    # The last output is left out: at the end time the prescribed motion's constraint already
    # turns to the curve's end, where the tips stop, and its force holds that deceleration.
    curve = curve[:-1]
    ok = True

    def check(name, value, reference, tol):
        nonlocal ok
        err = abs(value - reference) / abs(reference)
        good = err <= tol
        ok = ok and good
        print(f"  {'ok  ' if good else 'FAIL'} {name}: {value:.5g} against {reference:.5g} "
              f"({100 * err:.2f} %, limit {100 * tol:.0f} %)")

    # The peak of the load smoothed over 9 outputs (the ringing, below).
    smooth = [sum(c[2] for c in curve[max(0, i - 4):i + 5]) / len(curve[max(0, i - 4):i + 5])
              for i in range(len(curve))]
    i_peak = max(range(len(curve)), key=lambda i: smooth[i])
    t_peak, d_peak, p_peak = curve[i_peak][0], curve[i_peak][1], smooth[i_peak]
    print(f"DCB {run}: dx {p['dx']}, {p['ny']} across; lambda {cf['lambda']:.4f}/mm, "
          f"peak at opening {d_peak:.4g} mm")
    lin = [(d, f) for _, d, f in curve[:i_peak] if 0.1 * d_peak < d < 0.6 * d_peak]
    stiff = sum(f * d for d, f in lin) / sum(d * d for d, f in lin)  # least squares through 0
    check("linear branch stiffness P/delta [N/mm]", stiff, 1.0 / cf["compliance"], 0.05)
    check("peak load (9 outputs smoothed) against the cohesive beam [N]", p_peak, beam["peak"],
          0.05)
    # The tip force rings with the arms' high modes (each released node sets them going): the
    # quasi-static branch is the mean over bins of 0.5 mm of opening.
    prop = [(d, f) for _, d, f in curve[i_peak:] if d > 1.5 * d_peak]
    bins = {}
    for d, f in prop:
        bins.setdefault(int((d - prop[0][0]) / 0.5), []).append((d, f))
    # A bin's mean spans the arms' ringing only when the bin is about full: the run's last,
    # partial bin (a few outputs) is left out.
    full = sorted(len(b) for b in bins.values())[len(bins) // 2]
    means = [(sum(d for d, _ in b) / len(b), sum(f for _, f in b) / len(b))
             for _, b in sorted(bins.items()) if len(b) >= max(5, full // 2)]
    worst = max(means, key=lambda x: abs(x[1] / cf["propagation"](x[0]) - 1))
    check(f"propagation branch, worst of {len(means)} bin means (opening {worst[0]:.3g} mm) [N]",
          worst[1], cf["propagation"](worst[0]), 0.05)
    spread = max(abs(f / cf["propagation"](d) - 1) for d, f in prop)
    print(f"       (single outputs ring about the branch by up to {100 * spread:.0f} %)")
    # Energy books.
    gl = rows(os.path.join(run, "glstat.csv"))
    last = gl[-1]
    ratio = float(last["energy_ratio"])
    check("energy ratio at the end", ratio, 1.0, 0.01)
    # Throughout: every row once a thousandth of the final external work has entered (before,
    # the ratio compares round-off of a model at rest).
    entered = 1e-3 * float(last["external_work"])
    worst_row = max((r for r in gl if float(r["external_work"]) > entered),
                    key=lambda r: abs(float(r["energy_ratio"]) - 1.0))
    check(f"energy ratio, farthest from 1 of every output (t = {float(worst_row['time']):.4g} s)",
          float(worst_row["energy_ratio"]), 1.0, 0.01)
    # Quasi-static: the arms' kinetic energy after the first millisecond (the tips' smooth
    # start, over which the still small strain energy is a few times the tips' motion's kinetic
    # energy: 2.2 % at 1 ms itself) stays a small share of their strain energy.
    late = [r for r in gl if float(r["time"]) > 1.1e-3 and float(r["internal"]) > 0.0]
    kin = max(late, key=lambda r: float(r["kinetic"]) / float(r["internal"]))
    kin_share = float(kin["kinetic"]) / float(kin["internal"])
    good = kin_share < 0.02
    ok = ok and good
    print(f"  {'ok  ' if good else 'FAIL'} kinetic / internal energy after 1 ms, largest: "
          f"{100 * kin_share:.2f} % at t = {float(kin['time']):.4g} s (limit 2 %, from 1.1 ms)")
    hg_share = max(float(r["hourglass"]) / float(r["internal"]) for r in gl
                   if float(r["internal"]) > 1e-3 * float(last["internal"]))
    good = hg_share < 0.05
    ok = ok and good
    print(f"  {'ok  ' if good else 'FAIL'} hourglass / internal energy, largest: "
          f"{100 * hg_share:.2f} % (limit 5 %)")
    scale = float(last["external_work"])
    lowest = min(float(r["contact"]) for r in gl)
    good = lowest >= -1e-6 * scale
    ok = ok and good
    print(f"  {'ok  ' if good else 'FAIL'} contact energy never negative: lowest {lowest:.3g}")
    # Damage energy against G_Ic times the cracked area; the crack front where beta = 1/2 on
    # the history nodes along the path.
    ie = [r for r in rows(os.path.join(run, "interface_energy.csv"))]
    # The interface's own books at every output: its work = what the law stores + damage +
    # viscous + friction + damping (docs/contact.md) less the surface book (what the surfaces'
    # own changes did), within 1 % of the work, once the work is a thousandth of its final value.
    keys = ("stored", "damage", "viscous", "friction", "damping")

    def worked(r):
        return float(r["work"]) + float(r.get("surface", 0.0))

    final_work = float(ie[-1]["work"])
    worst_books = max((r for r in ie if float(r["work"]) > 1e-3 * final_work),
                      key=lambda r: abs(sum(float(r[k]) for k in keys) / worked(r) - 1))
    check(f"the interface's books against its work, worst output (t = "
          f"{float(worst_books['time']):.4g} s; damping {float(worst_books['damping']):.3g} mJ)",
          sum(float(worst_books[k]) for k in keys), worked(worst_books), 0.01)
    damage = float(ie[-1]["damage"]) + float(ie[-1]["viscous"])
    coh = rows(os.path.join(run, "cohesive.csv"))
    t_end = coh[-1]["time"]
    front = max([p["a0"]] + [node_x(p, int(r["node"])) for r in coh
                 if r["time"] == t_end and float(r["beta"]) < 0.5])
    area = p["width"] * (front - p["a0"])
    check(f"damage energy [mJ] against G_Ic B (a - a0), a = {front:.4g} mm", damage,
          cf["G_Ic"] * area, 0.05)
    if plot:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("  (no matplotlib: no plot)")
        else:
            fig, ax = plt.subplots(figsize=(7, 4.5))
            ax.plot([d for _, d, _ in curve], [f for _, _, f in curve], label="plyform")
            dl = [0.0, 1.2 * d_peak]
            ax.plot(dl, [x / cf["compliance"] for x in dl], "--", label="beam on elastic foundation")
            dp = [d_peak * (0.8 + 0.05 * i) for i in range(200)
                  if d_peak * (0.8 + 0.05 * i) <= curve[-1][1]]
            ax.plot(dp, [cf["propagation"](x) for x in dp], ":",
                    label="LEFM propagation sqrt(2K^3 / (3 E I delta))")
            ax.axhline(beam["peak"], color="grey", lw=0.5, label="peak of the cohesive beam")
            ax.axhline(cf["peak"], color="grey", lw=0.5, ls="--",
                       label="LEFM peak with the root rotation")
            ax.set_xlabel("tip opening delta [mm]")
            ax.set_ylabel("load P [N]")
            ax.set_title(f"DCB, G_Ic = {cf['G_Ic']:.3g} N/mm, dx = {p['dx']} mm")
            ax.legend()
            fig.tight_layout()
            fig.savefig(plot, dpi=120)
            print(f"  plot: {plot}")
    print("DCB checks:", "all passed" if ok else "FAILED")
    return 0 if ok else 1


def node_x(p, node):
    """x of an upper-arm node (first row) from its id (generate.py numbering)."""
    nx = round(p["length"] / p["dx"])
    return p["length"] * ((node - 100001) % (nx + 1)) / nx


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
