#!/usr/bin/env python3
"""Plots and checks of the fundamental model (run by run.sh; needs numpy and matplotlib).

    plot.py OUTDIR

OUTDIR holds the runs of run.sh: full/ (the full cycle), full_2threads/, partial/ and
temperature_<T>/ (partial cycle at T_LO, the midpoint and T_HI), each with the generator's
parameters (<name>.json) and plyform's outputs. Every check compares the run with a closed
form of docs/contact-law.md; any failure exits 1 after all checks are printed.

Writes fundamental_forces.png (the paper's fig. 6), fundamental_damage.png (fig. 7) and
fundamental_temperature.png.
"""

import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

failures = []


def check(name, value, expected, tol, relative=True):
    err = abs(value - expected) / abs(expected) if relative else abs(value - expected)
    ok = err <= tol
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {value:.6g} against {expected:.6g} "
          f"({'relative ' if relative else ''}error {err:.3g}, tolerance {tol:g})")
    if not ok:
        failures.append(name)


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    out = {}
    for key in rows[0]:
        try:
            out[key] = np.array([float(r[key]) for r in rows])
        except ValueError:
            out[key] = np.array([r[key] for r in rows])
    return out


def run(outdir, sub, name):
    """Parameters, rcforc.csv, the history node's rows of cohesive.csv, the run's folder."""
    d = os.path.join(outdir, sub)
    with open(os.path.join(d, name + ".json")) as f:
        params = json.load(f)
    co = table(os.path.join(d, "cohesive.csv"))
    mine = co["node"] == params["history_node"]
    co = {k: v[mine] for k, v in co.items()}
    return params, table(os.path.join(d, "rcforc.csv")), co, d


def vtu_check(d, node, co, state_index=13):
    """The ParaView state `state_index` (t = 13 ms: re-healing under pressure) carries the
    point arrays beta, contact_pressure, gap, contact_state; at the history node they equal
    the row of cohesive.csv written at the same cycle."""
    try:
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError:
        print("skip VTU read-back: python3-vtk9 is not installed")
        return
    name = f"results_{state_index:04d}.vtu"
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(d, name))
    reader.Update()
    grid = reader.GetOutput()
    pd = grid.GetPointData()
    time = grid.GetFieldData().GetArray("TimeValue")
    ids = vtk_to_numpy(pd.GetArray("node_id"))
    i = int(np.where(ids == node)[0][0])
    states = ["APPROACHING", "CONTACT", "SEPARATING", "DETACHED"]
    got = [float(vtk_to_numpy(pd.GetArray(a))[i]) for a in ("beta", "contact_pressure", "gap")]
    state = states[int(vtk_to_numpy(pd.GetArray("contact_state"))[i])]
    t_state = time.GetValue(0) if time is not None else 1e-3 * state_index
    row = int(np.argmin(abs(co["time"] - t_state)))
    want = [co["beta"][row], co["pressure"][row], co["gap"][row]]
    same = (np.allclose(got, want, rtol=1e-9, atol=0) and state == co["state"][row]
            and 0.0 < got[0] < 1.0)
    print(f"{'ok  ' if same else 'FAIL'} {name}: beta, contact_pressure, gap, contact_state of "
          f"node {node} = cohesive.csv at t = {co['time'][row]:.6g} ({got}, {state})")
    if not same:
        failures.append("vtu")


def sigma_max(p, temperature):
    if temperature <= p["t_lo"]:
        return p["smax_lo"]
    if temperature >= p["t_hi"]:
        return p["smax_hi"]
    s = (temperature - p["t_lo"]) / (p["t_hi"] - p["t_lo"])
    return p["smax_lo"] + (p["smax_hi"] - p["smax_lo"]) * s * s * (3 - 2 * s)


def main(outdir):
    # --- Full cycle ------------------------------------------------------------------------
    p, rc, co, d = run(outdir, "full", "fundamental")
    area = p["slave_area"]
    smax = sigma_max(p, p["temperature"])
    gc = smax / p["cn"]
    t, fx, fz = rc["time"], rc["fx"], rc["fz"]
    curve = p["curve"]
    first_pull = (t > curve[2][0]) & (t < curve[4][0])
    second_pull = t > curve[6][0]
    check("first peak tension / area = sigma_max", -fz[first_pull].min() / area, smax, 0.03)
    # Softening branch of the history node against -sigma_max (g_c / g)^3 up to 4 g_c.
    tc, gap, pres, beta = co["time"], co["gap"], co["pressure"], co["beta"]
    branch = (tc > curve[2][0]) & (tc < curve[4][0]) & (gap > 1.2 * gc) & (gap < 4 * gc)
    ratio = pres[branch] / (-smax * (gc / gap[branch]) ** 3)
    check("softening branch P / (-sigma_max (g_c/g)^3), worst point", ratio[np.argmax(abs(ratio - 1))], 1.0, 0.05)
    hold = (t > 0.5 * (curve[1][0] + curve[2][0])) & (t < curve[2][0])
    check("pressing: friction force / normal force = mu", float(np.mean(-fx[hold] / fz[hold])), p["mu"], 0.01)
    # Second press: beta of the history node grows by the integral of zeta P dt.
    press2 = (tc >= curve[4][0]) & (tc <= curve[6][0]) & (pres > 0)
    i0 = np.argmax(press2)
    i1 = len(press2) - 1 - np.argmax(press2[::-1])
    healed = beta[i0 - 1] + p["zeta"] * np.trapz(pres[i0 - 1:i1 + 1], tc[i0 - 1:i1 + 1])
    check("re-healing: beta after the second press = integral of zeta P dt", beta[i1], min(1.0, healed), 0.02)
    b_h = beta[i1]
    pull2 = tc > curve[6][0]
    check("second peak of the history node = sigma_max beta_h^1.5", -pres[pull2].min(), smax * b_h ** 1.5, 0.03)
    # Energy: the balance of the whole model, and the interface's own books.
    gl = table(os.path.join(d, "glstat.csv"))
    worst = np.max(abs(gl["total"] - (gl["kinetic"][0] + gl["external_work"]))) / gl["external_work"][-1]
    check("energy balance |total - (kinetic0 + external work)| / external work", worst, 0.0, 0.01, relative=False)
    ie = table(os.path.join(d, "interface_energy.csv"))
    books = ie["stored"] + ie["damage"] + ie["viscous"] + ie["friction"] + ie["damping"]
    worked = ie["work"] + ie.get("surface", 0.0)
    check("interface work + surface = stored + damage + viscous + friction + damping", books[-1], worked[-1], 0.01)
    check("glstat contact energy = interface work", gl["contact"][-1], ie["work"][-1], 1e-9)
    # The last ParaView state carries the interface arrays: read it back with VTK.
    vtu_check(d, p["history_node"], co)
    # Threads: the same numbers, bit for bit.
    with open(os.path.join(d, "rcforc.csv")) as a, open(os.path.join(outdir, "full_2threads", "rcforc.csv")) as b:
        same = a.read() == b.read()
    print(f"{'ok  ' if same else 'FAIL'} rcforc.csv identical with 1 and 2 threads")
    if not same:
        failures.append("threads")

    fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax[0].plot(t * 1e3, fz, label="normal force $F_z$")
    ax[0].plot(t * 1e3, fx, label="tangential force $F_x$")
    ax[0].set_ylabel("contact force on the slave plate [N]")
    ax[0].legend()
    ax[0].set_title("Fundamental model: contact forces (paper fig. 6)")
    ax[1].plot(tc * 1e3, beta, label=r"$\beta$ (centre node)")
    ax[1].set_xlabel("time [ms]")
    ax[1].set_ylabel(r"adhesion intensity $\beta$")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "fundamental_forces.png"), dpi=120)

    # --- Partial damage --------------------------------------------------------------------
    p, rc, co, d = run(outdir, "partial", "fundamental_partial")
    g_max = p["g_max_partial"]
    check("partial damage: final beta = omega / (C_N g_max^2)", co["beta"][-1], (gc / g_max) ** 2, 0.02)
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    ax[0].plot(co["time"] * 1e3, co["beta"])
    ax[0].set_xlabel("time [ms]")
    ax[0].set_ylabel(r"$\beta$ (centre node)")
    ax[0].set_title("Partial damage (paper fig. 7)")
    sep = co["gap"] > 0
    ax[1].plot(co["gap"][sep] / gc, -co["pressure"][sep] / smax, label="plyform")
    g = np.linspace(1, g_max / gc, 50)
    ax[1].plot(g, g ** -3, "--", label=r"$(g_c/g)^3$")
    ax[1].set_xlabel(r"$g / g_c$")
    ax[1].set_ylabel(r"$-P / \sigma_{max}$")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "fundamental_damage.png"), dpi=120)

    # --- Temperature -----------------------------------------------------------------------
    fig, ax = plt.subplots(figsize=(7, 4))
    for temp in (p["t_lo"], 0.5 * (p["t_lo"] + p["t_hi"]), p["t_hi"]):
        sub = f"temperature_{temp:g}"
        pt, rt, ct, _ = run(outdir, sub, sub)
        expected = sigma_max(pt, temp)
        check(f"peak tension at T = {temp:g}: two-region cubic sigma_max", -rt["fz"].min() / area, expected, 0.03)
        sep = ct["gap"] > 0
        ax.plot(ct["gap"][sep], -ct["pressure"][sep], label=f"T = {temp:g}")
    ax.set_xlabel("gap [mm]")
    ax.set_ylabel("cohesive tension [MPa]")
    ax.set_title("Temperature dependence of the peak")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "fundamental_temperature.png"), dpi=120)

    if failures:
        print(f"plot.py: {len(failures)} check(s) failed: {', '.join(failures)}")
        return 1
    print("plot.py: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "fundamental_out"))
