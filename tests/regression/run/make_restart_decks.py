#!/usr/bin/env python3
"""Writes the decks of the restart tests into DECKDIR, from the examples' generators.

    python3 make_restart_decks.py DECKDIR

restart_shell.k  the three-layer square cup (examples/square_cup: rigid punch, die and blank
                 holder, friction contacts, cohesive interfaces between the layers), coarse
                 (10 elements along the quarter blank's edge) and drawn 2 mm; a checkpoint
                 every 1000 cycles.
restart_solid.k  decks/block_threads.k (576 elastic hex8, one face clamped, the other pulled,
                 a lateral initial velocity); a checkpoint every 50 cycles.
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
    with_checkpoints(os.path.join(out, "restart_shell.k"), 1000)
    with open(os.path.join(HERE, "decks", "block_threads.k")) as f:
        solid = f.read()
    with open(os.path.join(out, "restart_solid.k"), "w") as f:
        f.write(solid)
    with_checkpoints(os.path.join(out, "restart_solid.k"), 50)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
