#!/usr/bin/env python3
"""Studies of the hot deep drawing (examples/deep_drawing): the same draw with one thing
changed, run one after the other, each checked (check.py), the punch forces and the beta maps
side by side, and a table of the results.

    /usr/bin/python3 study.py PLYFORM OUTDIR --study NAME [--n N] [--threads T] [--reuse DIR]

NAME:
  interface    the interlayer coupling: two-way (the cohesive contacts and a plain contact of
               the core against each skin), one-way (the cohesive contacts alone, the paper's
               model), tiebreak (LS-DYNA's built-in *CONTACT_..._TIEBREAK, OPTION 2)
  temperature  the blank's (and so the interfaces') temperature at the start: 240, 260, 280 C
  sigma_max    the melt's adhesive strength SMAX_HI: 0.25, 0.5, 1.0 MPa
  mesh         the coarse mesh N (default 28, the test suite's) and the default mesh (40). A
               REGRESSION check, not a verification: the punch force against stroke of the
               two meshes, each smoothed over 1 mm of stroke, within 10 % of the default
               mesh's wherever that exceeds a quarter of its peak (the draw proper, past the
               first bending over the tools' radii), and within 10 % of its peak everywhere
               (exit 1 when not)

--reuse DIR: a finished run of the first variant's deck (run.sh's OUTDIR, e.g. the ctest
example.deep_drawing's): when DIR holds deep_drawing.k identical to the deck this study
generates for its first variant and that run's summary.json, the study checks and uses that run
instead of running the same deck again (the mesh study in the suite saves its coarse run).

Writes OUTDIR/study_NAME_forces.png (with the curves of the first variant), OUTDIR/
study_NAME_maps.png and OUTDIR/study_NAME.md. Needs numpy, matplotlib and VTK.
"""

import argparse
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
COARSE_N, DEFAULT_N = 28, 40  # skin elements along the quarter's edge (generate.py --n)

STUDIES = {
    "interface": [("two-way", ["--interface", "two-way"]), ("one-way", ["--interface", "one-way"]),
                  ("tiebreak", ["--interface", "tiebreak"])],
    "temperature": [(f"{t} C", ["--set", f"T_BLANK={t}"]) for t in (240, 260, 280)],
    "sigma_max": [(f"sigma_max {s} MPa", ["--set", f"SMAX_HI={s}"]) for s in (0.25, 0.5, 1.0)],
}


def finished_run(reuse, deck):
    """The run directory in `reuse` (run.sh's OUTDIR) of the same deck, or None."""
    if not reuse:
        return None
    done, run_dir = os.path.join(reuse, "deep_drawing.k"), os.path.join(reuse, "deep_drawing")
    if not (os.path.isfile(done) and os.path.isfile(os.path.join(run_dir, "summary.json"))):
        return None
    with open(done) as a, open(deck) as b:
        return run_dir if a.read() == b.read() else None


def run_variant(plyform, outdir, name, options, threads, reuse=None):
    gen = [sys.executable, os.path.join(HERE, "generate.py"), outdir, "--name", name] + options
    subprocess.run(gen, check=True)
    run_dir = finished_run(reuse, os.path.join(outdir, name + ".k"))
    if run_dir:
        print(f"study.py: {name}: the same deck's run in {run_dir} ({' '.join(options)})",
              flush=True)
    else:
        run_dir = os.path.join(outdir, name)
        print(f"study.py: {name}: plyform run ({' '.join(options)})", flush=True)
        subprocess.run([plyform, "run", os.path.join(outdir, name + ".k"), "-o", run_dir,
                        "--threads", str(threads)], check=True, stdout=subprocess.DEVNULL,
                       stdin=subprocess.DEVNULL)
    checked = subprocess.run([sys.executable, os.path.join(HERE, "check.py"), run_dir,
                              os.path.join(outdir, name + ".json")], capture_output=True,
                             text=True)
    print(checked.stdout, end="", flush=True)
    failed = [line.split("check(s) failed: ", 1)[1] for line in checked.stdout.splitlines()
              if "check(s) failed: " in line]
    return run_dir, checked.returncode == 0, failed[0] if failed else ""


def smoothed(res, width=1.0):
    s, f = np.array(res["punch"]).T
    grid = np.linspace(s.min(), s.max(), 400)
    kernel = [np.mean(f[(s >= g - 0.5 * width) & (s <= g + 0.5 * width)]) for g in grid]
    return grid, np.array(kernel)


def main():
    a = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    a.add_argument("plyform")
    a.add_argument("outdir")
    a.add_argument("--study", required=True, choices=sorted(STUDIES) + ["mesh"])
    a.add_argument("--n", type=int, default=COARSE_N)
    a.add_argument("--threads", type=int, default=2)
    a.add_argument("--reuse", default=None)
    args = a.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    if args.study == "mesh":
        variants = [(f"n {args.n}", ["--n", str(args.n)]),
                    (f"n {DEFAULT_N}", ["--n", str(DEFAULT_N)])]
    else:
        variants = [(label, ["--n", str(args.n)] + opts) for label, opts in STUDIES[args.study]]
    runs, table, status = [], [], 0
    for k, (label, opts) in enumerate(variants):
        name = f"{args.study}_{k}"
        run_dir, ok, failed = run_variant(args.plyform, args.outdir, name, opts, args.threads,
                                          args.reuse if k == 0 else None)
        status |= 0 if ok else 1
        res = json.load(open(os.path.join(run_dir, "results.json")))
        summary = json.load(open(os.path.join(run_dir, "summary.json")))
        runs.append((label, run_dir, res))
        peak = max(f for _, f in res["punch"])
        bonded = res.get("bonded_share_end")
        table.append(f"| {label} | {'passed' if ok else 'failed: ' + failed} | "
                     f"{summary['energy_ratio']:.4f} | {peak / 1000:.1f} | "
                     + (f"{100 * bonded:.1f} %" if bonded is not None else "-") + " | "
                     f"{res['draw_in'][1][0]:.2f} / {res['draw_in'][2][0]:.2f} | "
                     f"{summary['wall_seconds']:.0f} s |")
    plot = [os.path.join(HERE, "plot.py")]
    pairs = [f"{label}={run_dir}" for label, run_dir, _ in runs]
    subprocess.run([sys.executable] + plot + ["curves", os.path.join(
        args.outdir, f"study_{args.study}_forces.png")] + pairs, check=True)
    subprocess.run([sys.executable] + plot + ["maps", os.path.join(
        args.outdir, f"study_{args.study}_maps.png")] + pairs, check=True)
    lines = [f"# Study: {args.study}", "",
             "| variant | checks | energy ratio | peak punch force (kN) | skin nodes bonded at "
             "the end | draw-in x, core / upper skin (mm) | wall |",
             "|---|---|---|---|---|---|---|"] + table
    if args.study == "mesh":
        (s1, f1), (s2, f2) = smoothed(runs[0][2]), smoothed(runs[1][2])
        grid = np.linspace(0.0, min(s1.max(), s2.max()), 400)
        coarse, fine = np.interp(grid, s1, f1), np.interp(grid, s2, f2)
        peak = fine.max()
        drawn = fine > 0.25 * peak
        pointwise = float(np.max(np.abs(coarse - fine)[drawn] / fine[drawn]))
        overall = float(np.max(np.abs(coarse - fine)) / peak)
        ok = pointwise <= 0.10 and overall <= 0.10
        status |= 0 if ok else 1
        lines += ["", f"Regression check (not a verification): where the default mesh's punch "
                  f"force exceeds a quarter of its peak ({peak / 1000:.1f} kN), the two meshes "
                  f"differ by at most {100 * pointwise:.1f} % of it; over the whole stroke by at "
                  f"most {100 * overall:.1f} % of the peak ({'within' if ok else 'NOT within'} "
                  f"10 %)."]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(args.outdir, f"study_{args.study}.md"), "w") as f:
        f.write(text)
    print(text)
    return status


if __name__ == "__main__":
    sys.exit(main())
