#!/usr/bin/env python3
"""Writes the decks of the restart tests into DECKDIR, from the examples' generators.

    python3 make_restart_decks.py DECKDIR

restart_shell.k  the three-layer square cup (examples/square_cup: rigid punch, die and blank
                 holder, friction contacts, cohesive interfaces between the layers), coarse
                 (10 elements along the quarter blank's edge, written plainly: no backup
                 contacts, no PENOPT) and drawn 2 mm; a checkpoint every 250 cycles (about
                 1100 in all); spcforc.csv, matsum.csv, sleout.csv and elout.csv (the first
                 and last shell of the blank's first layer) on glstat's interval.
restart_solid.k  decks/block_threads.k (576 elastic hex8, one face clamped, the other pulled,
                 a lateral initial velocity); a checkpoint every 50 cycles; elout.csv (the
                 first and last hexahedron) on glstat's interval.
restart_thermal.k the same block with computed temperatures (SOLN 2, a thermal step every few
                 mechanical steps, TSF 1e5): the clamped face held at 500 K, the rest starting
                 at 300 K, of *MAT_ELASTIC_PLASTIC_THERMAL (yielding, expanding, heated by its
                 plastic work), on selective reduced hexahedra (ELFORM 2); a checkpoint every
                 50 cycles.
Standard library only.
"""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "..", "..", "examples")


def with_checkpoints(path, cycles):
    with open(path) as f:
        text = f.read()
    marker = "*CONTROL_TERMINATION"
    if marker not in text:
        sys.exit(f"make_restart_decks.py: {path} has no {marker}")
    text = text.replace(marker, f"*DATABASE_BINARY_D3DUMP\n{cycles}\n{marker}", 1)
    with open(path, "w") as f:
        f.write(text)


def element_ids(lines, keyword):
    """The ids of the elements of the first `keyword` block that are in the part of its first
    element (the cup's first blank layer, not a rigid tool; comment lines skipped)."""
    at = lines.index(keyword) + 1
    ids, part = [], None
    while at < len(lines) and not lines[at].startswith("*"):
        line = lines[at]
        if line.strip() and not line.startswith("$"):
            fields = line.split(",") if "," in line else [line[:8], line[8:16]]
            part = int(fields[1]) if part is None else part
            if int(fields[1]) == part:
                ids.append(int(fields[0]))
        at += 1
    if not ids:
        sys.exit(f"make_restart_decks.py: no {keyword} elements")
    return ids


def with_part_outputs(path, names=("SPCFORC", "MATSUM", "SLEOUT"), history=None):
    """Adds the *DATABASE_ outputs `names` on the interval of *DATABASE_GLSTAT and, with
    `history` ("SHELL" or "SOLID"), elout.csv of the first and last element of the first
    part of that kind."""
    with open(path) as f:
        lines = f.read().split("\n")
    at = lines.index("*DATABASE_GLSTAT")
    interval = lines[at + 1]
    extra = []
    for name in names:
        extra += [f"*DATABASE_{name}", interval]
    if history is not None:
        ids = element_ids(lines, f"*ELEMENT_{history}")
        extra += ["*DATABASE_ELOUT", interval, f"*DATABASE_HISTORY_{history}",
                  f"{ids[0]:10d}{ids[-1]:10d}"]
    lines[at + 2:at + 2] = extra
    with open(path, "w") as f:
        f.write("\n".join(lines))


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = os.path.abspath(argv[1])
    os.makedirs(out, exist_ok=True)
    py = sys.executable
    subprocess.run([py, os.path.join(EXAMPLES, "square_cup", "generate.py"), out, "--layers", "3",
                    "--n", "10", "--depth", "2", "--name", "restart_shell"],
                   check=True, stdout=subprocess.DEVNULL)
    with_checkpoints(os.path.join(out, "restart_shell.k"), 250)
    with_part_outputs(os.path.join(out, "restart_shell.k"), history="SHELL")
    with open(os.path.join(HERE, "decks", "block_threads.k")) as f:
        solid = f.read()
    with open(os.path.join(out, "restart_solid.k"), "w") as f:
        f.write(solid)
    with_checkpoints(os.path.join(out, "restart_solid.k"), 50)
    with_part_outputs(os.path.join(out, "restart_solid.k"), names=(), history="SOLID")
    # Steel in mm, tonne, s: c = 5e8 mm^2/(s^2 K), k = 50 N/(s K).
    thermal = solid.replace(
        "         1         1         1         0         0\n",
        "         1         1         1         0         0         0         0         1\n", 1)
    thermal = thermal.replace(
        "*END",
        "*CONTROL_SOLUTION\n2\n*CONTROL_THERMAL_SOLVER\n1,0,12\n0,0,0,1e-9,0,,,1e5\n"
        "*CONTROL_THERMAL_TIMESTEP\n0,0.5,2e-7\n*MAT_THERMAL_ISOTROPIC\n1,0.0\n5e8,50.0\n"
        "*INITIAL_TEMPERATURE_SET\n0,300.0\n*BOUNDARY_TEMPERATURE_SET\n1,0,500.0\n*END", 1)
    # The thermal elasto-plastic law with expansion (yielding: plastic-work heat), so the
    # element temperatures and the plastic work since the last thermal step are restarted too.
    elastic = "*MAT_ELASTIC\n$      MID        RO         E        PR\n         1   7.85e-9  210000.0       0.3\n"
    thermal = thermal.replace(
        elastic,
        "*MAT_ELASTIC_PLASTIC_THERMAL\n1,7.85e-9\n0,2000\n210000.0,150000.0\n0.3,0.3\n"
        "1.2e-5,1.6e-5\n20.0,5.0\n1000.0,500.0\n", 1)
    # Selective reduced hexahedra (ELFORM 2): the thermal shock at the held face rings the
    # one-point elements' hourglass modes (17 % of the largest internal energy, viscous or
    # stiffness control: a run whose results are not to be trusted).
    section = "*SECTION_SOLID\n$    SECID    ELFORM\n         1         1\n"
    if thermal.count(section) != 1:
        sys.exit("make_restart_decks.py: decks/block_threads.k changed: its *SECTION_SOLID")
    thermal = thermal.replace(section, section.replace("         1         1\n",
                                                       "         1         2\n"))
    if thermal.count("*CONTROL_SOLUTION") != 1 or "0         0         1\n" not in thermal or \
            "*MAT_ELASTIC_PLASTIC_THERMAL" not in thermal:
        sys.exit("make_restart_decks.py: decks/block_threads.k changed: its PART card or *END")
    with open(os.path.join(out, "restart_thermal.k"), "w") as f:
        f.write(thermal)
    with_checkpoints(os.path.join(out, "restart_thermal.k"), 50)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
