#!/usr/bin/env python3
"""Checks a run of the deformable test model (generate.py) and draws its figures.

    check.py RUNDIR [--plots DIR]

RUNDIR holds deformable.json (generate.py) and what `plyform run` wrote there: cohesive.csv
(the two interface points), glstat.csv, rbdout.csv (the tool's position), results.pvd and its
VTU states. Prints each check with its figures; exits 1 when one fails. With --plots, writes
into DIR:
  deformable_pressure.png   the interface pressure along the block's centre line at several
                            instants (compression under the tool, tension at the peel front)
  deformable_points.png     pressure and beta against time at the two points (paper fig. 10)
  deformable_section.png    the deformed centre section with sigma_zz and the interface
                            pressure, at three instants (paper fig. 9)
  deformable_energy.png     the energy books

References (README.md): the tensile peak of the pressure at both points is the deck's
sigma_max (the RCCM law's closed form for an opening at a rate far below the law's viscous
scale, Lambda = eta v / (omega g_c) << 1), within 5 %; each point is compressed while the tool
is above it before it is pulled open (the largest pressure before its tensile peak: after it the
freed flap may strike the plate, a transient of the coarse, undamped model that round-off sizes,
README), and carries no tension once freed (beta 0); beta stays in [0, 1]; the energy books close (glstat ratio
within 1 +- 0.02, internal energy positive, hourglass energy below 5 % of it, the contact's work
never negative); the interface's damage energy is omega = sigma_max^2 / C_N times the area it
lost (5 %). Needs /usr/bin/python3 (numpy, matplotlib, python3-vtk9).
"""

import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from histories import rows, states  # noqa: E402


def read_state(path):
    """Points (current), point arrays and cells of one VTU state, as numpy arrays."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    grid = r.GetOutput()
    pd, cd = grid.GetPointData(), grid.GetCellData()
    out = {"x": vtk_to_numpy(grid.GetPoints().GetData()).copy()}
    for name in ("displacement", "contact_pressure", "beta", "contact_state", "node_id"):
        out[name] = vtk_to_numpy(pd.GetArray(name)).copy()
    for name in ("stress", "part"):
        a = cd.GetArray(name)
        out[name] = vtk_to_numpy(a).copy() if a is not None else None
    conn = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        conn.append([ids.GetId(i) for i in range(ids.GetNumberOfIds())])
    out["cells"] = conn
    return out


def tool_x(run, part):
    """The tool's x (its centre of mass) against time, from rbdout.csv."""
    t, x = [], []
    for r in rows(os.path.join(run, "rbdout.csv")):
        if int(r["part"]) == part:
            t.append(float(r["time"]))
            x.append(float(r["x"]))
    return np.array(t), np.array(x)


def main(argv):
    if not argv:
        sys.exit(__doc__)
    run = argv[0]
    plots = argv[argv.index("--plots") + 1] if "--plots" in argv else None
    with open(os.path.join(run, "deformable.json")) as f:
        p = json.load(f)
    smax = p["sigma_max"]
    ok = True

    def report(good, text):
        nonlocal ok
        ok = ok and good
        print(f"  {'ok  ' if good else 'FAIL'} {text}")

    print(f"deformable {run}: {p['elements']} hexahedra (dx {p['dx']:g}, dz0 {p['dz0']:g}), "
          f"sigma_max {smax:g} MPa, C_N {p['cn']:g} MPa/mm")
    # --- The two interface points: pressure (positive in compression) and beta. --------------
    coh = rows(os.path.join(run, "cohesive.csv"))
    tt, tx = tool_x(run, p["tool_part"])
    hist = {}
    for name, node in p["points"].items():
        h = [(float(r["time"]), float(r["pressure"]), float(r["beta"])) for r in coh
             if int(r["node"]) == node]
        hist[name] = np.array(h)
    for name, h in hist.items():
        t, pr, beta = h[:, 0], h[:, 1], h[:, 2]
        x_point = p["point_x"][name]
        i_t = int(np.argmin(pr))
        i_c = int(np.argmax(pr))
        peak = -pr[i_t]
        err = abs(peak - smax) / smax
        report(err <= 0.05, f"point x = {x_point:g} mm: tensile peak {peak:.4f} MPa at "
               f"t = {t[i_t]:.4f} s against sigma_max {smax:g} ({100 * err:.2f} %, limit 5 %)")
        # Compression under the tool: the largest pressure before the tensile peak, while the
        # point is still bonded. After the peak the point is free and its pressure is not the
        # interface's but that of whatever strikes the plate: each node row of the peel front lets
        # go at once (the cohesive zone, E omega / sigma_max^2 = 0.24 mm, is shorter than an
        # element), the stored energy rings the freed flap, which nothing damps, and a freed node
        # may slap back onto the plate for a step or two. That strike's penalty pressure is set by
        # the step's phase, the penalty and round-off (0 to 1.7 MPa between processors, README),
        # so it is reported, not checked; what the law fixes after release is no tension.
        i_c = int(np.argmax(pr[:i_t + 1]))
        x_tool = float(np.interp(t[i_c], tt, tx))
        good = pr[i_c] > smax and abs(x_tool - x_point) < p["radius"]
        report(good, f"point x = {x_point:g} mm: compressed first, {pr[i_c]:.3f} MPa at "
               f"t = {t[i_c]:.4f} s with the tool's axis at x = {x_tool:.2f} mm (within its "
               f"radius {p['radius']:g} mm), before the tension")
        freed = np.nonzero(beta <= 0.0)[0]
        if len(freed):
            i_f = int(freed[0])
            after = pr[i_f:]
            report(after.min() >= 0.0, f"point x = {x_point:g} mm: no tension once freed "
                   f"(beta 0 from t = {t[i_f]:.4f} s): lowest pressure {after.min():.3g} MPa")
        if i_t + 1 < len(pr):
            i_s = i_t + 1 + int(np.argmax(pr[i_t + 1:]))
            if pr[i_s] > 0.0:
                x_s = float(np.interp(t[i_s], tt, tx))
                print(f"       (not checked: after the tension the freed point struck the plate "
                      f"with {pr[i_s]:.3f} MPa at t = {t[i_s]:.4f} s, the tool's axis at "
                      f"x = {x_s:.2f} mm: a transient of the undamped flap, see the README)")
        report(beta.min() >= 0.0 and beta.max() <= 1.0,
               f"point x = {x_point:g} mm: beta in [0, 1] (from {beta.max():.4g} to "
               f"{beta.min():.4g}); separated behind the tool: beta {beta[-1]:.3g} at the end")
    # --- Energy books. --------------------------------------------------------------------------
    gl = rows(os.path.join(run, "glstat.csv"))
    last = gl[-1]
    w_end = float(last["external_work"])
    live = [r for r in gl if float(r["external_work"]) > 0.01 * w_end]
    ratios = [float(r["energy_ratio"]) for r in live]
    worst = max(ratios, key=lambda x: abs(x - 1.0))
    report(abs(worst - 1.0) <= 0.02, f"energy ratio within 1 +- 0.02 once 1 % of the work is "
           f"done: worst {worst:.5f}, at the end {float(last['energy_ratio']):.5f}")
    internal = [float(r["internal"]) for r in live]
    report(min(internal) > 0.0, f"internal energy positive: lowest {min(internal):.4g} mJ, at "
           f"the end {float(last['internal']):.4g} mJ")
    hg = max(float(r["hourglass"]) / float(r["internal"]) for r in live)
    report(hg < 0.05, f"hourglass energy / internal energy, largest: {100 * hg:.2f} % (limit 5 %)")
    lowest = min(float(r["contact"]) for r in gl)
    report(lowest >= -1e-6 * w_end, f"contact energy never negative: lowest {lowest:.3g} mJ "
           f"(at the end {float(last['contact']):.4g} of {w_end:.4g} mJ of work)")
    # --- beta on every interface node of every state. ----------------------------------------
    sts = states(run)
    b_lo, b_hi = 1.0, 0.0
    field = []
    line = set(p["line_nodes"])
    for t, path in sts:
        s = read_state(path)
        b = s["beta"][np.isfinite(s["beta"])]
        b_lo, b_hi = min(b_lo, b.min()), max(b_hi, b.max())
        sel = np.array([i for i, n in enumerate(s["node_id"]) if int(n) in line])
        x0 = s["x"][sel, 0] - s["displacement"][sel, 0]
        order = np.argsort(x0)
        field.append((t, x0[order], s["contact_pressure"][sel][order], s["beta"][sel][order]))
    # The interface's damage energy against the adhesion energy omega of the area it lost:
    # omega sum A_i (1 - beta_i) over the bonded face's nodes at the end (tributary areas of
    # the regular grid), the law's books (interface_energy.csv) against the states.
    s_end = read_state(sts[-1][1])
    bonded_face = np.isfinite(s_end["beta"])
    x0 = s_end["x"] - s_end["displacement"]
    dx = p["dx"]
    wx = np.where((x0[:, 0] < 1e-6) | (x0[:, 0] > p["length"] - 1e-6), 0.5 * dx, dx)
    wy = np.where((x0[:, 1] < 1e-6) | (x0[:, 1] > p["width"] - 1e-6), 0.5 * dx, dx)
    lost = float(np.sum((wx * wy * (1.0 - s_end["beta"]))[bonded_face]))
    omega = smax ** 2 / p["cn"]
    ie = [r for r in rows(os.path.join(run, "interface_energy.csv"))
          if int(r["interface"]) == p["interface"]]
    damage = float(ie[-1]["damage"])
    err = abs(damage - omega * lost) / (omega * lost)
    report(err <= 0.05, f"interface damage energy {damage:.4g} mJ against omega times the area "
           f"lost, {omega:g} x {lost:.4g} mm^2 = {omega * lost:.4g} mJ ({100 * err:.2f} %, "
           f"limit 5 %)")
    report(b_lo >= 0.0 and b_hi <= 1.0, f"beta in [0, 1] on every interface node of the "
           f"{len(sts)} states: from {b_lo:.4g} to {b_hi:.4g}")
    tension = min(f[2].min() for f in field)
    print(f"       (largest tension in the states along the centre line: {-tension:.4f} MPa; "
          f"the states sample it every {sts[1][0] - sts[0][0]:.4g} s)")
    if plots:
        os.makedirs(plots, exist_ok=True)
        draw(p, run, plots, hist, field, sts, gl, tt, tx)
    print("deformable checks:", "all passed" if ok else "FAILED")
    return 0 if ok else 1


def draw(p, run, plots, hist, field, sts, gl, tt, tx):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    smax = p["sigma_max"]
    colours = ["tab:blue", "tab:red"]
    # Pressure along the centre line at instants spread over the slide: in each fifth of it,
    # the state with the most tension (the tension lives at the peel front, a node or two wide,
    # which a state catches near its peak only now and then).
    t0, t1 = p["t_press"], p["t_press"] + p["t_move"]
    picks = []
    for k in range(5):
        lo, hi = t0 + (t1 - t0) * k / 5, t0 + (t1 - t0) * (k + 1) / 5
        window = [f for f in field if lo <= f[0] < hi] or [field[-1]]
        picks.append(min(window, key=lambda f: f[2].min()))
    fig, ax = plt.subplots(figsize=(8, 4.5))
    cmap = plt.get_cmap("viridis")
    for k, (t, x, pr, beta) in enumerate(picks):
        c = cmap(k / 4)
        ax.plot(x, pr, "-o", ms=2.5, color=c, label=f"t = {t:.3f} s")
        ax.axvline(float(np.interp(t, tt, tx)), color=c, lw=0.8, ls=":")
    ax.axhline(-smax, color="k", lw=0.8, ls="--", label=f"-sigma_max = -{smax:g} MPa")
    ax.axhline(0.0, color="grey", lw=0.5)
    for name, xp in p["point_x"].items():
        ax.annotate(f"point x = {xp:g}", (xp, -smax), xytext=(xp, -smax - 0.2), ha="center",
                    fontsize=8, arrowprops={"arrowstyle": "->", "lw": 0.6})
    ax.set_ylim(bottom=-smax - 0.28)
    ax.set_xlabel("x along the interface, centre line [mm] (dotted: the tool's axis)")
    ax.set_ylabel("interface pressure [MPa] (compression > 0)")
    ax.set_title("Interface pressure along the centre line: compression under the tool,\n"
                 "tension at the peel front behind it, zero where it has separated", fontsize=10)
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "deformable_pressure.png"), dpi=120)
    plt.close(fig)
    # Histories at the two points (paper fig. 10).
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for (name, h), c in zip(hist.items(), colours):
        label = f"x = {p['point_x'][name]:g} mm"
        a1.plot(h[:, 0], h[:, 2], color=c, label=label)
        a2.plot(h[:, 0], h[:, 1], color=c, label=label)
    a1.set_xlabel("time [s]")
    a1.set_ylabel("adhesion intensity beta")
    a1.set_title("Adhesive intensity")
    a1.set_ylim(-0.05, 1.05)
    a1.legend()
    a2.axhline(-smax, color="k", lw=0.8, ls="--", label=f"-sigma_max = -{smax:g} MPa")
    a2.axhline(0.0, color="grey", lw=0.5)
    a2.set_xlabel("time [s]")
    a2.set_ylabel("interface pressure [MPa] (compression > 0)")
    a2.set_title("Separation pressure")
    a2.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "deformable_points.png"), dpi=120)
    plt.close(fig)
    # Deformed centre section (y = W/2 plane of the block) at three instants.
    picks = [min(sts, key=lambda s: abs(s[0] - t)) for t in (t0, 0.5 * (t0 + t1), t1)]
    fig, axes = plt.subplots(len(picks), 1, figsize=(9, 3.3 * len(picks)), layout="constrained")
    line = set(p["line_nodes"])
    for ax, (t, path) in zip(axes, picks):
        s = read_state(path)
        x0 = s["x"] - s["displacement"]
        ids = s["node_id"]
        # The centre line's plane (y = W/2 or the row of nodes nearest to it).
        ymid = x0[next(i for i in range(len(ids)) if int(ids[i]) in line), 1]
        polys, szz = [], []
        for c, conn in enumerate(s["cells"]):
            if len(conn) != 8 or ids[conn[0]] >= 100000:
                continue
            face = [n for n in conn if abs(x0[n, 1] - ymid) < 1e-6]
            if len(face) != 4:
                continue
            xz = s["x"][face][:, [0, 2]]
            centre = xz.mean(axis=0)
            order = np.argsort(np.arctan2(xz[:, 1] - centre[1], xz[:, 0] - centre[0]))
            polys.append(xz[order])
            szz.append(s["stress"][c, 2])
        pc = PolyCollection(polys, array=np.array(szz), cmap="coolwarm", edgecolors="k",
                            linewidths=0.15)
        pc.set_clim(-1.5, 1.5)
        ax.add_collection(pc)
        # The tool's cross-section: its nodes in the middle ring (y = W/2).
        ring = [i for i in range(len(ids))
                if ids[i] >= 200000 and abs(x0[i, 1] - 0.5 * p["width"]) < 1e-6]
        ring.sort(key=lambda i: ids[i])
        xy = s["x"][ring][:, [0, 2]]
        ax.fill(xy[:, 0], xy[:, 1], color="0.75", ec="k", lw=0.6)
        # The interface: its pressure on the bottom nodes of the centre line.
        sel = sorted((i for i in range(len(ids)) if int(ids[i]) in line), key=lambda i: x0[i, 0])
        sc = ax.scatter(s["x"][sel, 0], s["x"][sel, 2] - 0.6, c=s["contact_pressure"][sel],
                        cmap="PiYG_r", vmin=-1.0, vmax=1.0, s=9, marker="s")
        ax.axhline(0.0, color="k", lw=1.2)
        ax.set_xlim(-3, p["length"] + 3)
        ax.set_ylim(-1.5, max(p["height"] + 2.0 * p["radius"], s["x"][:, 2].max()) + 0.5)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.3f} s: centre section; squares below: interface pressure",
                     fontsize=9)
    axes[-1].set_xlabel("x [mm]")
    fig.colorbar(pc, ax=axes, label="sigma_zz in the block [MPa]", shrink=0.5)
    fig.colorbar(sc, ax=axes, label="interface pressure [MPa] (compression > 0)", shrink=0.5)
    fig.savefig(os.path.join(plots, "deformable_section.png"), dpi=120)
    plt.close(fig)
    # Energies.
    fig, ax = plt.subplots(figsize=(7, 4.2))
    t = [float(r["time"]) for r in gl]
    for key in ("kinetic", "internal", "hourglass", "contact", "external_work", "total"):
        ax.plot(t, [float(r[key]) for r in gl], label=key)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy [mJ]")
    ax.set_title("Energy books (glstat.csv; contact: the work of both contacts)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "deformable_energy.png"), dpi=120)
    plt.close(fig)
    print(f"  plots: {plots}/deformable_{{pressure,points,section,energy}}.png")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
