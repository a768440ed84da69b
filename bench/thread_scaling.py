#!/usr/bin/env python3
"""One and two threads on the decks of docs/speed.md (a timed example, figures printed).

    python3 thread_scaling.py PLYFORM [--before PLYFORM_BEFORE] [--rounds R] [--threads T]
                              [--only plate|punch|draw ...]

Generates three decks in a temporary folder and runs each on 1 and T threads (default 2), R
rounds (default 2), the runs of one round back to back:
  plate  the 100 x 100 Belytschko-Tsay plate, NIP 5, *MAT_003 (bench/decks/plate.py, 2,000
         cycles): the element loop alone;
  punch  the same plate under a rigid dome punch (--punch): one contact interface whose slave
         nodes are mostly far from the tool;
  draw   the hot deep drawing at --n 20 to 3 ms (examples/deep_drawing): three layers of
         ELFORM 16, five contact interfaces, computed temperatures.
With --before, a second build runs each deck right after the first, so that both see the
machine in the same state (its speed drifts within the hour). Prints each run's loop seconds
(the `time loop` line of `plyform run`) and, per deck and build, the range over the rounds and
the speed-up of T threads over one. Run it with nothing else running. Standard library only.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PLATE = os.path.join(HERE, "decks", "plate.py")
DRAW = os.path.join(HERE, "..", "examples", "deep_drawing", "generate.py")
LOOP = re.compile(r"time loop's ([0-9.]+) s wall")


def generate(workdir, only):
    decks = {}
    py = sys.executable
    if "plate" in only:
        d = os.path.join(workdir, "plate")
        subprocess.run([py, PLATE, d, "--cycles", "2000"], check=True, stdout=subprocess.DEVNULL)
        decks["plate"] = os.path.join(d, "plate.k")
    if "punch" in only:
        d = os.path.join(workdir, "punch")
        subprocess.run([py, PLATE, d, "--cycles", "2000", "--punch"], check=True,
                       stdout=subprocess.DEVNULL)
        decks["punch"] = os.path.join(d, "plate.k")
    if "draw" in only:
        d = os.path.join(workdir, "draw")
        subprocess.run([py, DRAW, d, "--n", "20", "--end", "0.003"], check=True,
                       stdout=subprocess.DEVNULL)
        decks["draw"] = os.path.join(d, "deep_drawing.k")
    return decks


def loop_seconds(plyform, deck, outdir, threads):
    p = subprocess.run([plyform, "run", deck, "-o", outdir, "--threads", str(threads)],
                       stdin=subprocess.DEVNULL, capture_output=True, text=True)
    m = LOOP.search(p.stdout + p.stderr)
    if p.returncode != 0 or m is None:
        sys.exit(f"thread_scaling.py: {plyform} run {deck} --threads {threads} exited "
                 f"{p.returncode}:\n{p.stderr[-2000:]}")
    return float(m.group(1))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("plyform")
    ap.add_argument("--before", help="a second build, run right after the first on each deck")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", nargs="+", choices=("plate", "punch", "draw"),
                    default=["plate", "punch", "draw"])
    a = ap.parse_args(argv[1:])
    builds = [("now", os.path.abspath(a.plyform))]
    if a.before:
        builds.insert(0, ("before", os.path.abspath(a.before)))
    counts = (1, a.threads)
    with tempfile.TemporaryDirectory(prefix="plyform_threads_") as work:
        decks = generate(work, a.only)
        seconds = {}  # (deck, build, threads) -> [s, ...]
        for r in range(a.rounds):
            for name, deck in decks.items():
                for build, plyform in builds:
                    for t in counts:
                        s = loop_seconds(plyform, deck, os.path.join(work, "out"), t)
                        seconds.setdefault((name, build, t), []).append(s)
                        print(f"round {r + 1}: {name:5s} {build:6s} {t} thread(s): {s:.3f} s",
                              flush=True)
    print(f"\n| deck | build | 1 thread | {a.threads} threads | speed-up |")
    print("|---|---|---|---|---|")
    for name in decks:
        for build, _ in builds:
            one, many = seconds[(name, build, 1)], seconds[(name, build, a.threads)]
            ups = [x / y for x, y in zip(one, many)]
            print(f"| {name} | {build} | {min(one):.2f}-{max(one):.2f} s | "
                  f"{min(many):.2f}-{max(many):.2f} s | {min(ups):.2f}-{max(ups):.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
