#!/usr/bin/env python3
"""What computing the temperatures costs in a forming run (a timed example, figures printed).

    python3 thermal_cost.py PLYFORM [--n N] [--depth D] [--threads T] [--solver 11|12]

Generates the three-layer square cup (examples/square_cup: aluminium 0.25 / core 1.00 /
aluminium 0.25 mm, two cohesive interfaces, rigid punch, die and blank holder) twice: once
mechanics only, once coupled (SOLN 2: every layer conducts, every contact is _THERMAL (the
tools and the two cohesive interfaces), a variable thermal step growing to TMAX = 100
mechanical steps, the blank starting at 250 C and its symmetry plane x = 0 held at 150 C, so that heat
flows), runs both on the same machine one
after the other and prints the wall times, the thermal steps and the thermal share of the
cycle. Run it with nothing else running on the machine. Standard library only.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
GENERATOR = os.path.join(HERE, "..", "examples", "square_cup", "generate.py")

# mm, t, s: c in mm^2 / (s^2 K), k in N / (s K).
THERMAL = """*CONTROL_SOLUTION
2
*CONTROL_THERMAL_SOLVER
1,0,{solver}
*CONTROL_THERMAL_TIMESTEP
1,0.5,1e-12
*MAT_THERMAL_ISOTROPIC
1,0.0
9.0e8,200.0
*MAT_THERMAL_ORTHOTROPIC
2,0.0,0,0.0,2
1.7e9,5.0,5.0,0.3
0,0,0,1,0,0
0,1,0,
*INITIAL_TEMPERATURE_SET
0,523.0
*BOUNDARY_TEMPERATURE_SET
1,0,423.0
"""


def make(base, solver, out):
    text = open(base).read()
    for pid in (1, 2, 3):  # the three layers get TMID 1 (skins) and 2 (core)
        old = f"{pid:10d}{pid:10d}{1 if pid != 2 else 2:10d}{0:10d}{1:10d}\n"
        new = old[:-1] + f"{0:10d}{0:10d}{2 if pid == 2 else 1:10d}\n"
        if old not in text:
            sys.exit(f"thermal_cost.py: the generated deck has no part card for part {pid}")
        text = text.replace(old, new, 1)
    # Every contact carries heat: the tools (which do not conduct: they keep their
    # temperature) and the two cohesive interfaces, with a closed-gap conductance of
    # 5000 W/(m^2 K) (5 in t/(s^3 K), the deck's mm, t, s) up to 0.1 mm.
    lines = text.split("\n")
    kept = []
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("*CONTACT_") and line.endswith("_ID"):
            kept.append(line[:-3] + "_THERMAL_ID")
            kept.extend(lines[i + 1:i + 5])  # ID card, cards 1, 2, 3
            kept.append("0,0,5.0,0.0,0.1,0.5,0,0")
            i += 5
            continue
        kept.append(line)
        i += 1
    text = "\n".join(kept)
    text = text.replace("*END", THERMAL.format(solver=solver) + "*END", 1)
    with open(out, "w") as f:
        f.write(text)


def run(plyform, deck, outdir, threads):
    subprocess.run([plyform, "run", deck, "-o", outdir, "--threads", str(threads)], check=True,
                   stdout=subprocess.DEVNULL)
    with open(os.path.join(outdir, "summary.json")) as f:
        return json.load(f)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("plyform")
    p.add_argument("--n", type=int, default=20)
    p.add_argument("--depth", type=float, default=3.0)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--solver", type=int, default=11)
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([sys.executable, GENERATOR, tmp, "--layers", "3", "--n", str(a.n),
                        "--depth", str(a.depth), "--name", "cup"], check=True,
                       stdout=subprocess.DEVNULL)
        base = os.path.join(tmp, "cup.k")
        hot = os.path.join(tmp, "cup_thermal.k")
        make(base, a.solver, hot)
        cold = run(a.plyform, base, os.path.join(tmp, "mech"), a.threads)
        warm = run(a.plyform, hot, os.path.join(tmp, "thermal"), a.threads)
    share = (warm["wall_seconds"] - cold["wall_seconds"]) / cold["wall_seconds"]
    print(f"three-layer cup, n = {a.n}, depth {a.depth} mm, {a.threads} thread(s), "
          f"solver {a.solver}: {cold['elements']} elements, {cold['cycles']} cycles")
    print(f"  mechanics only: {cold['wall_seconds']:.3f} s wall")
    print(f"  coupled:        {warm['wall_seconds']:.3f} s wall ({warm['cycles']} cycles)")
    print(f"  {warm['thermal_steps']} thermal steps "
          f"({warm['cycles'] / max(1, warm['thermal_steps']):.0f} cycles each), "
          f"{warm['thermal_iterations']} conjugate-gradient iterations")
    print(f"  the thermal passes cost {100.0 * share:.1f} % of the mechanical cycle")


if __name__ == "__main__":
    main()
